// ./relight bench: the paper's Table 1 (sampling) and Table 2 (relighting), measured in
// one run on this machine, with the hardware ceilings they are compared against.
// A benchmark, not a test: it prints numbers and ratios, it never judges them.
#include "Solve/LightSolutions.h"
#include "Relight/MovingLights.h"
#include "Solve/PatchBasis.h"
#include "Relight/Relight.h"
#include "Base/WorkerPool.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRadiosityMesher.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace radiosity;

namespace
{
double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// Best of `repeats` wall times of f(), to damp noise from other processes.
template <typename F>
double Best(int repeats, const F& f)
{
  double best = 1e300;
  for (int r = 0; r < repeats; ++r)
  {
    const double t0 = Now();
    f();
    best = std::min(best, Now() - t0);
  }
  return best;
}

struct Scene
{
  SceneMesh Mesh;
  std::vector<Vec3> Emission;
  int Lights = 0;
};

bool LoadMeshed(const std::string& path, double patch, double element, Scene& scene)
{
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<vtkRadiosityMesher> mesher;
  mesher->SetInputConnection(reader->GetOutputPort());
  mesher->SetPatchSize(patch);
  mesher->SetElementSize(element);
  mesher->Update();
  vtkPolyData* data = mesher->GetOutput();
  if (data->GetNumberOfCells() == 0)
  {
    std::fprintf(stderr, "cannot read or mesh %s\n", path.c_str());
    return false;
  }
  SceneMesh& m = scene.Mesh;
  for (vtkIdType p = 0; p < data->GetNumberOfPoints(); ++p)
  {
    double x[3];
    data->GetPoint(p, x);
    m.Points.push_back({ x[0], x[1], x[2] });
  }
  vtkIdType npts;
  const vtkIdType* ids;
  auto* polys = data->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    m.AddPolygon(std::vector<int>(ids, ids + npts));
  }
  vtkDataArray* rho = data->GetCellData()->GetArray("Reflectance");
  vtkDataArray* light = data->GetCellData()->GetArray("LightId");
  vtkDataArray* patchId = data->GetCellData()->GetArray("PatchId");
  vtkDataArray* emission = data->GetCellData()->GetArray("Emission");
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
  {
    double r[3], e[3] = { 1, 1, 1 };
    rho->GetTuple(c, r);
    if (emission)
    {
      emission->GetTuple(c, e);
    }
    m.Reflectance.push_back({ r[0], r[1], r[2] });
    m.LightId.push_back(static_cast<int>(light->GetComponent(c, 0)));
    m.PatchId.push_back(static_cast<int>(patchId->GetComponent(c, 0)));
    scene.Emission.push_back({ e[0], e[1], e[2] });
  }
  const std::string error = ValidateScene(m, scene.Lights);
  if (!error.empty())
  {
    std::fprintf(stderr, "%s: %s\n", path.c_str(), error.c_str());
    return false;
  }
  return true;
}

/// Occlusion rays between random points of the scene's bounding box, on all threads: the
/// ceiling for anything that casts shadow rays in this scene.
double RawOcclusionRate(const Visibility& rays, const SceneGeometry& g, const WorkerPool& pool, int count)
{
  std::vector<Vec3> from(count), to(count);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(g.Centroid.size()) - 1);
  for (int i = 0; i < count; ++i)
  {
    // Element centroid to element centroid, like the solver's rays (both ends on surfaces).
    const int a = pick(rng), b = pick(rng);
    from[i] = g.Centroid[a] + g.Normal[a] * (1e-6 * g.SceneDiagonal);
    to[i] = g.Centroid[b] + g.Normal[b] * (1e-6 * g.SceneDiagonal);
  }
  std::vector<char> blocked(count);
  const double t = Best(3, [&] {
    pool.For(count, 1024, [&](int begin, int end) {
      for (int i = begin; i < end; ++i)
      {
        blocked[i] = rays.Occluded(from[i], to[i], 1e-6);
      }
    });
  });
  return count / t;
}

struct Row
{
  std::string Table, Name;
  double Value;
  std::string Unit;
};
} // namespace

