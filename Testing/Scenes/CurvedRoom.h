// A plain room with lamps and tessellated spheres on its floor: the scene of
// `./relight bench polygons` and of the face-cluster tests (many small curved polygons).
#ifndef RadiosityScenes_CurvedRoom_h
#define RadiosityScenes_CurvedRoom_h

#include "FurnishedRoom.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <tuple>

namespace radiosity_scenes
{

/// Adds a UV sphere of about `triangles` triangles (outward, sharing points as a
/// tessellated model does), rings from pole to pole.
inline void AddSphere(RoomPolygons& r, const Vec3& centre, double radius, int triangles, const Vec3& rho)
{
  const int rings = std::max(3, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
  const int segments = 2 * rings;
  const int base = static_cast<int>(r.Points.size());
  for (int i = 0; i <= rings; ++i)
  {
    const double theta = radiosity::Pi * i / rings;
    for (int j = 0; j < segments; ++j)
    {
      const double phi = 2 * radiosity::Pi * j / segments;
      r.Points.push_back(centre + Vec3{ std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) } * radius);
    }
  }
  auto id = [&](int i, int j) { return base + i * segments + (j % segments); };
  auto triangle = [&](int a, int b, int c) {
    for (int v : { a, b, c })
    {
      r.Connectivity.push_back(v);
    }
    r.Offsets.push_back(static_cast<int>(r.Connectivity.size()));
    r.Reflectance.push_back(rho);
    r.LightId.push_back(-1);
  };
  for (int i = 0; i < rings; ++i)
  {
    for (int j = 0; j < segments; ++j)
    {
      // Outward: counter-clockwise seen from outside (theta grows downwards, phi eastwards).
      if (i > 0)
      {
        triangle(id(i, j), id(i + 1, j), id(i, j + 1));
      }
      if (i + 1 < rings)
      {
        triangle(id(i, j + 1), id(i + 1, j), id(i + 1, j + 1));
      }
    }
  }
}

/// Adds the triangles of an OFF file (a CGAL demo mesh), scaled so its largest extent is
/// `size` and standing 1 cm above the floor at (x, y); returns false if it cannot be read.
inline bool AddOffMesh(RoomPolygons& r, const std::string& path, double size, double x, double y, const Vec3& rho)
{
  std::ifstream in(path);
  std::string magic;
  int vertices = 0, faces = 0, edges = 0;
  if (!(in >> magic >> vertices >> faces >> edges) || magic != "OFF")
  {
    return false;
  }
  std::vector<Vec3> points(vertices);
  Vec3 lo{ 1e300, 1e300, 1e300 }, hi{ -1e300, -1e300, -1e300 };
  for (Vec3& p : points)
  {
    in >> p.x >> p.y >> p.z;
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  const double scale = size / std::max({ hi.x - lo.x, hi.y - lo.y, hi.z - lo.z });
  const int base = static_cast<int>(r.Points.size());
  for (const Vec3& p : points)
  {
    r.Points.push_back({ x + (p.x - 0.5 * (lo.x + hi.x)) * scale, y + (p.y - 0.5 * (lo.y + hi.y)) * scale, 0.01 + (p.z - lo.z) * scale });
  }
  for (int f = 0; f < faces; ++f)
  {
    int count = 0;
    in >> count;
    for (int v = 0, id = 0; v < count && in >> id; ++v)
    {
      r.Connectivity.push_back(base + id);
    }
    r.Offsets.push_back(static_cast<int>(r.Connectivity.size()));
    r.Reflectance.push_back(rho);
    r.LightId.push_back(-1);
  }
  return static_cast<bool>(in);
}

/// Room 6 x 5 x 3 m with `lamps` 0.3 m ceiling lamps (each its own light) and `spheres`
/// spheres of radius 0.6 m on the floor, about `triangles` triangles in all.
inline RoomPolygons CurvedRoom(int lamps, int spheres, int triangles)
{
  RoomPolygons r;
  const double X = 6, Y = 5, Z = 3;
  AddRoomShell(r, X, Y, Z);
  for (int s = 0; s < spheres; ++s)
  {
    const double x = 1.0 + (s % 4) * 1.3, y = 1.5 + (s / 4 % 2) * 2.0;
    AddSphere(r, { x, y, 0.62 }, 0.6, triangles / std::max(spheres, 1), { 0.7, 0.7, 0.65 });
  }
  for (int light = 0; light < lamps; ++light)
  {
    const double h = 0.15, z = Z - 0.01;
    const double x = 0.9 + (light % 4) * 1.4, y = light / 4 % 2 ? 3.7 : 1.3;
    r.Quad({ x - h, y - h, z }, { x + h, y - h, z }, { x + h, y + h, z }, { x - h, y + h, z }, { 0.8, 0.8, 0.8 },
      { 0, 0, -1 }, light);
    r.LightNames.push_back("Lamp" + std::to_string(light));
  }
  return r;
}

/// Meshes it as the mesher filter does: polygons of one material share a surface key, so
/// small curved ones may form face clusters (`clusterAngle` 0: never).
inline std::string MeshByMaterial(const RoomPolygons& r, double patch, double element, double clusterAngle,
  radiosity::SceneMesh& mesh)
{
  radiosity::MesherOptions options;
  options.PatchSize = patch;
  options.ElementSize = element;
  options.ClusterAngle = clusterAngle;
  std::map<std::tuple<double, double, double, int>, int> materials;
  std::vector<int> keys;
  for (size_t c = 0; c < r.Reflectance.size(); ++c)
  {
    const Vec3& rho = r.Reflectance[c];
    keys.push_back(materials.emplace(std::make_tuple(rho.x, rho.y, rho.z, r.LightId[c]), static_cast<int>(materials.size()))
                     .first->second);
  }
  return MeshWithKeys(r, keys, options, mesh);
}

} // namespace radiosity_scenes

#endif
