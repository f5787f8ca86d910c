#include "vtkLightTaggedRadiosity.h"
#include "vtkRadiosityAbort.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityPieces.h"
#include "vtkRadiosityPreparedScenes.h"
#include "vtkRadiositySolveOutput.h"

#include "Base/AccuracyLevels.h"
#include "Solve/LightChecks.h"
#include "Solve/LightSolutions.h"
#include "Solve/PatchBasis.h"
#include "Solve/SolverMethods.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkTable.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>

vtkStandardNewMacro(vtkLightTaggedRadiosity);

int vtkLightTaggedRadiosity::GetPreparedScenesHeld()
{
  return vtkRadiosityPreparedScenes::Held();
}

void vtkLightTaggedRadiosity::ReleasePreparedScenes()
{
  vtkRadiosityPreparedScenes::Clear();
}

vtkLightTaggedRadiosity::vtkLightTaggedRadiosity()
{
  this->SetNumberOfOutputPorts(2);
}

int vtkLightTaggedRadiosity::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkTable");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

int vtkLightTaggedRadiosity::GetNumberOfSolverMethods()
{
  return static_cast<int>(radiosity::SolverMethodTable().size()) + 1;
}

const char* vtkLightTaggedRadiosity::GetSolverMethodName(int value)
{
  if (value == SOLVER_AUTO)
  {
    return "Auto";
  }
  const radiosity::MethodEntry* entry = radiosity::FindSolverMethod(static_cast<radiosity::SolverMethod>(value));
  return entry ? entry->Name : nullptr;
}

void vtkLightTaggedRadiosity::SetMethodSetting(const char* name, double value)
{
  const std::string key = name ? name : "";
  const auto found = this->MethodSettings.find(key);
  if (found == this->MethodSettings.end() || !(found->second == value))
  {
    this->MethodSettings[key] = value;
    this->Modified();
  }
}

void vtkLightTaggedRadiosity::ClearMethodSettings()
{
  if (!this->MethodSettings.empty())
  {
    this->MethodSettings.clear();
    this->Modified();
  }
}

std::string vtkLightTaggedRadiosity::DescribeMethodSettings()
{
  std::string text;
  for (const radiosity::MethodEntry& entry : radiosity::SolverMethodTable())
  {
    for (const radiosity::MethodSetting& own : entry.Settings)
    {
      char row[160];
      std::snprintf(row, sizeof(row), "%s%s (%s, %g to %g)", text.empty() ? "" : "; ", own.Name, entry.Name, own.Min,
        own.Max);
      text += row;
    }
  }
  return text + ".";
}

namespace
{
/// Setting i over every row of the method table, with its method; null past them.
const radiosity::MethodSetting* KnownSetting(int i, const char** method = nullptr)
{
  for (const radiosity::MethodEntry& entry : radiosity::SolverMethodTable())
  {
    if (i >= 0 && i < static_cast<int>(entry.Settings.size()))
    {
      if (method)
      {
        *method = entry.Name;
      }
      return &entry.Settings[i];
    }
    i -= static_cast<int>(entry.Settings.size());
  }
  return nullptr;
}
} // namespace

int vtkLightTaggedRadiosity::GetNumberOfKnownMethodSettings()
{
  int count = 0;
  for (const radiosity::MethodEntry& entry : radiosity::SolverMethodTable())
  {
    count += static_cast<int>(entry.Settings.size());
  }
  return count;
}

const char* vtkLightTaggedRadiosity::GetKnownMethodSettingName(int i)
{
  const radiosity::MethodSetting* known = KnownSetting(i);
  return known ? known->Name : nullptr;
}

const char* vtkLightTaggedRadiosity::GetKnownMethodSettingMethod(int i)
{
  const char* method = nullptr;
  return KnownSetting(i, &method) ? method : nullptr;
}

double vtkLightTaggedRadiosity::GetKnownMethodSettingDefault(int i)
{
  const radiosity::MethodSetting* known = KnownSetting(i);
  return known ? known->Default : 0.0;
}

double vtkLightTaggedRadiosity::GetKnownMethodSettingMinimum(int i)
{
  const radiosity::MethodSetting* known = KnownSetting(i);
  return known ? known->Min : 0.0;
}

