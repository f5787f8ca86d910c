#include "Solve/WorkPlane.h"

#include "Geometry/Visibility.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace radiosity
{

double WorkPlaneSpacing(double longer)
{
  return longer > 0 ? std::min(10.0, 0.2 * std::pow(5.0, std::log10(longer))) : 0.0;
}

WorkPlaneGrid LayWorkPlane(const double bounds[6], int up, double height, double border, double spacing,
  std::string& error)
{
  WorkPlaneGrid grid;
  const int a = (up + 1) % 3, b = (up + 2) % 3;
  const double lowA = bounds[2 * a] + border, highA = bounds[2 * a + 1] - border;
  const double lowB = bounds[2 * b] + border, highB = bounds[2 * b + 1] - border;
  const double level = bounds[2 * up] + height;
  std::ostringstream s;
  if (!(highA > lowA) || !(highB > lowB))
  {
    s << "a border of " << border << " leaves no area inside the scene's " << bounds[2 * a + 1] - bounds[2 * a] << " x "
      << bounds[2 * b + 1] - bounds[2 * b];
  }
  else if (!(height >= 0) || !(level < bounds[2 * up + 1]))
  {
    s << "a height of " << height << " is not inside the scene's " << bounds[2 * up + 1] - bounds[2 * up];
  }
  else if (!(spacing >= 0) || !std::isfinite(spacing))
  {
    s << "the spacing " << spacing << " is not 0 (EN 12464-1's) or more";
  }
  error = s.str();
  if (!error.empty())
  {
    return grid;
  }
  const double longer = std::max(highA - lowA, highB - lowB);
  const double p = spacing > 0 ? spacing : WorkPlaneSpacing(longer);
  grid.Nu = std::max(1, static_cast<int>(std::ceil((highA - lowA) / p - 1e-9)));
  grid.Nv = std::max(1, static_cast<int>(std::ceil((highB - lowB) / p - 1e-9)));
  grid.SpacingU = (highA - lowA) / grid.Nu;
  grid.SpacingV = (highB - lowB) / grid.Nv;
  grid.Normal[up] = 1;
  for (int j = 0; j < grid.Nv; ++j)
  {
    for (int i = 0; i < grid.Nu; ++i)
    {
      Vec3 point;
      point[up] = level;
      point[a] = lowA + (i + 0.5) * grid.SpacingU;
      point[b] = lowB + (j + 0.5) * grid.SpacingV;
      grid.Points.push_back(point);
      if (i + 1 < grid.Nu && j + 1 < grid.Nv)
      {
        const int corner = j * grid.Nu + i;
        grid.Quads.push_back({ corner, corner + 1, corner + grid.Nu + 1, corner + grid.Nu });
      }
    }
  }
  return grid;
}

std::vector<char> PointsInRoom(
  const WorkPlaneGrid& grid, int up, double height, bool ceiling, const Visibility& rays, const std::vector<Vec3>& normals)
{
  std::vector<char> keep(grid.Points.size(), 1);
  Vec3 axis;
  axis[up] = 1;
  // Both rays start a hair above the point, so a point lying on a desk stands on it and
  // does not see its top as a ceiling.
  const double lift = 1e-4 * std::max({ height, grid.SpacingU, grid.SpacingV });
  for (size_t p = 0; p < grid.Points.size() && height > 0; ++p)
  {
    const Vec3 from = grid.Points[p] + axis * lift;
    Visibility::Hit floor, top;
    const bool below = rays.Intersect(from, axis * -1.0, floor) && floor.Polygon >= 0 &&
      floor.Distance <= 1.5 * height + lift && Dot(normals[floor.Polygon], axis) > 0;
    keep[p] = below &&
      (!ceiling || (rays.Intersect(from, axis, top) && top.Polygon >= 0 && Dot(normals[top.Polygon], axis) < 0));
  }
  return keep;
}

WorkPlaneGrid KeptPoints(const WorkPlaneGrid& grid, const std::vector<char>& keep)
{
  WorkPlaneGrid kept;
  kept.Nu = grid.Nu;
  kept.Nv = grid.Nv;
  kept.Normal = grid.Normal;
  kept.SpacingU = grid.SpacingU;
  kept.SpacingV = grid.SpacingV;
  std::vector<int> index(grid.Points.size(), -1);
  for (size_t p = 0; p < grid.Points.size(); ++p)
  {
    if (keep[p])
    {
      index[p] = static_cast<int>(kept.Points.size());
      kept.Points.push_back(grid.Points[p]);
    }
  }
  for (const std::array<int, 4>& q : grid.Quads)
  {
    if (index[q[0]] >= 0 && index[q[1]] >= 0 && index[q[2]] >= 0 && index[q[3]] >= 0)
    {
      kept.Quads.push_back({ index[q[0]], index[q[1]], index[q[2]], index[q[3]] });
    }
  }
  return kept;
}

PlaneStatistics WorkPlaneStatistics(const std::vector<double>& illuminance)
{
  PlaneStatistics s;
  if (illuminance.empty())
  {
    return s;
  }
  s.Mean = std::accumulate(illuminance.begin(), illuminance.end(), 0.0) / illuminance.size();
  s.Minimum = *std::min_element(illuminance.begin(), illuminance.end());
  s.Maximum = *std::max_element(illuminance.begin(), illuminance.end());
  s.Uniformity = s.Mean > 0 ? s.Minimum / s.Mean : 0;
  return s;
}

} // namespace radiosity
