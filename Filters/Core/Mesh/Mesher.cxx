#include "Mesh/Mesher.h"
#include "Geometry/Visibility.h"
#include "Mesh/AreaGrid.h"
#include "Mesh/ConvexPieces.h"
#include "Mesh/CoincidentCopies.h"
#include "Mesh/OverlapCuts.h"
#include "Mesh/ContactCuts.h"
#include "Mesh/FaceClusters.h"
#include "Mesh/Surfaces.h"
#include "Geometry/Polygon.h"
#include "Mesh/TrianglePairs.h"

#include <algorithm>
#include <functional>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

namespace radiosity
{

/// How far, in LampGrading's reach (ElementSize / LampGrading), a lamp's shadows grade
/// the patches (MesherOptions::ShadowGrading): the rooms it lights.
constexpr double kShadowReach = 6.0;

namespace
{
/// Grid lines of a quad's side, 0..1: `patches` equal patches, patch p cut into `cuts[p]`.
std::vector<double> GridLines(int patches, const std::vector<int>& cuts)
{
  std::vector<double> lines{ 0.0 };
  for (int p = 0; p < patches; ++p)
  {
    for (int a = 1; a <= cuts[p]; ++a)
    {
      lines.push_back((p + static_cast<double>(a) / cuts[p]) / patches);
    }
  }
  return lines;
}

/// Emits the elements of a convex quad on a bilinear grid: emit(corners, 4, local patch).
/// Near a lamp (MesherOptions::LampGrading) a patch's column and row take the finer count
/// it wants. Returns the number of patches.
template <typename Emit>
int SplitQuad(const Vec3* q, const MesherOptions& o, double noise, const Emit& emit)
{
  const double lu = std::max(Norm(q[1] - q[0]), Norm(q[2] - q[3]));
  const double lv = std::max(Norm(q[3] - q[0]), Norm(q[2] - q[1]));
  const int pu = Divisions(lu, o.PatchSize, noise), pv = Divisions(lv, o.PatchSize, noise);
  // Every point comes from the same bilinear formula, so neighbours share exact values.
  auto at = [&](double s, double t) {
    return q[0] * ((1 - s) * (1 - t)) + q[1] * (s * (1 - t)) + q[2] * (s * t) + q[3] * ((1 - s) * t);
  };
  std::vector<int> eu(pu, Divisions(lu / pu, o.ElementSize, noise / pu));
  std::vector<int> ev(pv, Divisions(lv / pv, o.ElementSize, noise / pv));
  for (int j = 0; j < pv && !o.GradingLamps.empty(); ++j)
  {
    for (int i = 0; i < pu; ++i)
    {
      const double s0 = static_cast<double>(i) / pu, s1 = (i + 1.0) / pu, t0 = static_cast<double>(j) / pv,
                   t1 = (j + 1.0) / pv;
      const Vec3 patch[4] = { at(s0, t0), at(s1, t0), at(s1, t1), at(s0, t1) };
      const double size = std::min(GradedElementSize(o.GradingLamps, patch, 4, o.ElementSize, o.LampGrading),
        ShadowGradedSize(o.GradingLamps, o.ShadowRays.get(), patch, 4, o.ElementSize, o.ShadowGrading,
          kShadowReach * o.ElementSize / o.LampGrading));
      eu[i] = std::max(eu[i], Divisions(lu / pu, size, noise / pu));
      ev[j] = std::max(ev[j], Divisions(lv / pv, size, noise / pv));
    }
  }
  const std::vector<double> su = GridLines(pu, eu), tv = GridLines(pv, ev);
  for (size_t j = 0, patchRow = 0, rowEnd = ev[0]; j + 1 < tv.size(); ++j)
  {
    if (j == rowEnd)
    {
      rowEnd += ev[++patchRow];
    }
    for (size_t i = 0, patchColumn = 0, columnEnd = eu[0]; i + 1 < su.size(); ++i)
    {
      if (i == columnEnd)
      {
        columnEnd += eu[++patchColumn];
      }
      const Vec3 corners[4] = { at(su[i], tv[j]), at(su[i + 1], tv[j]), at(su[i + 1], tv[j + 1]), at(su[i], tv[j + 1]) };
      emit(corners, 4, static_cast<int>(patchRow * pu + patchColumn));
    }
  }
  return pu * pv;
}

/// Patches along a triangle's longest edge. A sliver (narrower than a quarter of its length, as
/// triangulated walls and roofs of real models are full of) is split by its area instead:
/// cutting a 3 m x 2 cm strip into 72 patches of nothing made a house of 16k polygons 66k
/// patches, and every patch is a shooter.
int TrianglePatchDivisions(const Vec3& a, const Vec3& b, const Vec3& c, double longest, double patch, double noise)
{
  const double width = Norm(Cross(b - a, c - a)) / longest; // twice the area over the base
  return width < 0.25 * longest ? Divisions(std::sqrt(width * longest), patch, noise)
                                : Divisions(longest, patch, noise);
}

/// Emits the elements of a triangle on a barycentric lattice, local patches counted from
/// `firstPatch`. Returns the number of patches.
template <typename Emit>
int SplitTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const MesherOptions& o, double noise, int firstPatch,
  const Emit& emit)
{
  const double longest = std::max({ Norm(b - a), Norm(c - b), Norm(a - c) });
  const int np = TrianglePatchDivisions(a, b, c, longest, o.PatchSize, noise);
  const Vec3 corners[3] = { a, b, c };
  const double size = std::min(GradedElementSize(o.GradingLamps, corners, 3, o.ElementSize, o.LampGrading),
    ShadowGradedSize(o.GradingLamps, o.ShadowRays.get(), corners, 3, o.ElementSize, o.ShadowGrading,
      kShadowReach * o.ElementSize / o.LampGrading));
  const int ne = Divisions(longest / np, size, noise / np);
  const int n = np * ne;
  auto at = [&](int i, int j) {
    return a + (b - a) * (static_cast<double>(i) / n) + (c - a) * (static_cast<double>(j) / n);
  };
  // A patch is a cell of the coarse lattice: upright (I, J) or inverted; the element's
  // centroid in coarse coordinates tells which.
  auto patchOf = [&](double ci, double cj) {
    const int I = static_cast<int>(std::floor(ci / ne)), J = static_cast<int>(std::floor(cj / ne));
    const bool inverted = (ci / ne - I) + (cj / ne - J) > 1;
    return firstPatch + (I * np + J) * 2 + (inverted ? 1 : 0);
  };
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; i + j < n; ++j)
    {
      const Vec3 upright[3] = { at(i, j), at(i + 1, j), at(i, j + 1) };
      emit(upright, 3, patchOf(i + 1.0 / 3, j + 1.0 / 3));
      if (i + j + 1 < n)
      {
        const Vec3 inverted[3] = { at(i + 1, j), at(i + 1, j + 1), at(i, j + 1) };
        emit(inverted, 3, patchOf(i + 2.0 / 3, j + 2.0 / 3));
      }
    }
  }
  return np * np * 2;
}

