#include "Mesh/AreaGrid.h"
#include "Geometry/Polygon.h"

namespace radiosity
{

namespace
{
/// The polygon's plane: a corner, the grid's two directions, and the loop's extent along them.
struct GridFrame
{
  Vec3 Origin, U, V;
  double Low[2] = { 0, 0 }, High[2] = { 0, 0 };
};

GridFrame FrameOf(const std::vector<Vec3>& loop)
{
  GridFrame f;
  f.Origin = loop[0];
  size_t far = 0;
  for (size_t k = 1; k < loop.size(); ++k)
  {
    far = Norm(loop[k] - f.Origin) > Norm(loop[far] - f.Origin) ? k : far;
  }
  f.U = Normalized(loop[far] - f.Origin);
  f.V = Normalized(Cross(Normalized(NewellVector(loop.data(), static_cast<int>(loop.size()))), f.U));
  for (const Vec3& p : loop)
  {
    const double at[2] = { Dot(p - f.Origin, f.U), Dot(p - f.Origin, f.V) };
    for (int a = 0; a < 2; ++a)
    {
      f.Low[a] = std::min(f.Low[a], at[a]);
      f.High[a] = std::max(f.High[a], at[a]);
    }
  }
  return f;
}

/// The part of `loop` between two grid lines across direction `axis`. Neighbours cut along
/// the same line compute the same points (the same edges, a negated normal), so they weld.
void Band(const std::vector<Vec3>& loop, const Vec3& axis, const Vec3& low, const Vec3& high, std::vector<Vec3>& half,
  std::vector<Vec3>& band)
{
  ClipToHalfSpace(loop.data(), static_cast<int>(loop.size()), low, axis, half);
  ClipToHalfSpace(half.data(), static_cast<int>(half.size()), high, axis * -1.0, band);
}

/// The band's corners without repeats (a corner on a grid line comes out twice).
void DropRepeats(std::vector<Vec3>& piece, double noise)
{
  std::vector<Vec3> kept;
  for (const Vec3& p : piece)
  {
    if (kept.empty() || Norm(p - kept.back()) > noise)
    {
      kept.push_back(p);
    }
  }
  while (kept.size() > 1 && Norm(kept.front() - kept.back()) <= noise)
  {
    kept.pop_back();
  }
  piece.swap(kept);
}
} // namespace

int SplitByAreaGrid(const std::vector<Vec3>& loop, double patchSize, double elementSize, double noise,
  const std::function<void(const Vec3*, int, int)>& cell)
{
  const GridFrame f = FrameOf(loop);
  const double lu = f.High[0] - f.Low[0], lv = f.High[1] - f.Low[1];
  const int pu = Divisions(lu, patchSize, noise), pv = Divisions(lv, patchSize, noise);
  const int eu = Divisions(lu / pu, elementSize, noise / pu), ev = Divisions(lv / pv, elementSize, noise / pv);
  const int nu = pu * eu, nv = pv * ev;
  const auto lineU = [&](int i) { return f.Origin + f.U * (f.Low[0] + lu * i / nu); };
  const auto lineV = [&](int j) { return f.Origin + f.V * (f.Low[1] + lv * j / nv); };
  const double thinnest = noise * std::max(lu / nu, lv / nv);
  std::vector<Vec3> half, column, piece;
  for (int i = 0; i < nu; ++i)
  {
    Band(loop, f.U, lineU(i), lineU(i + 1), half, column);
    for (int j = 0; j < nv && column.size() >= 3; ++j)
    {
      Band(column, f.V, lineV(j), lineV(j + 1), half, piece);
      DropRepeats(piece, noise);
      if (piece.size() >= 3 && PolygonArea(piece.data(), static_cast<int>(piece.size())) > thinnest)
      {
        cell(piece.data(), static_cast<int>(piece.size()), (j / ev) * pu + i / eu);
      }
    }
  }
  return pu * pv;
}

double AreaGridCells(const std::vector<Vec3>& loop, double patchSize, double elementSize)
{
  const GridFrame f = FrameOf(loop);
  const double lu = f.High[0] - f.Low[0], lv = f.High[1] - f.Low[1];
  const double pu = Divisions(lu, patchSize), pv = Divisions(lv, patchSize);
  return pu * Divisions(lu / pu, elementSize) * pv * Divisions(lv / pv, elementSize);
}

double CountAreaGrid(const std::vector<Vec3>& loop, double patchSize, double elementSize, double noise)
{
  double count = 0;
  SplitByAreaGrid(loop, patchSize, elementSize, noise, [&](const Vec3*, int, int) { ++count; });
  return count;
}

} // namespace radiosity
