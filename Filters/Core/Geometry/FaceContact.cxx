#include "Geometry/FaceContact.h"

#include "Geometry/Polygon.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace radiosity
{

bool InsideElement(const SceneMesh& mesh, const SceneGeometry& g, int e, const Vec3& x, double tolerance)
{
  const Vec3& n = g.Normal[e];
  if (std::fabs(Dot(n, x - g.Centroid[e])) > tolerance)
  {
    return false;
  }
  const int* ids = mesh.Polygon(e);
  for (int v = 0; v < mesh.PolygonSize(e); ++v)
  {
    const Vec3& a = mesh.Points[ids[v]];
    const Vec3& b = mesh.Points[ids[(v + 1) % mesh.PolygonSize(e)]];
    // Within `tolerance` of an edge counts as inside: a centroid on the edge two elements
    // share would otherwise fall, by rounding, in neither.
    if (Dot(Cross(b - a, x - a), n) < -tolerance * Norm(b - a))
    {
      return false;
    }
  }
  return true;
}

Bounds ElementBounds(const SceneMesh& mesh, int e)
{
  Bounds b;
  for (int v = 0; v < mesh.PolygonSize(e); ++v)
  {
    b.Add(mesh.Points[mesh.Polygon(e)[v]]);
  }
  return b;
}

namespace
{

/// The candidates' centroids hashed on a grid of cells as large as the median of them: a
/// query visits few cells per element (the largest would put every candidate in one cell
/// when one of them is a whole floor).
struct CentroidGrid
{
  double Step = 0;
  Bounds All;
  std::map<std::array<long long, 3>, std::vector<int>> Cells;

  CentroidGrid(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<int>& candidates)
  {
    std::vector<double> sizes;
    for (int c : candidates)
    {
      sizes.push_back(ElementBounds(mesh, c).Diagonal());
      All.Add(g.Centroid[c]);
    }
    std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
    Step = std::max(sizes[sizes.size() / 2], 1e-12 * std::max(1.0, g.SceneDiagonal));
    for (int c : candidates)
    {
      Cells[QuantizedPoint(g.Centroid[c], Step)].push_back(c);
    }
  }

  /// Calls visit(c) for every candidate whose centroid may lie in `box`.
  template <typename Visit>
  void Near(const Bounds& box, const std::vector<int>& candidates, Visit visit) const
  {
    const auto lo = QuantizedPoint(box.Lo, Step), hi = QuantizedPoint(box.Hi, Step);
    double cells = 1;
    for (int a = 0; a < 3; ++a)
    {
      cells *= static_cast<double>(hi[a] - lo[a] + 1);
    }
    if (cells > static_cast<double>(candidates.size())) // a large element: cheaper to try them all
    {
      std::for_each(candidates.begin(), candidates.end(), visit);
      return;
    }
    for (long long x = lo[0]; x <= hi[0]; ++x)
      for (long long y = lo[1]; y <= hi[1]; ++y)
        for (long long z = lo[2]; z <= hi[2]; ++z)
        {
          const auto found = Cells.find({ x, y, z });
          if (found != Cells.end())
          {
            std::for_each(found->second.begin(), found->second.end(), visit);
          }
        }
  }
};
} // namespace

std::vector<int> FaceToFace(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<int>& candidates,
  double tolerance)
{
  if (candidates.empty())
  {
    return {};
  }
  const CentroidGrid grid(mesh, g, candidates);
  std::vector<char> touching(g.Normal.size(), 0);
  for (int f = 0; f < mesh.NumberOfPolygons(); ++f)
  {
    Bounds box = ElementBounds(mesh, f);
    if (!box.Overlaps(grid.All, tolerance))
    {
      continue;
    }
    box.Lo = box.Lo - Vec3{ tolerance, tolerance, tolerance };
    box.Hi = box.Hi + Vec3{ tolerance, tolerance, tolerance };
    grid.Near(box, candidates, [&](int c) {
      if (!touching[c] && c != f && Dot(g.Normal[c], g.Normal[f]) < -1 + 1e-6 &&
        InsideElement(mesh, g, f, g.Centroid[c], tolerance))
      {
        touching[c] = 1;
      }
    });
  }
  std::vector<int> found;
  std::copy_if(candidates.begin(), candidates.end(), std::back_inserter(found), [&](int c) { return touching[c]; });
  return found;
}

} // namespace radiosity
