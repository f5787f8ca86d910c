#include "vtkLightTaggedRadiosity.h"
#include "vtkRadiosityAbort.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityPieces.h"
#include "vtkRadiosityPreparedScenes.h"

#include "Solve/Effects.h"
#include "Solve/LightChecks.h"
#include "Geometry/PointAverages.h"
#include "Solve/LightSolutions.h"
#include "Base/Memory.h"
#include "Solve/PatchBasis.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>

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

void vtkLightTaggedRadiosity::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SolutionMode: " << this->SolutionMode << "\n";
  os << indent << "FormFactorMethod: " << this->FormFactorMethod << "\n";
  os << indent << "FormFactorSamples: " << this->FormFactorSamples << "\n";
  os << indent << "SolverMethod: " << this->SolverMethod << "\n";
  os << indent << "MaximumShots: " << this->MaximumShots << "\n";
  os << indent << "ConvergenceThreshold: " << this->ConvergenceThreshold << "\n";
  os << indent << "TimeBudget: " << this->TimeBudget << "\n";
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
vtkSmartPointer<vtkFloatArray> MakeArray(const std::string& name,
  const std::vector<radiosity::Vec3>& values, int columns, int column, size_t count)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(count));
  float* out = array->GetPointer(0);
  for (size_t i = 0; i < count; ++i)
  {
    const radiosity::Vec3& v = values[i * columns + column];
    out[3 * i + 0] = static_cast<float>(v.x);
    out[3 * i + 1] = static_cast<float>(v.y);
    out[3 * i + 2] = static_cast<float>(v.z);
  }
  return array;
}

/// Names of the solutions: a light's own name, or its bank's members joined by '+'.
std::vector<std::string> SolutionNames(
  const std::vector<std::string>& lights, const radiosity::LightGrouping& grouping)
{
  std::vector<std::string> names(grouping.Solutions);
  for (size_t i = 0; i < lights.size(); ++i)
  {
    std::string& name = names[grouping.SolutionOfLight[i]];
    name += (name.empty() ? "" : "+") + lights[i];
  }
  return names;
}

/// The method that ran, with what its transport held (field array SolverMethod).
std::string DescribeMethod(const radiosity::SolverStatistics& stats)
{
  char text[256];
  if (stats.Method == radiosity::SolverMethod::Hierarchical)
  {
    std::snprintf(text, sizeof(text), "Hierarchical: %lld patch links, %lld element links, %.1f MB of links",
      stats.PatchLinks, stats.ElementLinks, stats.LinkBytes / 1048576.0);
  }
  else
  {
    std::snprintf(text, sizeof(text), "ProgressiveRefinement: %lld form factors", stats.FormFactorCount);
  }
  std::string described = text;
  if (stats.FaceClusters > 0)
  {
    described += "; " + std::to_string(stats.FaceClusters) + " face clusters";
  }
  return stats.MethodReason.empty() ? described : described + "; " + stats.MethodReason;
}

/// How the solve ended (field array SolverStatus); an aborted result is partial.
std::string DescribeStatus(const radiosity::SolverStatistics& stats, bool aborted)
{
  if (aborted || stats.Aborted)
  {
    return "aborted";
  }
  if (stats.Converged)
  {
    return "converged";
  }
  return stats.OutOfTime ? "stopped at TimeBudget" : "stopped at MaximumShots";
}

/// The preparation kept for `input`'s mesh where every rank has one (MarkEnclosed is
/// collective: the ranks must all prepare or all reuse), else a new one, kept for the next
/// solve, the relight and the pictures of this mesh.
std::string PrepareOrReuse(vtkPolyData* input, const radiosity::SceneMesh& mesh, int threads,
  const radiosity::ProcessGroup& group, radiosity::PreparedScene& prepared, bool& reused)
{
  prepared = vtkRadiosityPreparedScenes::Find(input, true);
  reused = radiosity::AgreeOnFailure(group, prepared.Geometry ? "" : "not kept", "not kept").empty();
  if (reused)
  {
    return "";
  }
  // Kept here but not on every rank: all prepare again (rays kept here are reused).
  prepared.Geometry.reset();
  prepared.SplitPatches = 0;
  const std::string error = radiosity::PrepareTransport(mesh, threads, group, prepared);
  if (error.empty())
  {
    vtkRadiosityPreparedScenes::Keep(input, prepared);
  }
  return error;
}

