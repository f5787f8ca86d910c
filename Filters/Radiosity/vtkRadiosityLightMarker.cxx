#include "vtkRadiosityLightMarker.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityLuminaires.h"
#include "vtkRadiosityPieces.h"

#include "Solve/LightChecks.h"
#include "Import/LightMarking.h"
#include "Geometry/Polygon.h"
#include "Geometry/PreparedScene.h"
#include "Import/SceneImport.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExtractSelection.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSelection.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkRadiosityLightMarker);

struct vtkRadiosityLightMarker::Choices
{
  std::vector<vtkIdType> CellIds;
  std::vector<radiosity::AreaLight> AreaLights;
  std::vector<radiosity::LuminaireRow> Luminaires;
};

namespace
{

/// The light arrays as vectors (created: -1 and black where the input has none).
struct LightArrays
{
  std::vector<int> Id;
  std::vector<radiosity::Vec3> Emission;
  std::vector<std::string> Names;
};

LightArrays ReadLights(vtkPolyData* data)
{
  LightArrays lights;
  const vtkIdType cells = data->GetNumberOfCells();
  vtkDataArray* ids = data->GetCellData()->GetArray("LightId");
  vtkDataArray* emission = data->GetCellData()->GetArray("Emission");
  int count = 0;
  for (vtkIdType c = 0; c < cells; ++c)
  {
    lights.Id.push_back(ids ? static_cast<int>(ids->GetComponent(c, 0)) : -1);
    count = std::max(count, lights.Id.back() + 1);
    double e[3] = { 0, 0, 0 };
    if (emission && emission->GetNumberOfComponents() == 3)
    {
      emission->GetTuple(c, e);
    }
    lights.Emission.push_back({ e[0], e[1], e[2] });
  }
  lights.Names = vtkRadiosityAdapter::LightNames(data->GetFieldData(), count);
  return lights;
}

void WriteLights(const LightArrays& lights, vtkPolyData* data)
{
  vtkNew<vtkIntArray> ids;
  ids->SetName("LightId");
  ids->SetNumberOfValues(static_cast<vtkIdType>(lights.Id.size()));
  std::copy(lights.Id.begin(), lights.Id.end(), ids->GetPointer(0));
  vtkNew<vtkDoubleArray> emission;
  emission->SetName("Emission");
  emission->SetNumberOfComponents(3);
  emission->SetNumberOfTuples(static_cast<vtkIdType>(lights.Emission.size()));
  for (size_t c = 0; c < lights.Emission.size(); ++c)
  {
    const radiosity::Vec3& e = lights.Emission[c];
    emission->SetTuple3(static_cast<vtkIdType>(c), e.x, e.y, e.z);
  }
  data->GetCellData()->AddArray(ids);
  data->GetCellData()->AddArray(emission);
  vtkNew<vtkStringArray> names;
  names->SetName("LightNames");
  for (const std::string& name : lights.Names)
  {
    names->InsertNextValue(name);
  }
  data->GetFieldData()->AddArray(names);
}

/// Index of the light called `name`, added at the end when new.
int LightIndex(LightArrays& lights, const std::string& name)
{
  const auto found = std::find(lights.Names.begin(), lights.Names.end(), name);
  if (found != lights.Names.end())
  {
    return static_cast<int>(found - lights.Names.begin());
  }
  lights.Names.push_back(name);
  return static_cast<int>(lights.Names.size()) - 1;
}

/// Cells whose material matches `pattern`; an error if the arrays are missing or none matches.
std::string ChooseByMaterial(vtkPolyData* data, const std::string& pattern, std::vector<char>& chosen)
{
  vtkDataArray* ids = data->GetCellData()->GetArray("MaterialIds");
  auto* names = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray("MaterialNames"));
  if (!ids || !names)
  {
    return "MaterialPattern needs the cell array MaterialIds and the field array MaterialNames "
           "(as the scene reader writes them)";
  }
  std::vector<char> matches(names->GetNumberOfValues());
  std::string all;
  for (vtkIdType m = 0; m < names->GetNumberOfValues(); ++m)
  {
    matches[m] = radiosity::MatchesPattern(pattern, names->GetValue(m));
    all += (m ? ", '" : "'") + names->GetValue(m) + "'";
  }
  int count = 0;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
  {
    const vtkIdType m = static_cast<vtkIdType>(ids->GetComponent(c, 0));
    if (m >= 0 && m < static_cast<vtkIdType>(matches.size()) && matches[m])
    {
      chosen[c] = 1;
      ++count;
    }
  }
  return count ? std::string() : "no cell has a material matching '" + pattern + "'; the materials are " + all;
}

