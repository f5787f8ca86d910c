#include "Geometry/Visibility.h"

#include "Geometry/FaceContact.h"
#include "Geometry/Polygon.h"
#include "Base/WorkerPool.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <numeric>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace radiosity
{

struct Visibility::Internals
{
  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;
  std::string Error;
  std::vector<int> TrianglePolygon;        // source polygon of each triangle
  std::vector<unsigned> TriangleCorners;   // 3 point ids per triangle
  Vec3 Origin;                             // points are stored relative to this, in float
  unsigned MeshId = RTC_INVALID_GEOMETRY_ID;
  std::shared_ptr<const Visibility> Fixed; // the instanced scene of a layered one
};

namespace
{
/// One Embree device for the process: a device starts its own threads, and scenes (one
/// per solve, relight or picture) share them. Made on first use, kept to the end.
RTCDevice SharedDevice()
{
  static const RTCDevice device = rtcNewDevice(nullptr);
  return device;
}

/// Embree's last error on this thread, as words; empty if none.
std::string DeviceError(RTCDevice device)
{
  const RTCError code = rtcGetDeviceError(device);
  return code == RTC_ERROR_NONE ? std::string()
                                : "Embree error " + std::to_string(static_cast<int>(code)) + " while building the scene";
}

/// The polygons of `mesh` as an Embree triangle geometry, points relative to `origin`;
/// `polygonOf` and `corners` (if given) receive each triangle's polygon and point ids.
RTCGeometry TriangleGeometry(RTCDevice device, const SceneMesh& mesh, const Vec3& origin, std::vector<int>& polygonOf,
  std::vector<unsigned>& corners)
{
  std::vector<Vec3> loop;
  for (int i = 0; i < mesh.NumberOfPolygons(); ++i)
  {
    const int* ids = mesh.Polygon(i);
    loop.clear();
    for (int v = 0; v < mesh.PolygonSize(i); ++v)
    {
      loop.push_back(mesh.Points[ids[v]]);
    }
    const std::vector<int> triangle = Triangulate(loop.data(), static_cast<int>(loop.size()));
    for (size_t t = 0; t + 2 < triangle.size(); t += 3)
    {
      corners.insert(corners.end(), { static_cast<unsigned>(ids[triangle[t]]),
                                      static_cast<unsigned>(ids[triangle[t + 1]]),
                                      static_cast<unsigned>(ids[triangle[t + 2]]) });
      polygonOf.push_back(i);
    }
  }
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
    RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.Points.size()));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0,
    RTC_FORMAT_UINT3, 3 * sizeof(unsigned), polygonOf.size()));
  if (vertices && indices)
  {
    for (size_t p = 0; p < mesh.Points.size(); ++p)
    {
      const Vec3 q = mesh.Points[p] - origin;
      vertices[3 * p + 0] = static_cast<float>(q.x);
      vertices[3 * p + 1] = static_cast<float>(q.y);
      vertices[3 * p + 2] = static_cast<float>(q.z);
    }
    std::copy(corners.begin(), corners.end(), indices);
  }
  rtcCommitGeometry(geom);
  return geom;
}

void InitRay(RTCRay& ray, const Vec3& origin, const Vec3& direction, float tfar)
{
  ray.org_x = static_cast<float>(origin.x);
  ray.org_y = static_cast<float>(origin.y);
  ray.org_z = static_cast<float>(origin.z);
  ray.dir_x = static_cast<float>(direction.x);
  ray.dir_y = static_cast<float>(direction.y);
  ray.dir_z = static_cast<float>(direction.z);
  ray.tnear = 0.0f;
  ray.tfar = tfar;
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
}
} // namespace

