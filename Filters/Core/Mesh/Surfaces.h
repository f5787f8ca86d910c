// The mesher's elements stitched into surfaces: elements on one plane (and of one caller
// key) share an OpenMesh surface, so neighbours share their corners; small polygons of a
// surface share patches; the surfaces flattened into the mesher's output.
#ifndef RadiosityCore_Surfaces_h
#define RadiosityCore_Surfaces_h

#include "Mesh/CoplanarGroups.h"
#include "Mesh/Mesher.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <array>
#include <map>
#include <tuple>
#include <vector>

namespace radiosity
{

/// The elements of one input polygon before they are stitched into a surface.
struct Piece
{
  std::vector<Vec3> Corners; // flattened, `Sides` per element
  std::vector<int> Sides;
  std::vector<int> LocalPatch;
  int PatchCount = 0;
};

class SurfaceAssembly
{
public:
  /// `quantum`: points closer than this are one point; `noise`: how far points may be off
  /// their places (MeshNoise); `centre`: the scene's, which plane offsets are measured from
  /// (so they stay small wherever the scene is placed); `planes`: every polygon of the
  /// mesher's list, which are grouped into surfaces (CoplanarGroups.h) before any is added.
  SurfaceAssembly(double quantum, double noise, const Vec3& centre, const MesherOptions& options,
    const std::vector<PolygonPlane>& planes);

  /// Polygon `polygon` of the mesher's list (added in the list's order), `loop` (its
  /// distinct corners), cut into `piece`, from input cell `source`. `outline`: the input
  /// cell's own corners where overlaps cut it (else empty): the first polygon of a surface
  /// hangs the surface's patch grid from its first edge, and a cut's corners are float
  /// noise away from where a turned scene puts them.
  void Add(const std::vector<Vec3>& loop, const Piece& piece, int polygon, int source,
    const std::vector<Vec3>& outline = {});

  /// Every surface's points and elements into `out`, patch ids compacted to 0..patches-1.
  void Flatten(MeshedPolygons& out) const;

private:
  // OpenMesh stores float points by default; radiosity scenes span many orders of magnitude.
  struct DoublePrecision : OpenMesh::DefaultTraits
  {
    typedef OpenMesh::Vec3d Point;
    typedef OpenMesh::Vec3d Normal;
    /// Each element remembers its input polygon and its patch.
    FaceTraits
    {
      int Source = -1;
      int Patch = -1;
      int Polygon = -1; ///< in the mesher's list (a warped input polygon is several)
    };
  };
  using SurfaceMesh = OpenMesh::PolyMesh_ArrayKernelT<DoublePrecision>;
  /// A surface's plane: its founder's unit normal and offset (CoplanarGroups).
  struct Plane
  {
    Vec3 Normal;
    double Offset = 0;
  };
  /// The surface of polygon `polygon` (its group's), made on its group's first polygon.
  int SurfaceOf(int polygon, const std::vector<Vec3>& loop, const std::vector<Vec3>& outline);
  /// The first patch id of the piece and how many new patches it takes: a polygon that
  /// fits in one patch shares it with its surface's others in the same PatchSize cell.
  std::pair<int, int> PatchesOf(int surface, const std::vector<Vec3>& loop, const Piece& piece);
  /// The piece's elements into the surface, welded to the corners already there.
  void Stitch(int surface, const Piece& piece, int polygon, int source, int firstPatch);

  const double Quantum, Noise;
  const Vec3 Centre;
  const MesherOptions& Options;
  int Patches = 0;
  CoplanarGroups Groups;
  std::vector<Plane> Planes;
  std::vector<SurfaceMesh> Meshes;
  std::vector<std::map<std::array<long long, 3>, SurfaceMesh::VertexHandle>> Welds;
  /// Per surface: the origin and in-plane axes of its patch-sharing grid.
  std::vector<std::array<Vec3, 3>> GridFrames;
  std::map<std::tuple<int, long long, long long>, int> SharedPatch;
};

} // namespace radiosity

#endif
