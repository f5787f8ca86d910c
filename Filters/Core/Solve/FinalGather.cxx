#include "Solve/FinalGather.h"
#include "Solve/GatherPass.h"
#include "Solve/IrradianceCache.h"

#include "Base/WorkerPool.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

namespace radiosity
{
using namespace gathering;

namespace
{
/// Each point that shares its representative's place and surface takes its values.
void CopyToCopies(const std::vector<int>& rep, int solutions, GatheredPoints& out)
{
  for (size_t p = 0; p < rep.size(); ++p)
  {
    const int r = rep[p];
    for (int m = 0; m < solutions && r >= 0 && static_cast<size_t>(r) != p; ++m)
    {
      out.Radiosity[p * solutions + m] = out.Radiosity[static_cast<size_t>(r) * solutions + m];
      out.Direct[p * solutions + m] = out.Direct[static_cast<size_t>(r) * solutions + m];
      out.Irradiance[p * solutions + m] = out.Irradiance[static_cast<size_t>(r) * solutions + m];
    }
    if (r >= 0)
    {
      out.Hidden[p] = out.Hidden[r];
    }
  }
}

/// Elements a sweep does not evaluate (enclosed, or of no area) keep what they had, the
/// solver's value (a lamp shut in a box keeps its emission).
void KeepUnswept(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& before, int solutions,
  GatheredPoints& swept)
{
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    for (int m = 0; m < solutions && (g.Enclosed[e] || g.Area[e] <= 0); ++m)
    {
      const size_t at = static_cast<size_t>(e) * solutions + m;
      swept.Radiosity[at] = before[at];
      swept.Direct[at] = before[at];
    }
  }
}

/// Sums `values` over the ranks in place (each rank filled only its own points).
void SumOverRanks(Collective& ranks, std::vector<Vec3>& values)
{
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three doubles");
  ranks.Sum(reinterpret_cast<double*>(values.data()), 3 * values.size());
}

/// Calls evaluate(i, scratch) for i in [0, count) on the pool (on several ranks each every
/// `Ranks()`-th item: the caller sums what they wrote, and as each item is computed by one
/// rank alone the sum is the serial answer bit for bit), in blocks between which `progress`
/// may stop it (all ranks agree). Returns the rays evaluate reported, summed over items on
/// this rank, or -1 where it was stopped.
template <typename Evaluate>
long long ForEachItem(size_t count, const WorkerPool& pool, Collective& ranks,
  const std::function<bool(double)>& progress, double from, double to, const Evaluate& evaluate)
{
  const size_t rank = static_cast<size_t>(ranks.Rank()), share = static_cast<size_t>(ranks.Ranks());
  const int blocks = static_cast<int>(std::min<size_t>(64, std::max<size_t>(1, count / 256)));
  std::vector<long long> itemRays(count, 0);
  for (int block = 0; block < blocks; ++block)
  {
    const size_t first = count * block / blocks, last = count * (block + 1) / blocks;
    pool.For(static_cast<int>(last - first), 16, [&](int begin, int end) {
      std::vector<Vec3> scratch;
      for (int i = begin; i < end; ++i)
      {
        const size_t item = first + i;
        if (item % share == rank)
        {
          itemRays[item] = evaluate(item, scratch);
        }
      }
    });
    double stop = progress && !progress(from + (to - from) * (block + 1) / blocks) && block + 1 < blocks ? 1 : 0;
    ranks.Sum(&stop, 1);
    if (stop > 0)
    {
      return -1;
    }
  }
  return std::accumulate(itemRays.begin(), itemRays.end(), 0LL);
}

/// A sweep: every element of `gather` evaluated whole, direct light and interreflection (each
/// rank its share, then summed), in blocks between which `progress` may stop it. The direct
/// light arriving ([point * solutions + m]) is computed into an empty `arriving` and read from
/// a full one: a later sweep casts only its cosine rays.
GatheredPoints Run(const Gather& gather, int solutions, const WorkerPool& pool, const ProcessGroup& group,
  const std::function<bool(double)>& progress, double from, double to, std::vector<Vec3>& arriving)
{
  Collective ranks(group);
  GatheredPoints out;
  const size_t points = gather.Points();
  const bool known = arriving.size() == points * solutions;
  if (!known)
  {
    arriving.assign(points * solutions, Vec3());
  }
  out.Radiosity.assign(points * solutions, Vec3());
  out.Direct.assign(points * solutions, Vec3());
  out.Irradiance.assign(points * solutions, Vec3());
  out.Hidden.assign(points, 0);
  const long long rays = ForEachItem(points, pool, ranks, progress, from, to, [&](size_t p, std::vector<Vec3>& scratch) {
    return gather.Evaluate(p, &out.Radiosity[p * solutions], &out.Direct[p * solutions], &out.Irradiance[p * solutions],
      &arriving[p * solutions], known, scratch, out.Hidden[p]);
  });
  out.Aborted = rays < 0;
  double total = static_cast<double>(std::max(0LL, rays));
  if (!out.Aborted && ranks.Distributed())
  {
    SumOverRanks(ranks, out.Radiosity);
    SumOverRanks(ranks, out.Direct);
    SumOverRanks(ranks, out.Irradiance);
    if (!known)
    {
      SumOverRanks(ranks, arriving);
    }
    std::vector<double> hidden(out.Hidden.begin(), out.Hidden.end());
    ranks.Sum(hidden);
    ranks.Sum(&total, 1);
    for (size_t p = 0; p < points; ++p)
    {
      out.Hidden[p] = hidden[p] > 0 ? 1 : 0;
    }
  }
  out.Rays = static_cast<long long>(total);
  return out;
}

/// The gathered interreflection of `list`'s points as irradiance-cache records (Point: the
/// index into `list`'s own list of points, `items`), each rank its share; their values go
/// to `gathered` by point, their gradients (IrradianceGradients: 3 translation then 3
/// rotation per solution) after `gradients`' end, in the records' order.
std::vector<CacheRecord> GatherRecords(const Gather& gather, const std::vector<int>& items,
  const std::vector<int>& list, double accuracy, double largest, const WorkerPool& pool, Collective& ranks,
  const std::function<bool(double)>& progress, double from, double to, std::vector<Vec3>& gathered,
  std::vector<Vec3>& gradients, long long& rays)
{
  const int S = static_cast<int>(gathered.size() / items.size());
  const size_t per = 6 * static_cast<size_t>(S);
  std::vector<Vec3> values(list.size() * S), slopes(list.size() * per);
  std::vector<double> reach(list.size(), 0.0);
  const long long cast = ForEachItem(list.size(), pool, ranks, progress, from, to, [&](size_t i, std::vector<Vec3>&) {
    thread_local StratifiedRays samples;
    HitDistances hits;
    hits.Samples = &samples;
    const long long n = gather.IndirectAt(items[list[i]], &values[i * S], hits);
    IrradianceGradients(samples, &slopes[i * per], &slopes[i * per + 3 * S]);
    // A record that saw mostly back faces holds for nobody else (FillHidden mends it): -1.
    reach[i] = gather.SeesBacks(hits) ? -1.0 : RecordReach(accuracy, hits.InverseSum, gather.GatherRays(), hits.Nearest, largest);
    return n;
  });
  if (cast < 0)
  {
    return {};
  }
  double total = static_cast<double>(cast);
  if (ranks.Distributed())
  {
    SumOverRanks(ranks, values);
    SumOverRanks(ranks, slopes);
    ranks.Sum(reach);
    ranks.Sum(&total, 1);
  }
  rays += static_cast<long long>(total);
  std::vector<CacheRecord> records(list.size());
  for (size_t i = 0; i < list.size(); ++i)
  {
    const PointFrame& f = gather.Frame(items[list[i]]);
    records[i] = { list[i], f.Origin, f.Normal, std::max(0.0, reach[i]), reach[i] < 0 };
    std::copy(values.begin() + i * S, values.begin() + (i + 1) * S, gathered.begin() + static_cast<size_t>(list[i]) * S);
  }
  gradients.insert(gradients.end(), slopes.begin(), slopes.end());
  return records;
}

/// Each point that did not gather for itself (own[i] 0) takes the weighted mean of the
/// records that reach it, each moved to the point by its gradients (`gradients`, 6 per
/// solution, at slot[record's point]).
void Interpolate(const IrradianceCache& cache, const std::vector<char>& own, const std::vector<Vec3>& origins,
  const std::vector<Vec3>& normals, const std::vector<int>& slot, const std::vector<Vec3>& gradients, int solutions,
  const WorkerPool& pool, std::vector<Vec3>& gathered)
{
  const size_t per = 6 * static_cast<size_t>(solutions);
  pool.For(static_cast<int>(own.size()), 256, [&](int begin, int end) {
    std::vector<std::pair<int, double>> weights;
    for (int i = begin; i < end; ++i)
    {
      const double sum = own[i] ? 0.0 : cache.Weights(origins[i], normals[i], weights);
      if (!(sum > 0))
      {
        continue;
      }
      Vec3* out = &gathered[static_cast<size_t>(i) * solutions];
      std::fill(out, out + solutions, Vec3());
      for (const auto& w : weights)
      {
        const CacheRecord& r = cache.Records()[w.first];
        const Vec3 moved = origins[i] - r.Origin, turned = Cross(r.Normal, normals[i]);
        const Vec3* slopes = &gradients[slot[r.Point] * per];
        const Vec3* at = &gathered[static_cast<size_t>(r.Point) * solutions];
        for (int m = 0; m < solutions; ++m)
        {
          const Vec3* slope = slopes + 3 * m;
          const Vec3* turn = slope + 3 * solutions;
          const Vec3 change{ Dot(slope[0], moved) + Dot(turn[0], turned), Dot(slope[1], moved) + Dot(turn[1], turned),
            Dot(slope[2], moved) + Dot(turn[2], turned) };
          out[m] += (at[m] + change) * w.second;
        }
      }
      for (int m = 0; m < solutions; ++m)
      {
        out[m] = out[m] * (1.0 / sum);
      }
    }
  });
}

/// The direct light arriving at each of `items`' points, into arriving[p * S ...] (each
/// rank its share, then summed); returns the rays cast, -1 where it was stopped.
long long PointsDirect(const Gather& gather, const std::vector<int>& items, int solutions, const WorkerPool& pool,
  Collective& ranks, const std::function<bool(double)>& progress, double from, double to, std::vector<Vec3>& arriving)
{
  const long long cast = ForEachItem(items.size(), pool, ranks, progress, from, to,
    [&](size_t i, std::vector<Vec3>& scratch) { return gather.DirectAt(items[i], &arriving[items[i] * solutions], scratch); });
  if (cast < 0)
  {
    return cast;
  }
  double total = static_cast<double>(cast);
  if (ranks.Distributed())
  {
    SumOverRanks(ranks, arriving);
    ranks.Sum(&total, 1);
  }
  return static_cast<long long>(total);
}

/// The points' values from their direct light `arriving` and their gathered interreflection
/// (`gathered`, [i * S + m] for items[i]).
void ComposePoints(const Gather& gather, const std::vector<int>& items, int solutions,
  const std::vector<Vec3>& arriving, const std::vector<Vec3>& gathered, GatheredPoints& out)
{
  const size_t points = gather.Points();
  out.Radiosity.assign(points * solutions, Vec3());
  out.Direct.assign(points * solutions, Vec3());
  out.Irradiance.assign(points * solutions, Vec3());
  for (size_t i = 0; i < items.size(); ++i)
  {
    const size_t p = items[i];
    gather.Compose(p, &arriving[p * solutions], &gathered[i * solutions], &out.Radiosity[p * solutions],
      &out.Direct[p * solutions], &out.Irradiance[p * solutions]);
  }
}

/// Every point gathers its own interreflection.
GatheredPoints EveryPointGathers(const Gather& gather, const std::vector<int>& items, int solutions,
  const std::vector<Vec3>& arriving, const WorkerPool& pool, Collective& ranks,
  const std::function<bool(double)>& progress, double from, double to)
{
  GatheredPoints out;
  std::vector<Vec3> gathered(items.size() * solutions);
  std::vector<double> hidden(items.size(), 0.0);
  const long long cast = ForEachItem(items.size(), pool, ranks, progress, from, to, [&](size_t i, std::vector<Vec3>&) {
    HitDistances hits;
    const long long n = gather.IndirectAt(items[i], &gathered[i * solutions], hits);
    hidden[i] = gather.SeesBacks(hits) ? 1 : 0;
    return n;
  });
  out.Aborted = cast < 0;
  if (out.Aborted)
  {
    return out;
  }
  double total = static_cast<double>(cast);
  if (ranks.Distributed())
  {
    SumOverRanks(ranks, gathered);
    ranks.Sum(hidden);
    ranks.Sum(&total, 1);
  }
  out.Rays = static_cast<long long>(total);
  out.Hidden.assign(gather.Points(), 0);
  for (size_t i = 0; i < items.size(); ++i)
  {
    out.Hidden[items[i]] = hidden[i] > 0 ? 1 : 0;
  }
  ComposePoints(gather, items, solutions, arriving, gathered, out);
  return out;
}

/// The points' interreflection shared through an irradiance cache (IrradianceCache.h):
/// gathered at the points PlaceRecords picks and interpolated between them elsewhere.
/// Records that saw mostly back faces are the hidden points.
GatheredPoints PointsShareGathers(const Gather& gather, const std::vector<int>& items, int solutions,
  const std::vector<Vec3>& arriving, double accuracy, const WorkerPool& pool, Collective& ranks,
  const std::function<bool(double)>& progress, double from, double to)
{
  GatheredPoints out;
  std::vector<Vec3> gathered(items.size() * solutions), origins(items.size()), normals(items.size());
  for (size_t i = 0; i < items.size(); ++i)
  {
    origins[i] = gather.Frame(items[i]).Origin;
    normals[i] = gather.Frame(items[i]).Normal;
  }
  Vec3 low = origins.empty() ? Vec3() : origins[0], high = low;
  for (const Vec3& o : origins)
  {
    low = { std::min(low.x, o.x), std::min(low.y, o.y), std::min(low.z, o.z) };
    high = { std::max(high.x, o.x), std::max(high.y, o.y), std::max(high.z, o.z) };
  }
  const double largest = LargestReach(Norm(high - low));
  int level = 0;
  long long rays = 0;
  std::vector<Vec3> gradients;
  const std::vector<CacheRecord> records = PlaceRecords(origins, normals,
    [&](const std::vector<int>& list) {
      const double a = from + (to - from) * std::min(1.0, level / 5.0), b = from + (to - from) * std::min(1.0, ++level / 5.0);
      std::vector<CacheRecord> found =
        GatherRecords(gather, items, list, accuracy, largest, pool, ranks, progress, a, b, gathered, gradients, rays);
      out.Aborted = found.empty();
      return found;
    },
    [&](int count, const std::function<void(int, int)>& body) { pool.For(count, 256, body); });
  out.Rays = rays;
  out.Records = static_cast<int>(records.size());
  std::vector<char> own(items.size(), 0);
  std::vector<int> slot(items.size(), -1);
  out.Hidden.assign(gather.Points(), 0);
  for (size_t k = 0; k < records.size(); ++k)
  {
    const CacheRecord& r = records[k];
    own[r.Point] = 1;
    slot[r.Point] = static_cast<int>(k);
    out.Hidden[items[r.Point]] = r.Hidden ? 1 : 0;
  }
  if (out.Aborted)
  {
    return out;
  }
  Interpolate(IrradianceCache(records), own, origins, normals, slot, gradients, solutions, pool, gathered);
  ComposePoints(gather, items, solutions, arriving, gathered, out);
  return out;
}

/// The used frames of `frames`, in order.
std::vector<int> UsedFrames(const std::vector<PointFrame>& frames)
{
  std::vector<int> items;
  for (size_t p = 0; p < frames.size(); ++p)
  {
    if (frames[p].Used)
    {
      items.push_back(static_cast<int>(p));
    }
  }
  return items;
}

} // namespace

