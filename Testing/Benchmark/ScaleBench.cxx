// ./relight bench scale: time, memory and accuracy of the solver methods as the furnished
// room grows from 10k to 1M elements, k = 8 lights. Prints ratios measured in one run and
// writes a CSV; it never judges them.
#include "BenchClock.h"
#include "BenchMethods.h"
#include "ProbeReference.h"
#include "FurnishedRoom.h"
#include "Geometry/PointAverages.h"
#include "Solve/LightSolutions.h"
#include "Relight/MovingLights.h"
#include "Solve/PatchBasis.h"
#include "Base/WorkerPool.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace radiosity;
using namespace radiosity_bench;
using namespace radiosity_scenes;

namespace
{

/// What the path tracer would need to give every element of this mesh, for every light,
/// the error the solver reached: its noise falls as 1 / sqrt(paths), from the 0.74 % (in
/// this metric) measured at 4,096 paths between two renders with different seeds.
void ComparePathTracer(double seconds, size_t probes, int lights, int elements, double error, double solve)
{
  const double perPoint = seconds / (static_cast<double>(probes) * lights);
  const double paths = 4096 * std::pow(0.0074 / error, 2);
  const double total = perPoint * (paths / 4096) * elements * lights;
  std::printf("  Mitsuba to the same error (%.2f %%, about %.0f paths): %.2f ms per point and light, %.0f s for "
              "every element and light: %.0fx the solve\n",
    100 * error, paths, 1e3 * perPoint * paths / 4096, total, total / solve);
}

struct Run
{
  Solution Result;
  double Seconds = 0, MemoryMB = 0;
};

Run SolveRoom(const RadiositySolver& solver, const SceneMesh& mesh, int lights, SolutionMode mode,
  SolverOptions options)
{
  ResetPeakMemory();
  Run run;
  const double t0 = Now();
  run.Result = SolveLights(solver, mesh, LightGrouping::OnePerLight(lights), {}, mode, options);
  run.Seconds = Now() - t0;
  run.MemoryMB = PeakMemoryMB();
  return run;
}

struct Csv
{
  std::ostringstream Text;
  Csv() { Text << "elements,patches,method,mode,lights,seconds,shots,converged,peak_mb,links_mb,mean_error,max_error\n"; }
  void Add(const SceneMesh& mesh, int patches, const Run& run, const char* mode, int lights, double mean,
    double worst)
  {
    const SolverStatistics& s = run.Result.Statistics;
    Text << mesh.NumberOfPolygons() << ',' << patches << ',' << ShortMethodName(s.SolverMethod) << ',' << mode << ',' << lights
         << ',' << run.Seconds << ',' << s.Shots << ',' << (s.Converged ? 1 : 0) << ',' << run.MemoryMB << ','
         << s.LinkBytes / 1048576.0 << ',' << mean << ',' << worst << '\n';
  }
};

/// The moving-light basis on this mesh (Auto level): its memory against what a basis per
/// element would take, the time to solve it, and one frame (direct shadow rays plus basis).
void MeasureBasis(const RadiositySolver& solver, const SceneMesh& mesh)
{
  const SceneGeometry& g = solver.Geometry();
  const double n = static_cast<double>(g.Normal.size()), P = static_cast<double>(g.PatchElements.size());
  ResetPeakMemory();
  const double t0 = Now();
  SolverStatistics stats;
  PatchBasis basis;
  const std::string error = SolvePatchBasis(solver, mesh, SolverOptions(), BasisLevel::Auto, stats, basis);
  const double solve = Now() - t0;
  if (!error.empty())
  {
    std::printf("  moving-light basis: %s\n", error.c_str());
    return;
  }
  const double peak = PeakMemoryMB();
  MovingLightShader shader(mesh, solver.Prepared(), nullptr);
  std::vector<MovingLight> light(1);
  light[0].Position = { 2.0, 2.0, 2.2 };
  light[0].Intensity = 50;
  WorkerPool pool(0);
  std::vector<Vec3> direct, result;
  const double t1 = Now();
  const int frames = 5;
  for (int f = 0; f < frames; ++f)
  {
    light[0].Position.x += 0.1;
    shader.Direct(light, pool, direct);
    AddBasisInterreflection(g, direct, View(basis), pool, result);
  }
  std::printf("  moving-light basis (%s): %d patches x %d receivers, %.1f MB (per element it would be %.0f MB), "
              "solved in %.1f s (%d shots, %s), peak %.0f MB; %.1f ms per frame\n",
    basis.Node.empty() ? "per element" : "per patch node", basis.Patches, basis.Receivers, basis.Bytes() / 1048576.0,
    12 * n * P / 1048576.0, solve, stats.Shots, stats.Converged ? "converged" : "not converged", peak,
    1e3 * (Now() - t1) / frames);
}

void Print(const char* label, const SceneMesh& mesh, int patches, const Run& run, double mean, double worst)
{
  const SolverStatistics& s = run.Result.Statistics;
  std::printf("%-28s %9d %7d %9.2f %7d %5s %8.0f %8.1f %8.2f%% %7.2f%%\n", label, mesh.NumberOfPolygons(), patches,
    run.Seconds, s.Shots, s.Converged ? "yes" : "NO", run.MemoryMB, s.LinkBytes / 1048576.0, 100 * mean,
    100 * worst);
  std::fflush(stdout);
}
} // namespace