double CountLattice(const std::vector<Vec3>& loop, double patch, double element, double noise);

/// Grids of more cells than this are not cut to count them (a polygon that large is over
/// any element budget either way, and its triangles' lattice is counted at once).
constexpr double kMostAreaGridCells = 1e5;

/// A convex polygon of more than four corners whose triangles would make more than twice
/// the elements of a grid over its area (a circle's slivers) is meshed by the grid: the
/// elements that grid makes, else -1.
double AreaGridElements(const std::vector<Vec3>& loop, double patch, double element, double noise)
{
  if (loop.size() <= 4 || !IsConvex(loop.data(), static_cast<int>(loop.size()), noise))
  {
    return -1;
  }
  const double cells = AreaGridCells(loop, patch, element);
  const double grid = cells <= kMostAreaGridCells ? CountAreaGrid(loop, patch, element, noise) : cells;
  return 2 * grid < CountLattice(loop, patch, element, noise) ? grid : -1;
}

double CountPlain(const std::vector<Vec3>& loop, double patchSize, double elementSize, double noise);

/// A non-convex polygon of more than kManyCorners corners whose triangles would make more
/// than twice the elements of its convex pieces (a gear's slivers) is meshed piece by
/// piece: those pieces (and in `elements`, what they make), else none.
constexpr size_t kManyCorners = 8;
std::vector<std::vector<Vec3>> PiecesToMesh(
  const std::vector<Vec3>& loop, double patch, double element, double noise, double* elements = nullptr)
{
  if (loop.size() <= kManyCorners || IsConvex(loop.data(), static_cast<int>(loop.size()), noise))
  {
    return {};
  }
  std::vector<std::vector<Vec3>> pieces;
  double made = 0;
  for (const std::vector<int>& piece : ConvexPieces(loop, noise))
  {
    pieces.emplace_back();
    for (int i : piece)
    {
      pieces.back().push_back(loop[i]);
    }
    made += CountPlain(pieces.back(), patch, element, noise);
  }
  if (!(2 * made < CountLattice(loop, patch, element, noise)))
  {
    return {};
  }
  if (elements)
  {
    *elements = made;
  }
  return pieces;
}

/// Emits a polygon's elements: convex quads on a bilinear grid, convex polygons of many
/// corners by area (AreaGridElements), non-convex ones of many corners by their convex
/// pieces (PiecesToMesh), others ear-clipped into triangles split on a barycentric
/// lattice. Returns the number of patches.
template <typename Emit>
int SplitPolygon(const std::vector<Vec3>& loop, const MesherOptions& o, double noise, const Emit& emit)
{
  if (loop.size() == 4 && IsConvex(loop.data(), 4, noise))
  {
    return SplitQuad(loop.data(), o, noise, emit);
  }
  if (AreaGridElements(loop, o.PatchSize, o.ElementSize, noise) >= 0)
  {
    return SplitByAreaGrid(loop, o.PatchSize, o.ElementSize, noise, emit);
  }
  const std::vector<std::vector<Vec3>> pieces = PiecesToMesh(loop, o.PatchSize, o.ElementSize, noise);
  if (!pieces.empty())
  {
    int patches = 0;
    // One Emit type for every piece (a lambda per level would instantiate without end).
    const std::function<void(const Vec3*, int, int)> shifted = [&](const Vec3* corners, int count, int patch) {
      emit(corners, count, patches + patch);
    };
    for (const std::vector<Vec3>& piece : pieces)
    {
      patches += SplitPolygon(piece, o, noise, shifted);
    }
    return patches;
  }
  const std::vector<int> corners = Triangulate(loop.data(), static_cast<int>(loop.size()), noise);
  int patches = 0;
  for (size_t t = 0; t + 2 < corners.size(); t += 3)
  {
    patches += SplitTriangle(loop[corners[t]], loop[corners[t + 1]], loop[corners[t + 2]], o, noise, patches, emit);
  }
  return patches;
}

/// A polygon's elements, each cut along the contact lines that cross it.
void MakePiece(const std::vector<Vec3>& loop, const MesherOptions& o, double noise, const ContactCutter& cutter,
  Piece& piece)
{
  std::vector<std::vector<Vec3>> parts;
  piece.PatchCount = SplitPolygon(loop, o, noise, [&](const Vec3* corners, int count, int patch) {
    if (cutter.Cut(corners, count, parts) == 0)
    {
      piece.Corners.insert(piece.Corners.end(), corners, corners + count);
      piece.Sides.push_back(count);
      piece.LocalPatch.push_back(patch);
      return;
    }
    for (const std::vector<Vec3>& part : parts)
    {
      piece.Corners.insert(piece.Corners.end(), part.begin(), part.end());
      piece.Sides.push_back(static_cast<int>(part.size()));
      piece.LocalPatch.push_back(patch);
    }
  });
}