namespace
{
/// Points that see mostly back faces lie behind something resting on their surface (the
/// ceiling over a lamp hung just below it, the floor under a cabinet): dark for a reason
/// that stops at the object's edge, and no one sees them. Each takes the mean of the
/// visible points it shares an element with, as a baker dilates its texels into such
/// places, so interpolation does not carry the dark out past the edge (a ring around every
/// lamp of the demo room otherwise). A few passes reach hidden points beside hidden ones.
void FillHidden(const SceneMesh& mesh, int solutions, std::vector<char>& hidden,
  const std::vector<std::vector<Vec3>*>& values)
{
  for (int pass = 0; pass < 4; ++pass)
  {
    // Sums for the hidden points only: a million points hold a few hundred.
    std::vector<int> slot(hidden.size(), -1), list;
    for (size_t p = 0; p < hidden.size(); ++p)
    {
      if (hidden[p])
      {
        slot[p] = static_cast<int>(list.size());
        list.push_back(static_cast<int>(p));
      }
    }
    std::vector<std::vector<Vec3>> sums(values.size(), std::vector<Vec3>(list.size() * solutions));
    std::vector<int> count(list.size(), 0);
    for (int e = 0; e < mesh.NumberOfPolygons() && !list.empty(); ++e)
    {
      const int* ids = mesh.Polygon(e);
      for (int a = 0; a < mesh.PolygonSize(e); ++a)
      {
        const int at = slot[ids[a]];
        for (int b = 0; b < mesh.PolygonSize(e) && at >= 0; ++b)
        {
          if (hidden[ids[b]])
          {
            continue;
          }
          ++count[at];
          for (size_t v = 0; v < values.size(); ++v)
          {
            for (int m = 0; m < solutions; ++m)
            {
              sums[v][static_cast<size_t>(at) * solutions + m] += (*values[v])[static_cast<size_t>(ids[b]) * solutions + m];
            }
          }
        }
      }
    }
    bool filled = false;
    for (size_t i = 0; i < list.size(); ++i)
    {
      const size_t p = list[i];
      for (size_t v = 0; v < values.size() && count[i] > 0; ++v)
      {
        for (int m = 0; m < solutions; ++m)
        {
          (*values[v])[p * solutions + m] = sums[v][i * solutions + m] * (1.0 / count[i]);
        }
      }
      filled = filled || count[i] > 0;
      hidden[p] = count[i] == 0;
    }
    if (!filled)
    {
      break;
    }
  }
}
} // namespace

