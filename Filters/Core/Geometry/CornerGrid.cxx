#include "Geometry/CornerGrid.h"

#include <algorithm>
#include <cmath>

namespace radiosity
{

CornerGrid::CornerGrid(const Vec3* loop, int count, const Vec3& unitNormal, const std::vector<int>& members)
  : U(count, 0.0)
  , V(count, 0.0)
{
  // Any two axes across the normal: the inside test's turns are 2-D cross products there.
  const Vec3 helper = std::fabs(unitNormal.x) < 0.6 ? Vec3{ 1, 0, 0 } : Vec3{ 0, 1, 0 };
  const Vec3 axisU = Normalized(Cross(unitNormal, helper));
  const Vec3 axisV = Cross(unitNormal, axisU);
  double maxU = -1e300, maxV = -1e300;
  MinU = MinV = 1e300;
  // From a corner, not the origin: far along the normal, a dot product with the whole
  // coordinate rounds by more than the pad, and a corner inside an ear fell in a cell
  // the ear did not visit (a loop 1e8 times its size off the origin, turned).
  const Vec3 origin = count > 0 ? loop[0] : Vec3();
  for (int i = 0; i < count; ++i)
  {
    U[i] = Dot(axisU, loop[i] - origin);
    V[i] = Dot(axisV, loop[i] - origin);
    MinU = std::min(MinU, U[i]);
    MinV = std::min(MinV, V[i]);
    maxU = std::max(maxU, U[i]);
    maxV = std::max(maxV, V[i]);
  }
  const double width = std::max(maxU - MinU, maxV - MinV);
  if (std::isfinite(width) && width > 1e-300)
  {
    // About one member a cell.
    const double side = std::ceil(std::sqrt(static_cast<double>(std::max<size_t>(members.size(), 1))));
    Cell = width / side;
    Columns = static_cast<int>(std::floor((maxU - MinU) / Cell)) + 1;
    Rows = static_cast<int>(std::floor((maxV - MinV) / Cell)) + 1;
    Pad = 1e-9 * std::max({ width, std::fabs(MinU), std::fabs(MinV), std::fabs(maxU), std::fabs(maxV) });
  }
  Cells.assign(static_cast<size_t>(Columns) * Rows, {});
  for (int corner : members)
  {
    Cells[static_cast<size_t>(Row(V[corner])) * Columns + Column(U[corner])].push_back(corner);
  }
}

int CornerGrid::Column(double u) const
{
  const double at = std::floor((u - MinU) / Cell);
  return at >= 0 && at < Columns ? static_cast<int>(at) : (at >= Columns ? Columns - 1 : 0); // NaN: 0
}

int CornerGrid::Row(double v) const
{
  const double at = std::floor((v - MinV) / Cell);
  return at >= 0 && at < Rows ? static_cast<int>(at) : (at >= Rows ? Rows - 1 : 0);
}

void CornerGrid::Remove(int corner)
{
  std::vector<int>& cell = Cells[static_cast<size_t>(Row(V[corner])) * Columns + Column(U[corner])];
  const auto at = std::find(cell.begin(), cell.end(), corner);
  if (at != cell.end())
  {
    *at = cell.back();
    cell.pop_back();
  }
}

bool CornerGrid::SpanInRow(int a, int b, int c, int j, double& uLo, double& uHi) const
{
  const double vLo = MinV + j * Cell - Pad, vHi = MinV + (j + 1) * Cell + Pad;
  const bool first = j == 0, last = j == Rows - 1; // the outer rows hold what lies beyond
  uLo = 1e300;
  uHi = -1e300;
  const int corners[3] = { a, b, c };
  for (int k = 0; k < 3; ++k)
  {
    const int p = corners[k], q = corners[(k + 1) % 3];
    // The edge p-q clipped to the band, its ends' u taken.
    double t0 = 0, t1 = 1;
    const double dv = V[q] - V[p];
    if (dv != 0)
    {
      const double tLo = first ? (dv > 0 ? -1e300 : 1e300) : (vLo - V[p]) / dv;
      const double tHi = last ? (dv > 0 ? 1e300 : -1e300) : (vHi - V[p]) / dv;
      t0 = std::max(t0, std::min(tLo, tHi));
      t1 = std::min(t1, std::max(tLo, tHi));
    }
    else if ((!first && V[p] < vLo) || (!last && V[p] > vHi))
    {
      continue;
    }
    if (!(t0 <= t1))
    {
      continue;
    }
    for (const double t : { t0, t1 })
    {
      const double u = U[p] + t * (U[q] - U[p]);
      uLo = std::min(uLo, u);
      uHi = std::max(uHi, u);
    }
  }
  return uLo <= uHi;
}

} // namespace radiosity
