#include "Solve/ClusteredRadiosity.h"
#include "Solve/AmbientTerm.h"
#include "Solve/Channels.h"
#include "Solve/ClusterGather.h"
#include "Solve/ConjugateBounces.h"
#include "Solve/ElementTree.h"
#include "Solve/RankTable.h"
#include "Base/Memory.h"
#include "Base/WorkerPool.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

namespace radiosity
{

namespace
{
using Clock = std::chrono::steady_clock;

double NonNegative(double v)
{
  return std::max(0.0, v);
}

Vec3 NonNegative(const Vec3& v)
{
  return { std::max(0.0, v.x), std::max(0.0, v.y), std::max(0.0, v.z) };
}

template <typename Channel>
class Gathering
{
public:
  using Value = typename Channel::Value;

  Gathering(const SceneMesh& mesh, const SceneGeometry& g, const Visibility& rays, const std::vector<Vec3>& emission,
    int solutions, const SolverOptions& options, Clock::time_point start, Solution& out)
    : Mesh(mesh)
    , G(g)
    , Rays(rays)
    , L(solutions)
    , N(static_cast<int>(g.Normal.size()))
    , P(static_cast<int>(g.PatchElements.size()))
    , Options(options)
    , Start(start)
    , Out(out)
    , Stats(out.Statistics)
    , Pool(options.Threads)
    , Group(options.Group)
    , Owned(OwnedPatches(g, Group.Rank(), Group.Ranks()))
    , Reflect(options.Interreflection != EffectMode::Off)
  {
    Initialize(emission);
  }

  void Run()
  {
    ShooterFormFactors estimator(Mesh, G, Rays, Pool, Options.Visibility == EffectMode::Auto);
    estimator.SetReceivers(&Owned);
    ShootEmitters(estimator);
    if (Reflect && !Stopped && AnyActive())
    {
      Interreflect(estimator);
    }
    Stats.Converged = !AnyActive();
    Finish(estimator);
  }

private:
  size_t At(int item, int m) const { return static_cast<size_t>(item) * L + m; }
  double Seconds() const { return std::chrono::duration<double>(Clock::now() - Start).count(); }

  void Initialize(const std::vector<Vec3>& emission)
  {
    Radiosity.assign(static_cast<size_t>(N) * L, Value());
    Last.assign(Radiosity.size(), Value());
    Unshot.assign(static_cast<size_t>(P) * L, Value());
    std::vector<double> reflected(L, 0.0);
    for (int e = 0; e < N; ++e)
    {
      const int p = G.ElementPatch[e];
      for (int m = 0; m < L; ++m)
      {
        const Value v = Channel::From(emission[At(e, m)]), r = ReflectedAt(e, m);
        // The reflected part waits in Last (each rank its own elements', summed after the
        // shots), to be added to the radiosity with the shots' reflected light.
        Radiosity[At(e, m)] = v - r;
        Last[At(e, m)] = Owned[p] ? r : Value();
        reflected[m] += Channel::Sum(r) * G.Area[e];
        if (G.PatchOpenArea[p] > 0 && !G.Enclosed[e]) // enclosed emission never gets out
        {
          Unshot[At(p, m)] += (v - r) * (G.Area[e] / G.PatchOpenArea[p]);
        }
      }
    }
    InitialPer.assign(L, 0.0);
    std::vector<double> power(P, 0.0);
    for (int p = 0; p < P; ++p)
    {
      for (int m = 0; m < L; ++m)
      {
        const double w = Channel::Sum(Unshot[At(p, m)]) * G.PatchOpenArea[p];
        InitialPer[m] += w;
        power[p] += w;
      }
      if (power[p] != 0)
      {
        Emitters.push_back(p);
      }
    }
    // The brightest first, as the shooting methods do: a stopped solve has the most light.
    std::stable_sort(Emitters.begin(), Emitters.end(), [&](int a, int b) { return power[a] > power[b]; });
    PendingPer = RemainingPer = InitialPer;
    for (int m = 0; m < L; ++m)
    {
      InitialPer[m] += reflected[m];
      RemainingPer[m] += reflected[m];
    }
    Initial = std::accumulate(InitialPer.begin(), InitialPer.end(), 0.0);
    Stats.EmittedPower = Stats.UnshotPower = Initial;
    Stats.ShotCap = ShotCap(Options, P);
    ReceiverScale.assign(N, 1.0);
  }

