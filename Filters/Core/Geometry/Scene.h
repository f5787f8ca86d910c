// The radiosity scene as the core sees it: polygons (elements) grouped into patches.
#ifndef RadiosityCore_Scene_h
#define RadiosityCore_Scene_h

#include "Base/Vec3.h"

#include <limits>
#include <string>
#include <vector>

namespace radiosity
{

/// Input mesh, flat arrays so a VTK adapter can fill it without VTK types leaking in.
/// Conventions used everywhere in the core:
/// - radiosity B and emission E are exitances (W/m^2 per channel), not radiances;
/// - a polygon's front side is given by the right-hand rule; emitters emit only forward.
struct SceneMesh
{
  std::vector<Vec3> Points;
  std::vector<int> Offsets{ 0 }; ///< polygon i uses Connectivity[Offsets[i], Offsets[i+1])
  std::vector<int> Connectivity;
  std::vector<Vec3> Reflectance; ///< per polygon, RGB in [0, 1]
  std::vector<int> LightId;      ///< per polygon, -1 or 0..k-1
  std::vector<int> PatchId;      ///< per polygon; empty: every polygon is its own patch
  /// How finely the coordinates were given: float input's spacing at its farthest
  /// coordinate (a surface there can sit that far off another it touches), 0 for double.
  double PointQuantum = 0;

  int NumberOfPolygons() const { return static_cast<int>(Offsets.size()) - 1; }
  int PolygonSize(int i) const { return Offsets[i + 1] - Offsets[i]; }
  const int* Polygon(int i) const { return Connectivity.data() + Offsets[i]; }
  void AddPolygon(const std::vector<int>& ids);
};

/// Empty, or why a cell's reflectance is not three numbers in [0, 1] (the one check, used
/// wherever reflectance is read).
std::string ReflectanceProblem(const Vec3& reflectance, long long cell);

/// Checks the input contract. Returns an empty string when valid, otherwise a message that
/// names the offending array, the item and the value. On success sets `numberOfLights`
/// (the cell lights; none is a problem unless the scene has `pointLights`).
std::string ValidateScene(const SceneMesh& mesh, int& numberOfLights, int pointLights = 0);

/// Geometry derived once per solve: element normals, areas, centroids and patch groups.
struct SceneGeometry
{
  std::vector<Vec3> Normal; ///< unit, per element
  std::vector<double> Area;
  std::vector<Vec3> Centroid;
  std::vector<std::vector<int>> PatchElements; ///< elements of each (compacted) patch
  std::vector<int> ElementPatch;               ///< compacted patch index of each element
  std::vector<double> PatchArea;
  /// Elements no light can reach or leave (inside a closed object, e.g. floor under a
  /// cabinet), and each patch's area without them: a patch's unshot energy is spread over
  /// its open area, or a patch straddling a footprint would shoot part of its power into
  /// the object and lose it (see MarkEnclosed). All open until marked.
  std::vector<char> Enclosed;
  std::vector<double> PatchOpenArea;
  /// Elements most of whose hemisphere is blocked at once (the ceiling just above a lamp's
  /// back, the floor at a cabinet's foot): dark for a reason that stops at their edge, so
  /// vertex averages leave them out where open neighbours exist, and patch links do not land
  /// on them. Enclosed implies sheltered.
  std::vector<char> Sheltered;
  double SceneDiagonal = 0;
  /// How far off its surface a ray starts: a millionth of the scene, and above the noise
  /// of float input far from the origin (there a flat polygon's corners can sit a float
  /// step off its plane, and a ray lifted less starts behind its own surface).
  double RayLift = 0;

  explicit SceneGeometry(const SceneMesh& mesh);
};

/// How far element e's farthest corner lies from its centroid: the radius of a ball about
/// the centroid that holds the element.
double ElementRadius(const SceneMesh& mesh, const SceneGeometry& g, int e);

/// The area mean of value(x) over element e, sampled at the centroids of its fan
/// triangles (centroid, corner, next corner): for where one centroid misjudges a quantity
/// that changes fast across the element. NaN when the element has no positive fan area.
template <typename PointValue>
double FanAverage(const SceneMesh& mesh, const SceneGeometry& g, int e, PointValue value)
{
  const Vec3& c = g.Centroid[e];
  const int* ids = mesh.Polygon(e);
  const int count = mesh.PolygonSize(e);
  double sum = 0, area = 0;
  for (int i = 0; i < count; ++i)
  {
    const Vec3& a = mesh.Points[ids[i]];
    const Vec3& b = mesh.Points[ids[(i + 1) % count]];
    const double part = 0.5 * Dot(Cross(a - c, b - c), g.Normal[e]);
    if (part > 0)
    {
      sum += part * value((c + a + b) * (1.0 / 3.0));
      area += part;
    }
  }
  return area > 0 ? sum / area : std::numeric_limits<double>::quiet_NaN();
}

} // namespace radiosity

#endif