/// Why a solve stopped short of convergence, for a warning; empty if it converged.
std::string DescribeEarlyStop(const radiosity::SolverStatistics& stats, double budget, double threshold)
{
  const double remaining = stats.RemainingHistory.empty() ? 1.0 : stats.RemainingHistory.back();
  std::ostringstream text;
  if (stats.Aborted)
  {
    text << "Solve aborted after " << stats.Shots << " shots; the output holds the partial result.";
  }
  else if (stats.OutOfTime)
  {
    text << "TimeBudget of " << budget << " s reached after " << stats.Shots
         << " shots; remaining unshot energy " << remaining << " of the initial.";
  }
  else if (!stats.Converged)
  {
    text << "Stopped at MaximumShots (" << stats.ShotCap << ") before converging: remaining unshot energy "
         << remaining << " of the initial, threshold " << threshold
         << ". Raise MaximumShots (or use the ambient term) for a converged result.";
  }
  return text.str();
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

void AddColumn(vtkTable* table, const std::string& name, const std::vector<double>& values,
  size_t stride, size_t offset)
{
  vtkNew<vtkDoubleArray> column;
  column->SetName(name.c_str());
  const size_t rows = stride ? values.size() / stride : 0;
  column->SetNumberOfValues(static_cast<vtkIdType>(rows));
  for (size_t r = 0; r < rows; ++r)
  {
    column->SetValue(static_cast<vtkIdType>(r), values[r * stride + offset]);
  }
  table->AddColumn(column);
}
}

int vtkLightTaggedRadiosity::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkTable* history = vtkTable::GetData(outputVector, 1);
  history->Initialize();
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkMultiProcessController* parallel = vtkRadiosityPieces::Parallel(outputVector->GetInformationObject(0));
  // On ParaView's MPI server every rank joins the gather even when its input failed
  // upstream (rank 0 then fails them all), so none is left waiting.
  return vtkRadiosityAdapter::Guarded(this, parallel ? nullptr : input, output, [&]() -> int {
    if (!parallel)
    {
      return this->Solve(input, output, history);
    }
    // Light transport needs the whole scene: every rank holds it, computes the transport
    // to its share of the receivers, and keeps its own piece of the result.
    return vtkRadiosityPieces::SolveTogether(parallel, input, output, history,
      [this, parallel](vtkPolyData* whole, vtkPolyData* solved, vtkTable* table) {
        return this->Solve(whole, solved, table, parallel);
      });
  });
}

