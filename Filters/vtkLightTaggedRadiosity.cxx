#include "vtkLightTaggedRadiosity.h"
#include "vtkRadiosityAdapter.h"

#include "LightSolutions.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <chrono>

vtkStandardNewMacro(vtkLightTaggedRadiosity);

vtkLightTaggedRadiosity::vtkLightTaggedRadiosity() = default;

void vtkLightTaggedRadiosity::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SolutionMode: " << this->SolutionMode << "\n";
  os << indent << "MaximumShots: " << this->MaximumShots << "\n";
  os << indent << "ConvergenceThreshold: " << this->ConvergenceThreshold << "\n";
  os << indent << "ShadowRays: " << this->ShadowRays << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}

namespace
{
vtkSmartPointer<vtkFloatArray> MakeArray(const std::string& name, const std::vector<radiosity::Vec3>& values,
  int columns, int column, size_t count)
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
}

int vtkLightTaggedRadiosity::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);

  radiosity::SceneMesh mesh;
  std::vector<radiosity::Vec3> emission;
  std::string error;
  int lights = 0;
  if (!vtkRadiosityAdapter::CopyPolygons(input, mesh, error) ||
    !vtkRadiosityAdapter::ReadSceneArrays(input, mesh, emission, error) ||
    !(error = radiosity::ValidateScene(mesh, lights)).empty())
  {
    vtkErrorMacro(<< "Cannot solve: " << error << ".");
    return 0;
  }

  const auto start = std::chrono::steady_clock::now();
  radiosity::ProgressiveRadiosity solver(mesh);
  if (!solver.Error().empty())
  {
    vtkErrorMacro(<< "Cannot solve: " << solver.Error() << ".");
    return 0;
  }
  radiosity::SolverOptions options;
  options.MaximumShots = this->MaximumShots;
  options.ConvergenceThreshold = this->ConvergenceThreshold;
  options.ShadowRays = this->ShadowRays;
  options.Threads = this->NumberOfThreads;
  options.Progress = [this](double f) {
    this->UpdateProgress(f);
    return !this->GetAbortExecute();
  };
  const auto mode = static_cast<radiosity::SolutionMode>(this->SolutionMode);
  const radiosity::LightSolutions result =
    radiosity::SolveLights(solver, mesh, lights, emission, mode, options);
  const std::vector<radiosity::Vec3> pointValues =
    radiosity::AverageToPoints(mesh, solver.Geometry(), result.Radiosity, result.Solutions);
  this->LastSolveSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->LastShots = result.Statistics.Shots;
  this->LastConverged = result.Statistics.Converged;
  this->LastShadowRays = result.Statistics.ShadowRayCount;
  if (result.Statistics.Aborted)
  {
    vtkWarningMacro(<< "Solve aborted after " << result.Statistics.Shots
                    << " shots; the output holds the partial result.");
  }

  output->ShallowCopy(input);
  const std::vector<std::string> names = vtkRadiosityAdapter::LightNames(input->GetFieldData(), lights);
  const size_t cells = mesh.NumberOfPolygons();
  const size_t points = mesh.points.size();
  for (int m = 0; m < result.Solutions; ++m)
  {
    const std::string name =
      mode == radiosity::SolutionMode::StandardCombined ? "Radiosity" : "Radiosity_" + names[m];
    output->GetCellData()->AddArray(MakeArray(name, result.Radiosity, result.Solutions, m, cells));
    output->GetPointData()->AddArray(MakeArray(name, pointValues, result.Solutions, m, points));
  }

  // Fresh field data: the input's arrays are shared, ours are added on top.
  vtkNew<vtkFieldData> fields;
  fields->ShallowCopy(input->GetFieldData());
  vtkNew<vtkStringArray> lightNames;
  lightNames->SetName("LightNames");
  for (const std::string& name : names)
  {
    lightNames->InsertNextValue(name);
  }
  fields->AddArray(lightNames);
  vtkNew<vtkDoubleArray> history;
  history->SetName("UnshotHistory");
  for (double r : result.Statistics.RemainingHistory)
  {
    history->InsertNextValue(r);
  }
  fields->AddArray(history);
  output->SetFieldData(fields);
  return 1;
}