int main(int argc, char* argv[])
{
  std::string data = "Data", csv = "out/bench/bench.csv";
  int shots = 100;
  int bigElements = 1000000;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string key = argv[i];
    if (key == "--data")
      data = argv[i + 1];
    else if (key == "--csv")
      csv = argv[i + 1];
    else if (key == "--shots")
      shots = std::atoi(argv[i + 1]);
    else if (key == "--big")
      bigElements = std::atoi(argv[i + 1]);
  }
  std::vector<Row> rows;
  WorkerPool all(0);
  std::printf("RadiosityRelight benchmark: %d hardware threads, %d shots per solve\n\n", all.Threads(), shots);

  // ---- Table 1: sampling time per method, k = 1, 3, 8 --------------------------------
  std::printf("Table 1 (sampling, %d shots, analytic form factors, %d shadow rays: the defaults)\n", shots,
    SolverOptions().FormFactorSamples);
  std::printf("%3s %9s %9s | %10s %10s %10s | %9s %9s\n", "k", "elements", "patches", "combined s",
    "separate s", "tagged s", "sep/tag", "tag/comb");
  double taggedRaysPerSecond = 0;
  Scene eight;
  for (int k : { 1, 3, 8 })
  {
    Scene scene;
    if (!LoadMeshed(data + "/paper_" + std::to_string(k) + "lights.vtp", 1.5, 0.375, scene))
    {
      return 1;
    }
    RadiositySolver solver(scene.Mesh);
    SolverOptions options;
    options.MaximumShots = shots;
    options.ConvergenceThreshold = 0; // exactly `shots` shots, as in the paper
    const LightGrouping grouping = LightGrouping::OnePerLight(scene.Lights);
    auto run = [&](SolutionMode mode) {
      Solution s;
      const double t = Best(3, [&] { s = SolveLights(solver, scene.Mesh, grouping, scene.Emission, mode, options); });
      return std::make_pair(t, s.Statistics);
    };
    const auto combined = run(SolutionMode::StandardCombined);
    const auto separate = run(SolutionMode::StandardSeparate);
    const auto tagged = run(SolutionMode::LightTagged);
    std::printf("%3d %9d %9zu | %10.4f %10.4f %10.4f | %8.2fx %8.3fx\n", k, scene.Mesh.NumberOfPolygons(),
      solver.Geometry().PatchElements.size(), combined.first, separate.first, tagged.first,
      separate.first / tagged.first, tagged.first / combined.first);
    const std::string K = "k=" + std::to_string(k);
    rows.push_back({ "table1", K + " combined", combined.first, "s" });
    rows.push_back({ "table1", K + " separate", separate.first, "s" });
    rows.push_back({ "table1", K + " tagged", tagged.first, "s" });
    rows.push_back({ "table1", K + " separate/tagged", separate.first / tagged.first, "ratio" });
    rows.push_back({ "table1", K + " tagged/combined", tagged.first / combined.first, "ratio" });
    if (k == 8)
    {
      taggedRaysPerSecond = tagged.second.RayCount / tagged.first;
      eight = scene;
    }
  }
  std::printf("paper (PIII 450 MHz, 128^2 hemicube): separate/tagged 6.30x at k = 8, tagged/combined 1.27x\n\n");

  // ---- Ceilings and scaling -------------------------------------------------------------
  RadiositySolver solver8(eight.Mesh);
  const double raw = RawOcclusionRate(solver8.Rays(), solver8.Geometry(), all, 2000000);
  std::printf("Embree occlusion rays: raw %.2f M/s; the tagged k = 8 solve casts %.2f M/s = %.0f %% of raw\n",
    raw / 1e6, taggedRaysPerSecond / 1e6, 100 * taggedRaysPerSecond / raw);
  rows.push_back({ "ceiling", "raw occlusion rays", raw, "rays/s" });
  rows.push_back({ "ceiling", "solver rays", taggedRaysPerSecond, "rays/s" });
  rows.push_back({ "ceiling", "solver/raw rays", taggedRaysPerSecond / raw, "ratio" });
  {
    SolverOptions options;
    options.MaximumShots = shots;
    options.ConvergenceThreshold = 0;
    const LightGrouping grouping = LightGrouping::OnePerLight(eight.Lights);
    options.Threads = 1;
    const double one = Best(3, [&] { SolveLights(solver8, eight.Mesh, grouping, eight.Emission, SolutionMode::LightTagged, options); });
    options.Threads = 0;
    const double many = Best(3, [&] { SolveLights(solver8, eight.Mesh, grouping, eight.Emission, SolutionMode::LightTagged, options); });
    std::printf("threads: tagged k = 8 takes %.4f s on 1 thread, %.4f s on %d: speed-up %.2fx\n\n", one, many,
      all.Threads(), one / many);
    rows.push_back({ "scaling", "1 thread", one, "s" });
    rows.push_back({ "scaling", "all threads", many, "s" });
    rows.push_back({ "scaling", "speed-up", one / many, "ratio" });
  }

  // ---- Table 2: relighting per frame and memory ------------------------------------------
  std::printf("Table 2 (relight one frame: combine k solutions into RGB, float)\n");
  std::printf("%9s %3s | %10s %12s | %11s %11s %8s\n", "elements", "k", "ms/frame", "memory", "relight GB/s",
    "memcpy GB/s", "fraction");
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  for (int n : { eight.Mesh.NumberOfPolygons(), bigElements })
  {
    for (int k : { 1, 3, 8 })
    {
      // The values do not change the cost; the 1 M element case uses synthetic solutions.
      std::vector<std::vector<float>> solutions(k, std::vector<float>(3 * static_cast<size_t>(n)));
      for (auto& s : solutions)
      {
        for (float& v : s)
        {
          v = value(rng);
        }
      }
      std::vector<const float*> pointers;
      for (auto& s : solutions)
      {
        pointers.push_back(s.data());
      }
      std::vector<double> weights(3 * k, 0.5);
      std::vector<float> out(3 * static_cast<size_t>(n));
      const int repeats = n > 100000 ? 20 : 2000;
      const double relight = Best(5, [&] {
        for (int r = 0; r < repeats; ++r)
        {
          CombineLights(pointers, weights, static_cast<size_t>(n), out.data(), &all);
        }
      }) / repeats;
      // The same bytes moved by memcpy on the same threads: the memory-bandwidth ceiling.
      const size_t bytes = sizeof(float) * 3 * static_cast<size_t>(n) * (k + 1);
      std::vector<char> src(bytes), dst(bytes);
      const int chunks = 64;
      const double copy = Best(5, [&] {
        for (int r = 0; r < repeats; ++r)
        {
          all.For(chunks, 1, [&](int b, int e) {
            const size_t lo = bytes * b / chunks, hi = bytes * e / chunks;
            std::memcpy(dst.data() + lo, src.data() + lo, hi - lo);
          });
        }
      }) / repeats;
      const double memory = sizeof(float) * 3.0 * n * k;
      std::printf("%9d %3d | %10.4f %9.1f KB | %11.2f %11.2f %7.0f %%\n", n, k, relight * 1e3, memory / 1024,
        bytes / relight / 1e9, bytes / copy / 1e9, 100 * copy / relight);
      const std::string K = "n=" + std::to_string(n) + " k=" + std::to_string(k);
      rows.push_back({ "table2", K + " relight", relight, "s/frame" });
      rows.push_back({ "table2", K + " memory", memory, "bytes" });
      rows.push_back({ "table2", K + " relight/memcpy bandwidth", copy / relight, "ratio" });
    }
  }
  std::printf("paper (software, 960 elements): 1.0 / 2.6 / 7.3 ms at k = 1 / 3 / 8; 12 / 35 / 95 KB\n");

  // ---- Moving lights (paper 2.4): per-frame time ------------------------------------------
  std::printf("\nMoving lights (one point light, paper 2.4): direct light + patch basis per frame\n");
  std::printf("%9s %8s | %10s %10s | %9s %9s %9s\n", "elements", "patches", "basis MB", "basis s", "direct ms",
    "basis ms", "frame ms");
  // The paper's scene size (about 30 patches, 1920 elements), then 100x the elements
  // (scaled down with --big for smoke runs).
  const double larger = 0.21 / std::sqrt(100.0 * bigElements / 1e6);
  for (double element : { 0.21, larger })
  {
    Scene scene;
    if (!LoadMeshed(data + "/paper_1lights.vtp", 2.0, element, scene))
    {
      return 1;
    }
    RadiositySolver solver(scene.Mesh);
    const SceneGeometry& g = solver.Geometry();
    const int n = scene.Mesh.NumberOfPolygons();
    const int P = static_cast<int>(g.PatchElements.size());
    // The paper's size keeps a basis per element; the larger scene stores it per patch node
    // (what Auto picks once an element basis passes its budget).
    const BasisLevel level = n > 100000 ? BasisLevel::Patches : BasisLevel::Elements;
    SolverOptions options;
    SolverStatistics stats;
    const double t0 = Now();
    PatchBasis basis;
    const std::string error = SolvePatchBasis(solver, scene.Mesh, options, level, stats, basis);
    if (!error.empty())
    {
      std::printf("  moving-light basis: %s\n", error.c_str());
      return 1;
    }
    const double basisSeconds = Now() - t0;
    MovingLightShader shader(scene.Mesh, solver.Prepared(), nullptr);
    std::vector<MovingLight> lights(1);
    std::vector<Vec3> direct, result;
    int frame = 0;
    auto place = [&] {
      lights[0].Position = { 1.0 + 0.02 * (frame % 100), 1.8, 1.0 + 0.01 * (frame % 100) };
      ++frame;
    };
    const int repeats = n > 100000 ? 5 : 50;
    const double directTime = Best(3, [&] {
      for (int r = 0; r < repeats; ++r)
      {
        place();
        shader.Direct(lights, all, direct);
      }
    }) / repeats;
    const double basisTime = Best(3, [&] {
      for (int r = 0; r < repeats; ++r)
      {
        AddBasisInterreflection(g, direct, View(basis), all, result);
      }
    }) / repeats;
    std::printf("%9d %8d | %10.2f %10.2f | %9.3f %9.3f %9.3f (basis per %s)\n", n, P, basis.Bytes() / 1048576.0,
      basisSeconds, directTime * 1e3, basisTime * 1e3, (directTime + basisTime) * 1e3,
      level == BasisLevel::Elements ? "element" : "patch node");
    const std::string K = "moving n=" + std::to_string(n) + " P=" + std::to_string(P);
    rows.push_back({ "moving", K + " frame", directTime + basisTime, "s/frame" });
    rows.push_back({ "moving", K + " basis memory", basis.Bytes(), "bytes" });
  }
  std::printf("paper: 30 patches, 1920 elements, 690 KB basis, \"near real-time\"\n");

  std::ofstream file(csv);
  if (!file)
  {
    std::fprintf(stderr, "cannot write %s\n", csv.c_str());
    return 1;
  }
  file << "table,name,value,unit\n";
  for (const Row& r : rows)
  {
    file << r.Table << "," << r.Name << "," << r.Value << "," << r.Unit << "\n";
  }
  std::printf("\nwrote %s\n", csv.c_str());
  return 0;
}
