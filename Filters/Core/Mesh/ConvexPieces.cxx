#include "Mesh/ConvexPieces.h"
#include "Geometry/CornerGrid.h"
#include "Geometry/Polygon.h"

#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <set>

namespace radiosity
{

namespace
{
/// Ear clipping that takes the smallest ear first and stops once what is left is convex:
/// a gear loses its teeth (each two small ears) and leaves its disk whole, where clipping
/// in order round the loop cuts slivers from rim to rim.
class SmallEarsFirst
{
public:
  SmallEarsFirst(const std::vector<Vec3>& loop, double noise)
    : Loop(loop)
    , Noise(noise)
    , Unit(Normalized(NewellVector(loop.data(), static_cast<int>(loop.size()))))
    , Scale(Norm(NewellVector(loop.data(), static_cast<int>(loop.size()))))
    , Prev(loop.size())
    , Next(loop.size())
    , Alive(loop.size(), 1)
    , Reflex(loop.size(), 0)
    , Key(loop.size(), kNoEar)
  {
    const int n = static_cast<int>(loop.size());
    for (int i = 0; i < n; ++i)
    {
      Prev[i] = (i + n - 1) % n;
      Next[i] = (i + 1) % n;
    }
  }

  /// False where no ear is left before the rest is convex (a self-intersecting loop).
  bool Run(std::vector<std::vector<int>>& triangles, std::vector<int>& rest)
  {
    Rescan();
    int left = static_cast<int>(Loop.size());
    while (left > 3 && Reflexes > 0)
    {
      if (Ears.empty() && (Rescan(), Ears.empty()))
      {
        return false;
      }
      const int b = Ears.begin()->second;
      Ears.erase(Ears.begin());
      Key[b] = kNoEar;
      const int a = Prev[b], c = Next[b];
      if (!Straight(a, b, c))
      {
        triangles.push_back({ a, b, c });
      }
      Next[a] = c;
      Prev[c] = a;
      Alive[b] = 0;
      --left;
      Update(a);
      Update(c);
    }
    for (int i = 0, n = static_cast<int>(Loop.size()); i < n; ++i)
    {
      if (Alive[i])
      {
        for (int k = i; rest.empty() || k != i; k = Next[k])
        {
          rest.push_back(k);
        }
        break;
      }
    }
    return true;
  }

private:
  static constexpr double kNoEar = -1e300, kStraight = -1e299;

  double Turn(int a, int b, int c) const { return Dot(Unit, Cross(Loop[b] - Loop[a], Loop[c] - Loop[b])); }
  bool Straight(int a, int b, int c) const
  {
    return std::fabs(Turn(a, b, c)) <= StraightLimit(Loop[a], Loop[b], Loop[c], Noise);
  }
  bool IsReflex(int b) const
  {
    return Turn(Prev[b], b, Next[b]) < -StraightLimit(Loop[Prev[b]], Loop[b], Loop[Next[b]], Noise);
  }

  /// The ear's rank by size (a straight corner first, making no triangle), or kNoEar.
  double EarKey(int b) const
  {
    const int a = Prev[b], c = Next[b];
    if (Straight(a, b, c))
    {
      return kStraight;
    }
    if (Reflex[b])
    {
      return kNoEar;
    }
    if (ReflexGrid->Any(a, b, c, [&](int r) {
          return Alive[r] && Reflex[r] && r != a && r != c && Turn(a, b, r) >= 0 && Turn(b, c, r) >= 0 &&
            Turn(c, a, r) >= 0;
        }))
    {
      return kNoEar; // a reflex corner inside: cutting it off would leave the loop
    }
    const double turn = Turn(a, b, c);
    if (!(turn > 0) || !(Scale > 0))
    {
      return kNoEar; // a corner turned reflex by a degenerate loop folding back: no ear
    }
    // By size to a quarter octave of the loop's area, then in the loop's order: a float-
    // stored model turned or scaled clips the same ears (sizes equal up to rounding tie).
    return std::round(4 * std::log2(turn / Scale));
  }

  void SetKey(int b, double key)
  {
    if (Key[b] != kNoEar)
    {
      Ears.erase({ Key[b], b });
    }
    Key[b] = key;
    if (key != kNoEar)
    {
      Ears.insert({ key, b });
    }
  }

  /// Corner b after a neighbour was cut off: it can only have become more convex.
  void Update(int b)
  {
    if (Reflex[b] && !IsReflex(b))
    {
      Reflex[b] = 0;
      ReflexGrid->Remove(b);
      --Reflexes;
    }
    SetKey(b, EarKey(b));
  }

  /// Every corner's state from scratch (at the start, and where a corner that stopped
  /// being reflex may have freed ears elsewhere).
  void Rescan()
  {
    ReflexList.clear();
    Reflexes = 0;
    for (size_t b = 0; b < Loop.size(); ++b)
    {
      Reflex[b] = Alive[b] && IsReflex(static_cast<int>(b));
      if (Reflex[b])
      {
        ReflexList.push_back(static_cast<int>(b));
        ++Reflexes;
      }
    }
    ReflexGrid = std::make_unique<CornerGrid>(Loop.data(), static_cast<int>(Loop.size()), Unit, ReflexList);
    for (size_t b = 0; b < Loop.size(); ++b)
    {
      if (Alive[b])
      {
        SetKey(static_cast<int>(b), EarKey(static_cast<int>(b)));
      }
    }
  }

