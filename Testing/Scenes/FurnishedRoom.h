// A furnished room with eight ceiling lamps, meshed by the core mesher at any size: the
// scene of `./relight bench scale` and of the large-scene tests.
#ifndef RadiosityScenes_FurnishedRoom_h
#define RadiosityScenes_FurnishedRoom_h

#include "Mesh/Mesher.h"
#include "Geometry/Scene.h"

#include <string>
#include <vector>

namespace radiosity_scenes
{
using radiosity::Vec3;

struct RoomPolygons
{
  std::vector<Vec3> Points;
  std::vector<int> Offsets{ 0 }, Connectivity;
  std::vector<Vec3> Reflectance;
  std::vector<int> LightId;
  std::vector<std::string> LightNames;

  /// A quad whose front (right-hand rule) faces along `front`, whatever order a..d are in.
  void Quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& rho, const Vec3& front,
    int light = -1)
  {
    const bool flip = radiosity::Dot(radiosity::Cross(b - a, c - a), front) < 0;
    for (const Vec3& p : { a, flip ? d : b, c, flip ? b : d })
    {
      Connectivity.push_back(static_cast<int>(Points.size()));
      Points.push_back(p);
    }
    Offsets.push_back(static_cast<int>(Connectivity.size()));
    Reflectance.push_back(rho);
    LightId.push_back(light);
  }

  /// An axis-aligned box with outward faces; `bottom` false leaves the face on the floor out.
  void Block(const Vec3& lo, const Vec3& hi, const Vec3& rho, bool bottom = false)
  {
    const double x0 = lo.x, y0 = lo.y, z0 = lo.z, x1 = hi.x, y1 = hi.y, z1 = hi.z;
    Quad({ x0, y0, z1 }, { x1, y0, z1 }, { x1, y1, z1 }, { x0, y1, z1 }, rho, { 0, 0, 1 });
    if (bottom)
    {
      Quad({ x0, y0, z0 }, { x1, y0, z0 }, { x1, y1, z0 }, { x0, y1, z0 }, rho, { 0, 0, -1 });
    }
    Quad({ x0, y0, z0 }, { x1, y0, z0 }, { x1, y0, z1 }, { x0, y0, z1 }, rho, { 0, -1, 0 });
    Quad({ x0, y1, z0 }, { x1, y1, z0 }, { x1, y1, z1 }, { x0, y1, z1 }, rho, { 0, 1, 0 });
    Quad({ x0, y0, z0 }, { x0, y1, z0 }, { x0, y1, z1 }, { x0, y0, z1 }, rho, { -1, 0, 0 });
    Quad({ x1, y0, z0 }, { x1, y1, z0 }, { x1, y1, z1 }, { x1, y0, z1 }, rho, { 1, 0, 0 });
  }
};

/// The floor, ceiling and four walls of an X x Y x Z room, facing inward (two walls colored).
inline void AddRoomShell(RoomPolygons& r, double X, double Y, double Z)
{
  const Vec3 wall{ 0.75, 0.72, 0.68 }, floor{ 0.45, 0.32, 0.22 }, ceiling{ 0.8, 0.8, 0.8 };
  r.Quad({ 0, 0, 0 }, { X, 0, 0 }, { X, Y, 0 }, { 0, Y, 0 }, floor, { 0, 0, 1 });
  r.Quad({ 0, 0, Z }, { X, 0, Z }, { X, Y, Z }, { 0, Y, Z }, ceiling, { 0, 0, -1 });
  r.Quad({ 0, 0, 0 }, { X, 0, 0 }, { X, 0, Z }, { 0, 0, Z }, wall, { 0, 1, 0 });
  r.Quad({ 0, Y, 0 }, { X, Y, 0 }, { X, Y, Z }, { 0, Y, Z }, { 0.3, 0.45, 0.65 }, { 0, -1, 0 });
  r.Quad({ 0, 0, 0 }, { 0, Y, 0 }, { 0, Y, Z }, { 0, 0, Z }, wall, { 1, 0, 0 });
  r.Quad({ X, 0, 0 }, { X, Y, 0 }, { X, Y, Z }, { X, 0, Z }, { 0.7, 0.35, 0.3 }, { -1, 0, 0 });
}