/// Cells the selection holds (their ids in `data`), through VTK's selection extraction.
int ChooseBySelection(vtkPolyData* data, vtkSelection* selection, std::vector<char>& chosen)
{
  vtkNew<vtkExtractSelection> extract;
  extract->SetInputData(0, data);
  extract->SetInputData(1, selection);
  extract->Update();
  auto* picked = vtkDataSet::SafeDownCast(extract->GetOutputDataObject(0));
  vtkDataArray* original = picked ? picked->GetCellData()->GetArray("vtkOriginalCellIds") : nullptr;
  int count = 0;
  for (vtkIdType i = 0; original && i < original->GetNumberOfTuples(); ++i)
  {
    const vtkIdType c = static_cast<vtkIdType>(original->GetComponent(i, 0));
    if (c >= 0 && c < data->GetNumberOfCells())
    {
      count += !chosen[c];
      chosen[c] = 1;
    }
  }
  return count;
}

/// Grows every array of `attributes` to `count` tuples, the new ones zero (or empty).
void GrowArrays(vtkDataSetAttributes* attributes, vtkIdType count)
{
  for (int a = 0; a < attributes->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = attributes->GetAbstractArray(a);
    const vtkIdType old = array->GetNumberOfTuples();
    array->Resize(count); // keeps the values; SetNumberOfTuples alone may reallocate without them
    array->SetNumberOfTuples(count);
    if (auto* numbers = vtkDataArray::SafeDownCast(array))
    {
      for (int c = 0; c < numbers->GetNumberOfComponents(); ++c)
      {
        for (vtkIdType t = old; t < count; ++t)
        {
          numbers->SetComponent(t, c, 0.0);
        }
      }
    }
  }
}

/// Appends an area light polygon with reflectance 0.8, its own material and patch.
void AppendAreaLight(vtkPolyData* data, const std::vector<radiosity::Vec3>& loop, const std::string& name)
{
  vtkPoints* points = data->GetPoints();
  const vtkIdType first = points->GetNumberOfPoints();
  std::vector<vtkIdType> ids;
  for (const radiosity::Vec3& p : loop)
  {
    ids.push_back(points->InsertNextPoint(p.x, p.y, p.z));
  }
  GrowArrays(data->GetPointData(), first + static_cast<vtkIdType>(loop.size()));
  const vtkIdType cell = data->GetNumberOfCells();
  data->GetPolys()->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  data->BuildCells();
  vtkCellData* cd = data->GetCellData();
  GrowArrays(cd, cell + 1);
  cd->GetArray("Reflectance")->SetTuple3(cell, 0.8, 0.8, 0.8);
  vtkDataArray* materials = cd->GetArray("MaterialIds");
  auto* names = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray("MaterialNames"));
  if (materials && names)
  {
    materials->SetComponent(cell, 0, static_cast<double>(names->InsertNextValue(name)));
  }
  if (vtkDataArray* patches = cd->GetArray("PatchId"))
  {
    // Its own patch: one past the largest id (scanned: GetRange's cache misses SetComponent).
    double largest = -1;
    for (vtkIdType c = 0; c < cell; ++c)
    {
      largest = std::max(largest, patches->GetComponent(c, 0));
    }
    patches->SetComponent(cell, 0, largest + 1);
  }
}

