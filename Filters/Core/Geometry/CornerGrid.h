// A polygon's corners hashed in its plane, so that ear clipping asks only the corners near
// an ear whether they lie inside it: with every corner asked, a 20,000-corner gear took
// 10 s to mesh (quadratic in corners); with the grid it is linear for such shapes.
#ifndef RadiosityCore_CornerGrid_h
#define RadiosityCore_CornerGrid_h

#include "Base/Vec3.h"

#include <algorithm>
#include <vector>

namespace radiosity
{

class CornerGrid
{
public:
  /// Corners `members` of `loop`, projected on the plane across `unitNormal`.
  CornerGrid(const Vec3* loop, int count, const Vec3& unitNormal, const std::vector<int>& members);

  void Remove(int corner);

  /// Calls `test` on every member whose projection lies in a cell that triangle a-b-c
  /// (padded far beyond rounding) crosses, until it returns true: for a triangle that turns
  /// left (an ear), a superset of the corners the caller's inside test can accept, so the
  /// answer is the one a test of every corner gives. Row by row, the cells under the triangle only: a long sliver across a ring of
  /// corners (ear clipping's fan) does not visit every corner in its bounding box.
  template <typename Test>
  bool Any(int a, int b, int c, const Test& test) const
  {
    const int rowLo = Row(std::min({ V[a], V[b], V[c] }) - Pad), rowHi = Row(std::max({ V[a], V[b], V[c] }) + Pad);
    for (int j = rowLo; j <= rowHi; ++j)
    {
      double uLo, uHi;
      if (!SpanInRow(a, b, c, j, uLo, uHi))
      {
        continue;
      }
      for (int i = Column(uLo - Pad), end = Column(uHi + Pad); i <= end; ++i)
      {
        for (int corner : Cells[static_cast<size_t>(j) * Columns + i])
        {
          if (test(corner))
          {
            return true;
          }
        }
      }
    }
    return false;
  }

private:
  int Column(double u) const;
  int Row(double v) const;
  /// The u-extent of triangle a-b-c within row j's band of v (padded); false if it misses.
  bool SpanInRow(int a, int b, int c, int j, double& uLo, double& uHi) const;

  std::vector<double> U, V; ///< each corner's coordinates in the plane
  double MinU = 0, MinV = 0, Cell = 1, Pad = 0;
  int Columns = 1, Rows = 1;
  std::vector<std::vector<int>> Cells;
};

} // namespace radiosity

#endif