  /// Light of the start already reflected once: sent along the links, not shot (where the
  /// interreflection runs and the element can exchange light; elsewhere it is emission).
  Value ReflectedAt(int e, int m) const
  {
    const std::vector<Vec3>* r = Options.ReflectedStart;
    return r && Reflect && !G.Enclosed[e] && r->size() == Radiosity.size() ? Channel::From((*r)[At(e, m)]) : Value();
  }

  bool AnyActive() const
  {
    for (int m = 0; m < L; ++m)
    {
      if (InitialPer[m] > 0 && RemainingPer[m] >= Options.ConvergenceThreshold * InitialPer[m])
      {
        return true;
      }
    }
    return false;
  }

  /// The stopping rules every rank applies together: the shot cap, the time budget, abort.
  bool KeepGoing(double fraction)
  {
    if (Stopped || Stats.Shots >= Stats.ShotCap)
    {
      return false;
    }
    double flags[2] = { Options.TimeBudget > 0 && Seconds() >= Options.TimeBudget ? 1.0 : 0.0, 0.0 };
    flags[1] = flags[0] == 0 && Options.Progress && !Options.Progress(std::min(1.0, std::max(0.0, fraction))) ? 1.0 : 0.0;
    Group.Sum(flags, 2);
    Stats.OutOfTime = flags[0] > 0;
    Stats.Aborted = !Stats.OutOfTime && flags[1] > 0;
    Stopped = Stats.OutOfTime || Stats.Aborted;
    return !Stopped;
  }

  /// Whether the links still fit, from what the first `done` of the build holds (`held`
  /// bytes on this rank): every rank agrees, and a build that would not fit stops with the
  /// direct light and says why.
  bool LinksFit(double done, double held, double sums, double points)
  {
    std::string problem;
    if (done >= 0.1) // the first tasks say too little of the rest
    {
      const double all = held / done, sorted = all * ClusterLinkBuilder::kSortedBytes / ClusterLinkBuilder::kFoundBytes;
      // The most held at once: the links found and sorted beside the build's ray ends, or
      // sorted beside the sums. Against a limit: all of it; against the free memory: what
      // is still to come.
      const double most = std::max(all + sorted + points, sorted + sums);
      problem = CheckMemory(Options.Clustered.MemoryLimit > 0 ? most : most - held - points,
        sums > all ? "the clustered method's links and sums" : "the clustered method's links", Options.Clustered.MemoryLimit);
    }
    return EveryRankFits(problem, "another rank's links would not fit in its memory");
  }

  /// The bytes of the gathering's sums per tree node and the solve's vectors (8 lights in
  /// RGB on a million elements: about 3 GB), known before the links are found.
  double SumsBytes(const ElementTree& tree) const
  {
    const double lanes = static_cast<double>(L) * Channel::Doubles;
    const double perNode = ClusterGather<Value>::BytesPerNode(lanes);
    const double perElement = 7 * lanes * sizeof(double); // near sums, gathered, the solve's four, its scratch
    return static_cast<double>(tree.Nodes().size()) * perNode + static_cast<double>(N) * perElement;
  }

  /// Every rank agrees: where one has a `problem`, the solve stops with the direct light
  /// and says why.
  bool EveryRankFits(const std::string& problem, const std::string& elsewhere)
  {
    double ranksShort = problem.empty() ? 0.0 : 1.0;
    Group.Sum(&ranksShort, 1);
    if (ranksShort > 0)
    {
      Stats.OutOfMemory = problem.empty() ? elsewhere : problem;
      Stopped = true;
    }
    return !Stopped;
  }