/// Drops the reader's note that the scene has no lights, now that it has some.
void DropNoLightsWarning(vtkFieldData* fields)
{
  auto* upstream = vtkStringArray::SafeDownCast(fields->GetAbstractArray("Warnings"));
  if (!upstream)
  {
    return;
  }
  vtkNew<vtkStringArray> kept;
  kept->SetName("Warnings");
  for (vtkIdType i = 0; i < upstream->GetNumberOfValues(); ++i)
  {
    if (upstream->GetValue(i).find(radiosity::NoLightsWarning) == std::string::npos)
    {
      kept->InsertNextValue(upstream->GetValue(i));
    }
  }
  fields->RemoveArray("Warnings");
  if (kept->GetNumberOfValues())
  {
    fields->AddArray(kept);
  }
}

/// The solver's checks of the lights (wrong winding, drawn in a surface's plane).
std::vector<std::string> CheckLights(vtkPolyData* data, const std::vector<std::string>& names)
{
  radiosity::SceneMesh mesh;
  std::vector<radiosity::Vec3> emission;
  std::string error;
  if (!vtkRadiosityAdapter::CopyPolygons(data, mesh, error) ||
    !vtkRadiosityAdapter::ReadSceneArrays(data, mesh, emission, error))
  {
    return { "the lights could not be checked: " + error };
  }
  const radiosity::SceneGeometry geometry(mesh);
  radiosity::PreparedScene prepared; // rays only: the checks need no split patches
  return radiosity::PrepareRays(mesh, vtkRadiosityAdapter::Threads(0), prepared).empty()
    ? radiosity::CheckLights(mesh, geometry, *prepared.Rays, names)
    : std::vector<std::string>();
}

} // namespace

vtkRadiosityLightMarker::vtkRadiosityLightMarker()
  : Chosen(new Choices)
{
  this->SetNumberOfInputPorts(2);
  this->SetLightName("Light");
}

vtkRadiosityLightMarker::~vtkRadiosityLightMarker()
{
  this->SetLightName(nullptr);
  this->SetMaterialPattern(nullptr);
}

void vtkRadiosityLightMarker::AddCellId(vtkIdType id)
{
  this->Chosen->CellIds.push_back(id);
  this->Modified();
}

void vtkRadiosityLightMarker::ClearCellIds()
{
  if (!this->Chosen->CellIds.empty())
  {
    this->Chosen->CellIds.clear();
    this->Modified();
  }
}

void vtkRadiosityLightMarker::AddAreaLight(const char* name, int shape, double cx, double cy, double cz, double nx,
  double ny, double nz, double width, double height, double r, double g, double b)
{
  radiosity::AreaLight light;
  light.Name = name ? name : "";
  light.Shape = shape == 1 ? radiosity::AreaShape::Disk : radiosity::AreaShape::Rectangle;
  light.Centre = { cx, cy, cz };
  light.Normal = { nx, ny, nz };
  light.Width = width;
  light.Height = height;
  light.Color = { r, g, b };
  this->Chosen->AreaLights.push_back(light);
  this->Modified();
}

void vtkRadiosityLightMarker::ClearAreaLights()
{
  if (!this->Chosen->AreaLights.empty())
  {
    this->Chosen->AreaLights.clear();
    this->Modified();
  }
}

void vtkRadiosityLightMarker::AddLuminaire(const char* name, const char* kind, const char* parameters, double x,
  double y, double z, double ax, double ay, double az, double rotation, double r, double g, double b)
{
  radiosity::LuminaireRow row;
  row.Name = name ? name : "";
  row.Kind = kind ? kind : "";
  row.Parameters = parameters ? parameters : "";
  row.Position = { x, y, z };
  row.Aim = { ax, ay, az };
  row.Rotation = rotation;
  row.Color = { r, g, b };
  this->Chosen->Luminaires.push_back(row);
  this->Modified();
}

int vtkRadiosityLightMarker::GetNumberOfLightKinds()
{
  return static_cast<int>(radiosity::LightKinds().size());
}

const char* vtkRadiosityLightMarker::GetLightKindName(int i)
{
  return i >= 0 && i < GetNumberOfLightKinds() ? radiosity::LightKinds()[i].Name : "";
}

void vtkRadiosityLightMarker::ClearLuminaires()
{
  if (!this->Chosen->Luminaires.empty())
  {
    this->Chosen->Luminaires.clear();
    this->Modified();
  }
}