int main(int argc, char* argv[])
{
  std::vector<long long> sizes = { 4000, 10000, 100000, 1000000 };
  double patch = 0.4;
  long long referenceElements = 40000;
  double mitsubaSeconds = 0; // wall time of the reference render (all probes, all lights)
  int gatherRays = 256;      // the final gather, as the solver filter does by default (0: off)
  double cache = GatherSettings().CacheAccuracy; // the gather's irradiance cache (0: every point gathers)
  int sweeps = GatherSettings().Sweeps, sweepRays = GatherSettings().SweepRays; // the gather's passes over the elements
  SolverMethod method = SolverMethod::Hierarchical; // --method: another (auto: Auto's choice)
  double lampGrading = 0.2;  // finer elements by the lamps, as the mesher filter does by default (0: off)
  int lightRays = GatherSettings().LightRays; // shadow rays a point casts to each lamp it sees
  bool combinedToo = true;   // also solve k = 1 combined, for the k=8 / k=1 ratio
  std::string csvPath = "out/bench/scale.csv", exportPath, mitsubaPath, valuesPath; // --values: ours at each probe
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string key = argv[i];
    if (key == "--sizes")
    {
      sizes.clear();
      std::istringstream list(argv[i + 1]);
      for (std::string item; std::getline(list, item, ',');)
      {
        sizes.push_back(std::atoll(item.c_str()));
      }
    }
    else if (key == "--patch")
      patch = std::atof(argv[i + 1]);
    else if (key == "--reference")
      referenceElements = std::atoll(argv[i + 1]);
    else if (key == "--csv")
      csvPath = argv[i + 1];
    else if (key == "--export")
      exportPath = argv[i + 1];
    else if (key == "--mitsuba")
      mitsubaPath = argv[i + 1];
    else if (key == "--mitsuba-seconds")
      mitsubaSeconds = std::atof(argv[i + 1]);
    else if (key == "--gather")
      gatherRays = std::atoi(argv[i + 1]);
    else if (key == "--sweeps")
      sweeps = std::atoi(argv[i + 1]);
    else if (key == "--sweep-rays")
      sweepRays = std::atoi(argv[i + 1]);
    else if (key == "--values")
      valuesPath = argv[i + 1];
    else if (key == "--light-rays")
      lightRays = std::atoi(argv[i + 1]);
    else if (key == "--cache")
      cache = std::atof(argv[i + 1]);
    else if (key == "--grading")
      lampGrading = std::atof(argv[i + 1]);
    else if (key == "--method")
    {
      method = MethodNamed(argv[i + 1]);
      if (method == SolverMethod::Auto && std::string(argv[i + 1]) != "auto")
      {
        std::fprintf(stderr, "--method: no method '%s' (progressive, hierarchical, clustered or auto)\n", argv[i + 1]);
        return 2;
      }
    }
    else if (key == "--combined")
      combinedToo = std::atoi(argv[i + 1]) != 0;
  }
  const RoomPolygons room = FurnishedRoom();
  const int lights = static_cast<int>(room.LightNames.size());
  const double area = TotalArea(room);
  const Probes probes(3000);
  WorkerPool pool(0);
  std::printf("Scale benchmark: furnished room, %zu polygons, %d lights, %.0f m^2, patch size %.2f m, %d threads, "
              "final gather %d rays, irradiance cache %.2f\n\n",
    room.Reflectance.size(), lights, area, patch, pool.Threads(), gatherRays, cache);

  // The probes are placed from a small mesh (the geometry, so the hit points, is the same
  // at every size). The reference: Mitsuba 3's path tracer where its values are given,
  // otherwise progressive refinement converged to 1e-5 on a fine mesh.
  // Exported probes always come from the same 5,000-element mesh, so a reference rendered
  // for them stays valid until the room itself changes.
  const double referenceSize = std::sqrt(area / (exportPath.empty() ? std::max(referenceElements, 1000LL) : 5000));
  SceneMesh referenceMesh;
  std::string error = MeshRoom(room, 2 * referenceSize, referenceSize, referenceMesh);
  if (!error.empty())
  {
    std::fprintf(stderr, "mesher: %s\n", error.c_str());
    return 1;
  }
  RadiositySolver referenceSolver(referenceMesh);
  if (!exportPath.empty())
  {
    ExportRoom(room, referenceSolver, referenceMesh, probes, exportPath);
    std::printf("wrote %s\n", exportPath.c_str());
    return 0;
  }
  std::printf("%-28s %9s %7s %9s %7s %5s %8s %8s %9s %8s\n", "run", "elements", "patches", "seconds", "shots",
    "conv", "peak MB", "links MB", "mean err", "max err");
  std::vector<double> referenceValues(probes.Origin.size() * lights, std::nan(""));
  if (!mitsubaPath.empty())
  {
    referenceValues = ReadReference(mitsubaPath, probes.Origin.size(), lights);
    std::printf("reference: Mitsuba 3 path tracing at the probes (%s)\n", mitsubaPath.c_str());
  }
  else if (referenceElements > 0)
  {
    SolverOptions converged;
    converged.SolverMethod = SolverMethod::ProgressiveRefinement;
    converged.ConvergenceThreshold = 1e-5;
    converged.MaximumShots = 1000000;
    const Run reference = SolveRoom(referenceSolver, referenceMesh, lights, SolutionMode::LightTagged, converged);
    referenceValues = Sample(referenceSolver, referenceMesh, reference.Result, probes);
    Print("reference (progressive 1e-5)", referenceMesh,
      static_cast<int>(referenceSolver.Geometry().PatchElements.size()), reference, 0, 0);
  }

  Csv csv;
  std::vector<std::pair<double, double>> growth; // (elements, seconds) of the method k = 8
  double lastTagged = 0, lastCombined = 0;
  for (long long target : sizes)
  {
    const double element = std::sqrt(area / target);
    SceneMesh mesh;
    const double t0 = Now();
    error = MeshRoom(room, std::max(patch, element), element, mesh, lampGrading);
    if (!error.empty())
    {
      std::fprintf(stderr, "mesher: %s\n", error.c_str());
      return 1;
    }
    const double t1 = Now();
    RadiositySolver solver(mesh); // geometry and the Embree scene, shared by the solves
    const double t2 = Now();
    const int patches = static_cast<int>(solver.Geometry().PatchElements.size());
    SolverOptions options;
    options.SolverMethod = method;
    options.MaximumShots = 1000000;
    options.Gather.Rays = gatherRays;
    options.Gather.CacheAccuracy = cache;
    options.Gather.Sweeps = sweeps;
    options.Gather.SweepRays = sweepRays;
    options.Gather.LightRays = lightRays;
    double worst = 0, mean = 0;
    const Run tagged = SolveRoom(solver, mesh, lights, SolutionMode::LightTagged, options);
    const std::vector<double> sampled = Sample(solver, mesh, tagged.Result, probes);
    mean = MeanError(sampled, referenceValues, lights, &worst);
    Print((ShortMethodName(tagged.Result.Statistics.SolverMethod) + ", k=8 tagged").c_str(), mesh, patches, tagged, mean, worst);
    if (!valuesPath.empty())
    {
      std::ofstream values(valuesPath);
      values << "probe,light,ours,reference\n";
      for (size_t i = 0; i < sampled.size(); ++i)
      {
        values << i / lights << ',' << i % lights << ',' << sampled[i] << ',' << referenceValues[i] << '\n';
      }
    }
    std::printf("  bias per light (sum of ours - reference over its sum):");
    for (double b : SignedError(sampled, referenceValues, lights))
    {
      std::printf(" %+.2f%%", 100 * b);
    }
    std::printf("\n");
    std::printf("  links: %lld to patches, %lld to elements\n", tagged.Result.Statistics.PatchLinks,
      tagged.Result.Statistics.ElementLinks);
    std::printf("  steps:");
    for (const SolverStatistics::Step& step : tagged.Result.Statistics.Steps)
    {
      std::printf(" %s %.1f s;", step.Name.c_str(), step.Seconds);
    }
    std::printf("\n");
    if (tagged.Result.GatherRecords > 0)
    {
      std::printf("  irradiance cache: %d of %d points gathered for themselves\n", tagged.Result.GatherRecords,
        tagged.Result.GatherPoints);
    }
    csv.Add(mesh, patches, tagged, "tagged", lights, mean, worst);
    growth.push_back({ static_cast<double>(mesh.NumberOfPolygons()), tagged.Seconds });
    lastTagged = tagged.Seconds;
    if (!combinedToo)
    {
      continue;
    }
    const Run combined = SolveRoom(solver, mesh, lights, SolutionMode::StandardCombined, options);
    Print((ShortMethodName(combined.Result.Statistics.SolverMethod) + ", k=1 combined").c_str(), mesh, patches, combined,
      std::nan(""), std::nan(""));
    csv.Add(mesh, patches, combined, "combined", 1, std::nan(""), std::nan(""));
    std::printf("  k=8 tagged / k=1 combined: %.2fx; before solving: meshing %.2f s, geometry and Embree %.2f s "
                "(k=8 end to end %.2f s)\n",
      tagged.Seconds / combined.Seconds, t1 - t0, t2 - t1, t2 - t0 + tagged.Seconds);
    if (mitsubaSeconds > 0 && mean > 0)
    {
      ComparePathTracer(mitsubaSeconds, probes.Origin.size(), lights, mesh.NumberOfPolygons(), mean, tagged.Seconds);
    }
    lastCombined = combined.Seconds;
    if (target >= 50000 && target <= 200000)
    {
      MeasureBasis(solver, mesh);
    }
    if (target <= 20000)
    {
      options.SolverMethod = SolverMethod::ProgressiveRefinement;
      const Run progressive = SolveRoom(solver, mesh, lights, SolutionMode::LightTagged, options);
      mean = MeanError(Sample(solver, mesh, progressive.Result, probes), referenceValues, lights, &worst);
      Print("progressive, k=8 tagged", mesh, patches, progressive, mean, worst);
      csv.Add(mesh, patches, progressive, "tagged", lights, mean, worst);
      const double methodError = MeanError(Sample(solver, mesh, tagged.Result, probes),
        Sample(solver, mesh, progressive.Result, probes), lights, &worst);
      const std::string ran = ShortMethodName(tagged.Result.Statistics.SolverMethod);
      std::printf("  progressive / %s: %.2fx time; %s vs progressive on this mesh: %.2f%% mean, %.2f%% worst light\n",
        ran.c_str(), progressive.Seconds / tagged.Seconds, ran.c_str(), 100 * methodError, 100 * worst);
    }
  }
  std::printf("\n");
  for (size_t i = 1; i < growth.size(); ++i)
  {
    const double exponent = std::log(growth[i].second / growth[i - 1].second) / std::log(growth[i].first / growth[i - 1].first);
    std::printf("time growth exponent %.0f -> %.0f elements: %.2f\n", growth[i - 1].first, growth[i].first, exponent);
  }
  if (combinedToo)
  {
    std::printf("largest size: k=8 tagged / k=1 combined %.2fx\n", lastTagged / std::max(lastCombined, 1e-9));
  }
  std::ofstream(csvPath) << csv.Text.str();
  std::printf("wrote %s\n", csvPath.c_str());
  return 0;
}
