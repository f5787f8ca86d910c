#include "Mesh/OverlapCuts.h"
#include "Mesh/KeepingOrder.h"
#include "Geometry/Polygon.h"
#include "Mesh/ConvexPieces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

namespace radiosity
{
namespace
{
using Loop = std::vector<Vec3>;

/// A convex polygon of a plane group: its corners, unit normal and box in the plane.
struct Face
{
  int Index = 0;   ///< in the polygons
  int Surface = 0; ///< its surface key
  bool Lamp = false;
  int LyingOn = 0; ///< other surfaces its polygon lies wholly on (KeepingOrder)
  Loop Corners;
  Vec3 Normal;
  Bounds Box;
};

/// How wide a convex loop is across (twice its area over its perimeter): a sliver along a
/// shared edge, left by rounding, is narrower than the tolerance.
double Width(const Loop& loop)
{
  if (loop.size() < 3)
  {
    return 0;
  }
  const double perimeter = Perimeter(loop);
  return perimeter > 0 ? 2 * PolygonArea(loop.data(), static_cast<int>(loop.size())) / perimeter : 0;
}

/// The loop without corners repeated within `tolerance` (clipping through a corner makes them).
Loop Distinct(const Loop& loop, double tolerance)
{
  Loop out;
  for (const Vec3& p : loop)
  {
    if (out.empty() || Norm(p - out.back()) > tolerance)
    {
      out.push_back(p);
    }
  }
  while (out.size() > 1 && Norm(out.front() - out.back()) <= tolerance)
  {
    out.pop_back();
  }
  return out;
}

/// The loop without corners that lie within `tolerance` of the line through their
/// neighbours: where a cut passes a corner, float rounding decides whether it adds one
/// beside it, and the mesher would grid the piece otherwise as the scene is turned.
Loop WithoutStraightCorners(Loop loop, double tolerance)
{
  for (size_t k = 0; loop.size() > 3 && k < loop.size();)
  {
    const Vec3& a = loop[(k + loop.size() - 1) % loop.size()];
    const Vec3& c = loop[(k + 1) % loop.size()];
    const Vec3 along = c - a;
    const double length = Norm(along);
    if (length > 0 && Norm(Cross(along, loop[k] - a)) / length <= tolerance)
    {
      loop.erase(loop.begin() + static_cast<long>(k));
      continue;
    }
    ++k;
  }
  return loop;
}

/// The half-plane inside edge k of convex `q` (normal `n`), as an origin and an inward direction.
std::pair<Vec3, Vec3> InsideEdge(const Loop& q, const Vec3& n, size_t k)
{
  const Vec3 edge = q[(k + 1) % q.size()] - q[k];
  return { q[k], Cross(n, edge) };
}

/// What of convex `p` lies inside convex `q`.
Loop Intersection(const Loop& p, const Face& q)
{
  Loop rest = p, next;
  for (size_t k = 0; k < q.Corners.size() && rest.size() >= 3; ++k)
  {
    const auto [origin, inward] = InsideEdge(q.Corners, q.Normal, k);
    ClipToHalfSpace(rest.data(), static_cast<int>(rest.size()), origin, inward, next);
    rest.swap(next);
  }
  return rest;
}

/// Convex `p` less convex `q`: the part outside each edge of q and inside the ones before
/// it, so the pieces do not overlap. Pieces narrower than `tolerance` are left out.
std::vector<Loop> Difference(const Loop& p, const Face& q, double tolerance)
{
  std::vector<Loop> pieces;
  Loop rest = p, outside, inside;
  for (size_t k = 0; k < q.Corners.size() && rest.size() >= 3; ++k)
  {
    const auto [origin, inward] = InsideEdge(q.Corners, q.Normal, k);
    ClipToHalfSpace(rest.data(), static_cast<int>(rest.size()), origin, -1.0 * inward, outside);
    outside = WithoutStraightCorners(Distinct(outside, 1e-3 * tolerance), tolerance);
    if (Width(outside) > tolerance)
    {
      pieces.push_back(outside);
    }
    ClipToHalfSpace(rest.data(), static_cast<int>(rest.size()), origin, inward, inside);
    rest.swap(inside);
  }
  return pieces;
}

/// A face of polygon `index` with `corners` (convex), its surface, normal and box.
Face MakeFace(int index, int surface, Loop corners, const Vec3& normal)
{
  Face face;
  face.Index = index;
  face.Surface = surface;
  face.Corners = std::move(corners);
  face.Normal = normal;
  for (const Vec3& p : face.Corners)
  {
    face.Box.Add(p);
  }
  return face;
}

/// The polygons of `polygons` as convex faces (a non-convex one as its convex pieces, each
/// a face of the same polygon), corners repeated or straight within `tolerance` left out:
/// a zero-length edge would have no inside.
std::vector<Face> ConvexFaces(
  const std::vector<Vec3>& points, const std::vector<int>& surfaceKey, double tolerance, const PairedPolygons& polygons)
{
  std::vector<Face> faces;
  for (size_t i = 0; i < polygons.Source.size(); ++i)
  {
    const Loop loop = Distinct(GatherLoop(points, polygons.Offsets, polygons.Connectivity, static_cast<int>(i)), tolerance);
    const Vec3 newell = loop.size() >= 3 ? NewellVector(loop.data(), static_cast<int>(loop.size())) : Vec3();
    const double length = Norm(newell);
    if (!(length > 0))
    {
      continue;
    }
    const int source = polygons.Source[i];
    const int surface = source < static_cast<int>(surfaceKey.size()) ? surfaceKey[source] : 0;
    const Vec3 normal = newell * (1.0 / length);
    if (IsConvex(loop.data(), static_cast<int>(loop.size()), tolerance))
    {
      faces.push_back(MakeFace(static_cast<int>(i), surface, loop, normal));
      continue;
    }
    for (const std::vector<int>& piece : ConvexPieces(loop, tolerance))
    {
      Loop corners;
      for (int k : piece)
      {
        corners.push_back(loop[k]);
      }
      faces.push_back(MakeFace(static_cast<int>(i), surface, std::move(corners), normal));
    }
  }
  return faces;
}

/// False when an axis in the plane (an edge's normal, of either face) parts the two convex
/// faces or lets them overlap by no more than `tolerance`: neighbours in a fan or a grid,
/// told apart without clipping.
bool MayOverlap(const Face& a, const Face& b, double tolerance)
{
  for (const Face* f : { &a, &b })
  {
    for (size_t k = 0; k < f->Corners.size(); ++k)
    {
      const Vec3 axis = Cross(f->Normal, f->Corners[(k + 1) % f->Corners.size()] - f->Corners[k]);
      const double length = Norm(axis);
      if (!(length > 0))
      {
        continue;
      }
      double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
      for (int side = 0; side < 2; ++side)
      {
        for (const Vec3& p : (side ? b : a).Corners)
        {
          const double t = Dot(axis, p) / length;
          lo[side] = std::min(lo[side], t);
          hi[side] = std::max(hi[side], t);
        }
      }
      if (std::min(hi[0], hi[1]) - std::max(lo[0], lo[1]) <= tolerance)
      {
        return false;
      }
    }
  }
  return true;
}

/// True when every corner of `a` lies within `tolerance` of `b`'s plane and they face the same side.
bool InPlaneOf(const Face& a, const Face& b, double tolerance)
{
  if (Dot(a.Normal, b.Normal) < 0.999)
  {
    return false;
  }
  for (const Vec3& p : a.Corners)
  {
    if (std::fabs(Dot(b.Normal, p - b.Corners[0])) > tolerance)
    {
      return false;
    }
  }
  return true;
}

/// Faces whose boxes span more than this many grid cells along an axis are checked against
/// every face rather than binned (a wall among a scan's small triangles).
constexpr double kMostCells = 8;

/// True when faces `a` and `b` are of different polygons, in one plane, facing one side,
/// and overlap by more than `tolerance` as far as their boxes and edges tell.
bool Candidates(const Face& a, const Face& b, double tolerance)
{
  return a.Index != b.Index && Dot(a.Normal, b.Normal) >= 0.999 &&
    a.Box.Overlaps(b.Box, tolerance) && InPlaneOf(a, b, tolerance) && InPlaneOf(b, a, tolerance) &&
    MayOverlap(a, b, tolerance);
}

/// For each face (by position in `faces`), the earlier ones that may overlap it: small
/// faces met through a grid of cells twice the median box size, faces larger than
/// kMostCells cells against all. Each pair is decided by its own geometry, so the answer
/// does not depend on how the scene is turned or moved; a fan of n triangles around one
/// corner still costs n^2 / 2 quick edge tests (its boxes all hold the corner).
std::vector<std::vector<int>> EarlierNeighbours(const std::vector<Face>& faces, double tolerance)
{
  std::vector<double> sizes;
  for (const Face& f : faces)
  {
    sizes.push_back(f.Box.Diagonal());
  }
  std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
  const double cell = std::max(2 * sizes[sizes.size() / 2], 4 * tolerance);
  const auto index = [&](double x) { return static_cast<long long>(std::floor(x / cell)); };
  std::unordered_map<long long, std::vector<int>> grid; // cells hashed by their three indices
  std::vector<int> large, seen(faces.size(), -1);
  std::vector<std::vector<int>> earlier(faces.size());
  const Vec3 margin{ tolerance, tolerance, tolerance };
  for (size_t i = 0; i < faces.size(); ++i)
  {
    const int me = static_cast<int>(i);
    const auto consider = [&](int j) {
      if (seen[j] != me && (seen[j] = me, Candidates(faces[i], faces[j], tolerance)))
      {
        earlier[i].push_back(j);
      }
    };
    const Vec3 lo = faces[i].Box.Lo - margin, hi = faces[i].Box.Hi + margin;
    const bool big = std::max({ hi.x - lo.x, hi.y - lo.y, hi.z - lo.z }) > kMostCells * cell;
    for (int j : large)
    {
      consider(j);
    }
    if (big)
    {
      for (int j = 0; j < me; ++j)
      {
        consider(j);
      }
      large.push_back(me);
    }
    for (long long x = index(lo.x); !big && x <= index(hi.x); ++x)
      for (long long y = index(lo.y); y <= index(hi.y); ++y)
        for (long long z = index(lo.z); z <= index(hi.z); ++z)
        {
          std::vector<int>& here = grid[CellHash(x, y, z)];
          for (int j : here)
          {
            consider(j);
          }
          here.push_back(me);
        }
    std::sort(earlier[i].begin(), earlier[i].end());
  }
  return earlier;
}

/// True when `pieces` (convex) leave nothing wider than `tolerance` outside `under`: the
/// polygon they make lies wholly on those faces. Their areas are compared first, so a floor
/// beside many small decals is not cut by each to find out.
bool CoveredBy(std::vector<Loop> pieces, const std::vector<const Face*>& under, double tolerance)
{
  double area = 0, below = 0;
  for (const Loop& piece : pieces)
  {
    area += PolygonArea(piece.data(), static_cast<int>(piece.size()));
  }
  for (const Face* f : under)
  {
    below += PolygonArea(f->Corners.data(), static_cast<int>(f->Corners.size()));
  }
  if (below < area - tolerance * std::sqrt(area))
  {
    return false;
  }
  for (const Face* f : under)
  {
    std::vector<Loop> left;
    for (const Loop& piece : pieces)
    {
      for (Loop& rest : Difference(piece, *f, tolerance))
      {
        left.push_back(std::move(rest));
      }
    }
    pieces.swap(left);
    if (pieces.empty())
    {
      return true;
    }
  }
  return false;
}

/// Per polygon (by index), the number of other surfaces it lies wholly on (the union of
/// each one's faces in its plane covering it: a poster over the diagonal of a wall drawn as
/// two triangles lies on the wall). A polygon lying wholly on its own surface (a part of a
/// wall drawn again) is part of that surface, and counts none: a poster over it keeps.
std::vector<int> SurfacesUnder(const std::vector<Face>& faces, const std::vector<std::vector<int>>& neighbours,
  size_t polygons, double tolerance)
{
  std::vector<std::vector<int>> facesOf(polygons);
  std::vector<std::map<int, std::set<int>>> under(polygons); // polygon -> surface -> faces overlapping it
  for (size_t i = 0; i < faces.size(); ++i)
  {
    facesOf[faces[i].Index].push_back(static_cast<int>(i));
    for (int j : neighbours[i])
    {
      under[faces[i].Index][faces[j].Surface].insert(j);
      under[faces[j].Index][faces[i].Surface].insert(static_cast<int>(i));
    }
  }
  std::vector<int> count(polygons, 0);
  for (size_t p = 0; p < polygons; ++p)
  {
    if (under[p].empty())
    {
      continue;
    }
    std::vector<Loop> pieces;
    for (int i : facesOf[p])
    {
      pieces.push_back(faces[i].Corners);
    }
    const int own = faces[facesOf[p].front()].Surface;
    bool partOfOwn = false;
    for (const auto& [surface, list] : under[p])
    {
      std::vector<const Face*> below;
      for (int j : list)
      {
        below.push_back(&faces[j]);
      }
      if (CoveredBy(pieces, below, tolerance))
      {
        partOfOwn = partOfOwn || surface == own;
        count[p] += surface == own ? 0 : 1;
      }
    }
    count[p] = partOfOwn ? 0 : count[p];
  }
  return count;
}

/// `faces` in the order in which they keep an overlap (KeepingOrder: lamps, then faces
/// lying on faces of other surfaces, then the earlier), with the earlier ones that may
/// overlap each (as EarlierNeighbours gives them) in `earlier`.
std::vector<Face> InKeepingOrder(std::vector<Face> faces, const std::vector<char>& lamps, const PairedPolygons& polygons,
  double tolerance, std::vector<std::vector<int>>& earlier)
{
  const KeepingOrder order(lamps, polygons);
  const std::vector<std::vector<int>> before = EarlierNeighbours(faces, tolerance);
  const std::vector<int> lyingOn = SurfacesUnder(faces, before, polygons.Source.size(), tolerance);
  for (Face& f : faces)
  {
    f.Lamp = order.IsLamp(f.Index);
    f.LyingOn = lyingOn[f.Index];
  }
  std::vector<int> sorted(faces.size()), position(faces.size());
  std::iota(sorted.begin(), sorted.end(), 0);
  std::stable_sort(sorted.begin(), sorted.end(), [&](int a, int b) {
    return order.Before(faces[a].Index, faces[b].Index, faces[a].LyingOn, faces[b].LyingOn);
  });
  std::vector<Face> ordered;
  for (size_t at = 0; at < sorted.size(); ++at)
  {
    position[sorted[at]] = static_cast<int>(at);
    ordered.push_back(std::move(faces[sorted[at]]));
  }
  // The pairs found once, in the new order: each face's partners that now come before it.
  earlier.assign(faces.size(), {});
  for (size_t i = 0; i < before.size(); ++i)
  {
    for (int j : before[i])
    {
      const int a = position[i], b = position[j];
      earlier[std::max(a, b)].push_back(std::min(a, b));
    }
  }
  for (std::vector<int>& list : earlier)
  {
    std::sort(list.begin(), list.end());
  }
  return ordered;
}

/// Cuts each face by the earlier ones (InKeepingOrder) that overlap it; returns each face's
/// pieces (its own corners where nothing overlaps it, none where it is covered), marks in
/// `cut` (by polygon) those that changed, and lists the overlapping pairs of different
/// surfaces (by polygon, the one that keeps the overlap first) in `differing`, to be said:
/// which one was meant cannot be told, but both would receive the full light; in `onTop`
/// where the one kept lies wholly on the other's surface (meant: a poster on its wall). Lamps of
/// two lights are not cut (each emits the power it was given), and listed in `lampsKept`.
std::vector<std::vector<Loop>> CutFaces(const std::vector<Face>& faces, const std::vector<std::vector<int>>& earlier,
  double tolerance, std::vector<char>& cut, std::vector<std::pair<int, int>>& differing,
  std::vector<std::pair<int, int>>& onTop, std::vector<std::pair<int, int>>& lampsKept)
{
  std::vector<std::vector<Loop>> pieces(faces.size());
  for (size_t i = 0; i < faces.size(); ++i)
  {
    pieces[i] = { faces[i].Corners };
    for (int j : earlier[i])
    {
      if (Width(Intersection(faces[i].Corners, faces[j])) <= tolerance)
      {
        continue; // neighbours along an edge
      }
      if (faces[j].Surface != faces[i].Surface && faces[j].Lamp && faces[i].Lamp)
      {
        lampsKept.emplace_back(faces[j].Index, faces[i].Index);
        continue; // lamps of two lights: each emits as given (cut, one would emit part of it)
      }
      if (faces[j].Surface != faces[i].Surface)
      {
        // A lamp keeps by being one; a poster by lying on its wall (meant, and said so).
        const bool meant = !faces[j].Lamp && faces[j].LyingOn > faces[i].LyingOn;
        (meant ? onTop : differing).emplace_back(faces[j].Index, faces[i].Index);
      }
      // A piece whose box stays clear of j's is kept whole (a floor under many decals of
      // another material was cut quadratically otherwise); a nearer one
      // is split along all of j's edges, also where clear of it: deciding by the overlap
      // itself let float noise decide a sliver's fate (TestInvariance).
      std::vector<Loop> left;
      for (Loop& piece : pieces[i])
      {
        Bounds box;
        for (const Vec3& p : piece)
        {
          box.Add(p);
        }
        if (!box.Overlaps(faces[j].Box, 4 * tolerance))
        {
          left.push_back(std::move(piece));
          continue;
        }
        for (Loop& rest : Difference(piece, faces[j], tolerance))
        {
          left.push_back(std::move(rest));
        }
      }
      pieces[i].swap(left);
      cut[faces[i].Index] = 1;
    }
  }
  return pieces;
}

} // namespace

OverlapCuts CutOverlaps(const std::vector<Vec3>& points, const std::vector<int>& surfaceKey,
  const std::vector<char>& lamps, double tolerance, PairedPolygons& polygons)
{
  OverlapCuts found;
  std::vector<char> cut(polygons.Source.size(), 0);
  std::vector<std::vector<Loop>> pieces(polygons.Source.size());
  std::vector<Face> faces = ConvexFaces(points, surfaceKey, tolerance, polygons);
  if (faces.size() < 2)
  {
    return found;
  }
  std::vector<std::vector<int>> earlier;
  faces = InKeepingOrder(std::move(faces), lamps, polygons, tolerance, earlier);
  std::vector<std::pair<int, int>> differing, onTop, lampsKept;
  std::vector<std::vector<Loop>> cutPieces = CutFaces(faces, earlier, tolerance, cut, differing, onTop, lampsKept);
  // By input polygon, once (a polygon's convex pieces are faces of their own).
  for (auto [pairs, into] :
    { std::pair{ &differing, &found.Differing }, { &onTop, &found.OnTop }, { &lampsKept, &found.LampsKept } })
  {
    std::sort(pairs->begin(), pairs->end());
    pairs->erase(std::unique(pairs->begin(), pairs->end()), pairs->end());
    for (const std::pair<int, int>& pair : *pairs)
    {
      into->emplace_back(polygons.Source[pair.first], polygons.Source[pair.second]);
    }
  }
  for (size_t f = 0; f < faces.size(); ++f)
  {
    for (Loop& piece : cutPieces[f])
    {
      pieces[faces[f].Index].push_back(std::move(piece));
    }
  }
  if (std::find(cut.begin(), cut.end(), 1) == cut.end())
  {
    return found;
  }
  PairedPolygons kept;
  kept.Points = points;
  kept.Merged = polygons.Merged;
  for (size_t i = 0; i < polygons.Source.size(); ++i)
  {
    const int source = polygons.Source[i];
    if (!cut[i])
    {
      kept.Connectivity.insert(kept.Connectivity.end(), polygons.Connectivity.begin() + polygons.Offsets[i],
        polygons.Connectivity.begin() + polygons.Offsets[i + 1]);
      kept.Offsets.push_back(static_cast<int>(kept.Connectivity.size()));
      kept.Source.push_back(source);
      continue;
    }
    (pieces[i].empty() ? found.Covered : found.Trimmed).push_back(source);
    for (const Loop& piece : pieces[i])
    {
      for (const Vec3& p : piece)
      {
        kept.Connectivity.push_back(static_cast<int>(kept.Points.size()));
        kept.Points.push_back(p);
      }
      kept.Offsets.push_back(static_cast<int>(kept.Connectivity.size()));
      kept.Source.push_back(source);
    }
  }
  polygons = std::move(kept);
  return found;
}

} // namespace radiosity