int vtkRadiosityLightMarker::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkSelection");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

namespace
{
/// What makes the settings unusable on this input, or nothing.
std::string SettingsProblem(vtkPolyData* input, const double emission[3], double least)
{
  std::string error;
  if (!vtkRadiosityAdapter::RequireCellArray(input, "Reflectance", 3, false, error))
  {
    return error;
  }
  for (int c = 0; c < 3; ++c)
  {
    if (!(std::isfinite(emission[c]) && emission[c] >= least))
    {
      std::ostringstream text;
      text << "Emission color component " << c << " = " << emission[c] << "; colors must be finite and >= 0";
      return text.str();
    }
  }
  return error;
}

/// The cells chosen by material name, by id and by the selection (`selected`: how many of
/// the selection's), or why they cannot be.
std::string ChooseCells(vtkPolyData* data, const char* pattern, const std::vector<vtkIdType>& ids,
  vtkSelection* selection, std::vector<char>& chosen, int& selected)
{
  if (pattern && *pattern)
  {
    const std::string error = ChooseByMaterial(data, pattern, chosen);
    if (!error.empty())
    {
      return error;
    }
  }
  for (vtkIdType id : ids)
  {
    if (id < 0 || id >= data->GetNumberOfCells())
    {
      return "cell id " + std::to_string(id) + " is not in 0.." + std::to_string(data->GetNumberOfCells() - 1);
    }
    chosen[id] = 1;
  }
  selected = selection ? ChooseBySelection(data, selection, chosen) : -1;
  return std::string();
}

/// The chosen cells become light `light` of `color`.
void MarkCells(const std::vector<char>& chosen, int light, const radiosity::Vec3& color, LightArrays& lights)
{
  for (size_t c = 0; c < chosen.size(); ++c)
  {
    if (chosen[c])
    {
      lights.Id[c] = light;
      lights.Emission[c] = color;
    }
  }
}

/// What was marked, in words for the log.
std::string Marked(int cells, const std::string& light, size_t areas, size_t luminaires)
{
  std::ostringstream text;
  if (cells > 0)
  {
    text << cells << (cells == 1 ? " cell" : " cells") << " made light '" << light << "'"
         << (areas || luminaires ? "; " : "");
  }
  if (areas > 0)
  {
    text << areas << (areas == 1 ? " area light" : " area lights") << " added" << (luminaires ? "; " : "");
  }
  if (luminaires > 0)
  {
    text << luminaires << (luminaires == 1 ? " luminaire" : " luminaires") << " added";
  }
  return cells > 0 || areas > 0 || luminaires > 0 ? text.str() : std::string("nothing marked");
}

/// Each area light as a polygon of its own, appended to the scene.
std::string AddAreaLights(const std::vector<radiosity::AreaLight>& areas, vtkPolyData* data, LightArrays& lights)
{
  for (const radiosity::AreaLight& area : areas)
  {
    std::vector<radiosity::Vec3> loop;
    const std::string error = radiosity::AreaLightLoop(area, loop);
    if (!error.empty())
    {
      return error;
    }
    AppendAreaLight(data, loop, area.Name);
    lights.Id.push_back(LightIndex(lights, area.Name));
    lights.Emission.push_back(area.Color);
  }
  return std::string();
}
} // namespace

