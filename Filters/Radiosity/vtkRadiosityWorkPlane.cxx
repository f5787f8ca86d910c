#include "vtkRadiosityWorkPlane.h"
#include "vtkRadiosityAbort.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityPreparedScenes.h"
#include "vtkRadiositySolveOutput.h"

#include "Solve/FinalGather.h"
#include "Solve/WorkPlane.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkRadiosityWorkPlane);

namespace
{
/// The element solution per solution as the solver wrote it (cell arrays
/// Radiosity_<name>, [e * solutions + m]); empty with `error` where one is missing.
std::vector<radiosity::Vec3> ElementSolution(vtkPolyData* input, const std::vector<std::string>& names, std::string& error)
{
  const vtkIdType n = input->GetNumberOfCells();
  const size_t s = names.size();
  std::vector<radiosity::Vec3> values(static_cast<size_t>(n) * s);
  for (size_t m = 0; m < s; ++m)
  {
    vtkDataArray* array = input->GetCellData()->GetArray(("Radiosity_" + names[m]).c_str());
    if (!array || array->GetNumberOfComponents() != 3 || array->GetNumberOfTuples() != n)
    {
      error = "the input has no cell array Radiosity_" + names[m] + " (give it the light-tagged solver's output)";
      return {};
    }
    for (vtkIdType e = 0; e < n; ++e)
    {
      double v[3];
      array->GetTuple(e, v);
      values[static_cast<size_t>(e) * s + m] = { v[0], v[1], v[2] };
    }
  }
  return values;
}

/// The grid's points and quads as polydata.
void WriteGrid(const radiosity::WorkPlaneGrid& grid, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const radiosity::Vec3& p : grid.Points)
  {
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> quads;
  for (const std::array<int, 4>& q : grid.Quads)
  {
    const vtkIdType ids[4] = { q[0], q[1], q[2], q[3] };
    quads->InsertNextCell(4, ids);
  }
  output->SetPoints(points);
  output->SetPolys(quads);
}

void AddValue(vtkFieldData* fields, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fields->AddArray(array);
}

/// Each solution's emission per element ([e * solutions + m]): the cell lights' as solved,
/// none for the luminaires' solutions after them.
std::vector<radiosity::Vec3> EveryEmission(const vtkRadiositySolveOutput::SceneInput& scene, int solutions)
{
  const std::vector<radiosity::Vec3> cells = radiosity::SolutionEmission(scene.Mesh, scene.Grouping, scene.Emission);
  const int own = scene.Grouping.Solutions;
  std::vector<radiosity::Vec3> wide(static_cast<size_t>(scene.Mesh.NumberOfPolygons()) * solutions);
  for (int e = 0; e < scene.Mesh.NumberOfPolygons(); ++e)
  {
    std::copy_n(cells.begin() + static_cast<size_t>(e) * own, own, wide.begin() + static_cast<size_t>(e) * solutions);
  }
  return wide;
}

/// The point arrays Illuminance_<light> and Illuminance (their sum at the lights' default
/// colors, the mean of the channels), and the field arrays of the plane's statistics.
radiosity::PlaneStatistics AddIlluminance(const vtkRadiositySolveOutput::SceneInput& scene,
  const std::vector<std::string>& names, const radiosity::GatheredPoints& at, vtkPolyData* output)
{
  std::vector<radiosity::Vec3> colors = radiosity::DefaultColors(scene.Mesh, scene.Grouping, scene.Emission);
  for (const radiosity::PointLight& light : scene.PointLights)
  {
    colors.push_back(light.Color);
  }
  const size_t s = names.size(), points = at.Irradiance.size() / std::max<size_t>(1, s);
  std::vector<double> combined(points, 0.0);
  for (size_t m = 0; m < s; ++m)
  {
    vtkNew<vtkFloatArray> array;
    array->SetName(("Illuminance_" + names[m]).c_str());
    array->SetNumberOfComponents(3);
    array->SetNumberOfTuples(static_cast<vtkIdType>(points));
    for (size_t p = 0; p < points; ++p)
    {
      const radiosity::Vec3& e = at.Irradiance[p * s + m];
      array->SetTuple3(static_cast<vtkIdType>(p), e.x, e.y, e.z);
      combined[p] += radiosity::Dot(radiosity::Times(colors[m], e), { 1.0 / 3, 1.0 / 3, 1.0 / 3 });
    }
    output->GetPointData()->AddArray(array);
  }
  vtkNew<vtkDoubleArray> total;
  total->SetName("Illuminance");
  for (double v : combined)
  {
    total->InsertNextValue(v);
  }
  output->GetPointData()->AddArray(total);
  output->GetPointData()->SetActiveScalars("Illuminance");
  const radiosity::PlaneStatistics stats = radiosity::WorkPlaneStatistics(combined);
  AddValue(output->GetFieldData(), "IlluminanceMean", stats.Mean);
  AddValue(output->GetFieldData(), "IlluminanceMinimum", stats.Minimum);
  AddValue(output->GetFieldData(), "IlluminanceMaximum", stats.Maximum);
  AddValue(output->GetFieldData(), "Uniformity", stats.Uniformity);
  vtkRadiosityAdapter::AddStrings(output->GetFieldData(), "LightNames", names);
  return stats;
}

int UpOf(int asked, const double bounds[6])
{
  if (asked >= 0)
  {
    return asked;
  }
  int up = 0;
  for (int a = 1; a < 3; ++a)
  {
    up = bounds[2 * a + 1] - bounds[2 * a] < bounds[2 * up + 1] - bounds[2 * up] ? a : up;
  }
  return up;
}
}