/// Room 6 x 5 x 3 m (faces inward) with a table, a sofa, two cabinets, a shelf and eight
/// 0.3 m lamps 1 cm under the ceiling, each its own light.
inline RoomPolygons FurnishedRoom()
{
  RoomPolygons r;
  const double X = 6, Y = 5, Z = 3;
  AddRoomShell(r, X, Y, Z);
  const Vec3 wood{ 0.55, 0.38, 0.22 }, fabric{ 0.2, 0.5, 0.3 }, white{ 0.85, 0.85, 0.85 };
  r.Block({ 2.2, 1.8, 0.72 }, { 3.8, 2.8, 0.78 }, wood, true); // table top
  for (const Vec3& leg : { Vec3{ 2.25, 1.85, 0 }, Vec3{ 3.69, 1.85, 0 }, Vec3{ 2.25, 2.69, 0 }, Vec3{ 3.69, 2.69, 0 } })
  {
    r.Block(leg, leg + Vec3{ 0.06, 0.06, 0.72 }, wood);
  }
  r.Block({ 0.3, 3.6, 0 }, { 2.6, 4.6, 0.45 }, fabric);   // sofa seat
  r.Block({ 0.3, 4.4, 0.45 }, { 2.6, 4.6, 0.9 }, fabric); // sofa back
  r.Block({ 4.9, 0.2, 0 }, { 5.8, 0.8, 1.9 }, white);     // cabinet
  r.Block({ 4.9, 3.8, 0 }, { 5.8, 4.8, 1.1 }, wood);      // sideboard
  r.Block({ 0.1, 0.4, 1.4 }, { 0.4, 2.4, 1.45 }, wood, true); // wall shelf
  int light = 0;
  for (double x : { 1.0, 2.3, 3.7, 5.0 })
  {
    for (double y : { 1.4, 3.6 })
    {
      const double h = 0.15, z = Z - 0.01;
      r.Quad({ x - h, y - h, z }, { x + h, y - h, z }, { x + h, y + h, z }, { x - h, y + h, z }, { 0.8, 0.8, 0.8 },
        { 0, 0, -1 }, light);
      r.LightNames.push_back("Lamp" + std::to_string(light++));
    }
  }
  return r;
}

/// Total area of the room's polygons (for choosing an element size from a count).
inline double TotalArea(const RoomPolygons& r)
{
  double area = 0;
  for (size_t c = 0; c + 1 < r.Offsets.size(); ++c)
  {
    const Vec3& a = r.Points[r.Connectivity[r.Offsets[c]]];
    const Vec3& b = r.Points[r.Connectivity[r.Offsets[c] + 1]];
    const Vec3& d = r.Points[r.Connectivity[r.Offsets[c] + 3]];
    area += radiosity::Norm(radiosity::Cross(b - a, d - a));
  }
  return area;
}

/// Meshes the room into a solver scene; returns an empty string or the mesher's error.
/// Meshes the polygons with these surface keys and options into a solver scene.
inline std::string MeshWithKeys(const RoomPolygons& r, const std::vector<int>& keys,
  const radiosity::MesherOptions& options, radiosity::SceneMesh& mesh)
{
  radiosity::MeshedPolygons out;
  const std::string error = radiosity::MeshPolygons(r.Points, r.Offsets, r.Connectivity, keys, options, out);
  if (!error.empty())
  {
    return error;
  }
  mesh = radiosity::SceneMesh();
  mesh.Points = out.Points;
  mesh.Offsets = out.Offsets;
  mesh.Connectivity = out.Connectivity;
  mesh.PatchId = out.PatchId;
  for (int source : out.SourcePolygon)
  {
    mesh.Reflectance.push_back(r.Reflectance[source]);
    mesh.LightId.push_back(r.LightId[source]);
  }
  return std::string();
}

/// `lampGrading`: MesherOptions::LampGrading (0: one element size everywhere).
inline std::string MeshRoom(
  const RoomPolygons& r, double patch, double element, radiosity::SceneMesh& mesh, double lampGrading = 0)
{
  radiosity::MesherOptions options;
  options.PatchSize = patch;
  options.ElementSize = element;
  options.LampGrading = lampGrading;
  for (int id : r.LightId)
  {
    options.Lamps.push_back(id >= 0 ? 1 : 0);
  }
  std::vector<int> keys(r.Reflectance.size());
  for (size_t c = 0; c < keys.size(); ++c)
  {
    keys[c] = static_cast<int>(c); // polygons never share points: each keeps its own shading
  }
  return MeshWithKeys(r, keys, options, mesh);
}

} // namespace radiosity_scenes

#endif