namespace
{
/// The cosine rays a point can take in what is left of `settings.TimeBudget` after
/// `elapsed` seconds that cast `cast` rays (the points' shadow rays and the sweeps), at that
/// pace, for `gathers` points: settings.Rays where it fits or there is no budget, 0 where
/// fewer than four would. Counted as if every point gathered (the cache makes it fewer).
int AffordableRays(const GatherSettings& settings, double elapsed, long long cast, int gathers)
{
  if (!(settings.TimeBudget > 0) || cast <= 0 || gathers <= 0 || !(elapsed > 0))
  {
    return settings.Rays;
  }
  const double perRay = elapsed / static_cast<double>(cast);
  const double affordable = (settings.TimeBudget - elapsed) / perRay / gathers;
  if (affordable >= settings.Rays)
  {
    return settings.Rays;
  }
  return affordable >= 4 ? static_cast<int>(affordable) : 0;
}
} // namespace

GatheredPoints GatherAtPoints(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, const std::vector<Vec3>& radiosity, int solutions,
  const GatherSettings& settings, int threads, const std::function<bool(double)>& progress, bool shadows)
{
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::pair<std::string, double>> steps;
  auto lapStart = start;
  const auto lap = [&](const char* step) {
    const auto now = std::chrono::steady_clock::now();
    steps.emplace_back(step, std::chrono::duration<double>(now - lapStart).count());
    lapStart = now;
  };
  const std::vector<Emitter> emitters = MakeEmitters(mesh, geometry, emission, solutions);
  const WorkerPool pool(threads);
  Collective ranks(settings.Group);
  const int sweeps = std::max(0, settings.Sweeps);
  // Progress: the points' direct light a fifth, then each sweep and the points alike.
  auto at = [&](double part) { return 0.2 + 0.8 * part / (sweeps + 1); };
  std::vector<Vec3> pointEmission, source = radiosity, cellDirect, cellIrradiance;
  const std::vector<int> rep = Representatives(mesh, geometry);
  const std::vector<PointFrame> frames = MakeFrames(mesh, geometry, emission, solutions, rep, pointEmission);
  const std::vector<int> items = UsedFrames(frames);
  // The points' direct light first (it does not depend on the sweeps).
  std::vector<Vec3> arriving(frames.size() * solutions);
  lap("gather: the points' frames");
  const Gather lit(mesh, geometry, rays, emission, source, solutions, emitters, frames, pointEmission, 1,
    settings.LightRays, shadows, 0, settings);
  long long cast = PointsDirect(lit, items, solutions, pool, ranks, progress, 0.0, 0.2, arriving);
  lap("gather: direct light at the points");
  GatheredPoints out;
  if (cast < 0)
  {
    out.Aborted = true;
    return out;
  }
  // (A sweep's small elements once took their corners' mean of it, and saved the sweep's
  // shadow rays; but a shadow ray grazing an edge then decided a cell's value too, and the
  // cells lost their scale invariance, TestHardCases; docs/benchmarks.md has the cost.)
  const std::vector<PointFrame> elementFrames = ElementFrames(mesh, geometry);
  std::vector<Vec3> elementsArriving;
  for (int sweep = 0; sweep < sweeps; ++sweep)
  {
    const Gather pass(mesh, geometry, rays, emission, source, solutions, emitters, elementFrames, emission,
      settings.SweepRays, settings.SweepLightRays, shadows, sweep + 1, settings);
    GatheredPoints elements =
      Run(pass, solutions, pool, settings.Group, progress, at(sweep), at(sweep + 1), elementsArriving);
    cast += elements.Rays;
    if (elements.Aborted)
    {
      out.Aborted = true;
      out.Rays = cast;
      return out;
    }
    KeepUnswept(mesh, geometry, source, solutions, elements);
    source = std::move(elements.Radiosity);
    cellDirect = std::move(elements.Direct);
    cellIrradiance = std::move(elements.Irradiance);
  }
  if (sweeps > 0)
  {
    lap("gather: sweeps over the elements");
  }
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  // Every rank gathers its share of the points: all take the fewest rays any can afford.
  const int pointRays = static_cast<int>(-LargestOverRanks(
    settings.Group, -AffordableRays(settings, elapsed.count(), cast, static_cast<int>(items.size()))));
  if (pointRays == 0 && sweeps > 0)
  {
    out.Rays = cast; // the points keep their elements' (swept) mean
    out.OutOfTime = true;
  }
  else
  {
    const Gather last(mesh, geometry, rays, emission, source, solutions, emitters, frames, pointEmission,
      std::max(pointRays, 1), settings.LightRays, shadows, 0, settings);
    out = settings.CacheAccuracy > 0
      ? PointsShareGathers(last, items, solutions, arriving, settings.CacheAccuracy, pool, ranks, progress, at(sweeps), 1.0)
      : EveryPointGathers(last, items, solutions, arriving, pool, ranks, progress, at(sweeps), 1.0);
    out.Rays += cast;
    out.PointRays = pointRays;
    out.Points = static_cast<int>(items.size());
  }
  if (out.Aborted)
  {
    out.Radiosity.clear();
    out.Direct.clear();
    out.Irradiance.clear();
    return out;
  }
  if (!out.OutOfTime)
  {
    CopyToCopies(rep, solutions, out);
    FillHidden(mesh, solutions, out.Hidden, { &out.Radiosity, &out.Direct, &out.Irradiance });
  }
  if (sweeps > 0)
  {
    out.Cells = std::move(source);
    out.CellsDirect = std::move(cellDirect);
    out.CellsIrradiance = std::move(cellIrradiance);
  }
  lap("gather: interreflection at the points");
  out.Steps = std::move(steps);
  return out;
}

