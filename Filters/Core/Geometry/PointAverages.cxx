#include "Geometry/PointAverages.h"

namespace radiosity
{

std::vector<char> PointsTouchingOpenElements(const SceneMesh& mesh, const SceneGeometry& geometry)
{
  std::vector<char> open(mesh.Points.size(), 0);
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    for (int v = 0; !geometry.Sheltered[e] && v < mesh.PolygonSize(e); ++v)
    {
      open[mesh.Polygon(e)[v]] = 1;
    }
  }
  return open;
}

std::vector<Vec3> AverageToPoints(
  const SceneMesh& mesh, const SceneGeometry& geometry, const std::vector<Vec3>& cells, int columns)
{
  const size_t points = mesh.Points.size();
  std::vector<Vec3> sums(points * columns);
  std::vector<double> weights(points, 0.0);
  // A sheltered element (under furniture, above a ceiling lamp's back) is dark because its
  // hemisphere is blocked, not because its surroundings are: where a vertex also touches
  // open elements, only they count, or every footprint would get a dark ring one element
  // wide (measured: the ceiling ring around the benchmark's lamps was 22 % too dark).
  const std::vector<char> open = PointsTouchingOpenElements(mesh, geometry);
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const int* ids = mesh.Polygon(e);
    const double w = geometry.Area[e];
    for (int v = 0; v < mesh.PolygonSize(e); ++v)
    {
      if (geometry.Sheltered[e] && open[ids[v]])
      {
        continue;
      }
      weights[ids[v]] += w;
      for (int m = 0; m < columns; ++m)
      {
        sums[static_cast<size_t>(ids[v]) * columns + m] += cells[static_cast<size_t>(e) * columns + m] * w;
      }
    }
  }
  for (size_t p = 0; p < points; ++p)
  {
    const double inv = weights[p] > 0 ? 1.0 / weights[p] : 0.0;
    for (int m = 0; m < columns; ++m)
    {
      sums[p * columns + m] = sums[p * columns + m] * inv;
    }
  }
  return sums;
}

} // namespace radiosity