  /// Progress through the iterations: the remaining power's way down to the threshold.
  double IterationFraction() const
  {
    const double threshold = Options.ConvergenceThreshold;
    const double left = Initial > 0 ? Stats.UnshotPower / Initial : 0.0;
    if (threshold <= 0 || threshold >= 1 || left <= 0)
    {
      return 0.7;
    }
    return 0.7 + 0.3 * std::min(1.0, std::max(0.0, std::log(left) / std::log(threshold)));
  }

  /// Each emitter's direct light to every element, with its own shadow rays.
  void ShootEmitters(ShooterFormFactors& estimator)
  {
    const StepTimer timer(Stats, "direct light");
    const int samples = Options.Visibility == EffectMode::Off ? 0 : Options.FormFactorSamples;
    std::vector<double> factors(N);
    for (size_t i = 0; i < Emitters.size(); ++i)
    {
      if (!KeepGoing(0.2 * i / Emitters.size()))
      {
        break;
      }
      const int p = Emitters[i];
      Stats.RayCount += estimator.Compute(p, FormFactorMethod::Analytic, samples, Stats.Shots, factors);
      Stats.FormFactorCount += N;
      double receiving = 0;
      for (int e = 0; e < N; ++e)
      {
        factors[e] = Owned[G.ElementPatch[e]] ? factors[e] : 0.0;
        receiving += factors[e] * G.Area[e];
      }
      Group.Sum(&receiving, 1);
      const double scale = estimator.ConservationScale(p, receiving);
      Pool.For(N, 512, [&](int begin, int end) {
        for (int e = begin; e < end; ++e)
        {
          for (int m = 0; m < L && factors[e] > 0; ++m)
          {
            Last[At(e, m)] += Channel::Reflect(Mesh.Reflectance[e], Unshot[At(p, m)], factors[e] * scale);
          }
        }
      });
      double shot = 0;
      for (int m = 0; m < L; ++m)
      {
        const double power = Channel::Sum(Unshot[At(p, m)]) * G.PatchOpenArea[p];
        PendingPer[m] -= power;
        shot += power;
        Unshot[At(p, m)] = Value();
      }
      Record(shot, shot / std::max(G.PatchOpenArea[p], 1e-300) * receiving * scale, false);
    }
    if (Group.Distributed())
    {
      SumOverRanks(Last); // each rank received for its own elements
    }
    for (size_t i = 0; i < Radiosity.size(); ++i)
    {
      Radiosity[i] += Last[i];
    }
    if (Options.SeparateDirect)
    {
      DirectPart = Radiosity;
    }
    UpdateRemaining(true);
  }

  void Interreflect(ShooterFormFactors& estimator)
  {
    auto linking = std::make_unique<StepTimer>(Stats, "links"); // the tree and the gather's sums too
    const ElementTree tree(Mesh, G);
    ClusterLinkSet links;
    if (!Link(tree, estimator, links))
    {
      return; // stopped before or while linking: the direct light stands, the rest stays unshot
    }
    Normalize(tree, links, estimator);
    ClusterGather<Value> gather(G, tree, links, Pool);
    linking.reset();
    if (KeepGoing(IterationFraction()))
    {
      SolveAlong(gather);
    }
  }