double vtkLightTaggedRadiosity::GetKnownMethodSettingMaximum(int i)
{
  const radiosity::MethodSetting* known = KnownSetting(i);
  return known ? known->Max : 0.0;
}

int vtkLightTaggedRadiosity::GetNumberOfMethodSettings() const
{
  return static_cast<int>(this->MethodSettings.size());
}

const char* vtkLightTaggedRadiosity::GetMethodSettingName(int i) const
{
  if (i < 0 || i >= this->GetNumberOfMethodSettings())
  {
    return nullptr;
  }
  return std::next(this->MethodSettings.begin(), i)->first.c_str();
}

double vtkLightTaggedRadiosity::GetMethodSettingValue(int i) const
{
  if (i < 0 || i >= this->GetNumberOfMethodSettings())
  {
    return 0.0;
  }
  return std::next(this->MethodSettings.begin(), i)->second;
}

void vtkLightTaggedRadiosity::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (const auto& setting : this->MethodSettings)
  {
    os << indent << "MethodSetting " << setting.first << ": " << setting.second << "\n";
  }
  os << indent << "SolutionMode: " << this->SolutionMode << "\n";
  os << indent << "FormFactorMethod: " << this->FormFactorMethod << "\n";
  os << indent << "FormFactorSamples: " << this->FormFactorSamples << "\n";
  os << indent << "SolverMethod: " << this->SolverMethod << "\n";
  os << indent << "MaximumShots: " << this->MaximumShots << "\n";
  os << indent << "ConvergenceThreshold: " << this->ConvergenceThreshold << "\n";
  os << indent << "TimeBudget: " << this->TimeBudget << "\n";
  os << indent << "GatherSweeps: " << this->GatherSweeps << "\n";
  os << indent << "GatherCache: " << this->GatherCache << "\n";
  os << indent << "ClusterSeparation: " << this->ClusterSeparation << "\n";
  os << indent << "GatherRays: " << this->GatherRays << "\n";
  os << indent << "AmbientTerm: " << this->AmbientTerm << "\n";
  os << indent << "SeparateDirect: " << this->SeparateDirect << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "Effects (visibility, interreflection, color, separation, converged): "
     << this->VisibilityEffect << " " << this->InterreflectionEffect << " " << this->ColorEffect << " "
     << this->LightSeparationEffect << " " << this->ConvergedLightsEffect
     << (this->ForceAllEffects ? " (all forced on)" : "") << "\n";
}