int vtkRadiosityWorkPlane::Execute(const Run& run)
{
  vtkPolyData* input = run.Input;
  vtkPolyData* output = run.Output;
  namespace steps = vtkRadiositySolveOutput;
  steps::SceneInput scene;
  std::string error = steps::ReadInput(input, radiosity::EffectMode::Auto, scene);
  const std::vector<std::string> names = steps::SolutionNames(scene, false);
  const std::vector<radiosity::Vec3> solution = error.empty() ? ElementSolution(input, names, error) : std::vector<radiosity::Vec3>();
  double bounds[6];
  input->GetBounds(bounds);
  const bool room = std::any_of(this->Area, this->Area + 6, [](double v) { return v != 0; });
  if (room)
  {
    std::copy(this->Area, this->Area + 6, bounds);
  }
  const int up = UpOf(this->UpAxis, bounds);
  const radiosity::WorkPlaneGrid laid = error.empty()
    ? radiosity::LayWorkPlane(bounds, up, this->Height, this->Border, this->Spacing, error)
    : radiosity::WorkPlaneGrid();
  const vtkRadiosityPreparedScenes::MeshKey key = vtkRadiosityPreparedScenes::KeyOf(input);
  radiosity::PreparedScene prepared = vtkRadiosityPreparedScenes::Find(input, key, true);
  if (error.empty() && !prepared.Geometry)
  {
    error = radiosity::PrepareTransport(scene.Mesh, vtkRadiosityAdapter::Threads(0), radiosity::ProcessGroup(), prepared);
    vtkRadiosityPreparedScenes::Keep(input, key, prepared);
  }
  // In a room's box, only the points inside the room (its floor below, its ceiling above);
  // over the whole scene, those over a floor.
  const radiosity::WorkPlaneGrid grid = error.empty()
    ? radiosity::KeptPoints(laid,
        radiosity::PointsInRoom(laid, up, this->Height, room, *prepared.Rays, prepared.Geometry->Normal))
    : laid;
  if (error.empty() && grid.Points.empty())
  {
    std::ostringstream none;
    none << "none of its " << laid.Points.size() << " points stands " << this->Height << " over a floor"
         << (room ? " under a ceiling (is the room's box right?)" : "");
    error = none.str();
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot lay the work plane: " << error << ".");
    return 0;
  }
  const int s = static_cast<int>(names.size());
  radiosity::GatherSettings settings;
  settings.Rays = this->GatherRays;
  settings.PointLights = &scene.PointLights;
  settings.FirstPointSolution = scene.Grouping.Solutions;
  const vtkRadiosityAbortWatch abort(this);
  const radiosity::GatheredPoints at = radiosity::IrradianceAtPoints(scene.Mesh, *prepared.Geometry, *prepared.Rays,
    EveryEmission(scene, s),
    solution, s, grid.Points, std::vector<radiosity::Vec3>(grid.Points.size(), grid.Normal), settings,
    vtkRadiosityAdapter::Threads(0), [this, &abort](double f) {
      this->UpdateProgress(f);
      return !abort.Stop();
    });
  if (at.Aborted)
  {
    vtkErrorMacro(<< "Cannot lay the work plane: aborted.");
    return 0;
  }
  WriteGrid(grid, output);
  const radiosity::PlaneStatistics stats = AddIlluminance(scene, names, at, output);
  vtkLogF(INFO, "Work plane: %d x %d points, %.3g apart, %d of them outside %s; mean %.4g, minimum %.4g, uniformity %.3f",
    grid.Nu, grid.Nv, std::max(grid.SpacingU, grid.SpacingV), static_cast<int>(laid.Points.size() - grid.Points.size()),
    room ? "the room" : "any floor", stats.Mean, stats.Minimum, stats.Uniformity);
  return 1;
}

void vtkRadiosityWorkPlane::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "Border: " << this->Border << "\n";
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "UpAxis: " << this->UpAxis << "\n";
  os << indent << "GatherRays: " << this->GatherRays << "\n";
  os << indent << "Area: " << this->Area[0] << " " << this->Area[1] << " " << this->Area[2] << " " << this->Area[3] << " "
     << this->Area[4] << " " << this->Area[5] << "\n";
}