GatheredPoints IrradianceAtPoints(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, const std::vector<Vec3>& radiosity, int solutions,
  const std::vector<Vec3>& points, const std::vector<Vec3>& normals, const GatherSettings& settings, int threads,
  const std::function<bool(double)>& progress)
{
  // A white, non-emitting surface at each point: what it would send is what arrives.
  std::vector<PointFrame> frames(points.size());
  for (size_t p = 0; p < points.size(); ++p)
  {
    PointFrame& f = frames[p];
    f.Origin = points[p];
    f.Normal = Normalized(normals[p]);
    Vec3 t, b;
    TangentFrame(f.Normal, t, b);
    f.Edge = t;
    f.Reflectance = { 1, 1, 1 };
    f.Used = Dot(f.Normal, f.Normal) > 0;
  }
  const std::vector<Emitter> emitters = MakeEmitters(mesh, geometry, emission, solutions);
  const WorkerPool pool(threads);
  const std::vector<Vec3> none(points.size() * solutions);
  const Gather free(mesh, geometry, rays, emission, radiosity, solutions, emitters, frames, none,
    std::max(0, settings.Rays), settings.LightRays, true, 0x17, settings); // 0 rays: direct light alone
  std::vector<Vec3> arriving;
  GatheredPoints out = Run(free, solutions, pool, settings.Group, progress, 0.0, 1.0, arriving);
  out.Hidden.clear();
  return out;
}

std::vector<Vec3> CellsFromPoints(const SceneMesh& mesh, const SceneGeometry& geometry,
  const std::vector<Vec3>& points, const std::vector<Vec3>& cells, int solutions)
{
  std::vector<Vec3> out = cells;
  for (int e = 0; e < mesh.NumberOfPolygons(); ++e)
  {
    const int count = mesh.PolygonSize(e);
    if (geometry.Sheltered[e] || count == 0)
    {
      continue;
    }
    const int* ids = mesh.Polygon(e);
    for (int m = 0; m < solutions; ++m)
    {
      Vec3 sum;
      for (int v = 0; v < count; ++v)
      {
        sum += points[static_cast<size_t>(ids[v]) * solutions + m];
      }
      out[static_cast<size_t>(e) * solutions + m] = sum * (1.0 / count);
    }
  }
  return out;
}

} // namespace radiosity
