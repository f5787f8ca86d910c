// The bookkeeping every shooting solver shares: radiosity and unshot energy per solution,
// shooter choice, stopping rules, the energy ledger, the ambient term and the output.
// The solvers differ only in how a shot's energy reaches the receivers.
#ifndef RadiosityCore_ShootingState_h
#define RadiosityCore_ShootingState_h

#include "PatchNodes.h"
#include "RadiositySolver.h"
#include "WorkerPool.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace radiosity
{

/// The solver's arithmetic for an RGB value (Vec3) or a single grey channel (double).
/// A grey scene solved as one channel gives the same numbers with a third of the work.
struct Rgb
{
  using Value = Vec3;
  static Value From(const Vec3& v) { return v; }
  static Vec3 To(const Value& v) { return v; }
  static double Sum(const Value& v) { return v.x + v.y + v.z; }
  static Value Reflect(const Vec3& rho, const Value& u, double f)
  {
    return { rho.x * u.x * f, rho.y * u.y * f, rho.z * u.z * f };
  }
};

struct Grey
{
  using Value = double;
  static Value From(const Vec3& v) { return (v.x + v.y + v.z) / 3.0; }
  static Vec3 To(Value v) { return { v, v, v }; }
  static double Sum(Value v) { return 3.0 * v; } // powers stay comparable with RGB runs
  static Value Reflect(const Vec3& rho, Value u, double f) { return (rho.x + rho.y + rho.z) / 3.0 * u * f; }
};

using SolverClock = std::chrono::steady_clock;

template <typename Channel>
class ShootingState
{
public:
  using Value = typename Channel::Value;

  ShootingState(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& emission,
    int solutions, const SolverOptions& options, SolverClock::time_point start, Solution& out)
    : Mesh(mesh)
    , G(g)
    , L(solutions)
    , Elements(static_cast<int>(g.normal.size()))
    , Patches(static_cast<int>(g.patchElements.size()))
    , Options(options)
    , Start(start)
    , Out(out)
    , Stats(out.Statistics)
    , Direct(options.SeparateDirect)
    , Reflect(options.Interreflection != EffectMode::Off)
    , Shot(solutions)
    , ShotEmission(solutions)
    , Distribute(solutions, 1)
    , Active(solutions, 0)
  {
    Initialize(emission);
  }

  /// Checks the stopping rules in order: converged, shot cap, time, abort.
  bool Continue()
  {
    if (!UpdateActive())
    {
      Stats.Converged = true;
      return false;
    }
    if (Stats.Shots >= Stats.ShotCap)
    {
      return false;
    }
    if (Options.TimeBudget > 0 && Seconds() >= Options.TimeBudget)
    {
      Stats.OutOfTime = true;
      return false;
    }
    if (Options.Progress && !Options.Progress(Fraction()))
    {
      Stats.Aborted = true;
      return false;
    }
    return true;
  }

  /// The patch with the largest unshot power over the solutions still being shot.
  int PickShooter()
  {
    const bool skipConverged = Options.ConvergedSolutions != EffectMode::On;
    for (int m = 0; m < L; ++m)
    {
      Distribute[m] = skipConverged ? Active[m] : 1;
    }
    int shooter = 0;
    double best = -1;
    for (int p = 0; p < Patches; ++p)
    {
      double sum = 0;
      for (int m = 0; m < L; ++m)
      {
        sum += Distribute[m] ? Power(p, m) : 0.0;
      }
      if (sum > best)
      {
        best = sum;
        shooter = p;
      }
    }
    return shooter;
  }

  /// True while the patch still holds emission it has not shot (its first shot).
  bool Emitting(int patch) const { return PendingEmission[patch] != 0; }

  /// Moves the shooter's unshot energy into Shot[] (ShotEmission[] for the direct part).
  void TakeShot(int shooter)
  {
    ShotSum = 0;
    PendingEmission[shooter] = 0;
    for (int m = 0; m < L; ++m)
    {
      const size_t i = Index(shooter, m);
      if (!Distribute[m])
      {
        Shot[m] = Value();
        ShotEmission[m] = Value();
        ++Stats.DistributionsSkipped;
        continue;
      }
      Shot[m] = Unshot[i];
      Unshot[i] = Value();
      ShotSum += Channel::Sum(Shot[m]);
      if (Direct)
      {
        ShotEmission[m] = UnshotEmission[i];
        UnshotEmission[i] = Value();
      }
    }
    Stats.ShotPower += ShotSum * G.patchOpenArea[shooter];
  }

  /// Element e receives the shot through F(e -> shooter) = f. Thread-safe per element.
  void Gather(int e, double f)
  {
    const Vec3& rho = Mesh.reflectance[e];
    for (int m = 0; m < L; ++m)
    {
      Radiosity[Index(e, m)] += Channel::Reflect(rho, Shot[m], f);
      if (Direct)
      {
        DirectPart[Index(e, m)] += Channel::Reflect(rho, ShotEmission[m], f);
      }
    }
  }

  /// What element e reflects of the shot joins its patch's unshot energy. Callers keep
  /// one patch's deposits in one thread, in a fixed order.
  void Deposit(int e, double f)
  {
    if (!Reflect)
    {
      return; // direct light only: what is received is not shot again
    }
    const int p = G.elementPatch[e];
    if (G.patchOpenArea[p] <= 0)
    {
      return;
    }
    const double w = f * G.area[e] / G.patchOpenArea[p];
    for (int m = 0; m < L; ++m)
    {
      Unshot[Index(p, m)] += Channel::Reflect(Mesh.reflectance[e], Shot[m], w);
    }
  }

  /// A whole patch receives the shot: `nodeFactors` are F(node -> shooter) at its nodes,
  /// interpolated over its elements in Finish; `meanFactor` is their area-weighted mean.
  void GatherPatch(int q, const float* nodeFactors, double meanFactor, const Vec3& meanReflectance)
  {
    for (int j = Nodes->Begin(q); j < Nodes->End(q); ++j)
    {
      const double f = nodeFactors[j - Nodes->Begin(q)];
      for (int m = 0; m < L; ++m)
      {
        Gathered[Index(j, m)] += Shot[m] * f;
      }
    }
    if (Reflect)
    {
      for (int m = 0; m < L; ++m)
      {
        Unshot[Index(q, m)] += Channel::Reflect(meanReflectance, Shot[m], meanFactor);
      }
    }
  }

  /// Patch-level gathering needs a buffer per patch node; only the hierarchical solver asks.
  void EnablePatchGathering(const PatchNodes& nodes)
  {
    Nodes = &nodes;
    Gathered.assign(static_cast<size_t>(nodes.Count()) * L, Value());
  }

  /// Ledger and history after a shot; `received` is the power that reached receivers.
  void EndShot(int shooter, double received)
  {
    Stats.ReceivedPower += received;
    Stats.EscapedPower += ShotSum * G.patchOpenArea[shooter] - received;
    std::fill(RemainingPer.begin(), RemainingPer.end(), 0.0);
    for (int p = 0; p < Patches; ++p)
    {
      for (int m = 0; m < L; ++m)
      {
        RemainingPer[m] += Power(p, m);
      }
    }
    double remaining = 0;
    for (int m = 0; m < L; ++m)
    {
      remaining += RemainingPer[m];
      Stats.RemainingPerSolution.push_back(InitialPer[m] > 0 ? RemainingPer[m] / InitialPer[m] : 0.0);
    }
    ++Stats.Shots;
    Stats.UnshotPower = remaining;
    Stats.RemainingHistory.push_back(remaining / Initial);
    Stats.TimeHistory.push_back(Seconds());
  }

  /// Takes the estimator's culling counts, then Finish.
  void Finish(const ShooterFormFactors& estimator)
  {
    Stats.RaysSkipped = estimator.RaysSkipped();
    Stats.PairsUnblockable = estimator.PairsUnblockable();
    Stats.BlockingSurfaces = estimator.BlockingPlanes();
    Finish();
  }

  /// Adds the patch-gathered irradiance, the ambient term, and writes the output.
  void Finish()
  {
    FinishGathered();
    if (Options.AmbientTerm && Reflect)
    {
      AddAmbient();
    }
    Out.Radiosity.resize(Radiosity.size());
    for (int e = 0; e < Elements; ++e)
    {
      const Vec3& rho = Mesh.reflectance[e];
      for (int m = 0; m < L; ++m)
      {
        const Vec3& a = Out.Ambient[m];
        Out.Radiosity[Index(e, m)] = Channel::To(Radiosity[Index(e, m)]) + Vec3{ rho.x * a.x, rho.y * a.y, rho.z * a.z };
      }
    }
    if (Direct)
    {
      Out.Direct.resize(DirectPart.size());
      for (size_t i = 0; i < DirectPart.size(); ++i)
      {
        Out.Direct[i] = Channel::To(DirectPart[i]);
      }
    }
  }

  /// How far the solve is: the larger of the shots against the cap and the unshot energy's
  /// way down to the threshold on a log scale (a converging solve ends far below its cap).
  double Fraction() const
  {
    double done = static_cast<double>(Stats.Shots) / std::max(Stats.ShotCap, 1);
    const double threshold = Options.ConvergenceThreshold;
    if (!Stats.RemainingHistory.empty() && threshold > 0 && threshold < 1 && Stats.RemainingHistory.back() > 0)
    {
      done = std::max(done, std::log(Stats.RemainingHistory.back()) / std::log(threshold));
    }
    return std::min(1.0, std::max(0.0, done));
  }

  double Seconds() const { return std::chrono::duration<double>(SolverClock::now() - Start).count(); }
  size_t Index(int item, int m) const { return static_cast<size_t>(item) * L + m; }
  double ShotTotal() const { return ShotSum; }
  /// The largest fraction of its own emitted power that any solution's shot carries.
  double ShotFraction(int shooter) const
  {
    double most = 0;
    for (int m = 0; m < L; ++m)
    {
      if (InitialPer[m] > 0)
      {
        most = std::max(most, Channel::Sum(Shot[m]) * G.patchOpenArea[shooter] / InitialPer[m]);
      }
    }
    return most;
  }

  const SceneMesh& Mesh;
  const SceneGeometry& G;
  const int L, Elements, Patches;
  const SolverOptions& Options;

private:
  void Initialize(const std::vector<Vec3>& emission)
  {
    Radiosity.assign(static_cast<size_t>(Elements) * L, Value());
    Unshot.assign(static_cast<size_t>(Patches) * L, Value());
    PendingEmission.assign(Patches, 0);
    for (int e = 0; e < Elements; ++e)
    {
      const int p = G.elementPatch[e];
      for (int m = 0; m < L; ++m)
      {
        const Value v = Channel::From(emission[Index(e, m)]);
        Radiosity[Index(e, m)] = v;
        // Unshot radiosity of a patch: its elements' emission spread over its open area.
        if (G.patchOpenArea[p] > 0 && !G.enclosed[e]) // enclosed emission never gets out
        {
          Unshot[Index(p, m)] += v * (G.area[e] / G.patchOpenArea[p]);
        }
        PendingEmission[p] = PendingEmission[p] || Channel::Sum(v) != 0;
      }
    }
    if (Direct)
    {
      DirectPart = Radiosity;
      UnshotEmission = Unshot; // the part of the unshot energy that is still emission
    }
    InitialPer.assign(L, 0.0);
    for (int p = 0; p < Patches; ++p)
    {
      for (int m = 0; m < L; ++m)
      {
        InitialPer[m] += Power(p, m);
      }
    }
    for (double v : InitialPer)
    {
      Initial += v;
    }
    Stats.EmittedPower = Stats.UnshotPower = Initial;
    Stats.ShotCap = ShotCap(Options, Patches);
    RemainingPer = InitialPer;
  }

  double Power(int p, int m) const { return Channel::Sum(Unshot[Index(p, m)]) * G.patchOpenArea[p]; }

  /// A solution is done once its unshot power is below the threshold of its own emission:
  /// then every light is accurate on its own scale, however dim it is.
  bool UpdateActive()
  {
    bool any = false;
    for (int m = 0; m < L; ++m)
    {
      Active[m] = InitialPer[m] > 0 && RemainingPer[m] >= Options.ConvergenceThreshold * InitialPer[m];
      any = any || Active[m];
    }
    return any;
  }

  void FinishGathered()
  {
    if (Gathered.empty())
    {
      return;
    }
    for (int e = 0; e < Elements; ++e)
    {
      const int q = G.elementPatch[e];
      const double* w = Nodes->Weights(e);
      for (int j = Nodes->Begin(q); j < Nodes->End(q); ++j)
      {
        const double weight = w[j - Nodes->Begin(q)];
        for (int m = 0; m < L; ++m)
        {
          Radiosity[Index(e, m)] += Channel::Reflect(Mesh.reflectance[e], Gathered[Index(j, m)], weight);
        }
      }
    }
  }

  /// Cohen et al. 1988: ambient = R * (sum_p U_p A_p) / (sum_p A_p), with the
  /// interreflection factor R = 1 / (1 - mean reflectance) per channel; each element
  /// shows rho * ambient on top of what it received.
  void AddAmbient()
  {
    Vec3 meanRho;
    double area = 0;
    for (int e = 0; e < Elements; ++e)
    {
      meanRho += Mesh.reflectance[e] * G.area[e];
      area += G.area[e];
    }
    meanRho = meanRho * (1.0 / area);
    Vec3 interreflection;
    for (int c = 0; c < 3; ++c)
    {
      // Capped: a closed scene of perfect reflectors has no finite ambient.
      interreflection[c] = 1.0 / std::max(1.0 - meanRho[c], 1e-6);
    }
    for (int m = 0; m < L; ++m)
    {
      Vec3 unshotPower;
      for (int p = 0; p < Patches; ++p)
      {
        unshotPower += Channel::To(Unshot[Index(p, m)]) * G.patchOpenArea[p];
      }
      const Vec3 a = unshotPower * (1.0 / area);
      Out.Ambient[m] = { interreflection.x * a.x, interreflection.y * a.y, interreflection.z * a.z };
    }
  }

  SolverClock::time_point Start;
  Solution& Out;
  SolverStatistics& Stats;
  const bool Direct, Reflect;
  std::vector<Value> Radiosity, DirectPart, Unshot, UnshotEmission, Gathered;
  std::vector<Value> Shot, ShotEmission;
  std::vector<char> Distribute, Active, PendingEmission;
  std::vector<double> InitialPer, RemainingPer;
  double Initial = 0, ShotSum = 0;
  const PatchNodes* Nodes = nullptr;
};

/// Calls body(Grey()) for a single grey channel, body(Rgb()) otherwise: the solver methods
/// are templates on the channel type.
template <typename Body>
void WithChannel(bool grey, const Body& body)
{
  if (grey)
  {
    body(Grey());
  }
  else
  {
    body(Rgb());
  }
}

/// Every element receives the shot through factors[e] = F(e -> shooter); returns the
/// power that arrived. Radiosity is updated in parallel, patch sums in element order.
template <typename Channel>
double DistributeToElements(ShootingState<Channel>& state, const WorkerPool& pool, const std::vector<double>& factors)
{
  pool.For(state.Elements, 512, [&](int begin, int end) {
    for (int e = begin; e < end; ++e)
    {
      if (factors[e] > 0)
      {
        state.Gather(e, factors[e]);
      }
    }
  });
  double received = 0;
  for (int e = 0; e < state.Elements; ++e)
  {
    if (factors[e] > 0)
    {
      received += state.ShotTotal() * factors[e] * state.G.area[e];
      state.Deposit(e, factors[e]);
    }
  }
  return received;
}

/// One shot from `shooter` to every element (TakeShot done): factors with their rays,
/// scaled so the shot delivers no more power than it has (exactly that in a closed scene),
/// then distributed to all solutions and booked.
template <typename Channel>
void ShootToElements(ShootingState<Channel>& state, const WorkerPool& pool, ShooterFormFactors& estimator,
  int shooter, FormFactorMethod method, int samples, SolverStatistics& stats, std::vector<double>& factors)
{
  factors.resize(state.Elements);
  // The expensive part, done once per shot whatever the number of solutions.
  stats.RayCount += estimator.Compute(shooter, method, samples, stats.Shots, factors);
  stats.FormFactorCount += state.Elements;
  estimator.Conserve(shooter, factors);
  state.EndShot(shooter, DistributeToElements(state, pool, factors));
}

} // namespace radiosity

#endif