/// The lamps that grade the elements (none without LampGrading): the whole scene's where
/// the polygons are one process's piece of it, so every piece grades by every lamp.
LampSpots GradingLampsFor(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const MesherOptions& options)
{
  if (!(options.LampGrading > 0))
  {
    return {};
  }
  const double reach = options.ElementSize / options.LampGrading; // the bins' size
  return options.WholeScene && options.WholeSurfaces
    ? FindLampSpots(options.WholeScene->Points, options.WholeScene->Offsets, options.WholeScene->Connectivity,
        options.WholeSurfaces->Lamps, reach, options.PointLamps)
    : FindLampSpots(points, offsets, connectivity, options.Lamps, reach, options.PointLamps);
}

/// The scene's polygons for the grading's shadow test (none without LampGrading): the
/// whole scene's where the polygons are one process's piece of it.
std::shared_ptr<const Visibility> ShadowRaysFor(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const MesherOptions& options)
{
  if (!(options.LampGrading > 0) || !(options.ShadowGrading > 0))
  {
    return nullptr;
  }
  SceneMesh scene;
  const bool whole = options.WholeScene != nullptr;
  scene.Points = whole ? options.WholeScene->Points : points;
  scene.Offsets = whole ? options.WholeScene->Offsets : offsets;
  scene.Connectivity = whole ? options.WholeScene->Connectivity : connectivity;
  auto rays = std::make_shared<const Visibility>(scene);
  return rays->Error().empty() ? rays : nullptr;
}

/// Surfaces closer than this stand on each other (relative, so units do not matter; and
/// never finer than float input can place them: 10 km from the origin, a millimetre).
double ContactTolerance(double span, double pointQuantum)
{
  return std::max(1e-6 * span, 2 * pointQuantum);
}

/// What SplitQuad / SplitTriangle will make, without making it.
double CountQuad(const Vec3* q, double patch, double element, double noise)
{
  const double lu = std::max(Norm(q[1] - q[0]), Norm(q[2] - q[3]));
  const double lv = std::max(Norm(q[3] - q[0]), Norm(q[2] - q[1]));
  const int pu = Divisions(lu, patch, noise), pv = Divisions(lv, patch, noise);
  return static_cast<double>(pu * Divisions(lu / pu, element, noise / pu)) * (pv * Divisions(lv / pv, element, noise / pv));
}

double CountTriangle(const Vec3& a, const Vec3& b, const Vec3& c, double patch, double element, double noise)
{
  const double longest = std::max({ Norm(b - a), Norm(c - b), Norm(a - c) });
  const int np = TrianglePatchDivisions(a, b, c, longest, patch, noise);
  const double n = static_cast<double>(np) * Divisions(longest / np, element, noise / np);
  return n * n;
}

double EstimateElements(const std::vector<Vec3>& loop, const MesherOptions& o)
{
  double longest = 0;
  for (size_t i = 0; i < loop.size(); ++i)
  {
    longest = std::max(longest, Norm(loop[(i + 1) % loop.size()] - loop[i]));
  }
  // Elements are never larger than patches, so the smaller size decides the count.
  const double per = std::ceil(longest / std::min(o.ElementSize, o.PatchSize)) + 1;
  return per * per * static_cast<double>(loop.size()); // double: absurd sizes must not overflow
}
} // namespace

