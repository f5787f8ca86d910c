// Segment occlusion queries against the scene's polygons with Embree.
#ifndef RadiosityCore_Visibility_h
#define RadiosityCore_Visibility_h

#include "Base/ProcessGroup.h"
#include "Geometry/Scene.h"

#include <memory>
#include <string>

namespace radiosity
{

/// Builds one Embree scene (polygons triangulated, non-convex ones by ear clipping) and answers "is the open segment
/// between two points blocked?" from any number of threads at once.
class Visibility
{
public:
  explicit Visibility(const SceneMesh& mesh);
  /// `fixed`'s scene, shared as it is (an Embree instance, not a copy), with `objects`
  /// beside it: moving objects that block rays at the cost of their own triangles. Hits on
  /// the objects report polygon -1; hits on `fixed` read as `fixed` reports them.
  Visibility(std::shared_ptr<const Visibility> fixed, const SceneMesh& objects);
  ~Visibility();
  Visibility(const Visibility&) = delete;
  Visibility& operator=(const Visibility&) = delete;

  /// Empty when the device and scene were built, otherwise Embree's error.
  const std::string& Error() const;

  /// True when a polygon intersects the segment strictly between `from` and `to`. The
  /// caller offsets the endpoints off their surfaces; `tolerance` (a fraction of the
  /// segment) keeps the far endpoint's own surface from counting as a blocker.
  bool Occluded(const Vec3& from, const Vec3& to, double tolerance = 1e-4) const;

  /// Closest hit along a ray: the triangle's source polygon and the barycentric coordinates
  /// in that triangle; returns false on a miss. Used to render images of a solution.
  struct Hit
  {
    int Polygon = -1;
    int Corner[3] = { -1, -1, -1 }; ///< point ids of the hit triangle
    double U = 0, V = 0;            ///< weights of Corner[1] and Corner[2]
    double Distance = 0;            ///< from the origin, in world units
  };
  bool Intersect(const Vec3& origin, const Vec3& direction, Hit& hit) const;

  /// Intersect for up to 8 rays from one origin (neighbouring pixels of a camera): one
  /// coherent packet through Embree where the device takes packets of 8, one ray at a time
  /// otherwise; the hits are the same. `found[i]` is false where ray i misses.
  static constexpr int PacketSize = 8;
  void IntersectPacket(const Vec3& origin, const Vec3* directions, int count, Hit* hits, bool* found) const;

  /// Occluded for up to 8 segments that end at one point (shadow rays to a light): one
  /// packet where the device takes them; `blocked[i]` as Occluded(from[i], to, tolerance).
  void OccludedPacket(const Vec3* from, const Vec3& to, int count, double tolerance, bool* blocked) const;

private:
  /// A hit as Embree reports it, in the mesh's terms; false for a miss.
  bool Decode(unsigned instance, unsigned geometry, unsigned triangle, float u, float v, double distance,
    Hit& hit) const;
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

/// Splits every patch whose elements fall into parts that cannot see each other (a wall
/// standing across a floor patch): otherwise light received on one side would be shot
/// again from the other, through the wall. Returns the number of patches added (new ones
/// get the next indices). Call before MarkEnclosed.
int SplitSeparatedPatches(const Visibility& rays, const SceneMesh& mesh, SceneGeometry& geometry);

/// Marks the elements that every one of 17 rays over their hemisphere (the normal, and 8
/// each at 45 and 80 degrees from it) finds closed off: each ray hits a back face (it
/// started inside an object) or a surface touching the element. Elements where at least
/// 9 of them are closed off are marked sheltered (SceneGeometry::Sheltered). An element
/// lying face to face on another surface (FaceToFace) is closed off too where at least 9
/// rays are, or all but those ending on a lamp: the rays start past the face on it (the
/// floor under a box, with a lamp shut in the box). Closed-off elements neither send
/// light nor show any (RadiositySolver::Solve); they leave their patch's open area.
/// With `threads` (0: all) per process; a group's ranks probe every Ranks-th element each.
void MarkEnclosed(const Visibility& rays, const SceneMesh& mesh, SceneGeometry& geometry, int threads = 0,
  const ProcessGroup& group = ProcessGroup());

} // namespace radiosity

#endif