namespace
{

/// The preparation kept for `input`'s mesh where every rank has one (MarkEnclosed is
/// collective: the ranks must all prepare or all reuse), else a new one, kept for the next
/// solve, the relight and the pictures of this mesh.
std::string PrepareOrReuse(vtkPolyData* input, const vtkRadiositySolveOutput::SceneInput& scene, int threads,
  const radiosity::ProcessGroup& group, radiosity::PreparedScene& prepared, bool& reused)
{
  prepared = vtkRadiosityPreparedScenes::Find(input, scene.Key, true);
  reused = radiosity::AgreeOnFailure(group, prepared.Geometry ? "" : "not kept", "not kept").empty();
  if (reused)
  {
    return "";
  }
  // Kept here but not on every rank: all prepare again (rays kept here are reused).
  prepared.Geometry.reset();
  prepared.SplitPatches = 0;
  const std::string error = radiosity::PrepareTransport(scene.Mesh, threads, group, prepared);
  if (error.empty())
  {
    vtkRadiosityPreparedScenes::Keep(input, scene.Key, prepared);
  }
  return error;
}

/// Solves the moving-light basis and adds its arrays (see PatchBasisLevel); false, with
/// the error reported, when the basis cannot be made.
bool AddPatchBasis(vtkAlgorithm* self, int level, const radiosity::RadiositySolver& solver,
  const radiosity::SceneMesh& mesh, const radiosity::SolverOptions& options, vtkPolyData* output,
  vtkFieldData* fields, std::vector<radiosity::EffectDecision>& effects,
  vtkRadiosityAdapter::WarningList& warnings)
{
  radiosity::SolverStatistics stats;
  radiosity::PatchBasis basis;
  const std::string error =
    radiosity::SolvePatchBasis(solver, mesh, options, static_cast<radiosity::BasisLevel>(level), stats, basis);
  // The node basis runs on every rank alone: an abort on one must drop the basis on all,
  // or the pieces would differ in their arrays.
  stats.Aborted = !radiosity::AgreeOnFailure(options.Group, stats.Aborted ? "aborted" : "", "aborted").empty();
  if (stats.Aborted)
  {
    warnings.Add(self, "Moving-light basis aborted: the output has the light solutions but no basis.");
    return true;
  }
  if (!error.empty())
  {
    vtkErrorWithObjectMacro(self, << "Cannot solve the moving-light basis: " << error);
    return false;
  }
  vtkNew<vtkFloatArray> values;
  values->SetName("PatchBasis");
  values->SetNumberOfComponents(3 * basis.Patches);
  values->SetNumberOfTuples(basis.Receivers);
  std::copy(basis.Values.begin(), basis.Values.end(), values->GetPointer(0));
  const bool perElement = basis.Node.empty();
  if (perElement)
  {
    output->GetCellData()->AddArray(values);
  }
  else
  {
    fields->AddArray(values);
    vtkNew<vtkIntArray> nodes;
    nodes->SetName("PatchBasisNodes");
    nodes->SetNumberOfComponents(3);
    nodes->SetNumberOfTuples(output->GetNumberOfCells());
    std::copy(basis.Node.begin(), basis.Node.end(), nodes->GetPointer(0));
    vtkNew<vtkFloatArray> weights;
    weights->SetName("PatchBasisWeights");
    weights->SetNumberOfComponents(3);
    weights->SetNumberOfTuples(output->GetNumberOfCells());
    std::copy(basis.Weight.begin(), basis.Weight.end(), weights->GetPointer(0));
    output->GetCellData()->AddArray(nodes);
    output->GetCellData()->AddArray(weights);
  }
  radiosity::RecordBasisEffect(basis, stats, effects);
  if (!stats.Converged)
  {
    warnings.Add(self, "The patch basis stopped before converging (" + std::to_string(stats.Shots) +
        " shots); moving lights will miss some interreflection.");
  }
  return true;
}

}

void vtkLightTaggedRadiosity::BeforeRun(const Run& run)
{
  vtkTable::GetData(run.Outputs, 1)->Initialize(); // the convergence history
}

bool vtkLightTaggedRadiosity::GuardsInput(const Run& run)
{
  // On ParaView's MPI server every rank joins the gather even when its input failed
  // upstream (rank 0 then fails them all), so none is left waiting.
  return !run.Parallel;
}

int vtkLightTaggedRadiosity::Execute(const Run& run)
{
  vtkTable* history = vtkTable::GetData(run.Outputs, 1);
  vtkMultiProcessController* parallel = run.Parallel;
  if (!parallel)
  {
    return this->Solve(run.Input, run.Output, history);
  }
  // Light transport needs the whole scene: every rank holds it, computes the transport
  // to its share of the receivers, and keeps its own piece of the result.
  return vtkRadiosityPieces::SolveTogether(parallel, run.Input, run.Output, history,
    [this, parallel](vtkPolyData* whole, vtkPolyData* solved, vtkTable* table) {
      return this->Solve(whole, solved, table, parallel);
    });
}

// Options() converts SolverMethod and FormFactorMethod by a cast: the filter's numbers are the core's.
static_assert(static_cast<int>(radiosity::SolverMethod::Auto) == vtkLightTaggedRadiosity::SOLVER_AUTO &&
    static_cast<int>(radiosity::SolverMethod::ProgressiveRefinement) == vtkLightTaggedRadiosity::PROGRESSIVE_REFINEMENT &&
    static_cast<int>(radiosity::SolverMethod::Hierarchical) == vtkLightTaggedRadiosity::HIERARCHICAL &&
    static_cast<int>(radiosity::SolverMethod::Clustered) == vtkLightTaggedRadiosity::CLUSTERED,
  "vtkLightTaggedRadiosity::SolverMethods must number the methods as radiosity::SolverMethod does");
static_assert(static_cast<int>(radiosity::FormFactorMethod::Analytic) == vtkLightTaggedRadiosity::ANALYTIC &&
    static_cast<int>(radiosity::FormFactorMethod::Hemicube) == vtkLightTaggedRadiosity::HEMICUBE &&
    static_cast<int>(radiosity::FormFactorMethod::MonteCarlo) == vtkLightTaggedRadiosity::MONTE_CARLO,
  "vtkLightTaggedRadiosity::FormFactorMethods must number the methods as radiosity::FormFactorMethod does");