  /// The links, when they and the sums beside them fit (said before any link is found
  /// where the sums alone do not) and nothing stopped the build.
  bool Link(const ElementTree& tree, const ShooterFormFactors& estimator, ClusterLinkSet& links)
  {
    const double sums = SumsBytes(tree);
    if (!EveryRankFits(CheckMemory(sums, "the clustered method's sums", Options.Clustered.MemoryLimit),
          "another rank's sums would not fit in its memory"))
    {
      return false;
    }
    ClusterLinkOptions options;
    options.Samples = Options.Visibility == EffectMode::Off ? 0 : Options.FormFactorSamples;
    options.Separation = Options.Clustered.Separation;
    options.MixedSeparation = 1.5 * Options.Clustered.Separation;
    ClusterLinkBuilder builder(Mesh, G, tree, Rays, estimator, options);
    const double points = ClusterLinkBuilder::PointBytes(tree);
    links = builder.Build(Pool, Group.Rank(), Group.Ranks(),
      [&](double f, double held) { return KeepGoing(0.2 + 0.5 * f) && LinksFit(f, held, sums, points); });
    Stats.RayCount += links.Rays;
    Stats.VolumeLinks += static_cast<long long>(links.FarCount());
    Stats.ElementLinks += static_cast<long long>(links.NearCount());
    Stats.LinkBytes += links.Bytes();
    return links.Complete;
  }

  /// The interreflection from the reflected direct light (Last), step by step until what
  /// one more bounce would add is below the threshold or the solve is stopped.
  void SolveAlong(ClusterGather<Value>& gather)
  {
    const StepTimer timer(Stats, "bounces");
    std::vector<Value> sent;
    Gather(gather, Last, sent);
    ConjugateBounces<Value> solve(G.Area, Weights(), L, static_cast<int>(Channel::Doubles));
    solve.Start(Last, sent);
    Row(solve.Increment());
    while (AnyActive() && KeepGoing(IterationFraction()))
    {
      Gather(gather, solve.Direction(), sent);
      solve.Step(sent);
      Row(solve.Increment());
    }
    Settle(solve);
  }

  /// What every element receives from `sending` along the links (all ranks' shares).
  void Gather(ClusterGather<Value>& gather, const std::vector<Value>& sending, std::vector<Value>& received)
  {
    gather.Scatter(sending, L);
    if (Group.Distributed())
    {
      gather.SumOverRanks(Group);
    }
    gather.Collect(L, received);
  }

  /// Per element and channel: the reflectance times the receiver scale.
  std::vector<double> Weights() const
  {
    const size_t channels = Channel::Doubles;
    std::vector<double> w(static_cast<size_t>(N) * channels);
    for (int e = 0; e < N; ++e)
    {
      const Value rho = Channel::Reflect(Mesh.Reflectance[e], Channel::From({ 1, 1, 1 }), ReceiverScale[e]);
      Channel::Store(rho, w.data() + e * channels);
    }
    return w;
  }

  /// A history row for one iteration: what is left is what one more bounce would add.
  void Row(const std::vector<Value>& increment)
  {
    for (int m = 0; m < L; ++m)
    {
      double left = 0;
      for (int e = 0; e < N; ++e)
      {
        left += Channel::Sum(Magnitude(increment[At(e, m)])) * G.Area[e];
      }
      RemainingPer[m] = PendingPer[m] + left;
    }
    Record(0, 0, true);
  }

  static double Magnitude(double v) { return std::abs(v); }
  static Vec3 Magnitude(const Vec3& v) { return { std::abs(v.x), std::abs(v.y), std::abs(v.z) }; }