  const std::vector<Vec3>& Loop;
  const double Noise;
  const Vec3 Unit;
  const double Scale; ///< twice the loop's area
  std::vector<int> Prev, Next;
  std::vector<char> Alive, Reflex;
  std::vector<double> Key;
  std::vector<int> ReflexList;
  std::unique_ptr<CornerGrid> ReflexGrid; ///< the reflex corners, where EarKey looks for them
  int Reflexes = 0;
  std::set<std::pair<double, int>> Ears;
};

/// `piece` turned to start at `from`, where its corner before `from` is `before`: empty
/// when it has no such edge.
std::vector<int> StartingAt(const std::vector<int>& piece, int before, int from)
{
  const size_t n = piece.size();
  for (size_t i = 0; i < n; ++i)
  {
    if (piece[i] == from && piece[(i + n - 1) % n] == before)
    {
      std::vector<int> turned(piece.begin() + static_cast<std::ptrdiff_t>(i), piece.end());
      turned.insert(turned.end(), piece.begin(), piece.begin() + static_cast<std::ptrdiff_t>(i));
      return turned;
    }
  }
  return {};
}

/// The union of two pieces that share the diagonal a -> b (in `p`; b -> a in `q`, as two
/// faces of one loop's orientation do): p from b round to a, then q past a round to b.
std::vector<int> Merged(const std::vector<int>& p, const std::vector<int>& q, int a, int b)
{
  std::vector<int> first = StartingAt(p, a, b), second = StartingAt(q, b, a);
  if (first.empty() || second.empty())
  {
    return {};
  }
  first.insert(first.end(), second.begin() + 1, second.end() - 1);
  return first;
}

std::vector<Vec3> Corners(const std::vector<Vec3>& loop, const std::vector<int>& piece)
{
  std::vector<Vec3> corners;
  corners.reserve(piece.size());
  for (int i : piece)
  {
    corners.push_back(loop[i]);
  }
  return corners;
}

bool Convex(const std::vector<Vec3>& loop, const std::vector<int>& piece, double noise)
{
  const std::vector<Vec3> corners = Corners(loop, piece);
  return IsConvex(corners.data(), static_cast<int>(corners.size()), noise);
}

/// True when a union of two convex pieces (Merged: the first's corners, `firstSize` of
/// them, then the second's between the diagonal's ends) turns back at a diagonal's end by
/// far more than IsConvex allows: then it is not convex, and IsConvex's walk round the
/// whole union is spared (each of a gear's teeth is tried against its disk). Pieces whose
/// Newell vectors (`first`, `second`) do not add up to the larger (a loop that touches
/// itself) are left to IsConvex.
bool ClearlyBentBack(const std::vector<Vec3>& loop, const std::vector<int>& merged, size_t firstSize,
  const Vec3& first, const Vec3& second, double noise)
{
  const Vec3 newell = first + second;
  if (!(Norm(newell) >= std::max(Norm(first), Norm(second))))
  {
    return false;
  }
  const Vec3 unit = Normalized(newell);
  const size_t n = merged.size();
  for (const size_t at : { size_t(0), firstSize - 1 }) // the diagonal's ends
  {
    const Vec3 &a = loop[merged[(at + n - 1) % n]], &b = loop[merged[at]], &c = loop[merged[(at + 1) % n]];
    if (Dot(unit, Cross(b - a, c - b)) < -2 * StraightLimit(a, b, c, noise) - 1e-9 * Norm(Cross(b - a, c - b)))
    {
      return true;
    }
  }
  return false;
}

/// Hertel & Mehlhorn: each piece merged with its neighbour across a shared edge where the
/// union stays convex.
void MergeAcrossDiagonals(const std::vector<Vec3>& loop, double noise, std::vector<std::vector<int>>& pieces)
{
  std::map<std::pair<int, int>, int> sideOf; // directed edge -> its piece
  for (int t = 0; t < static_cast<int>(pieces.size()); ++t)
  {
    for (size_t k = 0; k < pieces[t].size(); ++k)
    {
      sideOf[{ pieces[t][k], pieces[t][(k + 1) % pieces[t].size()] }] = t;
    }
  }
  std::vector<Vec3> newell(pieces.size()); // of each piece: a union's is the sum
  for (size_t t = 0; t < pieces.size(); ++t)
  {
    newell[t] = NewellVector(Corners(loop, pieces[t]).data(), static_cast<int>(pieces[t].size()));
  }
  std::vector<int> owner(pieces.size());
  std::iota(owner.begin(), owner.end(), 0);
  const auto find = [&](int t) {
    while (owner[t] != t)
    {
      t = owner[t] = owner[owner[t]];
    }
    return t;
  };
  for (const auto& [edge, t] : sideOf)
  {
    const auto other = sideOf.find({ edge.second, edge.first }); // a diagonal: the neighbour has it the other way
    if (other == sideOf.end() || other->second < t)
    {
      continue; // a side of the loop, or a diagonal taken from the other piece already
    }
    const int p = find(t), q = find(other->second);
    std::vector<int> merged = p == q ? std::vector<int>() : Merged(pieces[p], pieces[q], edge.first, edge.second);
    if (!merged.empty() && !ClearlyBentBack(loop, merged, pieces[p].size(), newell[p], newell[q], noise) &&
      Convex(loop, merged, noise))
    {
      pieces[p].swap(merged);
      pieces[q].clear();
      newell[p] += newell[q];
      owner[q] = p;
    }
  }
}
} // namespace

std::vector<std::vector<int>> ConvexPieces(const std::vector<Vec3>& loop, double noise)
{
  std::vector<std::vector<int>> pieces;
  std::vector<int> rest;
  if (loop.size() < 3 || !SmallEarsFirst(loop, noise).Run(pieces, rest))
  {
    return {};
  }
  if (rest.size() >= 3)
  {
    pieces.push_back(rest);
  }
  MergeAcrossDiagonals(loop, noise, pieces);
  std::vector<std::vector<int>> out;
  for (std::vector<int>& piece : pieces)
  {
    if (!piece.empty())
    {
      out.push_back(std::move(piece));
    }
  }
  return out;
}

} // namespace radiosity