namespace
{
/// Where surfaces stand on the polygons, and the distance that counts as standing.
struct Contacts
{
  std::vector<std::vector<ContactSegment>> Segments;
  double Touch = 0;
};

Contacts FindSceneContacts(const PolygonArrays& polygons, const PolygonArrays* wholeScene, double pointQuantum)
{
  const PolygonArrays& whole = wholeScene ? *wholeScene : polygons;
  Contacts contacts;
  contacts.Touch = ContactTolerance(Span(whole.Points), pointQuantum);
  contacts.Segments = FindContacts(polygons, whole, contacts.Touch);
  return contacts;
}

/// Polygons with contacts are counted by making their elements and cutting them, one at a
/// time. Above this many elements a polygon is counted without its cuts: it is over any
/// memory budget anyway, and making its elements would take minutes.
constexpr double kMostElementsCutToCount = 2e6;

/// The elements SplitPolygon makes of `loop`, without making them.
double CountPlain(const std::vector<Vec3>& loop, double patchSize, double elementSize, double noise)
{
  if (loop.size() == 4 && IsConvex(loop.data(), 4, noise))
  {
    return CountQuad(loop.data(), patchSize, elementSize, noise);
  }
  const double grid = AreaGridElements(loop, patchSize, elementSize, noise);
  if (grid >= 0)
  {
    return grid;
  }
  double pieces = 0;
  return !PiecesToMesh(loop, patchSize, elementSize, noise, &pieces).empty()
    ? pieces
    : CountLattice(loop, patchSize, elementSize, noise);
}

/// The elements of `loop`'s triangles' lattices.
double CountLattice(const std::vector<Vec3>& loop, double patchSize, double elementSize, double noise)
{
  double total = 0;
  const std::vector<int> corners = Triangulate(loop.data(), static_cast<int>(loop.size()), noise);
  for (size_t t = 0; t + 2 < corners.size(); t += 3)
  {
    total += CountTriangle(loop[corners[t]], loop[corners[t + 1]], loop[corners[t + 2]], patchSize, elementSize, noise);
  }
  return total;
}

/// `steps` float roundings of a scene `span` across, or the coarser step of float input
/// far from the origin.
double SpanNoise(double span, double pointQuantum, int steps = 1)
{
  return std::max(steps * FloatNoise(span), pointQuantum);
}

/// How far the points may be off their true places.
double MeshNoise(const std::vector<Vec3>& points, double pointQuantum)
{
  return SpanNoise(Span(points), pointQuantum);
}

/// How flat a triangle pair must be to join: within a few float steps of the scene's span,
/// or within one step of float input far from the origin. Rounding moves a flat quad's
/// corners off its plane by about one step; four let the tessellated models of a user's
/// export pair there too, but also joined a low-poly bull's folds of up to 5 mm at 10 km
/// (1,660 pairs against 95 at the origin), and the flattened quads, pushed behind their
/// neighbours, rendered as dark specks. One step: 1,043 pairs and no specks.
double PairFlatness(double span, double pointQuantum)
{
  return SpanNoise(span, pointQuantum, 4);
}

/// Whether polygon i (of a list whose input polygons are `source`) is a lamp: lamps are not
/// graded (a furnace's walls, all lamps, would all be made fine by each other).
bool IsLampPolygon(const std::vector<int>& source, const std::vector<char>& lamps, size_t i)
{
  return i < source.size() && source[i] >= 0 && static_cast<size_t>(source[i]) < lamps.size() && lamps[source[i]];
}

/// CountElements with the contacts found once (a budget's search counts many times): what
/// MeshPolygons makes. Polygons with contacts or near a lamp that grades them
/// (`grading`: LampGrading and GradingLamps; `source`, the input polygon of each, tells
/// the lamps, which are not graded) are made, one at a time, to count them.
double CountWithContacts(const PolygonArrays& polygons, double patchSize, double elementSize, const Contacts& contacts,
  double pointQuantum, const MesherOptions& grading, const std::vector<int>& source)
{
  if (!(patchSize > 0) || !(elementSize > 0))
  {
    return 0;
  }
  double total = 0;
  const double noise = MeshNoise(polygons.Points, pointQuantum); // as MeshPolygons decides
  MesherOptions sizes;
  sizes.PatchSize = patchSize;
  sizes.ElementSize = elementSize;
  sizes.LampGrading = grading.LampGrading;
  sizes.GradingLamps = grading.GradingLamps;
  sizes.ShadowRays = grading.ShadowRays;
  sizes.ShadowGrading = grading.ShadowGrading;
  MesherOptions plainSizes = sizes;
  plainSizes.GradingLamps.clear();
  plainSizes.ShadowRays.reset();
  std::vector<std::vector<Vec3>> parts;
  for (size_t i = 0; i + 1 < polygons.Offsets.size(); ++i)
  {
    const std::vector<Vec3> loop = GatherLoop(polygons.Points, polygons.Offsets, polygons.Connectivity, static_cast<int>(i));
    if (loop.size() < 3)
    {
      continue;
    }
    const double plain = CountPlain(loop, patchSize, elementSize, noise);
    const bool graded =
      !IsLampPolygon(source, grading.Lamps, i) && MayGrade(sizes.GradingLamps, loop, elementSize,
        sizes.ShadowRays ? sizes.LampGrading / kShadowReach : sizes.LampGrading); // shadows reach farther
    if ((contacts.Segments[i].empty() && !graded) || !(plain <= kMostElementsCutToCount))
    {
      total += graded ? 16 * plain : plain; // too large to make: at most a quarter of the size
      continue;
    }
    // Cuts depend on where the elements fall: make them, one at a time, to count them.
    const Vec3 normal = Normalized(NewellVector(loop.data(), static_cast<int>(loop.size())));
    const ContactCutter cutter(contacts.Segments[i], normal, contacts.Touch);
    SplitPolygon(loop, graded ? sizes : plainSizes, noise, [&](const Vec3* corners, int count, int) {
      total += std::max(1, cutter.Cut(corners, count, parts));
    });
  }
  return total;
}
} // namespace

