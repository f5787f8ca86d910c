#include "vtkRadiositySolveOutput.h"

#include "vtkRadiosityLuminaires.h"

#include "Base/Memory.h"
#include "Geometry/PointAverages.h"
#include "Solve/Effects.h"
#include "Solve/LightChecks.h"
#include "Solve/SolverMethods.h"

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace vtkRadiositySolveOutput
{
namespace
{
std::vector<int> FieldInts(vtkPolyData* input, const char* name)
{
  std::vector<int> values;
  if (vtkDataArray* array = input->GetFieldData()->GetArray(name))
  {
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
    {
      values.push_back(static_cast<int>(array->GetComponent(i, 0)));
    }
  }
  return values;
}

vtkSmartPointer<vtkFloatArray> MakeArray(
  const std::string& name, const std::vector<radiosity::Vec3>& values, int columns, int column, size_t count)
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

/// Cell and point arrays `name` for each solution of `cellValues`; the points take
/// `gathered` (the final gather) where there is one, else their cells' mean.
void AddPerSolution(vtkPolyData* output, const radiosity::SceneMesh& mesh, const radiosity::SceneGeometry& g,
  const std::vector<radiosity::Vec3>& cellValues, const std::vector<radiosity::Vec3>& gathered, int columns,
  const std::vector<std::string>& names, const std::string& prefix, bool combined)
{
  const std::vector<radiosity::Vec3> pointValues =
    gathered.empty() ? radiosity::AverageToPoints(mesh, g, cellValues, columns) : gathered;
  for (int m = 0; m < columns; ++m)
  {
    const std::string name = combined ? prefix : prefix + "_" + names[m];
    output->GetCellData()->AddArray(MakeArray(name, cellValues, columns, m, mesh.NumberOfPolygons()));
    output->GetPointData()->AddArray(MakeArray(name, pointValues, columns, m, mesh.Points.size()));
  }
}

void AddColumn(vtkTable* table, const std::string& name, const std::vector<double>& values, size_t stride,
  size_t offset)
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
  if (!stats.OutOfMemory.empty())
  {
    return "stopped: out of memory";
  }
  return stats.OutOfTime ? "stopped at TimeBudget" : "stopped at MaximumShots";
}
} // namespace

std::string ReadInput(vtkPolyData* input, radiosity::EffectMode separation, SceneInput& scene)
{
  std::string error;
  std::vector<radiosity::LuminaireRow> rows;
  if (!vtkRadiosityAdapter::CopyPolygons(input, scene.Mesh, error) ||
    !vtkRadiosityAdapter::ReadSceneArrays(input, scene.Mesh, scene.Emission, error) ||
    !vtkRadiosityLuminaires::Read(input->GetFieldData(), rows, error) ||
    !(error = radiosity::ValidateScene(scene.Mesh, scene.Lights, static_cast<int>(rows.size()))).empty())
  {
    return error;
  }
  scene.LightNames = vtkRadiosityAdapter::LightNames(input->GetFieldData(), scene.Lights);
  if (!(error = radiosity::LuminaireNamesProblem(rows, scene.LightNames)).empty())
  {
    return error;
  }
  scene.PointLights.resize(rows.size());
  for (size_t i = 0; i < rows.size() && error.empty(); ++i)
  {
    error = radiosity::MakePointLight(rows[i], scene.PointLights[i]);
    scene.PointLightNames.push_back(rows[i].Name);
  }
  return error.empty() ? radiosity::GroupLights(scene.Lights, FieldInts(input, "LightBanks"),
                           FieldInts(input, "StaticLights"), separation, scene.Grouping)
                       : error;
}

std::string CheckSolveMemory(
  const SceneInput& scene, int solutions, bool separateDirect, const radiosity::ProcessGroup& group)
{
  const int elements = scene.Mesh.NumberOfPolygons();
  std::string error = radiosity::CheckMemory(
    radiosity::SolveMemory(elements, static_cast<long long>(scene.Mesh.Points.size()), solutions, separateDirect),
    std::to_string(solutions) + " solutions on " + std::to_string(elements) + " elements");
  error = radiosity::AgreeOnFailure(group, error, "has too little memory for the solve");
  return error.empty() ? error
                       : error + "; group lights into LightBanks, solve StandardCombined, or use fewer elements";
}

