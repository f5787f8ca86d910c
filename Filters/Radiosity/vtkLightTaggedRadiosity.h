/**
 * @class   vtkLightTaggedRadiosity
 * @brief   solves one radiosity solution per light in a single progressive pass
 *
 * The modified progressive refinement of Nielsen & Christensen (Fig. 2) with
 * substructuring: patches (cell array `PatchId`, else every cell) shoot, elements (the
 * cells) receive. Each shot picks the patch with the largest unshot power summed over
 * lights, evaluates its form factors to every element once (Lambert's exact
 * point-to-polygon formula times the fraction of unblocked Embree shadow rays) and
 * distributes the unshot energy of all k lights with them.
 *
 * Input: polygons with cell arrays `Reflectance` (3), `LightId` (integer, -1 or 0..k-1),
 * optional `Emission` (3), `PatchId`, and field array `LightNames`. Light m's solution is
 * for unit exitance on its cells.
 *
 * Output port 0: the input plus, for each light (or bank), point and cell arrays
 * `Radiosity_<name>` (3 components, float, exitance) and with SeparateDirect also
 * `Direct_<name>`; field arrays `LightNames`, `LightDefaultColors` (the relight color
 * that reproduces the scene's Emission) and `UnshotHistory` (remaining unshot power /
 * initial after each shot). In StandardCombined mode one array `Radiosity` instead, with
 * every light at its `Emission`.
 * Output port 1: the convergence history as a table (Shot, Time, Remaining and
 * Remaining_<name> per solution), ready for a line chart.
 *
 * An optional field array `LightBanks` (k integers, 0..b-1) groups lights into banks that
 * share one solution (their relative Emission colors are kept inside it); an optional
 * field array `StaticLights` (k integers) marks lights nobody will change, merged into one
 * bank when LightSeparationEffect is Auto.
 *
 * Solves stop at MaximumShots, when every light's remaining unshot power falls below
 * ConvergenceThreshold times its emitted power, when TimeBudget seconds have passed, or
 * on abort; every stop leaves a valid partial result (a stop at the cap picked from the
 * scene, MaximumShots 0, adds the rest as the ambient term). Work is spread over all hardware
 * threads; results do not depend on the thread count.
 *
 * @sa vtkRadiosityMesher vtkRadiosityRelight
 */
#ifndef vtkLightTaggedRadiosity_h
#define vtkLightTaggedRadiosity_h

#include "vtkRadiosityAlgorithm.h"
#include "vtkRadiosityFiltersModule.h" // for export macro

#include <chrono> // for the solve's start time
#include <map>    // for the settings by name
#include <string> // for the settings by name

class vtkMultiProcessController;
class vtkTable;
namespace radiosity
{
struct ProcessGroup;
struct SolverOptions;
struct Solution;
class RadiositySolver;
enum class EffectMode;
}
namespace vtkRadiositySolveOutput
{
struct SceneInput;
}
namespace vtkRadiosityAdapter
{
class WarningList;
}

