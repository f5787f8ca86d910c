// A mesh made ready for light transport once, then shared read-only by whatever traces it:
// the solver (and a re-solve with other settings), the moving-light shader and the HDR view.
#ifndef RadiosityCore_PreparedScene_h
#define RadiosityCore_PreparedScene_h

#include "Base/ProcessGroup.h"
#include "Geometry/Scene.h"
#include "Geometry/Visibility.h"

#include <memory>
#include <string>

namespace radiosity
{

/// One Embree scene of the mesh's polygons and, for transport, the mesh's geometry with
/// its patches split where their parts cannot see each other (SplitSeparatedPatches) and
/// its enclosed elements marked (MarkEnclosed). Both depend on the points, the polygons
/// and the patch ids only, never on reflectance or lights, so the holder of one may pass it
/// to every solve, relight and picture of the same mesh. Geometry's patch order is the one
/// the solver's patch basis is written in.
struct PreparedScene
{
  std::shared_ptr<const Visibility> Rays;
  std::shared_ptr<const SceneGeometry> Geometry; ///< null where only rays were prepared
  int SplitPatches = 0;                          ///< patches SplitSeparatedPatches added
  /// The mesh it was made for, by size (a check against being given another mesh's).
  long long Points = 0, Polygons = 0, Corners = 0;

  /// True when it was made for a mesh of `mesh`'s sizes, with geometry where `transport`.
  bool Fits(const SceneMesh& mesh, bool transport) const;
};

/// The rays of `mesh` (a picture needs no more), the BVH built on `threads` threads (0:
/// all). Returns an empty string or Embree's error.
std::string PrepareRays(const SceneMesh& mesh, int threads, PreparedScene& scene);

/// Adds the geometry to `scene`, first its rays where it has none. The hemisphere probes of
/// MarkEnclosed run on `threads` threads, divided among the ranks of `group`: all of them
/// must call this together. Returns an empty string or why the scene cannot be prepared
/// (the same on every rank).
std::string PrepareTransport(const SceneMesh& mesh, int threads, const ProcessGroup& group, PreparedScene& scene);

} // namespace radiosity

#endif