namespace
{
/// The scene's luminaires with `added` (one of the same name replaced), each made once to
/// check its kind, parameters and file, written to the output's field data.
std::string AddLuminaires(const std::vector<radiosity::LuminaireRow>& added, const std::vector<std::string>& cellLights,
  vtkPolyData* output)
{
  std::vector<radiosity::LuminaireRow> rows;
  std::string error;
  if (!vtkRadiosityLuminaires::Read(output->GetFieldData(), rows, error))
  {
    return error;
  }
  for (const radiosity::LuminaireRow& row : added)
  {
    const auto same = std::find_if(rows.begin(), rows.end(), [&](const radiosity::LuminaireRow& r) { return r.Name == row.Name; });
    if (same != rows.end())
    {
      *same = row;
    }
    else
    {
      rows.push_back(row);
    }
    radiosity::PointLight light;
    if (!(error = radiosity::MakePointLight(row, light)).empty())
    {
      return error;
    }
  }
  if (!(error = radiosity::LuminaireNamesProblem(rows, cellLights)).empty())
  {
    return error;
  }
  vtkRadiosityLuminaires::Write(output->GetFieldData(), rows);
  return {};
}

/// What the marked scene tells: the upstream "no lights" warning gone where there now are
/// lights, the lights checked on the scene, the warnings in the output, and a log line.
void ReportMarked(vtkObject* self, vtkPolyData* output, const std::vector<std::string>& names,
  vtkRadiosityAdapter::WarningList& warnings, const std::string& marked)
{
  if (!names.empty())
  {
    DropNoLightsWarning(output->GetFieldData());
  }
  for (const std::string& warning : CheckLights(output, names))
  {
    warnings.Add(self, warning);
  }
  warnings.AddTo(output->GetFieldData());
  vtkLogF(INFO, "Mark Lights: %s; the scene has %d light%s", marked.c_str(), static_cast<int>(names.size()),
    names.size() == 1 ? "" : "s");
}
} // namespace

int vtkRadiosityLightMarker::Execute(const Run& run)
{
  vtkPolyData* input = run.Input;
  vtkPolyData* output = run.Output;
  vtkMultiProcessController* parallel = run.Parallel;
  if (input->GetNumberOfCells() == 0 && parallel)
  {
    output->ShallowCopy(input); // this rank's piece of the scene is empty: nothing to mark
    return 1;
  }
  const auto fail = [&](const std::string& error) {
    vtkErrorMacro(<< "Cannot mark lights: " << error << ".");
    return 0;
  };
  std::string error = SettingsProblem(input, this->Emission, GetEmissionMinValue());
  if (!error.empty())
  {
    return fail(error);
  }
  output->DeepCopy(input); // area lights grow its arrays; the input stays as it was
  LightArrays lights = ReadLights(output);
  std::vector<char> chosen(output->GetNumberOfCells(), 0);
  int selected = 0;
  error = ChooseCells(output, this->MaterialPattern, this->Chosen->CellIds, vtkSelection::GetData(run.Inputs[1]),
    chosen, selected);
  if (!error.empty())
  {
    return fail(error);
  }
  vtkRadiosityAdapter::WarningList warnings;
  if (selected == 0)
  {
    warnings.Add(this, "The selection holds no cell of the scene.");
  }
  const int count = static_cast<int>(std::count(chosen.begin(), chosen.end(), 1));
  if (count)
  {
    const int light = LightIndex(lights, this->LightName ? this->LightName : "Light");
    MarkCells(chosen, light, { this->Emission[0], this->Emission[1], this->Emission[2] }, lights);
  }
  if (!(error = AddAreaLights(this->Chosen->AreaLights, output, lights)).empty())
  {
    return fail(error);
  }
  if (!count && this->Chosen->AreaLights.empty() && this->Chosen->Luminaires.empty())
  {
    warnings.Add(this, "No cells chosen, no area lights and no luminaires: the scene passes unchanged.");
  }
  radiosity::CompactLights(lights.Id, lights.Names);
  WriteLights(lights, output);
  if (!(error = AddLuminaires(this->Chosen->Luminaires, lights.Names, output)).empty())
  {
    return fail(error);
  }
  ReportMarked(this, output, lights.Names, warnings,
    Marked(count, this->LightName ? this->LightName : "Light", this->Chosen->AreaLights.size(),
      this->Chosen->Luminaires.size()));
  return 1;
}

void vtkRadiosityLightMarker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightName: " << (this->LightName ? this->LightName : "(none)") << "\n";
  os << indent << "MaterialPattern: " << (this->MaterialPattern ? this->MaterialPattern : "(none)") << "\n";
  os << indent << "CellIds: " << this->Chosen->CellIds.size() << "\n";
  os << indent << "AreaLights: " << this->Chosen->AreaLights.size() << "\n";
  os << indent << "Luminaires: " << this->Chosen->Luminaires.size() << "\n";
}