int vtkLightTaggedRadiosity::Solve(
  vtkPolyData* input, vtkPolyData* output, vtkTable* history, vtkMultiProcessController* ranks)
{
  {
    radiosity::SceneMesh mesh;
    std::vector<radiosity::Vec3> emission;
    std::string error;
    int lights = 0;
    // pvbatch --verbosity=TRACE (or VTK_LOGGER_VERBOSITY) times the solve and its steps.
    vtkLogScopeF(TRACE, "solve");
    if (!vtkRadiosityAdapter::CopyPolygons(input, mesh, error) ||
      !vtkRadiosityAdapter::ReadSceneArrays(input, mesh, emission, error) ||
      !(error = radiosity::ValidateScene(mesh, lights)).empty())
    {
      vtkErrorMacro(<< "Cannot solve: " << error << ".");
      return 0;
    }
    auto effect = [this](int mode) {
      return this->ForceAllEffects ? radiosity::EffectMode::On : static_cast<radiosity::EffectMode>(mode);
    };
    auto fieldInts = [input](const char* name) {
      std::vector<int> values;
      if (vtkDataArray* array = input->GetFieldData()->GetArray(name))
      {
        for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
        {
          values.push_back(static_cast<int>(array->GetComponent(i, 0)));
        }
      }
      return values;
    };
    radiosity::LightGrouping grouping;
    error = radiosity::GroupLights(lights, fieldInts("LightBanks"), fieldInts("StaticLights"),
      effect(this->LightSeparationEffect), grouping);
    if (!error.empty())
    {
      vtkErrorMacro(<< "Cannot solve: " << error << ".");
      return 0;
    }

    const int solutions = this->SolutionMode == STANDARD_COMBINED ? 1 : grouping.Solutions;
    const radiosity::ProcessGroup group = vtkRadiosityPieces::Group(ranks);
    // The ranks' memory differs: all must agree before the first sum of the solve.
    error = radiosity::CheckMemory(radiosity::SolveMemory(mesh.NumberOfPolygons(),
              static_cast<long long>(mesh.points.size()), solutions, this->SeparateDirect),
      std::to_string(solutions) + " solutions on " + std::to_string(mesh.NumberOfPolygons()) + " elements");
    if (!(error = radiosity::AgreeOnFailure(group, error, "has too little memory for the solve")).empty())
    {
      vtkErrorMacro(<< "Cannot solve: " << error
                    << "; group lights into LightBanks, solve StandardCombined, or use fewer elements.");
      return 0;
    }
    const auto start = std::chrono::steady_clock::now();
    const int threads = vtkRadiosityAdapter::Threads(this->NumberOfThreads);
    vtkLogStartScope(TRACE, "prepare the scene");
    radiosity::PreparedScene prepared;
    bool reused = false;
    error = PrepareOrReuse(input, mesh, threads, group, prepared, reused);
    vtkLogEndScope("prepare the scene");
    if (!error.empty())
    {
      vtkErrorMacro(<< "Cannot solve: " << error << ".");
      return 0;
    }
    this->LastPreparationReused = reused;
    const radiosity::RadiositySolver solver(mesh, prepared);
    if (!solver.Error().empty())
    {
      vtkErrorMacro(<< "Cannot solve: " << solver.Error() << ".");
      return 0;
    }
    // Every rank finds the same warnings; rank 0 says them.
    vtkRadiosityAdapter::WarningList warnings(ranks && ranks->GetLocalProcessId() != 0);
    for (const std::string& warning : radiosity::CheckLights(
           mesh, solver.Geometry(), solver.Rays(), vtkRadiosityAdapter::LightNames(input->GetFieldData(), lights)))
    {
      warnings.Add(this, warning);
    }
    radiosity::SolverOptions options;
    options.Solver = static_cast<radiosity::SolverMethod>(this->SolverMethod);
    options.MaximumShots = this->MaximumShots;
    options.ConvergenceThreshold = this->ConvergenceThreshold;
    options.TimeBudget = this->TimeBudget;
    options.Method = static_cast<radiosity::FormFactorMethod>(this->FormFactorMethod);
    options.Samples = this->FormFactorSamples;
    options.Threads = threads;
    options.AmbientTerm = this->AmbientTerm;
    options.SeparateDirect = this->SeparateDirect;
    options.Visibility = effect(this->VisibilityEffect);
    options.Interreflection = effect(this->InterreflectionEffect);
    options.Color = effect(this->ColorEffect);
    options.ConvergedSolutions = effect(this->ConvergedLightsEffect);
    options.Group = group;
    const vtkRadiosityAbortWatch abort(this);
    options.Progress = [this, abort](double f) {
      this->UpdateProgress(f);
      return !abort.Stop();
    };
    const auto mode = static_cast<radiosity::SolutionMode>(this->SolutionMode);
    vtkLogStartScope(TRACE, "shoot");
    const radiosity::Solution result =
      radiosity::SolveLights(solver, mesh, grouping, emission, mode, options);
    vtkLogEndScope("shoot");
    vtkLogStartScope(TRACE, "average to points");
    const int columns = result.Solutions;
    const std::vector<radiosity::Vec3> pointValues =
      radiosity::AverageToPoints(mesh, solver.Geometry(), result.Radiosity, columns);
    const std::vector<radiosity::Vec3> pointDirect = result.Direct.empty()
      ? std::vector<radiosity::Vec3>()
      : radiosity::AverageToPoints(mesh, solver.Geometry(), result.Direct, columns);
    vtkLogEndScope("average to points");
    this->LastSolveSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const radiosity::SolverStatistics& stats = result.Statistics;
    this->LastShots = stats.Shots;
    this->LastConverged = stats.Converged;
    this->LastRays = stats.RayCount;
    const std::string stop = DescribeEarlyStop(stats, this->TimeBudget, this->ConvergenceThreshold);
    if (!stop.empty())
    {
      warnings.Add(this, stop);
    }

    output->ShallowCopy(input);
    if (solver.SplitPatches() > 0)
    {
      // Patches cut by a wall were split for the solve; say so in PatchId, so that the
      // relight filter (moving lights) groups elements as the solver did.
      vtkNew<vtkIntArray> patchIds;
      patchIds->SetName("PatchId");
      patchIds->SetNumberOfTuples(static_cast<vtkIdType>(mesh.NumberOfPolygons()));
      const std::vector<int>& patchOf = solver.Geometry().elementPatch;
      std::copy(patchOf.begin(), patchOf.end(), patchIds->GetPointer(0));
      output->GetCellData()->AddArray(patchIds);
      vtkLogF(INFO, "LightTaggedRadiosity: %d patches split where a surface stands across them",
        solver.SplitPatches());
    }
    // The output shares the input's points and polygons: the relight's moving lights and
    // the EXR writer find the solver's preparation under it, patches in the basis's order.
    vtkRadiosityPreparedScenes::Keep(output, solver.Prepared());
    const bool combined = mode == radiosity::SolutionMode::StandardCombined;
    const std::vector<std::string> names = combined
      ? std::vector<std::string>{ "" }
      : SolutionNames(vtkRadiosityAdapter::LightNames(input->GetFieldData(), lights), grouping);
    const size_t cells = mesh.NumberOfPolygons();
    const size_t points = mesh.points.size();
    for (int m = 0; m < columns; ++m)
    {
      const std::string name = combined ? "Radiosity" : "Radiosity_" + names[m];
      output->GetCellData()->AddArray(MakeArray(name, result.Radiosity, columns, m, cells));
      output->GetPointData()->AddArray(MakeArray(name, pointValues, columns, m, points));
      if (!result.Direct.empty())
      {
        const std::string direct = combined ? "Direct" : "Direct_" + names[m];
        output->GetCellData()->AddArray(MakeArray(direct, result.Direct, columns, m, cells));
        output->GetPointData()->AddArray(MakeArray(direct, pointDirect, columns, m, points));
      }
    }

    // Fresh field data: the input's arrays are shared, ours are added on top.
    vtkNew<vtkFieldData> fields;
    fields->ShallowCopy(input->GetFieldData());
    if (!combined)
    {
      vtkNew<vtkStringArray> lightNames;
      lightNames->SetName("LightNames");
      for (const std::string& name : names)
      {
        lightNames->InsertNextValue(name);
      }
      fields->AddArray(lightNames);
      vtkNew<vtkDoubleArray> defaults;
      defaults->SetName("LightDefaultColors");
      defaults->SetNumberOfComponents(3);
      const std::vector<radiosity::Vec3> colors = radiosity::DefaultColors(mesh, grouping, emission);
      for (size_t m = 0; m < colors.size(); ++m)
      {
        const radiosity::Vec3& c = colors[m];
        defaults->InsertNextTuple3(c.x, c.y, c.z);
        if (c.x + c.y + c.z <= 0)
        {
          warnings.Add(this, "Light '" + names[m] +
              "' has zero Emission: it stays dark when relit until it is given a colour (its unit solution is there).");
        }
      }
      fields->AddArray(defaults);
    }
    std::vector<radiosity::EffectDecision> effects = result.Effects;
    if (this->PatchBasis && !stats.Aborted && !AddPatchBasis(this, this->PatchBasisLevel, solver, mesh, options, output, fields, effects, warnings))
    {
      output->Initialize();
      return 0;
    }
    vtkNew<vtkStringArray> effectNames, decisions, reasons;
    effectNames->SetName("Effects");
    decisions->SetName("EffectDecisions");
    reasons->SetName("EffectReasons");
    for (const radiosity::EffectDecision& e : effects)
    {
      effectNames->InsertNextValue(e.Effect);
      decisions->InsertNextValue(e.Simulated ? "simulated" : "skipped");
      reasons->InsertNextValue(e.Reason);
    }
    fields->AddArray(effectNames);
    fields->AddArray(decisions);
    fields->AddArray(reasons);
    const std::string method = DescribeMethod(stats);
    vtkNew<vtkStringArray> methodArray;
    methodArray->SetName("SolverMethod");
    methodArray->InsertNextValue(method);
    fields->AddArray(methodArray);
    vtkNew<vtkStringArray> status;
    status->SetName("SolverStatus");
    status->InsertNextValue(DescribeStatus(stats, abort.Stop()));
    fields->AddArray(status);
    vtkLogF(INFO, "LightTaggedRadiosity: %s; %d shots, %.3f s; %s", method.c_str(), stats.Shots,
      this->LastSolveSeconds, radiosity::SummarizeEffects(effects).c_str());
    if (stats.Ranks > 1)
    {
      vtkLogF(INFO,
        "LightTaggedRadiosity: rank %d of %d received for %d of %d elements and cast %lld rays; %lld sums over the "
        "ranks, %.0f bytes per shot, %.3f MB in all, %.3f s in sums",
        ranks->GetLocalProcessId(), stats.Ranks, stats.ReceivingElements, mesh.NumberOfPolygons(), stats.OwnRays,
        stats.Collectives, stats.ShotCollectiveBytes / std::max(stats.Shots, 1), stats.CollectiveBytes / 1e6,
        stats.CollectiveSeconds);
    }

    vtkNew<vtkDoubleArray> unshot;
    unshot->SetName("UnshotHistory");
    for (double r : stats.RemainingHistory)
    {
      unshot->InsertNextValue(r);
    }
    fields->AddArray(unshot);
    warnings.AddTo(fields);
    output->SetFieldData(fields);

    vtkNew<vtkIntArray> shotColumn;
    shotColumn->SetName("Shot");
    for (int s = 1; s <= stats.Shots; ++s)
    {
      shotColumn->InsertNextValue(s);
    }
    history->AddColumn(shotColumn);
    AddColumn(history, "Time", stats.TimeHistory, 1, 0);
    AddColumn(history, "Remaining", stats.RemainingHistory, 1, 0);
    for (int m = 0; m < columns && !combined; ++m)
    {
      AddColumn(history, "Remaining_" + names[m], stats.RemainingPerSolution, columns, m);
    }
    return 1;
  }
}
