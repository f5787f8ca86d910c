// Probe points inside the 6 x 5 x 3 m rooms and an external renderer's radiosity at them:
// the independent reference of `./relight bench scale` and `./relight bench polygons`.
#ifndef RadiosityScenes_ProbeReference_h
#define RadiosityScenes_ProbeReference_h

#include "FurnishedRoom.h"
#include "Geometry/PointAverages.h"
#include "Solve/RadiositySolver.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace radiosity_scenes
{
using radiosity::Normalized;
using radiosity::RadiositySolver;
using radiosity::SceneMesh;
using radiosity::Solution;
using radiosity::Visibility;

/// Fixed rays from three viewpoints inside the room; each hit is a probe point.
struct Probes
{
  std::vector<Vec3> Origin, Direction;

  Probes(int count)
  {
    std::mt19937 rng(11);
    std::normal_distribution<double> normal;
    const Vec3 eyes[3] = { { 3.0, 2.5, 1.6 }, { 1.2, 1.0, 1.2 }, { 4.6, 3.9, 2.2 } };
    for (int i = 0; i < count; ++i)
    {
      Origin.push_back(eyes[i % 3]);
      Direction.push_back(Normalized(Vec3{ normal(rng), normal(rng), normal(rng) }));
    }
  }
};

/// Per probe and solution, the point-interpolated radiosity (channel sum) that a renderer
/// would show; NaN where the probe sees a lamp or nothing.
inline std::vector<double> Sample(const RadiositySolver& solver, const SceneMesh& mesh, const Solution& s,
  const Probes& probes)
{
  const int L = s.Solutions;
  const std::vector<Vec3> points = s.PointRadiosity.empty()
    ? radiosity::AverageToPoints(mesh, solver.Geometry(), s.Radiosity, L)
    : s.PointRadiosity; // the final gather's, where it ran
  std::vector<double> values(probes.Origin.size() * L, std::nan(""));
  for (size_t i = 0; i < probes.Origin.size(); ++i)
  {
    Visibility::Hit hit;
    if (!solver.Rays().Intersect(probes.Origin[i], probes.Direction[i], hit) || mesh.LightId[hit.Polygon] >= 0)
    {
      continue;
    }
    const double w[3] = { 1 - hit.U - hit.V, hit.U, hit.V };
    for (int m = 0; m < L; ++m)
    {
      double v = 0;
      for (int c = 0; c < 3; ++c)
      {
        const Vec3& b = points[static_cast<size_t>(hit.Corner[c]) * L + m];
        v += w[c] * (b.x + b.y + b.z);
      }
      values[i * L + m] = v;
    }
  }
  return values;
}

/// Mean over lights of mean |B - B_ref| / mean B_ref over the probes both see.
inline double MeanError(const std::vector<double>& values, const std::vector<double>& reference, int L, double* worst)
{
  double total = 0;
  *worst = 0;
  for (int m = 0; m < L; ++m)
  {
    double diff = 0, sum = 0;
    for (size_t i = m; i < values.size(); i += L)
    {
      if (!std::isnan(values[i]) && !std::isnan(reference[i]))
      {
        diff += std::fabs(values[i] - reference[i]);
        sum += reference[i];
      }
    }
    const double e = sum > 0 ? diff / sum : 0;
    total += e;
    *worst = std::max(*worst, e);
  }
  return total / L;
}

/// Per light, sum (B - B_ref) / sum B_ref over the probes both see: the bias that
/// MeanError's absolute differences cannot tell from noise.
inline std::vector<double> SignedError(const std::vector<double>& values, const std::vector<double>& reference, int L)
{
  std::vector<double> bias(L, 0.0);
  for (int m = 0; m < L; ++m)
  {
    double diff = 0, sum = 0;
    for (size_t i = m; i < values.size(); i += L)
    {
      if (!std::isnan(values[i]) && !std::isnan(reference[i]))
      {
        diff += values[i] - reference[i];
        sum += reference[i];
      }
    }
    bias[m] = sum > 0 ? diff / sum : 0;
  }
  return bias;
}

/// Writes the room's polygons and the probe points (where the probe rays hit, with the
/// surface normal) as JSON, for an external renderer to make a reference.
inline void ExportRoom(const RoomPolygons& room, const RadiositySolver& solver, const SceneMesh& mesh,
  const Probes& probes, const std::string& path)
{
  std::ofstream out(path);
  out.precision(9);
  out << "{\"lights\": " << room.LightNames.size() << ",\n\"polygons\": [\n";
  for (size_t c = 0; c + 1 < room.Offsets.size(); ++c)
  {
    out << (c ? ",\n" : "") << "{\"light\": " << room.LightId[c] << ", \"reflectance\": [" << room.Reflectance[c].x
        << ", " << room.Reflectance[c].y << ", " << room.Reflectance[c].z << "], \"points\": [";
    for (int v = room.Offsets[c]; v < room.Offsets[c + 1]; ++v)
    {
      const Vec3& p = room.Points[room.Connectivity[v]];
      out << (v > room.Offsets[c] ? ", " : "") << "[" << p.x << ", " << p.y << ", " << p.z << "]";
    }
    out << "]}";
  }
  out << "],\n\"probes\": [\n";
  for (size_t i = 0; i < probes.Origin.size(); ++i)
  {
    Visibility::Hit hit;
    const bool seen = solver.Rays().Intersect(probes.Origin[i], probes.Direction[i], hit) && mesh.LightId[hit.Polygon] < 0;
    const Vec3& n = solver.Geometry().Normal[seen ? hit.Polygon : 0];
    const Vec3 a = mesh.Points[hit.Corner[0]], b = mesh.Points[hit.Corner[1]], c = mesh.Points[hit.Corner[2]];
    const Vec3 x = seen ? a * (1 - hit.U - hit.V) + b * hit.U + c * hit.V : Vec3();
    out << (i ? ",\n" : "") << "{\"seen\": " << (seen ? "true" : "false") << ", \"point\": [" << x.x << ", " << x.y
        << ", " << x.z << "], \"normal\": [" << n.x << ", " << n.y << ", " << n.z << "]}";
  }
  out << "]}\n";
}

/// Reads `probe,light,r,g,b` rows (an external renderer's radiosity at the probes).
inline std::vector<double> ReadReference(const std::string& path, size_t probes, int lights)
{
  std::vector<double> values(probes * lights, std::nan(""));
  std::ifstream in(path);
  std::string line;
  std::getline(in, line); // header
  while (std::getline(in, line))
  {
    std::istringstream fields(line);
    std::string item;
    std::vector<double> row;
    while (std::getline(fields, item, ','))
    {
      row.push_back(std::atof(item.c_str()));
    }
    const size_t probe = static_cast<size_t>(row.at(0));
    const int light = static_cast<int>(row.at(1));
    if (probe < probes && light >= 0 && light < lights)
    {
      values[probe * lights + light] = row.at(2) + row.at(3) + row.at(4);
    }
  }
  return values;
}

} // namespace radiosity_scenes

#endif