radiosity::SolverOptions vtkLightTaggedRadiosity::Options(int threads, const radiosity::ProcessGroup& group) const
{
  radiosity::SolverOptions options;
  options.SolverMethod = static_cast<radiosity::SolverMethod>(this->SolverMethod);
  options.MaximumShots = this->MaximumShots;
  options.ConvergenceThreshold = this->ConvergenceThreshold;
  options.TimeBudget = this->TimeBudget;
  options.Clustered.Separation = this->ClusterSeparation;
  options.Gather.Rays = this->GatherRays;
  options.Gather.Sweeps = this->GatherSweeps;
  options.Gather.CacheAccuracy = this->GatherCache;
  options.FormFactorMethod = static_cast<radiosity::FormFactorMethod>(this->FormFactorMethod);
  options.FormFactorSamples = this->FormFactorSamples;
  options.Threads = threads;
  options.AmbientTerm = this->AmbientTerm;
  options.SeparateDirect = this->SeparateDirect;
  options.Visibility = this->Effect(this->VisibilityEffect);
  options.Interreflection = this->Effect(this->InterreflectionEffect);
  options.Color = this->Effect(this->ColorEffect);
  options.ConvergedLights = this->Effect(this->ConvergedLightsEffect);
  options.Group = group;
  for (const auto& setting : this->MethodSettings)
  {
    radiosity::ApplyMethodSetting(setting.first, setting.second, options); // checked in Solve
  }
  return options;
}

namespace
{
/// The mesher's Accuracy level, stamped on the input (field array Accuracy), sets the
/// gather's rays and the clustered method's separation; without it the filter's own do.
/// Returns the level (-1: none).
int FollowAccuracy(vtkPolyData* input, radiosity::SolverOptions& options)
{
  vtkDataArray* level = input ? input->GetFieldData()->GetArray("Accuracy") : nullptr;
  const double value = level && level->GetNumberOfTuples() == 1 ? level->GetTuple1(0) : -1;
  if (!(value >= 0 && value < radiosity::kAccuracyLevels))
  {
    return -1;
  }
  const radiosity::AccuracyLevel& chosen = radiosity::AccuracyLevelOf(static_cast<int>(value));
  options.Gather.Rays = chosen.GatherRays;
  options.Gather.Sweeps = chosen.GatherSweeps;
  options.Clustered.Separation = chosen.ClusterSeparation;
  return static_cast<int>(value);
}

/// The text of a setting's value: an estimator by name, a number as %g.
std::string SettingText(const char* name, double value)
{
  static const char* const estimators[] = { "Analytic", "Hemicube", "MonteCarlo" };
  char number[32];
  std::snprintf(number, sizeof(number), "%g", value);
  return std::string(name) == "FormFactorMethod" && value >= 0 && value <= 2 ? estimators[static_cast<int>(value)]
                                                                             : number;
}

/// A setting the user changed that the solve did not use says so: one only another method
/// than `ran` reads (the method table's OwnSettings) where the method was set, not chosen
/// by Auto (whose estimate reads them all), else one the input's Accuracy level (`level`,
/// -1: none) replaced. Changed: unlike a new filter's. The patch basis reads
/// FormFactorMethod whatever method ran.
void SayUnusedSettings(vtkLightTaggedRadiosity* self, int level, radiosity::SolverMethod ran,
  vtkRadiosityAdapter::WarningList& warnings)
{
  vtkNew<vtkLightTaggedRadiosity> fresh;
  const radiosity::AccuracyLevel& chosen = radiosity::AccuracyLevelOf(std::max(level, 0));
  const double none = std::nan("");
  const struct
  {
    const char* Name;
    double Value, Default, Stamped;
  } settings[] = {
    { "GatherRays", double(self->GetGatherRays()), double(fresh->GetGatherRays()), double(chosen.GatherRays) },
    { "GatherSweeps", double(self->GetGatherSweeps()), double(fresh->GetGatherSweeps()), double(chosen.GatherSweeps) },
    { "ClusterSeparation", self->GetClusterSeparation(), fresh->GetClusterSeparation(), chosen.ClusterSeparation },
    { "FormFactorMethod", double(self->GetFormFactorMethod()), double(fresh->GetFormFactorMethod()), none },
  };
  const radiosity::MethodEntry* ranEntry = radiosity::FindSolverMethod(ran);
  const bool chosenByAuto = self->GetSolverMethod() == vtkLightTaggedRadiosity::SOLVER_AUTO;
  const bool stamped = level >= 0;
  char text[320];
  for (const auto& s : settings)
  {
    const radiosity::MethodEntry* owner = radiosity::MethodOwning(s.Name);
    const bool basisReads = self->GetPatchBasis() && std::string(s.Name) == "FormFactorMethod";
    const std::string value = SettingText(s.Name, s.Value);
    if (s.Value == s.Default)
    {
      continue;
    }
    if (owner && ranEntry && owner != ranEntry && !basisReads && !chosenByAuto)
    {
      std::snprintf(text, sizeof(text), "%s %s was not used: only the %s method reads it, and %s ran", s.Name,
        value.c_str(), owner->Name, ranEntry->Name);
    }
    else if (stamped && !std::isnan(s.Stamped) && s.Value != s.Stamped)
    {
      std::snprintf(text, sizeof(text), "%s %s was not used: the input's Accuracy level (%s, set in the mesher) sets %g; "
        "set the mesher's Accuracy to Custom to use the solver's own", s.Name, value.c_str(), chosen.Name, s.Stamped);
    }
    else
    {
      continue;
    }
    warnings.Add(self, text);
  }
  // Settings by name: Auto's estimate reads none of them; the patch basis runs the
  // hierarchical method whatever ran (BasisOptions), so it reads that method's.
  for (int i = 0; i < self->GetNumberOfMethodSettings(); ++i)
  {
    const radiosity::MethodEntry* owner = radiosity::MethodOwning(self->GetMethodSettingName(i));
    const bool basisReads = self->GetPatchBasis() && owner && owner->Method == radiosity::SolverMethod::Hierarchical;
    if (owner && ranEntry && owner != ranEntry && !basisReads)
    {
      std::snprintf(text, sizeof(text), "%s %g was not used: only the %s method reads it, and %s ran",
        self->GetMethodSettingName(i), self->GetMethodSettingValue(i), owner->Name, ranEntry->Name);
      warnings.Add(self, text);
    }
  }
}
} // namespace