class VTKRADIOSITYFILTERS_EXPORT vtkLightTaggedRadiosity : public vtkRadiosityAlgorithm
{
public:
  static vtkLightTaggedRadiosity* New();
  vtkTypeMacro(vtkLightTaggedRadiosity, vtkRadiosityAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SolutionModes
  {
    LIGHT_TAGGED = 0,
    STANDARD_COMBINED = 1,
    STANDARD_SEPARATE = 2
  };

  ///@{
  /// LightTagged (default): k solutions in one pass. StandardCombined: one ordinary
  /// solution with the lights' Emission. StandardSeparate: k ordinary solutions one after
  /// the other (the paper's comparison, same output as LightTagged).
  vtkSetClampMacro(SolutionMode, int, LIGHT_TAGGED, STANDARD_SEPARATE);
  vtkGetMacro(SolutionMode, int);
  void SetSolutionModeToLightTagged() { this->SetSolutionMode(LIGHT_TAGGED); }
  void SetSolutionModeToStandardCombined() { this->SetSolutionMode(STANDARD_COMBINED); }
  void SetSolutionModeToStandardSeparate() { this->SetSolutionMode(STANDARD_SEPARATE); }
  ///@}

  enum SolverMethods
  {
    SOLVER_AUTO = 0,
    PROGRESSIVE_REFINEMENT = 1,
    HIERARCHICAL = 2,
    CLUSTERED = 3
  };

  ///@{
  /// How transport is organised. ProgressiveRefinement: every shot evaluates a form factor
  /// to every element (cost shots x elements; exact per element). Hierarchical: a shooter
  /// links once to far receiver patches as a whole (form factors at their corners and
  /// centre, interpolated) and to near ones per element, and reuses the links for later
  /// shots; direct light from emitters still reaches every element with its own shadow
  /// rays. Cost grows about linearly with elements. FormFactorMethod and
  /// FormFactorSamples' meaning for Hemicube/MonteCarlo apply to ProgressiveRefinement
  /// only; Hierarchical uses analytic factors with FormFactorSamples shadow rays.
  /// Clustered: hierarchical radiosity with clustering: links between groups of elements
  /// of any size, found once for the scene and gathered along for every light; direct
  /// light per element with its own shadow rays. Its cost follows the surfaces, not the
  /// polygons: for models of many small polygons (CAD, scans, BIM).
  /// Auto (default): ProgressiveRefinement below 5,000 element-patch pairs (elements x
  /// patches) or with Hemicube/MonteCarlo factors, else whichever of Hierarchical and
  /// Clustered a cost model fitted on measured solves expects to be faster (Clustered
  /// where there are many patches of few elements); SolverMethod says which and why.
  vtkSetClampMacro(SolverMethod, int, SOLVER_AUTO, CLUSTERED);
  vtkGetMacro(SolverMethod, int);
  void SetSolverMethodToAuto() { this->SetSolverMethod(SOLVER_AUTO); }
  void SetSolverMethodToProgressiveRefinement() { this->SetSolverMethod(PROGRESSIVE_REFINEMENT); }
  void SetSolverMethodToHierarchical() { this->SetSolverMethod(HIERARCHICAL); }
  void SetSolverMethodToClustered() { this->SetSolverMethod(CLUSTERED); }
  /// The values SolverMethod takes (Auto and every method of the core's table,
  /// Solve/SolverMethods.cxx) and their names, which the XML's enumeration repeats.
  static int GetNumberOfSolverMethods();
  static const char* GetSolverMethodName(int value);
  /// The name of the method set (what was asked: Auto stays Auto; the field array
  /// SolverMethod says what ran).
  const char* GetSolverMethodAsString() const { return GetSolverMethodName(this->SolverMethod); }
  ///@}

  ///@{
  /// Upper bound on shots (per solve). 0 (default): 25 per patch, at least 2000.
  vtkSetClampMacro(MaximumShots, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumShots, int);
  ///@}

  ///@{
  /// Stop when every light's remaining unshot power is below this fraction of the power
  /// it emitted (each light accurate on its own scale). Default 1e-3.
  vtkSetClampMacro(ConvergenceThreshold, double, 0.0, 1.0);
  vtkGetMacro(ConvergenceThreshold, double);
  ///@}

  enum FormFactorMethods
  {
    ANALYTIC = 0,
    HEMICUBE = 1,
    MONTE_CARLO = 2
  };

  ///@{
  /// Analytic (default): exact point-to-polygon factor at each receiver times the visible
  /// fraction of FormFactorSamples shadow rays. Hemicube: a hemicube of resolution
  /// FormFactorSamples at the shooter, pixels cast as rays. MonteCarlo: FormFactorSamples
  /// cosine-distributed rays per shot.
  vtkSetClampMacro(FormFactorMethod, int, ANALYTIC, MONTE_CARLO);
  vtkGetMacro(FormFactorMethod, int);
  void SetFormFactorMethodToAnalytic() { this->SetFormFactorMethod(ANALYTIC); }
  void SetFormFactorMethodToHemicube() { this->SetFormFactorMethod(HEMICUBE); }
  void SetFormFactorMethodToMonteCarlo() { this->SetFormFactorMethod(MONTE_CARLO); }
  ///@}

  ///@{
  /// Shadow rays per receiver (Analytic; 0 ignores occlusion), hemicube resolution, or
  /// rays per shot (MonteCarlo). Default 4, the fastest setting on the measured
  /// accuracy-time front (README, `./relight bench accuracy`).
  vtkSetClampMacro(FormFactorSamples, int, 0, 1 << 24);
  vtkGetMacro(FormFactorSamples, int);
  ///@}

  ///@{
  /// Clustered method only: two groups of elements exchange light as a whole when their
  /// centres are farther apart than this many times the sum of their radii (default 3,
  /// 2 or more; other values are an error at the update). Larger is more accurate and
  /// slower; with the final gather (GatherRays) the element solution is read one bounce
  /// away, and the FZK-Haus (112,740 elements) at probes traced from its lamps is 5.5 %
  /// from Mitsuba 3 at 2, 5.1 % at 3, 4.9 % at 4, solved in 18, 25 and 33 s
  /// (docs/benchmarks.md).
  vtkSetMacro(ClusterSeparation, double);
  static double GetClusterSeparationMinValue() { return 2.0; }
  static double GetClusterSeparationMaxValue() { return VTK_DOUBLE_MAX; }
  vtkGetMacro(ClusterSeparation, double);
  ///@}

  ///@{
  /// Settings one method alone reads, by name (the method table's rows name them and
  /// their ranges, Filters/Core/Solve/SolverMethods.cxx): Hierarchical's
  /// RefinementThreshold (a far link carrying this fraction of a solution's power is
  /// resolved per element; 0, the default, refines by geometry alone), Clustered's
  /// ClusterMemoryLimit (bytes its links may take; 0, the default, 90 % of the free
  /// memory). A name no method has, or a value out of its range, is an error at the
  /// update; one the method that ran does not read is said as a warning.
  void SetMethodSetting(const char* name, double value);
  void ClearMethodSettings();
  int GetNumberOfMethodSettings() const;
  /// Every method's settings by name, their methods and ranges, as one sentence (the
  /// plugin's XML documents the property with it).
  static std::string DescribeMethodSettings();
  /// The settings any method has, flat over the method table: name, method, default and
  /// range (the panel's Method Settings table offers and checks them); null/0 past them.
  static int GetNumberOfKnownMethodSettings();
  static const char* GetKnownMethodSettingName(int i);
  static const char* GetKnownMethodSettingMethod(int i);
  static double GetKnownMethodSettingDefault(int i);
  static double GetKnownMethodSettingMinimum(int i);
  static double GetKnownMethodSettingMaximum(int i);
  /// Setting `i` (in the order of their names): its name and value; null and 0 past them.
  const char* GetMethodSettingName(int i) const;
  double GetMethodSettingValue(int i) const;
  ///@}

  ///@{
  /// The final gather: at every point of the output, direct light from each emitter with
  /// shadow rays, and this many cosine rays into the element solution for the reflected
  /// light (default 256; 0: the points take the mean of their elements, as a plain
  /// radiosity solution does). Light cannot leak to a point through a wall, and an
  /// element's average no longer shows where a light's peak is steep. Fewer rays are
  /// noisier: the furnished room (37,007 elements) is 1.61 % from Mitsuba 3 without the
  /// gather, 1.95 % at 64 rays, 1.17 % at 256, 1.00 % at 1,024 (4.0, 5.6, 7.0, 13.0 s).
  vtkSetClampMacro(GatherRays, int, 0, 4096);
  vtkGetMacro(GatherRays, int);
  ///@}

  ///@{
  /// Passes of the final gather over the elements before the points read them (default
  /// 1, at most 4): each gathers every element's mean anew from rays, so what the element
  /// solution lost (light reaching dim places after several bounces) shrinks by the
  /// reflectance at each pass; a pass after the first reuses the first's direct light. On
  /// the FZK-Haus 4 passes gave 2.05 % from Mitsuba 3 instead of 2.28 %, for about a second
  /// (the Fine and Reference accuracy levels use 3 and 4); a room's hierarchical solution
  /// gains nothing from them (docs/benchmarks.md).
  vtkSetClampMacro(GatherSweeps, int, 0, 4);
  vtkGetMacro(GatherSweeps, int);
  ///@}

  ///@{
  /// The final gather's irradiance cache (Ward's a, default 0.15; 0: every point gathers
  /// for itself): a point gathers its interreflection only where no point gathered nearby
  /// reaches it, and reads those points' where they do; its direct light is its own. A
  /// point's reach is this fraction of the harmonic mean distance its rays travelled, never
  /// past the nearest surface they met, so it does not reach through a wall. Smaller is
  /// closer and slower. FinalGather in Effects says how many points gathered.
  vtkSetClampMacro(GatherCache, double, 0.0, 1.0);
  vtkGetMacro(GatherCache, double);
  ///@}

  ///@{
  /// Stop after this many seconds, the final gather included; 0 (default) means no limit.
  /// The gather takes what the shooting left: fewer rays a point where all would not fit,
  /// none (the points show their elements' mean) where that is spent; the FinalGather row
  /// of Effects says which.
  vtkSetClampMacro(TimeBudget, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(TimeBudget, double);
  ///@}

  ///@{
  /// Add each light's ambient term (Cohen et al. 1988) so unconverged results display
  /// sensibly. Off by default.
  vtkSetMacro(AmbientTerm, bool);
  vtkGetMacro(AmbientTerm, bool);
  vtkBooleanMacro(AmbientTerm, bool);
  ///@}

  ///@{
  /// Also output `Direct_<name>` (emission plus first bounce) per light, so indirect
  /// light can be scaled separately when relighting. Off by default.
  vtkSetMacro(SeparateDirect, bool);
  vtkGetMacro(SeparateDirect, bool);
  vtkBooleanMacro(SeparateDirect, bool);
  ///@}

  enum EffectModes
  {
    EFFECT_AUTO = 0,
    EFFECT_ON = 1,
    EFFECT_OFF = 2
  };

  ///@{
  /// Simulate only what the scene calls for. Each effect is Auto (default: simulated only
  /// where it can change the result, decided conservatively), On or Off:
  /// - Visibility: shadow rays; Auto skips pairs no surface can block (a convex room needs
  ///   none); Off ignores occlusion (Analytic method only).
  /// - Interreflection: Off keeps direct light only.
  /// - Color: Auto solves one channel when everything is grey; Off always does.
  /// - LightSeparation: Auto merges lights flagged in the field array `StaticLights`
  ///   (k integers, 1 = static) into one solution; On keeps every light separate; Off
  ///   merges all.
  /// - ConvergedLights: Auto and Off stop shooting a light whose unshot power is below the
  ///   threshold; On shoots every light until all converge.
  /// Decisions and savings go to the field arrays `Effects`, `EffectDecisions` and
  /// `EffectReasons`, and to a one-line log message.
  vtkSetClampMacro(VisibilityEffect, int, EFFECT_AUTO, EFFECT_OFF);
  vtkGetMacro(VisibilityEffect, int);
  vtkSetClampMacro(InterreflectionEffect, int, EFFECT_AUTO, EFFECT_OFF);
  vtkGetMacro(InterreflectionEffect, int);
  vtkSetClampMacro(ColorEffect, int, EFFECT_AUTO, EFFECT_OFF);
  vtkGetMacro(ColorEffect, int);
  vtkSetClampMacro(LightSeparationEffect, int, EFFECT_AUTO, EFFECT_OFF);
  vtkGetMacro(LightSeparationEffect, int);
  vtkSetClampMacro(ConvergedLightsEffect, int, EFFECT_AUTO, EFFECT_OFF);
  vtkGetMacro(ConvergedLightsEffect, int);
  /// By name, as the other enumerations: SetVisibilityEffectToOff() and so on.
  void SetVisibilityEffectToAuto() { this->SetVisibilityEffect(EFFECT_AUTO); }
  void SetVisibilityEffectToOn() { this->SetVisibilityEffect(EFFECT_ON); }
  void SetVisibilityEffectToOff() { this->SetVisibilityEffect(EFFECT_OFF); }
  void SetInterreflectionEffectToAuto() { this->SetInterreflectionEffect(EFFECT_AUTO); }
  void SetInterreflectionEffectToOn() { this->SetInterreflectionEffect(EFFECT_ON); }
  void SetInterreflectionEffectToOff() { this->SetInterreflectionEffect(EFFECT_OFF); }
  void SetColorEffectToAuto() { this->SetColorEffect(EFFECT_AUTO); }
  void SetColorEffectToOn() { this->SetColorEffect(EFFECT_ON); }
  void SetColorEffectToOff() { this->SetColorEffect(EFFECT_OFF); }
  void SetLightSeparationEffectToAuto() { this->SetLightSeparationEffect(EFFECT_AUTO); }
  void SetLightSeparationEffectToOn() { this->SetLightSeparationEffect(EFFECT_ON); }
  void SetLightSeparationEffectToOff() { this->SetLightSeparationEffect(EFFECT_OFF); }
  void SetConvergedLightsEffectToAuto() { this->SetConvergedLightsEffect(EFFECT_AUTO); }
  void SetConvergedLightsEffectToOn() { this->SetConvergedLightsEffect(EFFECT_ON); }
  void SetConvergedLightsEffectToOff() { this->SetConvergedLightsEffect(EFFECT_OFF); }
  ///@}

  ///@{
  /// Turn every effect above On (outputs such as SeparateDirect are not changed), to
  /// compare against the Auto decisions. Off by default.
  vtkSetMacro(ForceAllEffects, bool);
  vtkGetMacro(ForceAllEffects, bool);
  vtkBooleanMacro(ForceAllEffects, bool);
  ///@}

  ///@{
  /// Also solve the moving-light basis (paper 2.4): every patch a unit emitter. It holds
  /// only reflected light: each patch's own unit emission is removed, so that
  /// vtkRadiosityRelight adds it as the frame's direct light. Off by default. Memory and
  /// level are reported in EffectReasons (row MovingLightBasis).
  vtkSetMacro(PatchBasis, bool);
  vtkGetMacro(PatchBasis, bool);
  vtkBooleanMacro(PatchBasis, bool);
  ///@}

  enum BasisLevels
  {
    BASIS_AUTO = 0,
    BASIS_ELEMENTS = 1,
    BASIS_PATCHES = 2
  };

  ///@{
  /// Where the basis lives. ELEMENTS: the cell array `PatchBasis`, 3P float components
  /// per element (patch q's RGB at 3q), 12 P bytes per element. PATCHES: solved with each
  /// patch as one receiver and stored per patch node (corners and centre): the field
  /// array `PatchBasis` (3P components per node) and the cell arrays `PatchBasisNodes`
  /// and `PatchBasisWeights` (3 each) that interpolate it to the elements; its memory does
  /// not grow with the element count, and contact shadows in the interreflection blur to
  /// patch size. AUTO (default): ELEMENTS up to 256 MB, otherwise PATCHES.
  vtkSetClampMacro(PatchBasisLevel, int, BASIS_AUTO, BASIS_PATCHES);
  vtkGetMacro(PatchBasisLevel, int);
  ///@}

  ///@{
  /// Threads for the solve; 0 (default) uses VTK's SMP thread count where its backend runs
  /// threads (ParaView's Settings, Number of threads), else every hardware thread. Embree's
  /// build of the ray scene keeps to it too (ranks x threads on a node do not oversubscribe).
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Statistics of the last solve.
  vtkGetMacro(LastShots, int);
  vtkGetMacro(LastConverged, bool);
  vtkGetMacro(LastRays, long long);
  vtkGetMacro(LastSolveSeconds, double);
  /// True when the last solve reused a preparation kept for its mesh (a re-solve with other
  /// settings, or after the relight or the EXR writer prepared the same mesh): no BVH,
  /// patch splitting or hemisphere probes (vtkRadiosityPreparedScenes).
  vtkGetMacro(LastPreparationReused, bool);
  /// How many preparations the process holds (at most four; each goes when its mesh's
  /// points are deleted or edited), and a way to drop them all now.
  static int GetPreparedScenesHeld();
  static void ReleasePreparedScenes();
  ///@}

protected:
  vtkLightTaggedRadiosity();
  ~vtkLightTaggedRadiosity() override = default;
  int Execute(const Run& run) override;
  void BeforeRun(const Run& run) override;
  bool GuardsInput(const Run& run) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;

private:
  vtkLightTaggedRadiosity(const vtkLightTaggedRadiosity&) = delete;
  void operator=(const vtkLightTaggedRadiosity&) = delete;

  /// Solves `input` (a whole scene) into `output` and `history`; 0 with the error
  /// reported when the input cannot be solved. With `ranks`, every rank of it calls this
  /// on the same scene and each computes the transport to its share of the receivers.
  int Solve(vtkPolyData* input, vtkPolyData* output, vtkTable* history, vtkMultiProcessController* ranks = nullptr);
  /// The core's options from this filter's settings.
  radiosity::SolverOptions Options(int threads, const radiosity::ProcessGroup& group) const;
  /// An effect setting as the solver takes it (On for all with ForceAllEffects).
  radiosity::EffectMode Effect(int mode) const;
  /// Writes the solved scene's arrays, field data and convergence table; 0 with the error
  /// reported when the moving-light basis asked for cannot be made.
  int WriteResult(vtkPolyData* input, vtkPolyData* output, vtkTable* history,
    const vtkRadiositySolveOutput::SceneInput& scene, const radiosity::RadiositySolver& solver,
    const radiosity::Solution& result, const radiosity::SolverOptions& options, bool aborted,
    std::chrono::steady_clock::time_point start, vtkRadiosityAdapter::WarningList& warnings, int rank);

  int SolutionMode = LIGHT_TAGGED;
  int SolverMethod = SOLVER_AUTO;
  int MaximumShots = 0;
  double ConvergenceThreshold = 1e-3;
  int FormFactorMethod = ANALYTIC;
  int FormFactorSamples = 4;
  double TimeBudget = 0;
  double ClusterSeparation = 3.0;
  std::map<std::string, double> MethodSettings;
  int GatherRays = 256;
  int GatherSweeps = 1;
  double GatherCache = 0.15;
  bool AmbientTerm = false;
  bool SeparateDirect = false;
  int NumberOfThreads = 0;
  int VisibilityEffect = EFFECT_AUTO;
  int InterreflectionEffect = EFFECT_AUTO;
  int ColorEffect = EFFECT_AUTO;
  int LightSeparationEffect = EFFECT_AUTO;
  int ConvergedLightsEffect = EFFECT_AUTO;
  bool ForceAllEffects = false;
  bool PatchBasis = false;
  int PatchBasisLevel = BASIS_AUTO;
  int LastShots = 0;
  bool LastConverged = false;
  long long LastRays = 0;
  double LastSolveSeconds = 0;
  bool LastPreparationReused = false;
};

#endif