Visibility::Visibility(const SceneMesh& mesh)
  : Impl(new Internals)
{
  Internals& d = *Impl;
  // Embree works in float: center the scene so large coordinates keep their precision.
  d.Origin = Bounds(mesh.Points).Centre();
  d.Device = SharedDevice();
  if (!d.Device)
  {
    d.Error = "Embree could not create a device";
    return;
  }
  rtcRetainDevice(d.Device);
  DeviceError(d.Device); // clears an error left on this thread by an earlier scene
  d.Scene = rtcNewScene(d.Device);
  // Robust mode avoids rays slipping through shared edges and vertices (light leaks).
  rtcSetSceneFlags(d.Scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(d.Scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geom = TriangleGeometry(d.Device, mesh, d.Origin, d.TrianglePolygon, d.TriangleCorners);
  d.MeshId = rtcAttachGeometry(d.Scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(d.Scene);
  d.Error = DeviceError(d.Device);
}

Visibility::Visibility(std::shared_ptr<const Visibility> fixed, const SceneMesh& objects)
  : Impl(new Internals)
{
  Internals& d = *Impl;
  const Internals& base = *fixed->Impl;
  d.Device = base.Device;
  d.Origin = base.Origin; // the same frame, so the instance needs no transform
  d.Error = base.Error;
  if (!d.Device || !base.Scene || !d.Error.empty())
  {
    d.Error = d.Error.empty() ? "the fixed scene was not built" : d.Error;
    return;
  }
  rtcRetainDevice(d.Device);
  DeviceError(d.Device);
  d.Scene = rtcNewScene(d.Device);
  rtcSetSceneFlags(d.Scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry instance = rtcNewGeometry(d.Device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(instance, base.Scene);
  const float identity[12] = { 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0 };
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, identity);
  rtcCommitGeometry(instance);
  rtcAttachGeometry(d.Scene, instance);
  rtcReleaseGeometry(instance);
  if (objects.NumberOfPolygons() > 0)
  {
    std::vector<int> polygonOf;
    std::vector<unsigned> corners;
    RTCGeometry geom = TriangleGeometry(d.Device, objects, d.Origin, polygonOf, corners);
    rtcAttachGeometry(d.Scene, geom);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(d.Scene);
  d.Error = DeviceError(d.Device);
  d.Fixed = std::move(fixed);
}

Visibility::~Visibility()
{
  if (Impl->Scene)
  {
    rtcReleaseScene(Impl->Scene);
  }
  if (Impl->Device)
  {
    rtcReleaseDevice(Impl->Device);
  }
}

const std::string& Visibility::Error() const
{
  return Impl->Error;
}

bool Visibility::Occluded(const Vec3& from, const Vec3& to, double tolerance) const
{
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray;
  // Unnormalized direction: t runs from 0 (from) to 1 (to).
  InitRay(ray, from - Impl->Origin, to - from, static_cast<float>(1.0 - tolerance));
  rtcOccluded1(Impl->Scene, &context, &ray);
  return ray.tfar < 0.0f;
}

bool Visibility::Intersect(const Vec3& origin, const Vec3& direction, Hit& hit) const
{
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  InitRay(rh.ray, origin - Impl->Origin, direction, std::numeric_limits<float>::infinity());
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(Impl->Scene, &context, &rh);
  return Decode(
    rh.hit.instID[0], rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v, rh.ray.tfar * Norm(direction), hit);
}

namespace
{
/// True where the device traces packets of 8 natively (else packets would be emulated).
bool PacketsOf8(RTCDevice device)
{
  static const bool native = device && rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED);
  return native;
}

/// Ray i of a packet: from `origin` along `direction` up to `tfar` (in direction lengths).
void SetPacketRay(RTCRay8& ray, int i, const Vec3& origin, const Vec3& direction, float tfar)
{
  ray.org_x[i] = static_cast<float>(origin.x);
  ray.org_y[i] = static_cast<float>(origin.y);
  ray.org_z[i] = static_cast<float>(origin.z);
  ray.dir_x[i] = static_cast<float>(direction.x);
  ray.dir_y[i] = static_cast<float>(direction.y);
  ray.dir_z[i] = static_cast<float>(direction.z);
  ray.tnear[i] = 0.0f;
  ray.tfar[i] = tfar;
  ray.time[i] = 0.0f;
  ray.mask[i] = 0xFFFFFFFFu;
  ray.id[i] = static_cast<unsigned>(i);
  ray.flags[i] = 0;
}
} // namespace

void Visibility::OccludedPacket(const Vec3* from, const Vec3& to, int count, double tolerance, bool* blocked) const
{
  if (!PacketsOf8(Impl->Device) || count > PacketSize)
  {
    for (int i = 0; i < count; ++i)
    {
      blocked[i] = Occluded(from[i], to, tolerance);
    }
    return;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  alignas(32) RTCRay8 ray;
  alignas(32) int valid[PacketSize];
  for (int i = 0; i < PacketSize; ++i)
  {
    const Vec3& start = from[std::min(i, count - 1)];
    valid[i] = i < count ? -1 : 0;
    SetPacketRay(ray, i, start - Impl->Origin, to - start, static_cast<float>(1.0 - tolerance));
  }
  rtcOccluded8(valid, Impl->Scene, &context, &ray);
  for (int i = 0; i < count; ++i)
  {
    blocked[i] = ray.tfar[i] < 0.0f;
  }
}

void Visibility::IntersectPacket(const Vec3& origin, const Vec3* directions, int count, Hit* hits, bool* found) const
{
  if (!PacketsOf8(Impl->Device) || count > PacketSize)
  {
    for (int i = 0; i < count; ++i)
    {
      found[i] = Intersect(origin, directions[i], hits[i]);
    }
    return;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT; // one origin, neighbouring directions
  alignas(32) RTCRayHit8 rh;
  alignas(32) int valid[PacketSize];
  const Vec3 o = origin - Impl->Origin;
  for (int i = 0; i < PacketSize; ++i)
  {
    valid[i] = i < count ? -1 : 0;
    SetPacketRay(rh.ray, i, o, directions[std::min(i, count - 1)], std::numeric_limits<float>::infinity());
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect8(valid, Impl->Scene, &context, &rh);
  for (int i = 0; i < count; ++i)
  {
    found[i] = Decode(rh.hit.instID[0][i], rh.hit.geomID[i], rh.hit.primID[i], rh.hit.u[i], rh.hit.v[i],
      rh.ray.tfar[i] * Norm(directions[i]), hits[i]);
  }
}

bool Visibility::Decode(
  unsigned instance, unsigned geometry, unsigned triangle, float u, float v, double distance, Hit& hit) const
{
  if (geometry == RTC_INVALID_GEOMETRY_ID)
  {
    return false;
  }
  if (instance != RTC_INVALID_GEOMETRY_ID && Impl->Fixed)
  {
    return Impl->Fixed->Decode(RTC_INVALID_GEOMETRY_ID, geometry, triangle, u, v, distance, hit);
  }
  hit.Distance = distance;
  hit.U = u;
  hit.V = v;
  if (geometry != Impl->MeshId) // a dynamic object: no polygon of the mesh
  {
    hit.Polygon = -1;
    hit.Corner[0] = hit.Corner[1] = hit.Corner[2] = -1;
    return true;
  }
  hit.Polygon = Impl->TrianglePolygon[triangle];
  for (int c = 0; c < 3; ++c)
  {
    hit.Corner[c] = static_cast<int>(Impl->TriangleCorners[3 * triangle + c]);
  }
  return true;
}

namespace
{
/// How many of 17 hemisphere probes from the element's centroid are blocked at once (a back
/// face, or a surface touching it), and in `lit` how many end on a lamp's front; counting
/// stops once the element can be neither sheltered (9 blocked) nor shut in with a lamp
/// (every probe blocked or on a lamp).
int BlockedProbes(const Visibility& rays, const SceneMesh& mesh, const SceneGeometry& g, double touching, int e,
  int& lit)
{
  // The frame follows the element's first edge, not the world axes, so a rotated scene
  // probes the same directions relative to its geometry and is marked the same.
  const Vec3& n = g.Normal[e];
  const Vec3 edge = mesh.Points[mesh.Polygon(e)[1]] - mesh.Points[mesh.Polygon(e)[0]];
  const Vec3 t = Normalized(edge - n * Dot(edge, n)), b = Cross(n, t);
  const Vec3 origin = g.Centroid[e] + n * touching;
  int blocked = 0;
  lit = 0;
  for (int r = 0; r < 17 && (r - blocked < 9 || r == blocked + lit); ++r)
  {
    const double polar = r == 0 ? 0.0 : (r <= 8 ? 0.785398 : 1.396263);
    const double azimuth = 0.785398 * (r % 8);
    const Vec3 direction = n * std::cos(polar) + (t * std::cos(azimuth) + b * std::sin(azimuth)) * std::sin(polar);
    Visibility::Hit hit;
    if (!rays.Intersect(origin, direction, hit))
    {
      continue;
    }
    if (Dot(g.Normal[hit.Polygon], direction) > 0 || hit.Distance <= 2 * touching)
    {
      ++blocked;
    }
    else if (mesh.LightId[hit.Polygon] >= 0)
    {
      ++lit;
    }
  }
  return blocked;
}
} // namespace

namespace
{
int Root(std::vector<int>& parent, int i)
{
  while (parent[i] != i)
  {
    i = parent[i] = parent[parent[i]];
  }
  return i;
}
} // namespace

namespace
{
/// Each element's group (a union-find forest): elements of one patch that share an edge
/// are joined when they see each other just above the surface, so a wall standing on the
/// patch keeps its two sides apart.
std::vector<int> SeenAcrossEdges(const Visibility& rays, const SceneMesh& mesh, const SceneGeometry& g)
{
  const int n = mesh.NumberOfPolygons();
  const double lift = g.RayLift;
  // (edge, element) pairs sorted by edge: a map of a million elements' edges is slow.
  const long long points = static_cast<long long>(mesh.Points.size());
  std::vector<std::pair<long long, int>> edges;
  edges.reserve(mesh.Connectivity.size());
  for (int e = 0; e < n; ++e)
  {
    const int* ids = mesh.Polygon(e);
    for (int v = 0; v < mesh.PolygonSize(e); ++v)
    {
      const long long a = ids[v], b = ids[(v + 1) % mesh.PolygonSize(e)];
      edges.push_back({ std::min(a, b) * points + std::max(a, b), e });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i + 1 < edges.size(); ++i)
  {
    const int a = edges[i].second, b = edges[i + 1].second;
    if (edges[i].first == edges[i + 1].first && g.ElementPatch[a] == g.ElementPatch[b] &&
      Root(parent, a) != Root(parent, b) &&
      !rays.Occluded(g.Centroid[a] + g.Normal[a] * lift, g.Centroid[b] + g.Normal[b] * lift, 1e-6))
    {
      parent[Root(parent, a)] = Root(parent, b);
    }
  }
  return parent;
}

/// A face cluster (elements on several planes, FaceClusters.h; parallel ones too) stays
/// whole: it was grown over shared edges of its input polygons, and its elements have
/// points of their own per plane, so they share no edge by id.
bool OnSeveralPlanes(const SceneGeometry& g, const std::vector<int>& members)
{
  const Vec3& n = g.Normal[members[0]];
  const Vec3& c = g.Centroid[members[0]];
  return std::any_of(members.begin(), members.end(), [&](int e) {
    return Dot(g.Normal[e], n) < 1 - 1e-9 || std::fabs(Dot(n, g.Centroid[e] - c)) > 1e-9 * g.SceneDiagonal;
  });
}

/// Patch p keeps the group of its first element; each other group becomes a new patch.
int SplitPatch(int p, std::vector<int>& parent, SceneGeometry& g)
{
  std::map<int, std::vector<int>> groups;
  for (int e : g.PatchElements[p])
  {
    groups[Root(parent, e)].push_back(e);
  }
  if (groups.size() < 2)
  {
    return 0;
  }
  const int keep = Root(parent, g.PatchElements[p][0]);
  g.PatchElements[p] = groups[keep];
  for (auto& group : groups)
  {
    if (group.first != keep)
    {
      g.PatchElements.push_back(group.second);
    }
  }
  return static_cast<int>(groups.size()) - 1;
}
} // namespace

int SplitSeparatedPatches(const Visibility& rays, const SceneMesh& mesh, SceneGeometry& g)
{
  std::vector<int> parent = SeenAcrossEdges(rays, mesh, g);
  int added = 0;
  const size_t patches = g.PatchElements.size();
  for (size_t p = 0; p < patches; ++p)
  {
    added += OnSeveralPlanes(g, g.PatchElements[p]) ? 0 : SplitPatch(static_cast<int>(p), parent, g);
  }
  if (added == 0)
  {
    return 0;
  }
  g.PatchArea.assign(g.PatchElements.size(), 0.0);
  for (size_t p = 0; p < g.PatchElements.size(); ++p)
  {
    for (int e : g.PatchElements[p])
    {
      g.ElementPatch[e] = static_cast<int>(p);
      g.PatchArea[p] += g.Area[e];
    }
  }
  return added; // MarkEnclosed derives PatchOpenArea from these
}

void MarkEnclosed(const Visibility& rays, const SceneMesh& mesh, SceneGeometry& g, int threads, const ProcessGroup& group)
{
  // Touching, relative to the scene, and never finer than float input can place a surface
  // far from the origin (a leg standing on a floor 500 km away can float 3 cm above it).
  // Double input keeps its precision wherever it is: site coordinates are not float noise.
  const double touching = std::max(1e-6 * g.SceneDiagonal, 8.4 * mesh.PointQuantum);
  const WorkerPool pool(threads);
  Collective ranks(group);
  const int n = static_cast<int>(g.Normal.size()), step = ranks.Ranks();
  // Counts (blocked, then on a lamp), summed over the ranks that probed them.
  std::vector<double> counts(2 * static_cast<size_t>(n), 0.0);
  pool.For((n - ranks.Rank() + step - 1) / step, 256, [&](int begin, int end) {
    for (int i = begin; i < end; ++i)
    {
      const int e = ranks.Rank() + i * step;
      int lit = 0;
      counts[2 * e] = BlockedProbes(rays, mesh, g, touching, e, lit);
      counts[2 * e + 1] = lit;
    }
  });
  ranks.Sum(counts);
  std::vector<int> shutIn;
  for (int e = 0; e < n; ++e)
  {
    g.Enclosed[e] = counts[2 * e] == 17;
    g.Sheltered[e] = counts[2 * e] >= 9;
    if (!g.Enclosed[e] && (g.Sheltered[e] || counts[2 * e] + counts[2 * e + 1] == 17))
    {
      shutIn.push_back(e);
    }
  }
  // The floor under a box with a lamp inside: its probes start past the box's bottom and
  // see the lamp. Face to face with another surface, its view mostly closed or closed but
  // for lamps, an element is closed off; a thin wall drawn as two faces back to back sees
  // the room.
  for (int e : FaceToFace(mesh, g, shutIn, 2 * touching))
  {
    g.Enclosed[e] = 1;
  }
  // Summed, not subtracted: a wholly enclosed patch gets exactly 0.
  g.PatchOpenArea.assign(g.PatchArea.size(), 0.0);
  for (size_t e = 0; e < g.Normal.size(); ++e)
  {
    g.PatchOpenArea[g.ElementPatch[e]] += g.Enclosed[e] ? 0.0 : g.Area[e];
  }
}

} // namespace radiosity
