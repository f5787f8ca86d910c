#include "Solve/PatchBasis.h"

#include "Base/Memory.h"
#include "Geometry/PatchNodes.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

namespace radiosity
{

namespace
{
SolverOptions BasisOptions(const SolverOptions& options)
{
  SolverOptions basis = options;
  basis.AmbientTerm = false;
  basis.SeparateDirect = false;
  basis.Hierarchical.DirectToElements = false; // every patch emits: links, not P x N factors
  if (basis.SolverMethod == SolverMethod::Clustered)
  {
    // Its node sums hold every solution at every node: one per patch here is too many.
    basis.SolverMethod = SolverMethod::Hierarchical;
  }
  return basis;
}

/// Unit exitance over each patch's open area, one solution per patch.
std::vector<Vec3> UnitPatchEmission(const SceneGeometry& g)
{
  const size_t n = g.Normal.size(), P = g.PatchElements.size();
  std::vector<Vec3> emission(n * P);
  for (size_t e = 0; e < n; ++e)
  {
    if (!g.Enclosed[e])
    {
      emission[e * P + g.ElementPatch[e]] = { 1, 1, 1 };
    }
  }
  return emission;
}

void Store(const Vec3& reflected, float* b)
{
  b[0] = static_cast<float>(reflected.x);
  b[1] = static_cast<float>(reflected.y);
  b[2] = static_cast<float>(reflected.z);
}

const char* const AbortedMessage = "the patch basis was aborted";

std::string ElementBasis(const RadiositySolver& solver, const SolverOptions& options, SolverStatistics& stats,
  PatchBasis& basis)
{
  const SceneGeometry& g = solver.Geometry();
  const int n = static_cast<int>(g.Normal.size()), P = static_cast<int>(g.PatchElements.size());
  const std::vector<Vec3> emission = UnitPatchEmission(g);
  const Solution s = solver.Solve(emission, P, BasisOptions(options));
  stats = s.Statistics;
  if (stats.Aborted)
  {
    return AbortedMessage;
  }
  basis.Patches = P;
  basis.Receivers = n;
  basis.Values.resize(static_cast<size_t>(n) * 3 * P);
  for (size_t i = 0; i < emission.size(); ++i)
  {
    Store(s.Radiosity[i] - emission[i], &basis.Values[3 * i]);
  }
  return std::string();
}

/// A patch this much hidden (under furniture) still becomes one polygon: it shoots that
/// fraction of its power into the object, where a polygon per open element would make the
/// patch-level scene as large as the elements' around every table leg.
constexpr double MaximumHiddenFraction = 0.05;

/// The patch-level scene: a patch whose outline is one simple loop and which is at most
/// MaximumHiddenFraction enclosed becomes one polygon (`whole`); any other keeps its open
/// elements.
/// Polygon patch ids are the fine scene's.
SceneMesh PatchLevelMesh(const SceneMesh& mesh, const SceneGeometry& g, const PatchNodes& nodes, std::vector<char>& whole)
{
  const int P = static_cast<int>(g.PatchElements.size());
  SceneMesh coarse;
  whole.assign(P, 0);
  auto add = [&](const std::vector<Vec3>& corners, const Vec3& rho, int light, int patch) {
    std::vector<int> ids;
    for (const Vec3& c : corners)
    {
      ids.push_back(static_cast<int>(coarse.Points.size()));
      coarse.Points.push_back(c);
    }
    coarse.AddPolygon(ids);
    coarse.Reflectance.push_back(rho);
    coarse.LightId.push_back(light);
    coarse.PatchId.push_back(patch);
  };
  for (int p = 0; p < P; ++p)
  {
    const std::vector<int>& elements = g.PatchElements[p];
    whole[p] = nodes.End(p) - nodes.Begin(p) > 3 && g.PatchOpenArea[p] >= (1 - MaximumHiddenFraction) * g.PatchArea[p];
    if (whole[p])
    {
      Vec3 rho;
      for (int e : elements)
      {
        rho += mesh.Reflectance[e] * (g.Area[e] / g.PatchArea[p]);
      }
      std::vector<Vec3> corners;
      for (int k = nodes.Begin(p); k + 1 < nodes.End(p); ++k)
      {
        corners.push_back(nodes.Node(k));
      }
      add(corners, rho, mesh.LightId[elements[0]], p);
      continue;
    }
    for (int e : elements)
    {
      if (!g.Enclosed[e])
      {
        std::vector<Vec3> corners;
        for (int v = 0; v < mesh.PolygonSize(e); ++v)
        {
          corners.push_back(mesh.Points[mesh.Polygon(e)[v]]);
        }
        add(corners, mesh.Reflectance[e], mesh.LightId[e], p);
      }
    }
  }
  return coarse;
}

/// F[c * P + q]: the form factor from coarse polygon c to patch q (fine ids), with
/// visibility. A row summing above one (a receiver point close to a large patch, where the
/// point rule overestimates) is scaled to one: an enclosure cannot see more than all of it.
std::vector<double> PatchFormFactors(const SceneMesh& coarse, const RadiositySolver& solver, int P,
  const SolverOptions& options, const WorkerPool& pool, std::string& error)
{
  const SceneGeometry& g = solver.Geometry();
  const int n = coarse.NumberOfPolygons();
  ShooterFormFactors factors(coarse, g, solver.Rays(), pool, options.Visibility == EffectMode::Auto);
  const int samples = options.Visibility == EffectMode::Off ? 0 : options.FormFactorSamples;
  std::vector<double> F(static_cast<size_t>(n) * P, 0.0), column(n);
  for (size_t compact = 0; compact < g.PatchElements.size(); ++compact)
  {
    const int q = coarse.PatchId[g.PatchElements[compact][0]];
    factors.Compute(static_cast<int>(compact), options.FormFactorMethod, samples, 0, column);
    for (int c = 0; c < n; ++c)
    {
      // += : the coarse solver may split a patch into pieces (SplitSeparatedPatches, its
      // polygons share no points); the factor to the patch is the sum over its pieces.
      F[static_cast<size_t>(c) * P + q] += g.Enclosed[c] ? 0.0 : column[c];
    }
    if (options.Progress && !options.Progress(0.5 * compact / g.PatchElements.size()))
    {
      error = AbortedMessage;
      return {};
    }
  }
  for (int c = 0; c < n; ++c)
  {
    double* row = &F[static_cast<size_t>(c) * P];
    const double sum = std::accumulate(row, row + P, 0.0);
    for (int q = 0; sum > 1 && q < P; ++q)
    {
      row[q] /= sum;
    }
  }
  return F;
}

/// Inverts M in place (P x P, row-major) by Gauss-Jordan without pivoting: M = I - K with
/// K's rows summing below one is strictly diagonally dominant, so every pivot is positive.
void InvertDominant(std::vector<double>& M, int P, const WorkerPool& pool)
{
  std::vector<double> pivotRow(P);
  for (int k = 0; k < P; ++k)
  {
    double* rowK = &M[static_cast<size_t>(k) * P];
    const double inverse = 1.0 / rowK[k];
    rowK[k] = 1.0;
    for (int j = 0; j < P; ++j)
    {
      rowK[j] *= inverse;
    }
    std::copy(rowK, rowK + P, pivotRow.begin());
    pool.For(P, 16, [&](int begin, int end) {
      for (int i = begin; i < end; ++i)
      {
        double* row = &M[static_cast<size_t>(i) * P];
        const double factor = row[k];
        if (i == k || factor == 0)
        {
          continue;
        }
        row[k] = 0.0;
        for (int j = 0; j < P; ++j)
        {
          row[j] -= factor * pivotRow[j];
        }
      }
    });
  }
}

/// Per patch p and solution q, [p * P + q]: the reflected radiosity on the patch-level
/// scene, solved exactly: with K[p][q] = sum over p's polygons c of (A_c / A_p) rho_c
/// F(c -> q), patch radiosities are B = (I - K)^-1 E, and a unit emitter q gives column q,
/// its own emission removed. One inversion per channel replaces P progressive solves.
std::vector<Vec3> SolvePatchValues(const SceneMesh& coarse, int P, const SolverOptions& options,
  const WorkerPool& pool, SolverStatistics& stats, std::string& error)
{
  RadiositySolver solver(coarse);
  if (!solver.Error().empty())
  {
    error = "patch-level basis: " + solver.Error();
    return {};
  }
  const std::vector<double> F = PatchFormFactors(coarse, solver, P, options, pool, error);
  if (!error.empty())
  {
    stats.Aborted = error == AbortedMessage;
    return {};
  }
  const SceneGeometry& g = solver.Geometry();
  std::vector<double> area(P, 0.0);
  for (int c = 0; c < coarse.NumberOfPolygons(); ++c)
  {
    area[coarse.PatchId[c]] += g.Area[c];
  }
  std::vector<Vec3> values(static_cast<size_t>(P) * P);
  for (int channel = 0; channel < 3; ++channel)
  {
    std::vector<double> M(static_cast<size_t>(P) * P, 0.0);
    for (int c = 0; c < coarse.NumberOfPolygons(); ++c)
    {
      const int p = coarse.PatchId[c];
      const Vec3& rho = coarse.Reflectance[c];
      const double w = (channel == 0 ? rho.x : channel == 1 ? rho.y : rho.z) * g.Area[c] / area[p];
      for (int q = 0; q < P; ++q)
      {
        M[static_cast<size_t>(p) * P + q] -= w * F[static_cast<size_t>(c) * P + q];
      }
    }
    for (int p = 0; p < P; ++p)
    {
      M[static_cast<size_t>(p) * P + p] += 1.0;
    }
    InvertDominant(M, P, pool);
    for (size_t i = 0; i < M.size(); ++i)
    {
      const double reflected = M[i] - (i % (P + 1) == 0 ? 1.0 : 0.0);
      (channel == 0 ? values[i].x : channel == 1 ? values[i].y : values[i].z) = reflected;
    }
    if (options.Progress && !options.Progress(0.5 + (channel + 1) / 6.0))
    {
      stats.Aborted = true;
      error = AbortedMessage;
      return {};
    }
  }
  stats.Shots = P;
  stats.Converged = true;
  stats.FormFactorCount = static_cast<long long>(coarse.NumberOfPolygons()) * P;
  return values;
}

/// For each corner node, the patches whose values it averages (with area weights): the
/// patches with a corner at the same point facing the same way, the node's own included.
std::vector<std::vector<std::pair<int, double>>> CornerNeighbours(const SceneGeometry& g, const PatchNodes& nodes,
  const std::vector<char>& whole)
{
  const int P = static_cast<int>(g.PatchElements.size());
  std::map<std::tuple<double, double, double>, std::vector<int>> at; // corner point -> patches
  for (int p = 0; p < P; ++p)
  {
    for (int k = nodes.Begin(p); whole[p] && k + 1 < nodes.End(p); ++k)
    {
      const Vec3& x = nodes.Node(k);
      at[std::make_tuple(x.x, x.y, x.z)].push_back(p);
    }
  }
  std::vector<std::vector<std::pair<int, double>>> neighbours(nodes.Count());
  for (int p = 0; p < P; ++p)
  {
    const Vec3& normal = g.Normal[g.PatchElements[p][0]];
    for (int k = nodes.Begin(p); whole[p] && k + 1 < nodes.End(p); ++k)
    {
      const Vec3& x = nodes.Node(k);
      for (int other : at[std::make_tuple(x.x, x.y, x.z)])
      {
        if (Dot(g.Normal[g.PatchElements[other][0]], normal) > 0.99)
        {
          neighbours[k].push_back({ other, g.PatchOpenArea[other] });
        }
      }
    }
  }
  return neighbours;
}

/// Node values of every solution: corners average their coplanar neighbours, and the
/// centre takes what keeps the patch's mean (never below zero).
void FillNodeValues(const SceneGeometry& g, const PatchNodes& nodes, const std::vector<char>& whole,
  const std::vector<Vec3>& patchValues, PatchBasis& basis)
{
  const int P = basis.Patches;
  const auto neighbours = CornerNeighbours(g, nodes, whole);
  std::vector<Vec3> node(nodes.Count());
  for (int q = 0; q < P; ++q)
  {
    for (int p = 0; p < P; ++p)
    {
      const Vec3& mean = patchValues[static_cast<size_t>(p) * P + q];
      const int centre = nodes.End(p) - 1;
      double covered = nodes.CoveredArea(centre);
      Vec3 cornerSum;
      for (int k = nodes.Begin(p); k < centre; ++k)
      {
        Vec3 sum;
        double weight = 0;
        for (const auto& [other, area] : neighbours[k])
        {
          sum += patchValues[static_cast<size_t>(other) * P + q] * area;
          weight += area;
        }
        node[k] = weight > 0 ? sum * (1.0 / weight) : mean;
        cornerSum += node[k] * nodes.CoveredArea(k);
        covered += nodes.CoveredArea(k);
      }
      const double own = nodes.CoveredArea(centre);
      const Vec3 rest = mean * covered - cornerSum;
      node[centre] = own > 1e-9 * covered ? rest * (1.0 / own) : mean;
      node[centre] = { std::max(0.0, node[centre].x), std::max(0.0, node[centre].y), std::max(0.0, node[centre].z) };
    }
    for (int k = 0; k < nodes.Count(); ++k)
    {
      Store(node[k], &basis.Values[static_cast<size_t>(k) * 3 * P + 3 * q]);
    }
  }
}

/// Each element's (at most three) nodes and weights: the fan triangle holding its centroid.
void FillElementWeights(const SceneGeometry& g, const PatchNodes& nodes, PatchBasis& basis)
{
  const int n = static_cast<int>(g.Normal.size());
  basis.Node.assign(3 * static_cast<size_t>(n), 0);
  basis.Weight.assign(3 * static_cast<size_t>(n), 0.0f);
  for (int e = 0; e < n; ++e)
  {
    const int p = g.ElementPatch[e];
    const double* w = nodes.Weights(e);
    int used = 0;
    for (int k = nodes.Begin(p); k < nodes.End(p) && used < 3 && !g.Enclosed[e]; ++k)
    {
      if (w[k - nodes.Begin(p)] != 0)
      {
        basis.Node[3 * e + used] = k;
        basis.Weight[3 * e + used] = static_cast<float>(w[k - nodes.Begin(p)]);
        ++used;
      }
    }
  }
}

/// The patch nodes; the outlines they come from are freed before the coarse solve.
PatchNodes NodesOf(const SceneMesh& mesh, const RadiositySolver& solver, const WorkerPool& pool)
{
  const ShooterFormFactors outlines(mesh, solver.Geometry(), solver.Rays(), pool);
  return PatchNodes(solver.Geometry(), outlines.PatchLoops(), outlines.Centres());
}

std::string NodeBasis(const RadiositySolver& solver, const SceneMesh& mesh, const SolverOptions& options,
  SolverStatistics& stats, PatchBasis& basis)
{
  const SceneGeometry& g = solver.Geometry();
  const WorkerPool pool(options.Threads);
  const PatchNodes nodes = NodesOf(mesh, solver, pool);
  basis.Patches = static_cast<int>(g.PatchElements.size());
  basis.Receivers = nodes.Count();
  std::vector<char> whole;
  const SceneMesh coarse = PatchLevelMesh(mesh, g, nodes, whole);
  std::string error;
  const std::vector<Vec3> values = SolvePatchValues(coarse, basis.Patches, options, pool, stats, error);
  if (!error.empty())
  {
    basis = PatchBasis();
    return error;
  }
  basis.Values.resize(static_cast<size_t>(basis.Receivers) * 3 * basis.Patches);
  FillNodeValues(g, nodes, whole, values, basis);
  FillElementWeights(g, nodes, basis);
  return std::string();
}
} // namespace

BasisLevel ResolveBasisLevel(BasisLevel level, long long elements, long long patches)
{
  if (level != BasisLevel::Auto)
  {
    return level;
  }
  return 12.0 * elements * patches <= ElementBasisBudget ? BasisLevel::Elements : BasisLevel::Patches;
}

std::string SolvePatchBasis(const RadiositySolver& solver, const SceneMesh& mesh, const SolverOptions& options,
  BasisLevel level, SolverStatistics& stats, PatchBasis& basis)
{
  basis = PatchBasis();
  const SceneGeometry& g = solver.Geometry();
  const long long n = static_cast<long long>(g.Normal.size()), P = static_cast<long long>(g.PatchElements.size());
  level = ResolveBasisLevel(level, n, P);
  // Nodes: a patch has its corners and centre; 8 per patch bounds the estimate.
  const double bytes = 12.0 * P * (level == BasisLevel::Elements ? n : std::min(n, 8 * P));
  // Its solve holds about as much again; ranks solving together stop together.
  const std::string tooBig = AgreeOnFailure(options.Group, CheckMemory(2 * bytes, "the patch basis"),
    "has too little memory for the patch basis");
  if (!tooBig.empty())
  {
    return tooBig + "; use a larger patch size";
  }
  if (bytes > MaximumBasisBytes)
  {
    char text[256];
    std::snprintf(text, sizeof(text),
      "the patch basis would need about %.1f GB (%lld patches x %lld receivers); use a larger patch size",
      bytes / 1073741824.0, P, level == BasisLevel::Elements ? n : 8 * P);
    return text;
  }
  return level == BasisLevel::Elements ? ElementBasis(solver, options, stats, basis)
                                       : NodeBasis(solver, mesh, options, stats, basis);
}

void AddBasisInterreflection(const SceneGeometry& g, const std::vector<Vec3>& direct, const BasisView& basis,
  const WorkerPool& pool, std::vector<Vec3>& result)
{
  const int n = static_cast<int>(g.Normal.size());
  const int P = basis.Patches;
  // Each patch emits what it reflects directly: the area mean of D over its elements.
  std::vector<Vec3> emission(P);
  for (int e = 0; e < n; ++e)
  {
    const int q = g.ElementPatch[e];
    emission[q] += g.PatchOpenArea[q] > 0 ? direct[e] * (g.Area[e] / g.PatchOpenArea[q]) : Vec3();
  }
  std::vector<Vec3> received(basis.Receivers);
  const size_t stride = 3 * static_cast<size_t>(P);
  pool.For(basis.Receivers, 256, [&](int begin, int end) {
    for (int r = begin; r < end; ++r)
    {
      const float* b = basis.Values + r * stride;
      Vec3 sum;
      for (int q = 0; q < P; ++q)
      {
        sum.x += emission[q].x * b[3 * q + 0];
        sum.y += emission[q].y * b[3 * q + 1];
        sum.z += emission[q].z * b[3 * q + 2];
      }
      received[r] = sum;
    }
  });
  result = direct;
  for (int e = 0; e < n; ++e)
  {
    if (!basis.Node)
    {
      result[e] += received[e];
      continue;
    }
    for (int j = 0; j < 3; ++j)
    {
      result[e] += received[basis.Node[3 * e + j]] * basis.Weight[3 * e + j];
    }
  }
}

void RecordBasisEffect(const PatchBasis& basis, const SolverStatistics& stats, std::vector<EffectDecision>& effects)
{
  char reason[256];
  std::snprintf(reason, sizeof(reason), "simulated: asked for (PatchBasis), %d patches x %d %s, %.1f MB, %d shots",
    basis.Patches, basis.Receivers, basis.Node.empty() ? "elements" : "patch nodes", basis.Bytes() / 1048576.0,
    stats.Shots);
  const EffectDecision row{ "MovingLightBasis", true, reason };
  if (!effects.empty() && effects.back().Effect == row.Effect)
  {
    effects.back() = row;
  }
  else
  {
    effects.push_back(row);
  }
}

} // namespace radiosity
