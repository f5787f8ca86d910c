// The final gather's inputs: where each point and element is evaluated (its frame), the
// emitting patches, and the sampling steps the passes share. Only the final gather's own
// files use them (Solve/GatherPass.h, Solve/FinalGather.cxx).
#ifndef RadiosityCore_GatherFrames_h
#define RadiosityCore_GatherFrames_h

#include "Base/SampleStream.h"
#include "Geometry/Scene.h"

#include <vector>

namespace radiosity
{
namespace gathering
{

/// Where and how a point is evaluated: the mean of the elements around it.
struct PointFrame
{
  Vec3 Origin; ///< the point, a quarter of the way into its elements and a hair off them
  Vec3 Normal;
  /// An edge of its first element, so the gather's directions turn with the scene and the
  /// answer does not depend on its placement.
  Vec3 Edge;
  Vec3 Reflectance;
  bool Used = false;
  /// For an element's frame, the element: its rays then start at points spread over it,
  /// so they estimate its mean (a centroid overrates an element facing a lamp up close).
  int Element = -1;
  double Radius = 0; ///< for an element's frame, its farthest corner from the centroid
};

/// An emitter this many element radii away (from its bounding sphere) lights an element all
/// but linearly: the sweep takes its mean at the centre (Gather::SpreadDirectLight). The
/// centre underrates the mean of a 1/d^2 falloff by about (r/d)^2: 0.1 % here (at ten radii
/// it was 1 %, and TestPipeline's metered exposure moved by 1.6 %).
constexpr double kFar = 30.0;

/// An emitting patch: its elements' loops for Lambert's formula, its fan triangles for
/// shadow-ray ends, its emission per solution.
struct Emitter
{
  std::vector<int> Elements;
  std::vector<Vec3> Triangles; ///< a, b, c per fan triangle, each lifted off the surface
  std::vector<double> Cdf;     ///< cumulative area fraction per triangle
  Vec3 Centre, Normal;
  double Radius = 0;
  bool Planar = true;
  /// Where every element emits alike: the patch's outline (start, end pairs; the shared
  /// edges cancel), so Lambert's formula costs its outline, not its elements (a lamp meshed
  /// fine is thousands), and that exitance per solution.
  std::vector<Vec3> Outline;
  std::vector<Vec3> Exitance;
};

/// Whether any of `count` values has a positive channel (an emitting element; light that
/// arrives).
bool AnyPositive(const Vec3* values, int count);

/// Points at one place (equal coordinates) on one smooth surface of one material: the
/// corners a curved model's triangles each hold of their own (the CGAL bunny: 237,203
/// points for 89,163 elements). Each maps to the first of them whose elements' normals
/// agree with its own within 30 degrees, and that one is gathered for all (a quarter of the
/// bunny's solve, docs/benchmarks.md); a crease or another material keeps its own. -1 for points no polygon
/// uses.
std::vector<int> Representatives(const SceneMesh& mesh, const SceneGeometry& g);

/// Each representative point's frame from the elements around it (area-weighted, its own
/// only: the copies' elements, averaged in, could put a saddle's point under one of them),
/// and its emission per solution into `pointEmission`; other points stay unused.
std::vector<PointFrame> MakeFrames(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& emission,
  int solutions, const std::vector<int>& rep, std::vector<Vec3>& pointEmission);

/// Each open element as a frame of its own, for a sweep over the element solution (its rays
/// start at points spread over it, Gather::Spot).
std::vector<PointFrame> ElementFrames(const SceneMesh& mesh, const SceneGeometry& g);

/// The emitting, unenclosed elements grouped by patch.
std::vector<Emitter> MakeEmitters(
  const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& emission, int solutions);

/// A point of stratum r of `count` over the emitter, by area, from three numbers in [0, 1).
Vec3 EmitterPointAt(const Emitter& emitter, int r, int count, const double* xi);

/// The same, drawing its numbers from `random`.
Vec3 EmitterPoint(const Emitter& emitter, int r, int count, SampleStream& random);

/// A step coprime to n near n times the golden ratio's fraction: r -> (r * step + o) % n
/// visits every stratum once, far from the order it is given in.
int CoprimeStep(int n);

} // namespace gathering
} // namespace radiosity

#endif
