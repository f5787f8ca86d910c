// The light-tagged radiosity solver (Nielsen & Christensen, "Real-time dynamic radiosity
// relighting", Fig. 2): options, statistics and the solution, and the one interface every
// solver method implements (scene and options in, a Solution out).
#ifndef RadiosityCore_RadiositySolver_h
#define RadiosityCore_RadiositySolver_h

#include "Base/ProcessGroup.h"
#include "Geometry/Scene.h"
#include "Solve/ShooterFormFactors.h"
#include "Geometry/PreparedScene.h"
#include "Geometry/Visibility.h"
#include "Solve/ClusteredRadiosity.h"
#include "Solve/FinalGather.h"
#include "Solve/HierarchicalRadiosity.h"

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace radiosity
{

/// How an optional piece of simulation is chosen. Auto simulates it only where it can
/// change the result (decided conservatively); On always simulates it; Off never does.
enum class EffectMode
{
  Auto = 0,
  On = 1,
  Off = 2
};

/// How the transport is organised. Every method carries all solutions along each
/// evaluation (light tagging); the table of methods is SolverMethodTable() (SolverMethods.h).
enum class SolverMethod
{
  /// The method its estimated cost says is fastest for the scene (MethodCost.h: elements,
  /// patches and the pairs too near to group); SolverStatistics::MethodReason says why.
  Auto = 0,
  /// Every shot evaluates a form factor to every element: cost shots x elements.
  ProgressiveRefinement = 1,
  /// Two-level links (Hanrahan et al. 1991, in shooting order): a shooter links to a far,
  /// weakly lit receiver patch as a whole and to near or partly hidden ones element by
  /// element. Links are made at a patch's first shot and reused by its later shots.
  Hierarchical = 2,
  /// Hierarchical radiosity with clustering (Smits et al. 1994), gathering: links between
  /// groups of elements of any size, found once for the scene; direct light per element
  /// as in progressive refinement. Its cost follows the surfaces, not polygons x shooters.
  Clustered = 3
};

struct SolverOptions
{
  radiosity::SolverMethod SolverMethod = radiosity::SolverMethod::Auto;
  /// Shot cap; 0 (the default) picks it from the scene: 25 shots per patch, at least
  /// 2000, so a scene converges at the default threshold instead of hitting the cap
  /// (measured: 5-6 shots per patch reach 1e-3 in a furnished room).
  int MaximumShots = 0;
  /// Stop when every solution's remaining unshot power is below this fraction of its own
  /// emitted power.
  double ConvergenceThreshold = 1e-3;
  /// Stop after this many seconds of shooting (0: no limit); the result stays valid.
  double TimeBudget = 0;
  radiosity::FormFactorMethod FormFactorMethod = radiosity::FormFactorMethod::Analytic;
  /// Analytic: shadow rays per receiver and shot (0: ignore occlusion); Hemicube: the
  /// resolution of its top face; MonteCarlo: rays per shot.
  int FormFactorSamples = 4;
  int Threads = 0; ///< 0: all hardware threads
  /// Add the ambient term of Cohen et al. 1988 per solution: the unshot energy, spread
  /// evenly and interreflected in closed form, so unconverged results look plausible.
  bool AmbientTerm = false;
  /// Also keep each solution's direct part: emission plus the first bounce of it.
  bool SeparateDirect = false;
  /// Shadow rays. Auto skips them for pairs no surface can block: only a polygon with
  /// scene geometry behind its plane can come between two surfaces that see each other,
  /// so pairs whose bounding box meets no such polygon are unoccluded (a convex room has
  /// none at all). Off treats every pair as unoccluded. Analytic method only: the
  /// hemicube's and Monte Carlo's rays are the form factors themselves.
  EffectMode Visibility = EffectMode::Auto;
  /// Reflected light. Off keeps direct light only (emission and its first bounce).
  EffectMode Interreflection = EffectMode::Auto;
  /// RGB channels. Auto solves one channel when every reflectance and emission is grey
  /// (exact, a third of the work and memory); Off always does (using the mean).
  EffectMode Color = EffectMode::Auto;
  /// Shooting a solution whose remaining unshot power is already below the threshold of
  /// its own emitted power. Auto and Off stop shooting it; On keeps it going until every
  /// solution has converged.
  EffectMode ConvergedLights = EffectMode::Auto;
  /// Called between shots with the fraction done; returning false aborts the solve, which
  /// then keeps the valid partial result of the shots made so far.
  std::function<bool(double)> Progress;
  /// The part of the starting radiosity that is light already reflected once (the point
  /// lights' reflected direct light, [element * solutions + m]; null: none). The clustered
  /// method sends it along its links with the reflected light of its own emitters instead
  /// of shooting every lit patch as an emitter (a building lit by luminaires: thousands of
  /// shots); the other methods take it as emission.
  const std::vector<Vec3>* ReflectedStart = nullptr;
  /// What one method alone reads, defined beside that method.
  HierarchicalSettings Hierarchical;
  ClusteredSettings Clustered;
  /// The final gather at the mesh's points, run by SolveLights after the solve; its Rays
  /// are 0 here (a plain element solution), the solver filter's default turns it on.
  GatherSettings Gather{ 0 };
  /// Several processes solving together: each computes the transport to its own share of
  /// the receivers (OwnedPatches), and they agree on each shot through Group.SumAll. Every
  /// rank passes the whole scene and gets the whole solution. Default: one process.
  ProcessGroup Group;
};

struct SolverStatistics
{
  int Shots = 0;
  int ShotCap = 0; ///< the cap in force (MaximumShots, or the one picked from the scene)
  bool Converged = false;
  bool Aborted = false;
  bool OutOfTime = false;
  /// The ambient term was added because the solver's own shot cap stopped it (AddsAmbient).
  bool AmbientAtCap = false;
  /// Why the solve stopped short of memory (its links would not fit); empty otherwise.
  std::string OutOfMemory;
  /// Per shot: seconds since the start, remaining unshot power / initial (all solutions),
  /// and the same per solution ([shot * solutions + m]).
  std::vector<double> TimeHistory;
  std::vector<double> RemainingHistory;
  std::vector<double> RemainingPerSolution;
  long long RayCount = 0;
  long long RaysSkipped = 0;      ///< shadow rays Visibility=Auto proved unnecessary
  long long PairsUnblockable = 0; ///< receiver-shooter pairs no surface can block
  long long DistributionsSkipped = 0; ///< (shot, solution) pairs not distributed
  bool SingleChannel = false;     ///< solved one grey channel instead of RGB
  int BlockingSurfaces = -1;      ///< planes with geometry behind them (-1: not examined)
  long long FormFactorCount = 0; ///< receiver-shooter pairs evaluated
  radiosity::SolverMethod SolverMethod = radiosity::SolverMethod::ProgressiveRefinement; ///< the method that ran
  std::string MethodReason; ///< why: "as set", or Auto's measure of the scene
  int FaceClusters = 0;     ///< patches of several elements on more than one plane
  long long PatchLinks = 0;   ///< hierarchical: shooter-to-patch links made
  long long ElementLinks = 0; ///< hierarchical: shooter-to-element links made
  long long VolumeLinks = 0;  ///< hierarchical: links to whole far regions of patches
  double LinkBytes = 0;       ///< hierarchical: memory the links held
  /// Channel-summed power shot by patches and power arriving at receivers (irradiance
  /// times area, before reflection); equal up to discretization in a closed scene.
  double ShotPower = 0;
  double ReceivedPower = 0;
  /// Energy ledger (channel-summed): what the emitters put in, what left the scene
  /// (shot but received by no element: openings, back faces, closed-off elements), and
  /// what is still unshot.
  /// Emitted = absorbed + escaped + unshot, where absorbed follows from the radiosity.
  double EmittedPower = 0;
  double EscapedPower = 0;
  double UnshotPower = 0;
  /// Processes that solved together, their sums over the ranks, and the bytes each rank
  /// put into those sums (the final exchange of the solution included).
  int Ranks = 1;
  long long Collectives = 0;
  double CollectiveBytes = 0;
  double ShotCollectiveBytes = 0; ///< the part of CollectiveBytes spent during the shots
  double CollectiveSeconds = 0;   ///< this rank's time in the sums (waits for others too)
  int ReceivingElements = 0; ///< the elements this rank received for
  long long OwnRays = 0;     ///< the rays this rank cast (RayCount is the sum over ranks)
  /// Where the time went, step by step in the order each first ran ("direct light",
  /// "links", "bounces", "gather: ...", ...): a step run again, as each solve of the
  /// StandardSeparate mode runs them, adds to its own.
  struct Step
  {
    std::string Name;
    double Seconds = 0;
  };
  std::vector<Step> Steps;
  void Took(const std::string& step, double seconds);

  /// Takes in the statistics of a solve run after the ones already in (the
  /// StandardSeparate mode's solutions, one by one, into Sequence()): counts, links and
  /// powers add up, the method, its reason, the cap and the flags are the runs' (converged
  /// and single-channel only if all were), link memory is the most held at once. The
  /// histories stay the caller's: they are weighted by each solution's emitted power.
  void Append(const SolverStatistics& next);
  /// Statistics of no solve yet, to Append solves to.
  static SolverStatistics Sequence()
  {
    SolverStatistics s;
    s.Converged = true;
    s.SingleChannel = true;
    return s;
  }
};

/// Books the time from its making to its end as a step of a solve (SolverStatistics::Steps).
class StepTimer
{
public:
  StepTimer(SolverStatistics& stats, const char* step)
    : Stats(stats)
    , Name(step)
    , Begin(std::chrono::steady_clock::now())
  {
  }
  ~StepTimer() { Stats.Took(Name, std::chrono::duration<double>(std::chrono::steady_clock::now() - Begin).count()); }
  StepTimer(const StepTimer&) = delete;
  StepTimer& operator=(const StepTimer&) = delete;

private:
  SolverStatistics& Stats;
  const char* Name;
  std::chrono::steady_clock::time_point Begin;
};

/// One line of the solver's account of what it simulated and what it skipped.
struct EffectDecision
{
  std::string Effect;
  bool Simulated = true;
  std::string Reason; ///< why, and what skipping saved
};

struct Solution
{
  int Solutions = 0;
  std::vector<EffectDecision> Effects;
  std::vector<Vec3> Radiosity; ///< [element * Solutions + m], with the ambient term if asked
  std::vector<Vec3> Direct;    ///< same layout, only with SeparateDirect
  std::vector<Vec3> Ambient;   ///< per solution, the ambient radiosity (0 without it)
  /// The final gather (SolverOptions::Gather): per mesh point and solution
  /// ([point * Solutions + m]), empty where it was off or stopped. Radiosity and Direct
  /// then hold the gather's element values (its last sweep, or the corner means of the
  /// points without sweeps), no longer the element solution.
  std::vector<Vec3> PointRadiosity;
  std::vector<Vec3> PointDirect;
  /// The light arriving on each element's and point's front side, per solution (same
  /// layouts): illuminance in lux for a luminaire where the scene is in metres. The
  /// gather's where it ran (a black surface too); else (B - emission) / reflectance, 0
  /// where the reflectance is 0. Filled by SolveLights; PointIrradiance only with the gather.
  std::vector<Vec3> Irradiance;
  std::vector<Vec3> PointIrradiance;
  long long GatherRays = 0; ///< the rays the gather cast (the statistics count the solve's)
  int GatherPointRays = 0;  ///< the cosine rays a point took (fewer than asked on a TimeBudget)
  int GatherRecords = 0;    ///< points that gathered for themselves through the irradiance cache (0: off)
  int GatherPoints = 0;     ///< points the gather evaluated (copies share one)
  bool GatherOutOfTime = false; ///< the TimeBudget was spent before the points were gathered
  SolverStatistics Statistics;
};

/// What every solver method is: the prepared scene, k emissions and the options in; the
/// solution and its statistics out (`out` arrives with Solutions and Ambient sized, and
/// the statistics' SingleChannel decided as `grey`). A new method (a distributed or GPU
/// one) is one more function of this shape in a file of its own, one more SolverMethod
/// value and one more row of SolverMethodTable (Solve/SolverMethods.cxx).
using SolveFunction = void (*)(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, int solutions, bool grey, const SolverOptions& options,
  std::chrono::steady_clock::time_point start, Solution& out);

/// Empty, or which setting cannot mean anything (a NaN or infinite threshold or budget):
/// a NaN threshold stopped every solve at once, reported as converged.
std::string OptionsProblem(const SolverOptions& options);

/// Empty, or why the scene has no finite solution: every open surface reflects all of a
/// color channel and every patch sees a closed scene, so light in that channel never
/// leaves (a shooting method would run to its shot cap). Probe rays only when every
/// reflectance is 1 in some channel.
std::string NoFiniteSolution(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays);

/// The shot cap in force for `patches` patches (see SolverOptions::MaximumShots).
int ShotCap(const SolverOptions& options, int patches);

/// Whether a solve ends with the ambient term: asked for, or the solver's own shot cap
/// (MaximumShots 0) stopped it short of converging. That cap is met where light travels
/// long in a closed, highly reflective scene (rho 0.999 needs ~7,000 sweeps over the
/// patches), and there the slowest part of the light left is the nearly even light the
/// ambient term gives in closed form. Sets stats.AmbientAtCap.
bool AddsAmbient(const SolverOptions& options, SolverStatistics& stats);

/// The entry point: a mesh and its prepared scene (PreparedScene.h); several solves (k
/// separate solutions, or a re-solve with other emissions) reuse the preparation, and Solve
/// runs the method the options choose.
class RadiositySolver
{
public:
  /// Prepares `mesh` itself. `threads` and `group` as in SolverOptions: the preparation's
  /// rays (MarkEnclosed) run on that many threads, divided among the ranks of the group.
  explicit RadiositySolver(const SceneMesh& mesh, int threads = 0, const ProcessGroup& group = ProcessGroup());
  /// Solves `mesh` on a preparation made before (PrepareTransport on the same points,
  /// polygons and patch ids), shared, not copied.
  RadiositySolver(const SceneMesh& mesh, const PreparedScene& prepared);
  ~RadiositySolver();

  /// Empty when the scene could be prepared.
  const std::string& Error() const;
  const SceneGeometry& Geometry() const { return *Prepared_.Geometry; }
  const Visibility& Rays() const { return *Prepared_.Rays; }
  const PreparedScene& Prepared() const { return Prepared_; }
  /// Patches split because their parts cannot see each other (see SplitSeparatedPatches);
  /// then Geometry().ElementPatch, not the mesh's PatchId, is the patch of each element.
  int SplitPatches() const { return Prepared_.SplitPatches; }

  /// Solves `solutions` independent systems at once. `emission[e * solutions + m]` is the
  /// exitance of element e in solution m. Transport (form factors, links, rays) is computed
  /// once and the energy of every solution travels with it: this is the light tagging.
  /// The shooter is the patch with the largest unshot power summed over solutions.
  Solution Solve(const std::vector<Vec3>& emission, int solutions, const SolverOptions& options) const;

private:
  const SceneMesh& Mesh;
  PreparedScene Prepared_;
  std::string Error_;
};

/// Which patches `rank` of `ranks` receives for: each patch goes to the rank with the
/// fewest elements so far, in patch order, so the shares are even in elements and spread
/// over the whole scene (near and far receivers cost differently). 1 = this rank's.
std::vector<char> OwnedPatches(const SceneGeometry& geometry, int rank, int ranks);

} // namespace radiosity

#endif