namespace
{
/// How far the loop's farthest corner is off its plane, over its longest edge.
double Warp(const std::vector<Vec3>& loop)
{
  double size = 0;
  const double offset = WarpOffset(loop, &size);
  return size > 0 ? offset / size : 0.0;
}

/// Polygons of four or more corners farther off flat than this are said to be warped (and
/// meshed as their triangles, as all that are off flat by more than the float noise the
/// surfaces are flattened by).
constexpr double kMostWarp = 1e-3;

/// `polygons` with each warped one replaced by its triangles (same source): each corner
/// more than 4 `noise` off its plane (the surfaces flatten what is closer). Meshed as if
/// flat, a warped polygon was laid in its own plane and neighbours parted at their shared
/// edges (cracks through the Collada duck); left bent, its elements were not flat either,
/// and the probes that find closed-off elements started behind them: a duck's quads bent by
/// 2.7e-5 m (0.05 % of an edge) came out black.
PairedPolygons SplitWarped(const std::vector<Vec3>& points, const PairedPolygons& polygons, double noise)
{
  PairedPolygons out;
  out.Merged = polygons.Merged;
  out.Points = polygons.Points;
  for (size_t i = 0; i < polygons.Source.size(); ++i)
  {
    const int* ids = polygons.Connectivity.data() + polygons.Offsets[i];
    const int count = polygons.Offsets[i + 1] - polygons.Offsets[i];
    const std::vector<Vec3> loop = GatherLoop(points, polygons.Offsets, polygons.Connectivity, static_cast<int>(i));
    const std::vector<int> corners =
      count >= 4 && WarpOffset(loop) > 4 * noise ? Triangulate(loop.data(), count, noise) : std::vector<int>();
    for (size_t t = 0; t + 2 < corners.size(); t += 3)
    {
      out.Connectivity.insert(out.Connectivity.end(), { ids[corners[t]], ids[corners[t + 1]], ids[corners[t + 2]] });
      out.Offsets.push_back(static_cast<int>(out.Connectivity.size()));
      out.Source.push_back(polygons.Source[i]);
    }
    if (corners.empty())
    {
      out.Connectivity.insert(out.Connectivity.end(), ids, ids + count);
      out.Offsets.push_back(static_cast<int>(out.Connectivity.size()));
      out.Source.push_back(polygons.Source[i]);
    }
  }
  return out;
}

/// How close two corners are to be one, for copies and triangle pairs: a step of the scene's box.
double CornerTolerance(const std::vector<Vec3>& points)
{
  return 1e-7 * std::max(Bounds(points).Diagonal(), 1e-300);
}

/// The polygons with coincident copies left out and overlapping faces cut (CoincidentCopies.h,
/// OverlapCuts.h), found among these polygons or, for a piece, over the whole scene.
PairedPolygons WithoutCopiesAndOverlaps(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const std::vector<int>& surfaceKey, const MesherOptions& options,
  CoincidentCopies* copies, OverlapCuts* overlaps)
{
  if (options.WholeScene && options.WholeSurfaces)
  {
    const std::vector<Vec3>& all = options.WholeScene->Points;
    return CutAsWhole(*options.WholeScene, *options.WholeSurfaces, static_cast<int>(offsets.size()) - 1,
      CornerTolerance(all), 4 * MeshNoise(all, options.PointQuantum), copies, overlaps);
  }
  PairedPolygons polygons;
  polygons.Offsets = offsets;
  polygons.Connectivity = connectivity;
  for (size_t i = 0; i + 1 < offsets.size(); ++i)
  {
    polygons.Source.push_back(static_cast<int>(i));
  }
  const double tolerance = CornerTolerance(points);
  const CoincidentCopies found = DropCoincidentCopies(points, surfaceKey, options.Lamps, tolerance, polygons);
  if (copies)
  {
    *copies = found;
  }
  // From the scene's span (MeshNoise), not its box: which faces overlap must not turn with it.
  OverlapCuts cuts = CutOverlaps(points, surfaceKey, options.Lamps, 4 * MeshNoise(points, options.PointQuantum), polygons);
  if (overlaps)
  {
    *overlaps = std::move(cuts);
  }
  return polygons;
}

/// The polygons the mesher meshes: coincident copies left out (said in `copies`), faces
/// of one surface cut where they overlap in one plane (said in `overlaps`; their new
/// corners in the result's points), then triangle pairs joined where the options ask, and
/// warped polygons split into triangles.
PairedPolygons Paired(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const std::vector<int>& surfaceKey, const MesherOptions& options,
  CoincidentCopies* copies = nullptr, OverlapCuts* overlaps = nullptr)
{
  PairedPolygons polygons = WithoutCopiesAndOverlaps(points, offsets, connectivity, surfaceKey, options, copies, overlaps);
  const double tolerance = CornerTolerance(points);
  const double span = Span(points);
  const double noise = SpanNoise(span, options.PointQuantum);
  const std::vector<Vec3>& at = PointsOf(polygons, points);
  if (!options.MergeTriangles)
  {
    return SplitWarped(at, polygons, noise);
  }
  std::vector<int> keys(polygons.Source.size(), 0);
  for (size_t i = 0; i < keys.size(); ++i)
  {
    keys[i] = polygons.Source[i] < static_cast<int>(surfaceKey.size()) ? surfaceKey[polygons.Source[i]] : 0;
  }
  PairedPolygons merged = MergeTrianglePairs(at, polygons.Offsets, polygons.Connectivity, keys, tolerance, PairFlatness(span, options.PointQuantum));
  for (int& source : merged.Source)
  {
    source = polygons.Source[source]; // back to the input's numbering
  }
  merged.Points = std::move(polygons.Points);
  return SplitWarped(PointsOf(merged, points), merged, noise);
}

/// "1 cell is" or "3 cells are", for a warning.
std::string Counted(size_t count, const char* one, const char* many)
{
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

/// Up to five cell ids, for a warning.
std::string CellList(const std::vector<int>& cells)
{
  std::ostringstream text;
  for (size_t i = 0; i < cells.size() && i < 5; ++i)
  {
    text << (i ? ", " : "") << cells[i];
  }
  text << (cells.size() > 5 ? ", ..." : "");
  return text.str();
}

/// Up to five pairs of cell ids ("5 and 15; 7 and 16"), for a warning: a BIM model has
/// hundreds, and one pair named left the rest to be guessed.
std::string PairList(const std::vector<std::pair<int, int>>& pairs)
{
  std::ostringstream text;
  for (size_t i = 0; i < pairs.size() && i < 5; ++i)
  {
    text << (i ? "; " : "") << pairs[i].first << " and " << pairs[i].second;
  }
  text << (pairs.size() > 5 ? "; ..." : "");
  return text.str();
}

/// Says which input polygons were cut or left out where earlier ones of their surface cover
/// them, and which overlap others'.
void WarnAboutOverlaps(const OverlapCuts& overlaps, const MesherOptions& options)
{
  if (options.Warning && !overlaps.Trimmed.empty())
  {
    options.Warning(Counted(overlaps.Trimmed.size(), "cell overlaps", "cells overlap") + " other cells in one plane (cells " +
      CellList(overlaps.Trimmed) + "): meshed only where no cell that keeps the overlap lies (a lamp, else a cell lying wholly on "
      "another material, else the earlier), as each layer would receive the full light");
  }
  if (options.Warning && !overlaps.Covered.empty())
  {
    options.Warning(Counted(overlaps.Covered.size(), "cell lies", "cells lie") + " wholly under other cells in one plane (cells " +
      CellList(overlaps.Covered) + "): left out (a lamp, else a cell lying wholly on another material, else the earlier, "
      "keeps the overlap), as each layer would receive the full light");
  }
  if (options.Warning && !overlaps.Differing.empty())
  {
    options.Warning(Counted(overlaps.Differing.size(), "pair of cells overlaps", "pairs of cells overlap") +
      " in one plane, facing the same side, with different materials or lights (cells " + PairList(overlaps.Differing) +
      "): the second of each is cut where the first lies; to show it instead, move it a little in front");
  }
  if (options.Warning && !overlaps.OnTop.empty())
  {
    options.Warning(Counted(overlaps.OnTop.size(), "cell lies", "cells lie") +
      " wholly on a surface of another material in its plane (cells " + PairList(overlaps.OnTop) +
      ", each the one on top, then the one under it): kept whole, the cell under it cut around it (a poster on its "
      "wall), as both would receive the full light");
  }
  if (options.Warning && !overlaps.LampsKept.empty())
  {
    options.Warning(Counted(overlaps.LampsKept.size(), "pair of lamps overlaps", "pairs of lamps overlap") +
      " in one plane with different lights (cells " + PairList(overlaps.LampsKept) +
      "): both kept whole, each emitting the power it was given");
  }
}

/// Says which input polygons were left out as copies, or kept though they coincide.
void WarnAboutCopies(const CoincidentCopies& copies, const MesherOptions& options)
{
  const auto list = CellList;
  if (options.Warning && !copies.Dropped.empty())
  {
    options.Warning(Counted(copies.Dropped.size(), "cell repeats", "cells repeat") + " another cell's corners on the same side (cells " +
      list(copies.Dropped) + "): left out, as each copy would receive the full light");
  }
  if (options.Warning && !copies.Differing.empty())
  {
    options.Warning(Counted(copies.Differing.size(), "pair of cells coincides", "pairs of cells coincide") +
      " with different materials or lights (cells " + PairList(copies.Differing) +
      "): the second of each left out, as each copy would receive the full light (a lamp is kept over the surface it "
      "doubles, else the earlier cell); remove the one you do not mean");
  }
  if (options.Warning && !copies.LampsKept.empty())
  {
    options.Warning(Counted(copies.LampsKept.size(), "pair of lamps coincides", "pairs of lamps coincide") +
      " with different lights (cells " + PairList(copies.LampsKept) +
      "): both kept, each a light of its own; remove one if they are one lamp");
  }
}
} // namespace

struct ElementCounter::Internals
{
  PairedPolygons Pairs; ///< the polygons as the mesher pairs them (when the counter pairs)
  PolygonArrays Polygons;
  Contacts Found;
  double PointQuantum = 0; ///< MesherOptions::PointQuantum, where the counter has options
  MesherOptions Grading;   ///< LampGrading and GradingLamps, where the counter has options