  /// The radiosity from the solve: the reflected direct light plus what the links bring to
  /// the solution. The ledger: the solution was shot along the links; what one more bounce
  /// would add is left to travel; light added where the series would make radiosity negative
  /// is booked as received (the method makes it), not as left to travel, which it does not
  /// become by iterating.
  void Settle(const ConjugateBounces<Value>& solve)
  {
    double shot = 0, received = 0;
    for (int e = 0; e < N; ++e)
    {
      const Vec3& rho = Mesh.Reflectance[e];
      for (int m = 0; m < L; ++m)
      {
        const size_t i = At(e, m);
        const Value h = solve.Sent()[i] * ReceiverScale[e];
        const Value kept = Receivable(rho, Last[i], h);
        const Value added = Channel::Reflect(rho, kept - h, 1.0);
        const Value reflected = Last[i] + Channel::Reflect(rho, kept, 1.0);
        shot += Channel::Sum(solve.Solution()[i]) * G.Area[e];
        received += Channel::Sum(kept - added) * G.Area[e];
        Radiosity[i] += reflected - Last[i];
        Last[i] = reflected - added - solve.Solution()[i];
      }
    }
    Stats.ShotPower += shot;
    Stats.ReceivedPower += received;
    Stats.EscapedPower += shot - received;
    // The ledger takes the remainder with its signs (it closes exactly so); convergence and
    // the table keep its magnitude from the last row, so a stopped solve whose remainder
    // cancels out is not called converged.
    const std::vector<double> magnitude = RemainingPer;
    UpdateRemaining(true);
    Stats.UnshotPower = std::accumulate(RemainingPer.begin(), RemainingPer.end(), 0.0);
    RemainingPer = magnitude;
  }

  /// What the links bring (h), cut where the clamped cosine's series, which dips below zero
  /// near grazing, would take more than the direct light gave: no radiosity turns negative.
  static Value Receivable(const Vec3& rho, const Value& direct, const Value& h)
  {
    double d[3], r[3], out[3];
    Channel::Store(direct, d);
    Channel::Store(h, out);
    Channel::Store(Channel::Reflect(rho, Channel::From({ 1, 1, 1 }), 1.0), r);
    for (size_t c = 0; c < Channel::Doubles; ++c)
    {
      out[c] = std::max(out[c], r[c] > 0 ? -d[c] / r[c] : 0.0);
    }
    return Channel::Load(out);
  }

  /// Per element, the factor that makes what it gathers from a uniformly bright closed
  /// scene its full view (where its patch sees a closed scene; elsewhere only an excess is
  /// cut): the far-field factors of the cluster links and the point rule near a source do
  /// not sum to one on their own. A closed furnace then stays uniform.
  void Normalize(const ElementTree& tree, const ClusterLinkSet& links, ShooterFormFactors& estimator)
  {
    ClusterGather<double> unit(G, tree, links, Pool);
    unit.Scatter(std::vector<double>(N, 1.0), 1);
    unit.SumOverRanks(Group);
    std::vector<double> seen;
    unit.Collect(1, seen);
    for (int e = 0; e < N; ++e)
    {
      if (seen[e] > 1 || (seen[e] > 0 && estimator.ViewIsClosed(G.ElementPatch[e])))
      {
        ReceiverScale[e] = 1 / seen[e];
      }
    }
  }

  /// RemainingPer: emitters not yet shot, and the last bounce where it is still to travel.
  void UpdateRemaining(bool shared)
  {
    std::vector<double> last(L, 0.0);
    for (int e = 0; e < N && Reflect; ++e)
    {
      for (int m = 0; m < L && (shared || Owned[G.ElementPatch[e]]); ++m)
      {
        last[m] += Channel::Sum(Last[At(e, m)]) * G.Area[e];
      }
    }
    if (!shared)
    {
      Group.Sum(last);
    }
    for (int m = 0; m < L; ++m)
    {
      RemainingPer[m] = PendingPer[m] + last[m];
    }
  }

  /// The ledger and the histories after a shot or a bounce.
  void Record(double shot, double received, bool updated)
  {
    if (!updated)
    {
      UpdateRemaining(false);
    }
    ++Stats.Shots;
    Stats.ShotPower += shot;
    Stats.ReceivedPower += received;
    Stats.EscapedPower += shot - received;
    double remaining = 0;
    for (int m = 0; m < L; ++m)
    {
      remaining += RemainingPer[m];
      Stats.RemainingPerSolution.push_back(InitialPer[m] > 0 ? RemainingPer[m] / InitialPer[m] : 0.0);
    }
    Stats.UnshotPower = remaining;
    Stats.RemainingHistory.push_back(Initial > 0 ? remaining / Initial : 0.0);
    Stats.TimeHistory.push_back(Seconds());
  }

