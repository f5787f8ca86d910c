// The bookkeeping every shooting solver shares: radiosity and unshot energy per solution,
// shooter choice, stopping rules, the energy ledger, the ambient term and the output.
// The solvers differ only in how a shot's energy reaches the receivers.
#ifndef RadiosityCore_ShootingState_h
#define RadiosityCore_ShootingState_h

#include "Geometry/PatchNodes.h"
#include "Solve/RadiositySolver.h"
#include "Solve/AmbientTerm.h"
#include "Solve/Channels.h"
#include "Solve/RankTable.h"
#include "Solve/ReceiverNodes.h"
#include "Base/WorkerPool.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace radiosity
{

using SolverClock = std::chrono::steady_clock;

template <typename Channel>
class ShootingState
{
public:
  using Value = typename Channel::Value;

  ShootingState(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<Vec3>& emission,
    int solutions, const SolverOptions& options, SolverClock::time_point start, Solution& out)
    : Mesh(mesh)
    , Geometry(g)
    , Solutions(solutions)
    , Elements(static_cast<int>(g.Normal.size()))
    , Patches(static_cast<int>(g.PatchElements.size()))
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
    , Group(options.Group)
    , Owned(OwnedPatches(g, Group.Rank(), Group.Ranks()))
  {
    Initialize(emission);
  }

  /// True for the elements (of the patches) this process receives for; all of them unless
  /// several processes solve together.
  bool OwnsElement(int e) const { return Owned[Geometry.ElementPatch[e]] != 0; }
  int OwnedElements() const { return OwnedElementCount; }
  const std::vector<char>& OwnedPatchFlags() const { return Owned; }
  /// The processes solving together (one, where its sums do nothing).
  Collective& Ranks() { return Group; }

  /// Checks the stopping rules in order (converged, shot cap, time, abort) and picks the
  /// next shooter: the patch with the largest unshot power over the solutions still being
  /// shot. Several ranks decide both with one sum: out of time or aborted on any rank
  /// stops all at the same shot.
  bool Continue()
  {
    if (Group.Distributed())
    {
      return ContinueTogether();
    }
    if (!UpdateActive())
    {
      Stats.Converged = true;
      return false;
    }
    if (Stats.Shots >= Stats.ShotCap)
    {
      return false;
    }
    const bool outOfTime = Options.TimeBudget > 0 && Seconds() >= Options.TimeBudget;
    const bool abort = !outOfTime && Options.Progress && !Options.Progress(Fraction());
    double best = -1;
    Next = std::max(BestOwnedPatch(best), 0);
    Stats.OutOfTime = outOfTime;
    Stats.Aborted = abort;
    return !Stats.OutOfTime && !Stats.Aborted;
  }

  /// The shooter Continue picked.
  int PickShooter() const { return Next; }

  /// True while the patch still holds emission it has not shot (its first shot).
  bool Emitting(int patch) const { return PendingEmission[patch] != 0; }

  /// Moves the shooter's unshot energy into Shot[] (ShotEmission[] for the direct part).
  void TakeShot(int shooter)
  {
    ShotSum = 0;
    PendingEmission[shooter] = 0;
    for (int m = 0; m < Solutions; ++m)
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
    Stats.ShotPower += ShotSum * Geometry.PatchOpenArea[shooter];
  }

  /// Element e receives the shot through F(e -> shooter) = f. Thread-safe per element.
  void Gather(int e, double f)
  {
    const Vec3& rho = Mesh.Reflectance[e];
    for (int m = 0; m < Solutions; ++m)
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
    const int p = Geometry.ElementPatch[e];
    if (Geometry.PatchOpenArea[p] <= 0)
    {
      return;
    }
    const double w = f * Geometry.Area[e] / Geometry.PatchOpenArea[p];
    for (int m = 0; m < Solutions; ++m)
    {
      Unshot[Index(p, m)] += Channel::Reflect(Mesh.Reflectance[e], Shot[m], w);
    }
  }

  /// A whole patch receives the shot: `nodeFactors` are F(node -> shooter) at its nodes,
  /// interpolated over its elements in Finish; `meanFactor` is their area-weighted mean.
  void GatherPatch(int q, const float* nodeFactors, double meanFactor, const Vec3& meanReflectance)
  {
    for (int j = Nodes->Begin(q); j < Nodes->End(q); ++j)
    {
      const double f = nodeFactors[j - Nodes->Begin(q)];
      for (int m = 0; m < Solutions; ++m)
      {
        Gathered[Index(j, m)] += Shot[m] * f;
      }
    }
    if (Reflect)
    {
      for (int m = 0; m < Solutions; ++m)
      {
        Unshot[Index(q, m)] += Channel::Reflect(meanReflectance, Shot[m], meanFactor);
      }
    }
  }

  /// A whole patch receives the shot with one factor at all of its nodes (a part of a far
  /// volume link, where the factor does not vary across a patch).
  void GatherPatchUniform(int q, double factor, double meanFactor, const Vec3& meanReflectance)
  {
    for (int j = Nodes->Begin(q); j < Nodes->End(q); ++j)
    {
      for (int m = 0; m < Solutions; ++m)
      {
        Gathered[Index(j, m)] += Shot[m] * factor;
      }
    }
    if (Reflect)
    {
      for (int m = 0; m < Solutions; ++m)
      {
        Unshot[Index(q, m)] += Channel::Reflect(meanReflectance, Shot[m], meanFactor);
      }
    }
  }

  /// A face cluster's node (ReceiverNodes) receives the shot as a whole: F(e -> shooter) =
  /// n_e . v for each of its open elements, applied in Finish; what they reflect joins the
  /// cluster's unshot energy now. Callers keep one cluster's nodes in one thread.
  void GatherCluster(int node, const Vec3& v)
  {
    for (int m = 0; m < Solutions; ++m)
    {
      for (int k = 0; k < 3; ++k)
      {
        ClusterGathered[3 * Index(node, m) + k] += Shot[m] * v[k];
      }
    }
    const int q = Clusters->Patch[node];
    if (!Reflect || Geometry.PatchOpenArea[q] <= 0)
    {
      return;
    }
    const Vec3* r = ClusterReflectance.data() + 3 * static_cast<size_t>(node);
    const Vec3 reflected = Vec3{ Dot(r[0], v), Dot(r[1], v), Dot(r[2], v) } * (1.0 / Geometry.PatchOpenArea[q]);
    for (int m = 0; m < Solutions; ++m)
    {
      Unshot[Index(q, m)] += Channel::Reflect(reflected, Shot[m], 1.0);
    }
  }

  /// Cluster gathering needs three values per node and solution; only the hierarchical
  /// solver asks. Per node and channel, the sum of reflectance x area x normal of its open
  /// elements.
  void EnableClusterGathering(const ReceiverNodes& nodes)
  {
    Clusters = &nodes;
    ClusterGathered.assign(3 * static_cast<size_t>(nodes.Count()) * Solutions, Value());
    ClusterReflectance.assign(3 * static_cast<size_t>(nodes.Count()), Vec3());
    for (int n = 0; n < nodes.Count(); ++n)
    {
      for (int i = nodes.ElementBegin[n]; i < nodes.ElementEnd[n]; ++i)
      {
        const int e = nodes.Elements[i];
        for (int c = 0; c < 3 && !Geometry.Sheltered[e]; ++c)
        {
          ClusterReflectance[3 * static_cast<size_t>(n) + c] += Geometry.Normal[e] * (Geometry.Area[e] * Mesh.Reflectance[e][c]);
        }
      }
    }
  }

  /// Patch-level gathering needs a buffer per patch node; only the hierarchical solver asks.
  void EnablePatchGathering(const PatchNodes& nodes)
  {
    Nodes = &nodes;
    Gathered.assign(static_cast<size_t>(nodes.Count()) * Solutions, Value());
  }

  /// Ledger and history after a shot; `received` is the power that reached receivers.
  void EndShot(int shooter, double received)
  {
    Pending = { true, ShotSum * Geometry.PatchOpenArea[shooter], received, Seconds() };
    ++Stats.Shots;
    OwnedRemaining();
    if (!Group.Distributed())
    {
      RecordShot(); // several ranks record it after the next sum, which brings their parts
    }
  }

  /// The ledger and the history of the last shot, once RemainingPer and Pending.Received
  /// hold the whole scene's.
  void RecordShot()
  {
    Pending.Open = false;
    double remaining = 0;
    for (int m = 0; m < Solutions; ++m)
    {
      remaining += RemainingPer[m];
      Stats.RemainingPerSolution.push_back(InitialPer[m] > 0 ? RemainingPer[m] / InitialPer[m] : 0.0);
    }
    Stats.ReceivedPower += Pending.Received;
    Stats.EscapedPower += Pending.Shot - Pending.Received;
    Stats.UnshotPower = remaining;
    Stats.RemainingHistory.push_back(remaining / Initial);
    Stats.TimeHistory.push_back(Pending.Seconds);
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
    if (Reflect && AddsAmbient(Options, Stats))
    {
      AddAmbient();
    }
    // Each rank writes its own receivers, zero elsewhere; the sum gives every rank the whole.
    Out.Radiosity.assign(Radiosity.size(), Vec3());
    for (int e = 0; e < Elements; ++e)
    {
      const Vec3& rho = Mesh.Reflectance[e];
      for (int m = 0; m < Solutions && OwnsElement(e); ++m)
      {
        const Vec3& a = Out.Ambient[m];
        Out.Radiosity[Index(e, m)] = Channel::To(Radiosity[Index(e, m)]) + Vec3{ rho.x * a.x, rho.y * a.y, rho.z * a.z };
      }
    }
    if (Direct)
    {
      Out.Direct.assign(DirectPart.size(), Vec3());
      for (size_t i = 0; i < DirectPart.size(); ++i)
      {
        Out.Direct[i] = OwnsElement(static_cast<int>(i / Solutions)) ? Channel::To(DirectPart[i]) : Vec3();
      }
    }
    Stats.ReceivingElements = OwnedElementCount;
    Stats.OwnRays = Stats.RayCount;
    if (Group.Distributed())
    {
      GatherOverRanks(Group, Out);
    }
  }

  /// Scales a shot's factors to every element (zero where this rank does not receive) so
  /// that it delivers no more power than it has, exactly that in a closed scene.
  void Conserve(ShooterFormFactors& estimator, int shooter, std::vector<double>& factors)
  {
    double receiving = 0;
    for (int e = 0; e < Elements; ++e)
    {
      factors[e] = OwnsElement(e) ? factors[e] : 0.0;
      receiving += factors[e] * Geometry.Area[e];
    }
    Group.Sum(&receiving, 1);
    const double scale = estimator.ConservationScale(shooter, receiving);
    if (scale != 1.0)
    {
      for (double& f : factors)
      {
        f *= scale;
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
  size_t Index(int item, int m) const { return static_cast<size_t>(item) * Solutions + m; }
  double ShotTotal() const { return ShotSum; }
  /// The largest fraction of its own emitted power that any solution's shot carries.
  double ShotFraction(int shooter) const
  {
    double most = 0;
    for (int m = 0; m < Solutions; ++m)
    {
      if (InitialPer[m] > 0)
      {
        most = std::max(most, Channel::Sum(Shot[m]) * Geometry.PatchOpenArea[shooter] / InitialPer[m]);
      }
    }
    return most;
  }

  const SceneMesh& Mesh;
  const SceneGeometry& Geometry;
  const int Solutions, Elements, Patches;
  const SolverOptions& Options;

private:
  void Initialize(const std::vector<Vec3>& emission)
  {
    Radiosity.assign(static_cast<size_t>(Elements) * Solutions, Value());
    Unshot.assign(static_cast<size_t>(Patches) * Solutions, Value());
    PendingEmission.assign(Patches, 0);
    for (int e = 0; e < Elements; ++e)
    {
      const int p = Geometry.ElementPatch[e];
      for (int m = 0; m < Solutions; ++m)
      {
        const Value v = Channel::From(emission[Index(e, m)]);
        Radiosity[Index(e, m)] = v;
        // Unshot radiosity of a patch: its elements' emission spread over its open area.
        if (Geometry.PatchOpenArea[p] > 0 && !Geometry.Enclosed[e]) // enclosed emission never gets out
        {
          Unshot[Index(p, m)] += v * (Geometry.Area[e] / Geometry.PatchOpenArea[p]);
        }
        PendingEmission[p] = PendingEmission[p] || Channel::Sum(v) != 0;
      }
    }
    if (Direct)
    {
      DirectPart = Radiosity;
      UnshotEmission = Unshot; // the part of the unshot energy that is still emission
    }
    InitialPer.assign(Solutions, 0.0);
    for (int p = 0; p < Patches; ++p)
    {
      for (int m = 0; m < Solutions; ++m)
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
    for (int e = 0; e < Elements; ++e)
    {
      OwnedElementCount += OwnsElement(e) ? 1 : 0;
    }
    for (int p = 0; p < Patches; ++p)
    {
      if (Owned[p])
      {
        OwnedList.push_back(p);
      }
    }
    if (Group.Distributed())
    {
      OwnedRemaining(); // each rank brings its own receivers' part to the first sum
    }
  }

  double Power(int p, int m) const { return Channel::Sum(Unshot[Index(p, m)]) * Geometry.PatchOpenArea[p]; }

  /// RemainingPer over this rank's patches (all of them for one process).
  void OwnedRemaining()
  {
    std::fill(RemainingPer.begin(), RemainingPer.end(), 0.0);
    for (int p : OwnedList)
    {
      for (int m = 0; m < Solutions; ++m)
      {
        RemainingPer[m] += Power(p, m);
      }
    }
  }

  /// Of this rank's patches, the one with the largest unshot power over the solutions
  /// being shot (the first on ties; -1 when it has none), and that power.
  int BestOwnedPatch(double& best)
  {
    Distribute = Mask();
    int shooter = -1;
    for (int p : OwnedList)
    {
      double sum = 0;
      for (int m = 0; m < Solutions; ++m)
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

  /// Continue for several ranks, with one sum per shot (RankTable). The rules then apply in
  /// the order of one process, and every rank takes the winner's unshot energy, which only
  /// its owner has.
  bool ContinueTogether()
  {
    const bool outOfTime = Options.TimeBudget > 0 && Seconds() >= Options.TimeBudget;
    const bool abort = !outOfTime && Options.Progress && !Options.Progress(Fraction());
    RankTable<Channel> table(Solutions, Direct);
    table.Exchange(Group, MyRow(outOfTime, abort));
    Pending.Received = table.Received();
    for (int m = 0; m < Solutions; ++m)
    {
      RemainingPer[m] = table.Remaining(m);
    }
    if (Pending.Open)
    {
      RecordShot();
    }
    const std::vector<char> picked = Distribute; // the solutions the candidates were chosen for
    if (!UpdateActive())
    {
      Stats.Converged = true;
      return false;
    }
    if (Stats.Shots >= Stats.ShotCap)
    {
      return false;
    }
    Stats.OutOfTime = table.AnyOutOfTime();
    Stats.Aborted = !Stats.OutOfTime && table.AnyAborted();
    if (Stats.OutOfTime || Stats.Aborted)
    {
      return false;
    }
    if (Mask() != picked)
    {
      table.Exchange(Group, MyRow(false, false)); // a solution just converged: choose again without it
    }
    TakeWinner(table);
    return true;
  }

  /// The solutions a shot carries: those still being shot (all with ConvergedLights On).
  std::vector<char> Mask() const
  {
    std::vector<char> mask(Solutions);
    for (int m = 0; m < Solutions; ++m)
    {
      mask[m] = Options.ConvergedLights != EffectMode::On ? Active[m] : 1;
    }
    return mask;
  }

  /// This rank's row of the shot's table.
  RankRow<Channel> MyRow(bool outOfTime, bool abort)
  {
    RankRow<Channel> row;
    row.OutOfTime = outOfTime;
    row.Aborted = abort;
    row.Candidate = BestOwnedPatch(row.BestPower);
    row.Received = Pending.Open ? Pending.Received : 0.0;
    row.Remaining = RemainingPer;
    for (int m = 0; m < Solutions && row.Candidate >= 0; ++m)
    {
      row.Unshot.push_back(Unshot[Index(row.Candidate, m)]);
      if (Direct)
      {
        row.UnshotEmission.push_back(UnshotEmission[Index(row.Candidate, m)]);
      }
    }
    return row;
  }

  /// The next shooter from the summed table, with its unshot energy.
  void TakeWinner(const RankTable<Channel>& table)
  {
    std::vector<Value> unshot, emission;
    Next = 0;
    if (!table.Winner(Next, unshot, emission))
    {
      return;
    }
    for (int m = 0; m < Solutions; ++m)
    {
      Unshot[Index(Next, m)] = unshot[m];
      if (Direct)
      {
        UnshotEmission[Index(Next, m)] = emission[m];
      }
    }
  }

  /// A solution is done once its unshot power is below the threshold of its own emission:
  /// then every light is accurate on its own scale, however dim it is.
  bool UpdateActive()
  {
    bool any = false;
    for (int m = 0; m < Solutions; ++m)
    {
      Active[m] = InitialPer[m] > 0 && RemainingPer[m] >= Options.ConvergenceThreshold * InitialPer[m];
      any = any || Active[m];
    }
    return any;
  }

  void FinishGathered()
  {
    FinishClusters();
    if (Gathered.empty())
    {
      return;
    }
    for (int e = 0; e < Elements; ++e)
    {
      const int q = Geometry.ElementPatch[e];
      if (!Owned[q])
      {
        continue;
      }
      const double* w = Nodes->Weights(e);
      for (int j = Nodes->Begin(q); j < Nodes->End(q); ++j)
      {
        const double weight = w[j - Nodes->Begin(q)];
        for (int m = 0; m < Solutions; ++m)
        {
          Radiosity[Index(e, m)] += Channel::Reflect(Mesh.Reflectance[e], Gathered[Index(j, m)], weight);
        }
      }
    }
  }

  /// Each open element of a cluster node turns the node's gathered vectors into its own
  /// irradiance.
  void FinishClusters()
  {
    for (int node = 0; Clusters && node < Clusters->Count(); ++node)
    {
      if (!Owned[Clusters->Patch[node]])
      {
        continue;
      }
      for (int i = Clusters->ElementBegin[node]; i < Clusters->ElementEnd[node]; ++i)
      {
        const int e = Clusters->Elements[i];
        const Vec3& n = Geometry.Normal[e];
        for (int m = 0; m < Solutions && !Geometry.Sheltered[e]; ++m)
        {
          const Value* v = ClusterGathered.data() + 3 * Index(node, m);
          Radiosity[Index(e, m)] += Channel::Reflect(Mesh.Reflectance[e], v[0] * n.x + v[1] * n.y + v[2] * n.z, 1.0);
        }
      }
    }
  }

  /// Cohen et al. 1988: ambient = R * (sum_p U_p A_p) / (sum_p A_p), with the
  /// interreflection factor R = 1 / (1 - mean reflectance) per channel; each element
  /// shows rho * ambient on top of what it received.
  void AddAmbient()
  {
    const AmbientTerm ambient(Mesh, Geometry, Elements);
    for (int m = 0; m < Solutions; ++m)
    {
      Vec3 unshotPower;
      for (int p : OwnedList)
      {
        unshotPower += Channel::To(Unshot[Index(p, m)]) * Geometry.PatchOpenArea[p];
      }
      double summed[3] = { unshotPower.x, unshotPower.y, unshotPower.z };
      Group.Sum(summed, 3);
      Out.Ambient[m] = ambient.Of({ summed[0], summed[1], summed[2] });
    }
  }

  SolverClock::time_point Start;
  Solution& Out;
  SolverStatistics& Stats;
  const bool Direct, Reflect;
  std::vector<Value> Radiosity, DirectPart, Unshot, UnshotEmission, Gathered, ClusterGathered;
  std::vector<Vec3> ClusterReflectance;
  std::vector<Value> Shot, ShotEmission;
  std::vector<char> Distribute, Active, PendingEmission;
  std::vector<double> InitialPer, RemainingPer;
  double Initial = 0, ShotSum = 0;
  const PatchNodes* Nodes = nullptr;
  const ReceiverNodes* Clusters = nullptr;
  Collective Group;
  std::vector<char> Owned;
  std::vector<int> OwnedList;
  int OwnedElementCount = 0;
  int Next = 0; ///< the shooter Continue picked
  /// The last shot until it is recorded: open, its power, what this rank's receivers (all,
  /// for one process) received, and when it ended.
  struct
  {
    bool Open = false;
    double Shot = 0, Received = 0, Seconds = 0;
  } Pending;
};

} // namespace radiosity

#endif