std::vector<std::string> SolutionNames(const SceneInput& scene, bool combined)
{
  if (combined)
  {
    return { "" };
  }
  std::vector<std::string> names(scene.Grouping.Solutions);
  for (size_t i = 0; i < scene.LightNames.size(); ++i)
  {
    std::string& name = names[scene.Grouping.SolutionOfLight[i]];
    name += (name.empty() ? "" : "+") + scene.LightNames[i];
  }
  names.insert(names.end(), scene.PointLightNames.begin(), scene.PointLightNames.end());
  return names;
}

void AddSolutionArrays(vtkPolyData* output, const SceneInput& scene, const radiosity::RadiositySolver& solver,
  const radiosity::Solution& result, const std::vector<std::string>& names, bool combined)
{
  const radiosity::SceneMesh& mesh = scene.Mesh;
  if (solver.SplitPatches() > 0)
  {
    // Patches cut by a wall were split for the solve; say so in PatchId, so that the
    // relight filter (moving lights) groups elements as the solver did.
    vtkNew<vtkIntArray> patchIds;
    patchIds->SetName("PatchId");
    patchIds->SetNumberOfTuples(static_cast<vtkIdType>(mesh.NumberOfPolygons()));
    const std::vector<int>& patchOf = solver.Geometry().ElementPatch;
    std::copy(patchOf.begin(), patchOf.end(), patchIds->GetPointer(0));
    output->GetCellData()->AddArray(patchIds);
    vtkLogF(INFO, "LightTaggedRadiosity: %d patches split where a surface stands across them", solver.SplitPatches());
  }
  vtkLogScopeF(TRACE, "average to points");
  AddPerSolution(output, mesh, solver.Geometry(), result.Radiosity, result.PointRadiosity, result.Solutions, names,
    "Radiosity", combined);
  if (!result.Direct.empty())
  {
    AddPerSolution(output, mesh, solver.Geometry(), result.Direct, result.PointDirect, result.Solutions, names,
      "Direct", combined);
  }
  if (!result.Irradiance.empty())
  {
    AddPerSolution(output, mesh, solver.Geometry(), result.Irradiance, result.PointIrradiance, result.Solutions, names,
      "Illuminance", combined);
  }
}

void AddLightFields(vtkAlgorithm* self, vtkFieldData* fields, const SceneInput& scene,
  const std::vector<std::string>& names, vtkRadiosityAdapter::WarningList& warnings)
{
  vtkRadiosityAdapter::AddStrings(fields, "LightNames", names);
  vtkNew<vtkDoubleArray> defaults;
  defaults->SetName("LightDefaultColors");
  defaults->SetNumberOfComponents(3);
  std::vector<radiosity::Vec3> colors = radiosity::DefaultColors(scene.Mesh, scene.Grouping, scene.Emission);
  for (const radiosity::PointLight& light : scene.PointLights)
  {
    colors.push_back(light.Color); // a luminaire's solution is white, at its lumens
  }
  for (size_t m = 0; m < colors.size(); ++m)
  {
    const radiosity::Vec3& c = colors[m];
    defaults->InsertNextTuple3(c.x, c.y, c.z);
    if (c.x + c.y + c.z <= 0)
    {
      warnings.Add(self, "Light '" + names[m] +
          "' has zero Emission: it stays dark when relit until it is given a color (its unit solution is there).");
    }
  }
  fields->AddArray(defaults);
}