  void SumOverRanks(std::vector<Value>& values)
  {
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is summed as three doubles");
    Group.Sum(reinterpret_cast<double*>(values.data()), values.size() * Channel::Doubles);
  }

  /// The ambient term, then the output: each rank writes its own elements (the sum over
  /// the ranks gives every rank the whole).
  void Finish(const ShooterFormFactors& estimator)
  {
    Stats.RaysSkipped = estimator.RaysSkipped();
    Stats.PairsUnblockable = estimator.PairsUnblockable();
    Stats.BlockingSurfaces = estimator.BlockingPlanes();
    if (Reflect && AddsAmbient(Options, Stats))
    {
      AddAmbient();
    }
    Out.Radiosity.assign(Radiosity.size(), Vec3());
    if (Options.SeparateDirect)
    {
      Out.Direct.assign(Radiosity.size(), Vec3());
    }
    for (int e = 0; e < N; ++e)
    {
      const Vec3& rho = Mesh.Reflectance[e];
      for (int m = 0; m < L && Owned[G.ElementPatch[e]]; ++m)
      {
        const Vec3& a = Out.Ambient[m];
        Out.Radiosity[At(e, m)] = Channel::To(Radiosity[At(e, m)]) + Vec3{ rho.x * a.x, rho.y * a.y, rho.z * a.z };
        if (Options.SeparateDirect)
        {
          Out.Direct[At(e, m)] = Channel::To(DirectPart.empty() ? Radiosity[At(e, m)] : DirectPart[At(e, m)]);
        }
      }
      Stats.ReceivingElements += Owned[G.ElementPatch[e]] ? 1 : 0;
    }
    Stats.OwnRays = Stats.RayCount;
    if (Group.Distributed())
    {
      GatherOverRanks(Group, Out);
    }
  }

  /// Cohen et al. 1988, as the shooting methods add it: what is left to travel, spread
  /// evenly and interreflected in closed form.
  void AddAmbient()
  {
    const AmbientTerm ambient(Mesh, G, N);
    for (int m = 0; m < L; ++m)
    {
      Vec3 left;
      for (int p = 0; p < P; ++p)
      {
        left += Channel::To(Unshot[At(p, m)]) * G.PatchOpenArea[p];
      }
      for (int e = 0; e < N; ++e)
      {
        left += Channel::To(Last[At(e, m)]) * G.Area[e];
      }
      Out.Ambient[m] = ambient.Of(NonNegative(left)); // the remainder of a solve can overshoot a little
    }
  }

  const SceneMesh& Mesh;
  const SceneGeometry& G;
  const Visibility& Rays;
  const int L, N, P;
  const SolverOptions& Options;
  Clock::time_point Start;
  Solution& Out;
  SolverStatistics& Stats;
  WorkerPool Pool;
  Collective Group;
  std::vector<char> Owned;
  const bool Reflect;
  bool Stopped = false;
  /// Per element and solution: the radiosity so far, the last bounce (still to travel),
  /// and the direct part; per patch, the emission not yet shot.
  std::vector<Value> Radiosity, Last, DirectPart, Unshot;
  std::vector<int> Emitters;
  std::vector<double> InitialPer, PendingPer, RemainingPer, ReceiverScale;
  double Initial = 0;
};
} // namespace

void SolveClustered(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, int solutions, bool grey, const SolverOptions& options,
  Clock::time_point start, Solution& out)
{
  out.Statistics.SolverMethod = SolverMethod::Clustered;
  WithChannel(grey, [&](auto channel) {
    Gathering<decltype(channel)> gathering(mesh, geometry, rays, emission, solutions, options, start, out);
    gathering.Run();
  });
}

} // namespace radiosity