  Internals(const std::vector<Vec3>& points, const std::vector<int>& offsets, const std::vector<int>& connectivity)
    : Polygons{ points, offsets, connectivity }
  {
  }
  Internals(const std::vector<Vec3>& points, PairedPolygons pairs)
    : Pairs(std::move(pairs))
    , Polygons{ PointsOf(Pairs, points), Pairs.Offsets, Pairs.Connectivity }
  {
  }
};

ElementCounter::ElementCounter(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const PolygonArrays* wholeScene)
  : Impl(new Internals(points, offsets, connectivity))
{
  Impl->Found = FindSceneContacts(Impl->Polygons, wholeScene, 0);
}

ElementCounter::ElementCounter(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const std::vector<int>& surfaceKey, const MesherOptions& options)
  : Impl(new Internals(points, Paired(points, offsets, connectivity, surfaceKey, options)))
{
  Impl->Found = FindSceneContacts(Impl->Polygons, options.WholeScene, options.PointQuantum);
  Impl->PointQuantum = options.PointQuantum;
  Impl->Grading.LampGrading = options.LampGrading;
  Impl->Grading.Lamps = options.Lamps;
  Impl->Grading.GradingLamps = GradingLampsFor(points, offsets, connectivity, options);
  Impl->Grading.ShadowGrading = options.ShadowGrading;
  Impl->Grading.ShadowRays = ShadowRaysFor(points, offsets, connectivity, options);
}

ElementCounter::~ElementCounter() = default;

double ElementCounter::operator()(double patchSize, double elementSize) const
{
  return CountWithContacts(
    Impl->Polygons, patchSize, elementSize, Impl->Found, Impl->PointQuantum, Impl->Grading, Impl->Pairs.Source);
}

double CountElements(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, double patchSize, double elementSize, const PolygonArrays* wholeScene)
{
  return ElementCounter(points, offsets, connectivity, wholeScene)(patchSize, elementSize);
}

double ElementSizeForBudget(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, double patchSize, double elementSize, double budget)
{
  const ElementCounter count(points, offsets, connectivity);
  return ElementSizeForBudget([&](double size) { return count(patchSize, size); }, patchSize, elementSize, budget);
}

double ElementSizeForBudget(
  const std::function<double(double)>& count, double patchSize, double elementSize, double budget)
{
  if (count(elementSize) <= budget)
  {
    return elementSize;
  }
  // The count falls (in steps) as the size grows; bisect on a log scale for the smallest
  // size that fits. At the patch size every patch is one element: the floor.
  double fits = std::max(patchSize, elementSize), tooSmall = elementSize;
  for (int i = 0; i < 60 && fits > tooSmall * (1 + 1e-6); ++i)
  {
    const double middle = std::sqrt(fits * tooSmall);
    (count(middle) <= budget ? fits : tooSmall) = middle;
  }
  return fits;
}

namespace
{
/// The corners of polygon i without repeats (consecutive points closer than `quantum`
/// would make zero-area elements), or an error naming its cell.
std::string DistinctCorners(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, int i, int cell, double quantum, std::vector<Vec3>& loop)
{
  loop.clear();
  for (int k = offsets[i]; k < offsets[i + 1]; ++k)
  {
    const Vec3& p = points[connectivity[k]];
    if (loop.empty() || Norm(p - loop.back()) > quantum)
    {
      loop.push_back(p);
    }
  }
  while (loop.size() > 1 && Norm(loop.front() - loop.back()) <= quantum)
  {
    loop.pop_back();
  }
  if (offsets[i + 1] - offsets[i] >= 3 && loop.size() >= 3)
  {
    return std::string(); // the usual case: no error text to build
  }
  std::ostringstream err;
  if (offsets[i + 1] - offsets[i] < 3)
  {
    err << "cell " << cell << " has " << offsets[i + 1] - offsets[i] << " points; polygons need at least 3";
  }
  else if (loop.size() < 3)
  {
    err << "cell " << cell << " has zero area (only " << loop.size() << " distinct points); remove degenerate cells";
  }
  return err.str();
}

/// Refuses sizes that are not positive, or that would make more elements than allowed.
std::string CheckSizes(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const MesherOptions& options)
{
  std::ostringstream err;
  if (!(options.PatchSize > 0) || !(options.ElementSize > 0) || !std::isfinite(options.PatchSize))
  {
    err << "PatchSize (" << options.PatchSize << ") and ElementSize (" << options.ElementSize << ") must be positive";
    return err.str();
  }
  double estimate = 0;
  // At ElementSize: this bound is already loose (a polygon's longest edge squared), and at
  // a quarter of the size near the lamps it refused the FZK-Haus (2.6e7 against 20 M).
  for (int i = 0; i + 1 < static_cast<int>(offsets.size()); ++i)
  {
    estimate += EstimateElements(GatherLoop(points, offsets, connectivity, i), options);
  }
  if (!(estimate <= static_cast<double>(options.MaximumElements)))
  {
    err << "PatchSize " << options.PatchSize << " and ElementSize " << options.ElementSize << " would make about "
        << std::setprecision(3) << estimate << " elements, more than the limit of " << options.MaximumElements
        << "; choose a larger ElementSize (or PatchSize)";
  }
  return err.str();
}

/// MeshPolygons on polygons that came from input cells `source[i]` (for messages, keys and
/// the output's SourcePolygon), with the surfaces standing on them.
std::string MeshList(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const std::vector<int>& source, const std::vector<int>& surfaceKey,
  const Contacts& contacts, const MesherOptions& options, MeshedPolygons& out,
  const std::map<int, std::vector<Vec3>>& outlines = {})
{
  out = MeshedPolygons();
  const std::string problem = CheckSizes(points, offsets, connectivity, options);
  if (!problem.empty())
  {
    return problem;
  }
  const int count = static_cast<int>(offsets.size()) - 1;
  const double diagonal = Span(points); // not the bounding box's: that turns with the scene
  const double quantum = std::max(diagonal, 1e-300) * 1e-9;
  const double noise = MeshNoise(points, options.PointQuantum);
  std::vector<PolygonPlane> planes;
  std::vector<Vec3> loop;
  for (int i = 0; i < count; ++i)
  {
    const std::string bad = DistinctCorners(points, offsets, connectivity, i, source[i], quantum, loop);
    if (!bad.empty())
    {
      return bad;
    }
    planes.push_back(PlaneOf(loop, noise, surfaceKey[source[i]]));
  }
  SurfaceAssembly surfaces(quantum, noise, Bounds(points).Centre(), options, planes);
  MesherOptions ungraded = options; // for the lamps themselves
  ungraded.GradingLamps.clear();
  for (int i = 0; i < count; ++i)
  {
    if (options.Progress && !options.Progress(static_cast<double>(i) / std::max(count, 1)))
    {
      return "meshing was aborted";
    }
    DistinctCorners(points, offsets, connectivity, i, source[i], quantum, loop);
    Piece piece;
    MakePiece(loop, IsLampPolygon(source, options.Lamps, i) ? ungraded : options, noise,
      ContactCutter(contacts.Segments[i], planes[i].Normal, contacts.Touch), piece);
    const auto outline = outlines.find(source[i]);
    surfaces.Add(loop, piece, i, source[i], outline == outlines.end() ? std::vector<Vec3>() : outline->second);
  }
  surfaces.Flatten(out);
  return std::string();
}

} // namespace

namespace
{
/// A polygon whose corners leave its plane by more than 0.1 % of its size is meshed as if
/// flat: say so, with the worst one, so a twisted quad is not a silent surprise.
void WarnAboutWarpedPolygons(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const MesherOptions& options)
{
  int warped = 0, worst = -1;
  double worstRatio = 0;
  for (size_t i = 0; i + 1 < offsets.size(); ++i)
  {
    const std::vector<Vec3> loop = GatherLoop(points, offsets, connectivity, static_cast<int>(i));
    const double warp = loop.size() < 4 ? 0.0 : Warp(loop);
    if (warp > kMostWarp)
    {
      ++warped;
      if (warp > worstRatio)
      {
        worst = static_cast<int>(i);
        worstRatio = warp;
      }
    }
  }
  if (warped > 0 && options.Warning)
  {
    std::ostringstream text;
    text << warped << " polygon(s) are not flat and are meshed as their triangles; the worst, cell " << worst
         << ", has a corner " << 100 * worstRatio << " % of its longest edge off its plane.";
    options.Warning(text.str());
  }
}

/// ElementSize, or the size ElementBudget calls for; says which, and warns on a huge mesh.
/// Over the budget the lamps' grading goes first (`o.GradingLamps` emptied), then the size.
double ChooseElementSize(
  const PolygonArrays& polygons, const std::vector<int>& source, const Contacts& contacts, MesherOptions& o)
{
  auto count = [&](double size) {
    return CountWithContacts(polygons, o.PatchSize, size, contacts, o.PointQuantum, o, source);
  };
  std::ostringstream message;
  if (o.ElementBudget > 0 && !o.GradingLamps.empty() && count(std::min(o.ElementSize, o.PatchSize)) > o.ElementBudget)
  {
    o.GradingLamps.clear();
    message << "LampGrading left out: the finer elements by the lamps would exceed MaximumElements ("
            << o.ElementBudget << "). ";
  }
  const double wanted = count(o.ElementSize);
  double size = o.ElementSize;
  if (o.ElementSize > o.PatchSize && o.Warning)
  {
    // An element never spans patches, so a patch is as large as an element gets.
    std::ostringstream larger;
    larger << "ElementSize " << o.ElementSize << " is larger than PatchSize " << o.PatchSize
           << ": elements are patch-sized (" << o.PatchSize << ")";
    o.Warning(larger.str());
  }
  size = std::min(o.ElementSize, o.PatchSize);
  if (o.ElementBudget > 0 && wanted > o.ElementBudget)
  {
    size = ElementSizeForBudget(count, o.PatchSize, size, o.ElementBudget);
    message << "ElementSize " << o.ElementSize << " would make " << wanted << " elements, more than MaximumElements ("
            << o.ElementBudget << "); using " << size << " (" << count(size) << " elements).";
  }
  else if (wanted > 2e6)
  {
    message << "ElementSize " << size << " makes " << wanted << " elements: solving takes minutes and about "
            << wanted * 1.6e-6 << " GB if solved with 8 lights. Set MaximumElements (or a larger ElementSize) to "
               "bound it.";
  }
  if (o.Warning && !message.str().empty())
  {
    o.Warning(message.str());
  }
  return size;
}
} // namespace

std::string MeshPolygons(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, const std::vector<int>& surfaceKey,
  const MesherOptions& options, MeshedPolygons& out)
{
  // Checked first: a NaN point would otherwise make the element count NaN, and a figure 8
  // would be blamed on one of its elements by the solver.
  for (size_t i = 0; i + 1 < offsets.size(); ++i)
  {
    const std::vector<Vec3> loop = GatherLoop(points, offsets, connectivity, static_cast<int>(i));
    const std::string problem = loop.size() < 3 ? std::string() : PolygonProblem(loop.data(), static_cast<int>(loop.size()));
    if (!problem.empty())
    {
      return "cell " + std::to_string(i) + " " + problem;
    }
  }
  WarnAboutWarpedPolygons(points, offsets, connectivity, options);
  CoincidentCopies copies;
  OverlapCuts overlaps;
  const PairedPolygons polygons = Paired(points, offsets, connectivity, surfaceKey, options, &copies, &overlaps);
  // Coincident lamps are said once, as copies, not again as an overlap.
  std::vector<std::pair<int, int>>& overlapping = overlaps.LampsKept;
  overlapping.erase(std::remove_if(overlapping.begin(), overlapping.end(), [&](const std::pair<int, int>& p) {
    return std::find_if(copies.LampsKept.begin(), copies.LampsKept.end(), [&](const std::pair<int, int>& c) {
      return std::minmax(c.first, c.second) == std::minmax(p.first, p.second);
    }) != copies.LampsKept.end();
  }), overlapping.end());
  WarnAboutCopies(copies, options);
  WarnAboutOverlaps(overlaps, options);
  const std::vector<Vec3>& corners = PointsOf(polygons, points);
  const PolygonArrays paired{ corners, polygons.Offsets, polygons.Connectivity };
  const Contacts contacts = FindSceneContacts(paired, options.WholeScene, options.PointQuantum);
  MesherOptions sized = options;
  sized.GradingLamps = GradingLampsFor(points, offsets, connectivity, options);
  sized.ShadowRays = ShadowRaysFor(points, offsets, connectivity, options);
  sized.ElementSize = ChooseElementSize(paired, polygons.Source, contacts, sized);
  std::map<int, std::vector<Vec3>> outlines; // of the cells the overlaps cut
  const int first = options.WholeScene && options.WholeSurfaces ? options.WholeSurfaces->FirstPolygon : 0;
  for (int cell : overlaps.Trimmed)
  {
    const int own = cell - first; // the reports number the whole scene's cells
    DistinctCorners(points, offsets, connectivity, own, cell, 1e-9 * std::max(Span(points), 1e-300), outlines[own]);
  }
  const std::string error = MeshList(
    corners, polygons.Offsets, polygons.Connectivity, polygons.Source, surfaceKey, contacts, sized, out, outlines);
  out.MergedTrianglePairs = polygons.Merged;
  out.ElementSize = sized.ElementSize;
  if (error.empty())
  {
    out.ClusteredPatches =
      ClusterFaces(out, paired, surfaceKey, sized.PatchSize, options.ClusterAngle, 4 * MeshNoise(points, options.PointQuantum));
  }
  return error;
}

double SuggestPatchSize(const std::vector<Vec3>& points, const std::vector<int>& connectivity)
{
  std::vector<Vec3> corners;
  corners.reserve(connectivity.size());
  for (int id : connectivity)
  {
    corners.push_back(points[id]);
  }
  return PatchSizeForSpan(Span(corners)); // unlike a bounding box's diagonal, turning does not change it
}

double PatchSizeForSpan(double span)
{
  if (!(span > 0) || !std::isfinite(span))
  {
    return 0.0;
  }
  const double target = span / 6.0;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  double nice = decade;
  for (double step : { 2.0, 2.5, 5.0 })
  {
    nice = step * decade <= target ? step * decade : nice;
  }
  return nice;
}

SuggestedSizes SuggestMeshSizes(const std::vector<Vec3>& points, const std::vector<int>& offsets,
  const std::vector<int>& connectivity, double span)
{
  SuggestedSizes sizes;
  for (size_t i = 0; i + 1 < offsets.size(); ++i)
  {
    const std::vector<Vec3> loop = GatherLoop(points, offsets, connectivity, static_cast<int>(i));
    const double area = loop.size() >= 3 ? PolygonArea(loop.data(), static_cast<int>(loop.size())) : 0.0;
    sizes.Area += std::isfinite(area) ? area : 0.0;
  }
  const double patch = span > 0 ? PatchSizeForSpan(span) : SuggestPatchSize(points, connectivity);
  if (patch > 0)
  {
    sizes.PatchSize = patch;
    sizes.ElementSize = patch / 4.0;
    sizes.Elements = CountElements(points, offsets, connectivity, sizes.PatchSize, sizes.ElementSize);
  }
  return sizes;
}

} // namespace radiosity