void AddStatusFields(vtkFieldData* fields, const std::vector<radiosity::EffectDecision>& effects,
  const radiosity::SolverStatistics& stats, bool aborted, double seconds)
{
  std::vector<std::string> names, decisions, reasons;
  for (const radiosity::EffectDecision& e : effects)
  {
    names.push_back(e.Effect);
    decisions.push_back(e.Simulated ? "simulated" : "skipped");
    reasons.push_back(e.Reason);
  }
  vtkRadiosityAdapter::AddStrings(fields, "Effects", names);
  vtkRadiosityAdapter::AddStrings(fields, "EffectDecisions", decisions);
  vtkRadiosityAdapter::AddStrings(fields, "EffectReasons", reasons);
  vtkRadiosityAdapter::AddStrings(fields, "SolverMethod", { radiosity::DescribeSolve(stats) });
  vtkRadiosityAdapter::AddStrings(fields, "SolverStatus", { DescribeStatus(stats, aborted) });
  vtkNew<vtkDoubleArray> took;
  took->SetName("SolveSeconds");
  took->InsertNextValue(seconds);
  fields->AddArray(took);
  std::vector<std::string> steps;
  vtkNew<vtkDoubleArray> stepSeconds;
  stepSeconds->SetName("SolveStepSeconds");
  for (const radiosity::SolverStatistics::Step& step : stats.Steps)
  {
    steps.push_back(step.Name);
    stepSeconds->InsertNextValue(step.Seconds);
  }
  vtkRadiosityAdapter::AddStrings(fields, "SolveSteps", steps);
  fields->AddArray(stepSeconds);
  vtkNew<vtkDoubleArray> unshot;
  unshot->SetName("UnshotHistory");
  for (double r : stats.RemainingHistory)
  {
    unshot->InsertNextValue(r);
  }
  fields->AddArray(unshot);
}

void FillHistory(vtkTable* history, const radiosity::SolverStatistics& stats, const std::vector<std::string>& names,
  int columns, bool combined)
{
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
}

std::string DescribeEarlyStop(const radiosity::SolverStatistics& stats, double budget, double threshold)
{
  const double remaining = stats.RemainingHistory.empty() ? 1.0 : stats.RemainingHistory.back();
  std::ostringstream text;
  if (stats.Aborted)
  {
    text << "Solve aborted after " << stats.Shots << " shots; the output holds the partial result.";
  }
  else if (!stats.OutOfMemory.empty())
  {
    text << "Stopped: " << stats.OutOfMemory << "; the output holds the direct light. Use a larger ElementSize "
         << "(fewer elements) or SolverMethod Hierarchical.";
  }
  else if (stats.OutOfTime)
  {
    text << "TimeBudget of " << budget << " s reached after " << stats.Shots << " shots; remaining unshot energy "
         << remaining << " of the initial.";
  }
  else if (stats.AmbientAtCap)
  {
    text << "Stopped at the shot cap (" << stats.ShotCap << ") before converging: the remaining unshot energy ("
         << remaining << " of the initial) was added as the ambient term (spread evenly, interreflected in "
         << "closed form), which suits closed, highly reflective scenes, where the cap is met. Raise "
         << "MaximumShots for a result that does not rely on it.";
  }
  else if (!stats.Converged)
  {
    text << "Stopped at MaximumShots (" << stats.ShotCap << ") before converging: remaining unshot energy "
         << remaining << " of the initial, threshold " << threshold
         << ". Raise MaximumShots (or use the ambient term) for a converged result.";
  }
  return text.str();
}

void LogSolve(const radiosity::SolverStatistics& stats, double seconds, int elements, int rank,
  const std::vector<radiosity::EffectDecision>& effects)
{
  std::string steps;
  for (const radiosity::SolverStatistics::Step& step : stats.Steps)
  {
    char text[96];
    std::snprintf(text, sizeof(text), "%s%s %.1f s", steps.empty() ? "" : ", ", step.Name.c_str(), step.Seconds);
    steps += text;
  }
  vtkLogF(INFO, "LightTaggedRadiosity: %s; %d shots, %.3f s (%s); %s", radiosity::DescribeSolve(stats).c_str(),
    stats.Shots, seconds, steps.c_str(), radiosity::SummarizeEffects(effects).c_str());
  if (stats.Ranks > 1)
  {
    vtkLogF(INFO,
      "LightTaggedRadiosity: rank %d of %d received for %d of %d elements and cast %lld rays; %lld sums over the "
      "ranks, %.0f bytes per shot, %.3f MB in all, %.3f s in sums",
      rank, stats.Ranks, stats.ReceivingElements, elements, stats.OwnRays, stats.Collectives,
      stats.ShotCollectiveBytes / std::max(stats.Shots, 1), stats.CollectiveBytes / 1e6, stats.CollectiveSeconds);
  }
}
}