radiosity::EffectMode vtkLightTaggedRadiosity::Effect(int mode) const
{
  return this->ForceAllEffects ? radiosity::EffectMode::On : static_cast<radiosity::EffectMode>(mode);
}

int vtkLightTaggedRadiosity::Solve(
  vtkPolyData* input, vtkPolyData* output, vtkTable* history, vtkMultiProcessController* ranks)
{
  namespace steps = vtkRadiositySolveOutput;
  vtkLogScopeF(TRACE, "solve"); // pvbatch --verbosity=TRACE times the solve and its steps
  steps::SceneInput scene;
  const bool combined = this->SolutionMode == STANDARD_COMBINED;
  const radiosity::ProcessGroup group = vtkRadiosityPieces::Group(ranks);
  std::string error;
  for (const auto& setting : this->MethodSettings)
  {
    radiosity::SolverOptions unused;
    error = error.empty() ? radiosity::ApplyMethodSetting(setting.first, setting.second, unused) : error;
  }
  error = error.empty() ? radiosity::OptionsProblem(this->Options(1, group)) : error;
  error = error.empty() ? steps::ReadInput(input, this->Effect(this->LightSeparationEffect), scene) : error;
  if (error.empty())
  {
    error = steps::CheckSolveMemory(
      scene, combined ? 1 : scene.Grouping.Solutions + static_cast<int>(scene.PointLights.size()), this->SeparateDirect, group);
  }
  const auto start = std::chrono::steady_clock::now();
  const int threads = vtkRadiosityAdapter::Threads(this->NumberOfThreads);
  radiosity::PreparedScene prepared;
  if (error.empty())
  {
    vtkLogScopeF(TRACE, "prepare the scene");
    scene.Key = vtkRadiosityPreparedScenes::KeyOf(input);
    error = PrepareOrReuse(input, scene, threads, group, prepared, this->LastPreparationReused);
  }
  const radiosity::RadiositySolver solver(scene.Mesh, prepared);
  const double preparing = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (error.empty() && (error = solver.Error()).empty())
  {
    error = radiosity::NoFiniteSolution(scene.Mesh, solver.Geometry(), solver.Rays());
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot solve: " << error << ".");
    return 0;
  }
  // Every rank finds the same warnings; rank 0 says them.
  vtkRadiosityAdapter::WarningList warnings(ranks && ranks->GetLocalProcessId() != 0);
  for (const std::string& warning : radiosity::CheckLights(scene.Mesh, solver.Geometry(), solver.Rays(), scene.LightNames))
  {
    warnings.Add(this, warning);
  }
  radiosity::SolverOptions options = this->Options(threads, group);
  const int level = FollowAccuracy(input, options);
  const vtkRadiosityAbortWatch abort(this);
  options.Progress = [this, abort](double f) {
    this->UpdateProgress(f);
    return !abort.Stop();
  };
  const auto mode = static_cast<radiosity::SolutionMode>(this->SolutionMode);
  vtkLogStartScope(TRACE, "shoot");
  radiosity::Solution result = radiosity::SolveLights(solver, scene.Mesh, scene.Grouping, scene.Emission, mode, options, scene.PointLights);
  vtkLogEndScope("shoot");
  std::vector<radiosity::SolverStatistics::Step>& booked = result.Statistics.Steps;
  booked.insert(booked.begin(), { this->LastPreparationReused ? "scene kept" : "prepare the scene", preparing });
  SayUnusedSettings(this, level, result.Statistics.SolverMethod, warnings);
  return this->WriteResult(input, output, history, scene, solver, result, options, abort.Stop(), start, warnings,
    ranks ? ranks->GetLocalProcessId() : 0);
}

