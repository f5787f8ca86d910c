#include "Solve/RadiositySolver.h"
#include "Base/WorkerPool.h"
#include "Geometry/ClusterTree.h"
#include "Solve/MethodCost.h"
#include "Solve/ShooterFormFactors.h"
#include "Solve/SolverMethods.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace radiosity
{

namespace
{
/// Progressive refinement costs about shots x elements form factors, and shots grow with
/// the patches; hierarchical links are made once per shooter and reused. Measured under
/// Auto's old rule (progressive below 20,000 elements), the links won everywhere: 3.1 x
/// faster on the paper scene at 154 elements and 49 patches, 4-10 x on the paper scene and
/// the Cornell box up to 5,364 elements, 27 x on a curved model at 10,919 elements. Below
/// this many element-patch pairs a solve takes milliseconds either way, and progressive
/// refinement's exact per-element shots are kept.
constexpr double kHierarchicalPairs = 5000;

/// Auto's choice, and why, in `reason`; the hemicube and Monte Carlo estimators exist only
/// in progressive refinement.
SolverMethod ResolveMethod(
  const SolverOptions& options, const SceneMesh& mesh, const SceneGeometry& g, std::string& reason)
{
  const int elements = static_cast<int>(g.Centroid.size());
  const int patches = static_cast<int>(g.PatchElements.size());
  if (options.SolverMethod != SolverMethod::Auto && FindSolverMethod(options.SolverMethod))
  {
    reason = "as set";
    return options.SolverMethod;
  }
  char text[256];
  const double pairs = static_cast<double>(elements) * patches;
  if (options.FormFactorMethod != FormFactorMethod::Analytic)
  {
    reason = "chosen by Auto: the hemicube and Monte Carlo estimators are progressive only";
    return SolverMethod::ProgressiveRefinement;
  }
  if (pairs < kHierarchicalPairs)
  {
    std::snprintf(text, sizeof(text), "chosen by Auto: %d elements x %d patches = %.3g, < %.0f", elements, patches,
      pairs, kHierarchicalPairs);
    reason = text;
    return SolverMethod::ProgressiveRefinement;
  }
  const double near = EstimateNearPairs(mesh, g, options.Clustered.Separation);
  const double linked = HierarchicalSeconds(elements, patches), clustered = ClusteredSeconds(elements, near);
  // Not for the moving-light basis (every patch emits, one solution each: DirectToElements
  // off), whose solutions the clustered method's node sums could not hold.
  const bool cluster = clustered < linked && options.Hierarchical.DirectToElements;
  std::snprintf(text, sizeof(text),
    "chosen by Auto: %d elements, %d patches, about %.3g near pairs; estimated %.3g s clustered, %.3g s hierarchical",
    elements, patches, near, clustered, linked);
  reason = text;
  return cluster ? SolverMethod::Clustered : SolverMethod::Hierarchical;
}

int CountFaceClusters(const SceneGeometry& g)
{
  int clusters = 0;
  for (const std::vector<int>& elements : g.PatchElements)
  {
    clusters += elements.size() > 1 && ConeOf(g, elements).Spread > 1e-6 ? 1 : 0;
  }
  return clusters;
}

bool Grey3(const Vec3& v)
{
  return v.x == v.y && v.y == v.z;
}
} // namespace

std::string OptionsProblem(const SolverOptions& options)
{
  if (!std::isfinite(options.ConvergenceThreshold) || options.ConvergenceThreshold < 0)
  {
    return "ConvergenceThreshold is " + std::to_string(options.ConvergenceThreshold) +
      "; it is a fraction of the emitted power, from 0 to 1";
  }
  if (!std::isfinite(options.TimeBudget) || options.TimeBudget < 0)
  {
    return "TimeBudget is " + std::to_string(options.TimeBudget) + "; it is seconds, 0 for none";
  }
  if (!std::isfinite(options.Clustered.Separation) || options.Clustered.Separation < 2)
  {
    return "ClusterSeparation is " + std::to_string(options.Clustered.Separation) +
      "; it is a multiple of two groups' radii, 2 or more (4 by default)";
  }
  return std::string();
}

std::string NoFiniteSolution(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays)
{
  static const char* const names[3] = { "red", "green", "blue" };
  int channel = -1;
  for (int c = 0; c < 3 && channel < 0; ++c)
  {
    bool all = true;
    for (size_t e = 0; e < geometry.Normal.size() && all; ++e)
    {
      all = geometry.Enclosed[e] || mesh.Reflectance[e][c] >= 1.0;
    }
    channel = all ? c : -1;
  }
  if (channel < 0)
  {
    return std::string();
  }
  const WorkerPool pool(1);
  ShooterFormFactors probes(mesh, geometry, rays, pool);
  for (size_t p = 0; p < geometry.PatchElements.size(); ++p)
  {
    if (geometry.PatchOpenArea[p] > 0 && !probes.ViewIsClosed(static_cast<int>(p)))
    {
      return std::string(); // light escapes through an opening: the sum converges
    }
  }
  return std::string("every surface reflects all of the ") + names[channel] +
    " light and the scene is closed: light never leaves, so there is no finite solution; give the surfaces a "
    "reflectance below 1";
}

int ShotCap(const SolverOptions& options, int patches)
{
  if (options.MaximumShots > 0)
  {
    return options.MaximumShots;
  }
  return static_cast<int>(std::min<long long>(std::max<long long>(2000, 25LL * patches), 1000000000LL));
}

bool AddsAmbient(const SolverOptions& options, SolverStatistics& stats)
{
  stats.AmbientAtCap = !options.AmbientTerm && options.MaximumShots <= 0 && !stats.Converged && !stats.Aborted &&
    !stats.OutOfTime && stats.OutOfMemory.empty() && stats.Shots >= stats.ShotCap;
  return options.AmbientTerm || stats.AmbientAtCap;
}

namespace
{
/// Rays reach an element closed off by a face lying on it (the floor under a box, through
/// the box's bottom drawn in the same plane), but no light does: it shows only its own
/// emission, and what reached it counts as escaped, as light on a back face does: all of
/// it where its patch is closed off too (that patch never shoots), else the part it did
/// not reflect (its patch's open elements shoot the rest on).
void KeepClosedOffDark(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& emission, Solution& out)
{
  const size_t solutions = static_cast<size_t>(out.Solutions);
  for (size_t e = 0; e < g.Enclosed.size(); ++e)
  {
    const bool shut = g.PatchOpenArea[g.ElementPatch[e]] <= 0;
    for (size_t m = 0; g.Enclosed[e] && m < solutions; ++m)
    {
      const size_t i = e * solutions + m;
      for (int c = 0; c < 3; ++c)
      {
        const double rho = mesh.Reflectance[e][c], reached = (out.Radiosity[i][c] - emission[i][c]) / rho;
        out.Statistics.EscapedPower += rho > 0 ? reached * (shut ? 1.0 : 1 - rho) * g.Area[e] : 0.0;
      }
      out.Radiosity[i] = emission[i];
      if (!out.Direct.empty())
      {
        out.Direct[i] = emission[i];
      }
    }
  }
}
} // namespace

RadiositySolver::RadiositySolver(const SceneMesh& mesh, int threads, const ProcessGroup& group)
  : Mesh(mesh)
{
  Error_ = PrepareTransport(mesh, threads, group, Prepared_);
}

RadiositySolver::RadiositySolver(const SceneMesh& mesh, const PreparedScene& prepared)
  : Mesh(mesh)
  , Prepared_(prepared)
{
  if (!Prepared_.Fits(mesh, true))
  {
    Error_ = "the prepared scene is not this mesh's";
  }
}

RadiositySolver::~RadiositySolver() = default;

const std::string& RadiositySolver::Error() const
{
  return Error_;
}

Solution RadiositySolver::Solve(
  const std::vector<Vec3>& emission, int solutions, const SolverOptions& options) const
{
  const auto start = std::chrono::steady_clock::now();
  Solution out;
  const int n = Error_.empty() ? static_cast<int>(Geometry().Normal.size()) : 0;
  out.Solutions = solutions;
  out.Ambient.assign(std::max(solutions, 0), Vec3());
  if (solutions <= 0 || n == 0)
  {
    out.Radiosity = emission;
    out.Statistics.Converged = true;
    return out;
  }
  bool grey = options.Color == EffectMode::Off;
  if (options.Color == EffectMode::Auto)
  {
    grey = std::all_of(Mesh.Reflectance.begin(), Mesh.Reflectance.end(), Grey3) &&
      std::all_of(emission.begin(), emission.end(), Grey3);
  }
  out.Statistics.SingleChannel = grey;
  const SolverMethod method =
    ResolveMethod(options, Mesh, Geometry(), out.Statistics.MethodReason);
  out.Statistics.FaceClusters = CountFaceClusters(Geometry());
  FindSolverMethod(method)->Solve(Mesh, Geometry(), Rays(), emission, solutions, grey, options, start, out);
  // Sums of float links and conjugate-gradient steps leave a few values a hair below zero
  // (-1.25e-7 on a 75k-element engine), which no light can be.
  for (std::vector<Vec3>* values : { &out.Radiosity, &out.Direct })
  {
    for (Vec3& v : *values)
    {
      v = Vec3{ std::max(v.x, 0.0), std::max(v.y, 0.0), std::max(v.z, 0.0) };
    }
  }
  KeepClosedOffDark(Mesh, Geometry(), emission, out);
  return out;
}

void SolverStatistics::Append(const SolverStatistics& next)
{
  Shots += next.Shots;
  ShotCap = next.ShotCap;
  Converged = Converged && next.Converged;
  Aborted = next.Aborted;
  OutOfTime = next.OutOfTime;
  AmbientAtCap = AmbientAtCap || next.AmbientAtCap;
  OutOfMemory = next.OutOfMemory.empty() ? OutOfMemory : next.OutOfMemory;
  RayCount += next.RayCount;
  RaysSkipped += next.RaysSkipped;
  PairsUnblockable += next.PairsUnblockable;
  DistributionsSkipped += next.DistributionsSkipped;
  SingleChannel = SingleChannel && next.SingleChannel;
  BlockingSurfaces = next.BlockingSurfaces;
  FormFactorCount += next.FormFactorCount;
  SolverMethod = next.SolverMethod;
  MethodReason = next.MethodReason;
  FaceClusters = next.FaceClusters;
  PatchLinks += next.PatchLinks;
  ElementLinks += next.ElementLinks;
  VolumeLinks += next.VolumeLinks;
  LinkBytes = std::max(LinkBytes, next.LinkBytes);
  ShotPower += next.ShotPower;
  ReceivedPower += next.ReceivedPower;
  EmittedPower += next.EmittedPower;
  EscapedPower += next.EscapedPower;
  UnshotPower += next.UnshotPower;
  Ranks = next.Ranks;
  Collectives += next.Collectives;
  CollectiveBytes += next.CollectiveBytes;
  ShotCollectiveBytes += next.ShotCollectiveBytes;
  CollectiveSeconds += next.CollectiveSeconds;
  ReceivingElements = next.ReceivingElements;
  OwnRays += next.OwnRays;
  for (const Step& step : next.Steps)
  {
    Took(step.Name, step.Seconds);
  }
}

void SolverStatistics::Took(const std::string& step, double seconds)
{
  const auto same = std::find_if(Steps.begin(), Steps.end(), [&](const Step& s) { return s.Name == step; });
  if (same == Steps.end())
  {
    Steps.push_back({ step, seconds });
  }
  else
  {
    same->Seconds += seconds;
  }
}

std::vector<char> OwnedPatches(const SceneGeometry& geometry, int rank, int ranks)
{
  const size_t patches = geometry.PatchElements.size();
  if (ranks <= 1)
  {
    return std::vector<char>(patches, 1);
  }
  std::vector<char> owned(patches, 0);
  std::vector<size_t> load(ranks, 0);
  for (size_t p = 0; p < patches; ++p)
  {
    const auto least = std::min_element(load.begin(), load.end()); // the first on ties
    owned[p] = least - load.begin() == rank ? 1 : 0;
    *least += std::max<size_t>(geometry.PatchElements[p].size(), 1);
  }
  return owned;
}

} // namespace radiosity