int vtkLightTaggedRadiosity::WriteResult(vtkPolyData* input, vtkPolyData* output, vtkTable* history,
  const vtkRadiositySolveOutput::SceneInput& scene, const radiosity::RadiositySolver& solver,
  const radiosity::Solution& result, const radiosity::SolverOptions& options, bool aborted,
  std::chrono::steady_clock::time_point start, vtkRadiosityAdapter::WarningList& warnings, int rank)
{
  namespace steps = vtkRadiositySolveOutput;
  const bool combined = this->SolutionMode == STANDARD_COMBINED;
  const std::vector<std::string> names = steps::SolutionNames(scene, combined);
  output->ShallowCopy(input);
  steps::AddSolutionArrays(output, scene, solver, result, names, combined);
  this->LastSolveSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const radiosity::SolverStatistics& stats = result.Statistics;
  this->LastShots = stats.Shots;
  this->LastConverged = stats.Converged;
  this->LastRays = stats.RayCount;
  const std::string stop = steps::DescribeEarlyStop(stats, this->TimeBudget, this->ConvergenceThreshold);
  if (!stop.empty())
  {
    warnings.Add(this, stop);
  }
  // The output shares the input's points and polygons: the relight's moving lights and
  // the EXR writer find the solver's preparation under it, patches in the basis's order.
  vtkRadiosityPreparedScenes::Keep(output, vtkRadiosityPreparedScenes::WithPatchesOf(scene.Key, output), solver.Prepared());
  vtkNew<vtkFieldData> fields; // fresh: the input's arrays are shared, ours are added on top
  fields->ShallowCopy(input->GetFieldData());
  if (!combined)
  {
    steps::AddLightFields(this, fields, scene, names, warnings);
  }
  std::vector<radiosity::EffectDecision> effects = result.Effects;
  if (this->PatchBasis && !stats.Aborted &&
    !AddPatchBasis(this, this->PatchBasisLevel, solver, scene.Mesh, options, output, fields, effects, warnings))
  {
    output->Initialize();
    return 0;
  }
  steps::AddStatusFields(fields, effects, stats, aborted, this->LastSolveSeconds);
  steps::LogSolve(stats, this->LastSolveSeconds, scene.Mesh.NumberOfPolygons(), rank, effects);
  warnings.AddTo(fields, true); // the lights checked here again, on the mesh
  output->SetFieldData(fields);
  steps::FillHistory(history, stats, names, result.Solutions, combined);
  return 1;
}
