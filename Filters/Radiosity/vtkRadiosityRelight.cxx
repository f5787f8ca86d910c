#include "vtkRadiosityRelight.h"

#include "Relight/LightRig.h"
#include "Geometry/PointAverages.h"
#include "Base/Text.h"
#include "Relight/MovingLights.h"
#include "Solve/PatchBasis.h"
#include "Relight/Relight.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityLightDefaults.h"
#include "vtkRadiosityCombine.h"
#include "vtkRadiosityPieces.h"
#include "vtkRadiosityPreparedScenes.h"
#include "Base/WorkerPool.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkNew.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVariant.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <set>
#include <sstream>

vtkStandardNewMacro(vtkRadiosityRelight);

struct vtkRadiosityRelight::Internals
{
  std::vector<std::string> Names;                  ///< the lights the last execution found
  std::vector<radiosity::LightSetting> Effective; ///< and their settings in effect
  vtkRadiosityPieces::GatheredScene Gathered;      ///< the whole scene on an MPI server, kept
  double Metered = 0;           ///< the exposure metered at the lights' defaults
  vtkMTimeType MeteredFor = 0;  ///< for this input
  bool MeteredCells = false;    ///< on its cells (else its points)
  radiosity::SaidOnce Said; ///< the light settings' warnings, each said once
};

struct vtkRadiosityRelight::MovingState
{
  vtkMTimeType SceneTime = 0, DynamicTime = 0;
  radiosity::SceneMesh Scene, Dynamic;
  std::unique_ptr<radiosity::MovingLightShader> Shader;
  bool Reused = false; ///< the shader shades on the solver's kept preparation
};

vtkRadiosityRelight::vtkRadiosityRelight()
  : Internal(new Internals)
  , Lights(vtkSmartPointer<vtkRadiosityLights>::New())
{
  this->SetNumberOfInputPorts(3);
}

void vtkRadiosityRelight::SetLights(vtkRadiosityLights* lights)
{
  if (lights && lights != this->Lights)
  {
    this->Lights = lights;
    this->Modified();
  }
}

vtkMTimeType vtkRadiosityRelight::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Lights->GetMTime());
}

vtkRadiosityRelight::~vtkRadiosityRelight()
{
  delete this->Moving;
}

int vtkRadiosityRelight::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port > 0)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

namespace
{
/// result += values, tuple by tuple, as VTK's SMP tools split it (ParaView's threads).
void AddTo(vtkFloatArray* result, const std::vector<radiosity::Vec3>& values)
{
  float* out = result->GetPointer(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(values.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      out[3 * i + 0] += static_cast<float>(values[i].x);
      out[3 * i + 1] += static_cast<float>(values[i].y);
      out[3 * i + 2] += static_cast<float>(values[i].z);
    }
  });
}

/// The solver's basis, per element (cell array) or per patch node (field array plus the
/// cell arrays that interpolate it), checked against the scene's patches.
bool ReadBasis(vtkPolyData* scene, int patches, radiosity::BasisView& basis, std::string& error)
{
  const vtkIdType cells = scene->GetNumberOfCells();
  auto* perElement = vtkFloatArray::SafeDownCast(scene->GetCellData()->GetArray("PatchBasis"));
  auto* perNode = vtkFloatArray::SafeDownCast(scene->GetFieldData()->GetArray("PatchBasis"));
  auto* nodes = vtkIntArray::SafeDownCast(scene->GetCellData()->GetArray("PatchBasisNodes"));
  auto* weights = vtkFloatArray::SafeDownCast(scene->GetCellData()->GetArray("PatchBasisWeights"));
  vtkFloatArray* values = perElement ? perElement : perNode;
  if (!values || (!perElement && (!nodes || !weights)))
  {
    error = "'PatchBasis' must be a float array: per cell, or in the field data with the int cell array "
            "'PatchBasisNodes' and the float cell array 'PatchBasisWeights'";
    return false;
  }
  if (values->GetNumberOfComponents() != 3 * patches || (perElement && values->GetNumberOfTuples() != cells))
  {
    error = "'PatchBasis' has " + std::to_string(values->GetNumberOfTuples()) + " tuples of " +
      std::to_string(values->GetNumberOfComponents()) + " components; the scene needs " +
      (perElement ? std::to_string(cells) : std::string("one per node")) + " of " + std::to_string(3 * patches) +
      " (" + std::to_string(patches) + " patches)";
    return false;
  }
  basis = { patches, static_cast<int>(values->GetNumberOfTuples()), values->GetPointer(0) };
  if (perElement)
  {
    return true;
  }
  if (nodes->GetNumberOfComponents() != 3 || weights->GetNumberOfComponents() != 3 ||
    nodes->GetNumberOfTuples() != cells || weights->GetNumberOfTuples() != cells)
  {
    error = "'PatchBasisNodes' and 'PatchBasisWeights' need 3 components per cell";
    return false;
  }
  const int* node = nodes->GetPointer(0);
  if (std::any_of(node, node + 3 * cells, [&](int k) { return k < 0 || k >= basis.Receivers; }))
  {
    error = "'PatchBasisNodes' refers to a node outside 'PatchBasis' (" + std::to_string(basis.Receivers) + " nodes)";
    return false;
  }
  basis.Node = node;
  basis.Weight = weights->GetPointer(0);
  return true;
}
}

namespace
{
/// The moving lights of `lights` (points with Color, Intensity and optional Normal);
/// false with `error` naming the first bad one.
bool ReadMovingLights(vtkPolyData* lights, std::vector<radiosity::MovingLight>& movers, std::string& error)
{
  movers.assign(lights->GetNumberOfPoints(), radiosity::MovingLight());
  vtkDataArray* color = lights->GetPointData()->GetArray("Color");
  vtkDataArray* intensity = lights->GetPointData()->GetArray("Intensity");
  vtkDataArray* normal = lights->GetPointData()->GetArray("Normal");
  for (vtkDataArray* array : { color, intensity, normal })
  {
    if (array && array->GetNumberOfTuples() != lights->GetNumberOfPoints())
    {
      error = std::string("moving-light array '") + array->GetName() + "' needs one tuple per light";
      return false;
    }
  }
  for (vtkIdType i = 0; i < lights->GetNumberOfPoints(); ++i)
  {
    radiosity::MovingLight& light = movers[i];
    double v[3];
    lights->GetPoint(i, v);
    light.Position = { v[0], v[1], v[2] };
    if (color && color->GetNumberOfComponents() == 3)
    {
      color->GetTuple(i, v);
      light.Color = { v[0], v[1], v[2] };
    }
    if (intensity)
    {
      light.Intensity = intensity->GetComponent(i, 0);
    }
    if (normal && normal->GetNumberOfComponents() == 3)
    {
      normal->GetTuple(i, v);
      light.Normal = { v[0], v[1], v[2] };
    }
    const radiosity::Vec3& p = light.Position;
    const std::string invalid = radiosity::InvalidLightValues(light.Intensity, light.Color);
    if (!std::isfinite(p.x + p.y + p.z) || !invalid.empty())
    {
      error = "moving light " + std::to_string(i) + (invalid.empty() ? " has a non-finite position" : " " + invalid);
      return false;
    }
    const radiosity::Vec3& n = light.Normal;
    if (normal && normal->GetNumberOfComponents() == 3 && !(std::isfinite(n.x + n.y + n.z) && radiosity::Norm(n) > 0))
    {
      error = "moving light " + std::to_string(i) + " has a zero or non-finite Normal; leave the array out for "
                                                    "an isotropic light";
      return false;
    }
  }
  return true;
}
}

/// Where only the dynamic objects changed: swaps them in the shader's ray scene and keeps
/// the rest; false with `error` where they cannot be read or built.
bool vtkRadiosityRelight::SwapDynamicObjects(vtkPolyData* dynamic, std::string& error)
{
  MovingState& state = *this->Moving;
  const vtkMTimeType dynamicTime = dynamic ? dynamic->GetMTime() : 0;
  // Only the dynamic objects moved: swap them in the ray scene, keep the rest.
  state.Dynamic = radiosity::SceneMesh();
  if (dynamic && dynamic->GetNumberOfPolys() > 0 && !vtkRadiosityAdapter::CopyPolygons(dynamic, state.Dynamic, error))
  {
    error = "dynamic objects: " + error;
    state.DynamicTime = 0;
    return false;
  }
  bool swapped = false; // the objects' BVH is built on ParaView's threads
  vtkRadiosityAdapter::SharedPool()->Within([&] {
    swapped = state.Shader->SetDynamicObjects(state.Dynamic.NumberOfPolygons() > 0 ? &state.Dynamic : nullptr);
  });
  if (!swapped)
  {
    error = state.Shader->Error();
    state.Shader.reset();
    return false;
  }
  state.DynamicTime = dynamicTime;
  return true;
}

/// Reads the scene and the dynamic objects anew and makes the shader, on the solver's
/// preparation where it is kept; false with `error` where they cannot be read or prepared.
bool vtkRadiosityRelight::RebuildMovingScene(vtkPolyData* scene, vtkPolyData* dynamic, std::string& error)
{
  MovingState& state = *this->Moving;
  state = MovingState();
  std::vector<radiosity::Vec3> unused;
  int lightCount = 0;
  if (!vtkRadiosityAdapter::CopyPolygons(scene, state.Scene, error) ||
    !vtkRadiosityAdapter::ReadSceneArrays(scene, state.Scene, unused, error) ||
    !(error = radiosity::ValidateScene(state.Scene, lightCount)).empty())
  {
    return false;
  }
  if (dynamic && dynamic->GetNumberOfPolys() > 0 &&
    !vtkRadiosityAdapter::CopyPolygons(dynamic, state.Dynamic, error))
  {
    error = "dynamic objects: " + error;
    return false;
  }
  // The solver's preparation where it is kept (its patches are the basis's), else one
  // made here the same way and kept for the EXR writer.
  radiosity::PreparedScene prepared = vtkRadiosityPreparedScenes::Find(scene, true);
  state.Reused = prepared.Geometry != nullptr;
  if (!prepared.Geometry &&
    !(error = radiosity::PrepareTransport(state.Scene, vtkRadiosityAdapter::Threads(0), {}, prepared)).empty())
  {
    return false;
  }
  vtkRadiosityPreparedScenes::Keep(scene, prepared);
  vtkRadiosityAdapter::SharedPool()->Within([&] {
    state.Shader.reset(new radiosity::MovingLightShader(
      state.Scene, prepared, state.Dynamic.NumberOfPolygons() > 0 ? &state.Dynamic : nullptr));
  });
  if (!state.Shader->Error().empty())
  {
    error = state.Shader->Error();
    state.Shader.reset();
    return false;
  }
  state.SceneTime = scene->GetMTime();
  state.DynamicTime = dynamic ? dynamic->GetMTime() : 0;
  return true;
}

bool vtkRadiosityRelight::AddMovingLights(vtkPolyData* scene, vtkPolyData* lights, vtkPolyData* dynamic,
  vtkFloatArray* pointResult, vtkFloatArray* cellResult, std::string& error)
{
  const auto start = std::chrono::steady_clock::now();
  if (!scene->GetCellData()->GetArray("PatchBasis") && !scene->GetFieldData()->GetArray("PatchBasis"))
  {
    error = "moving lights need the solver's float array 'PatchBasis' (vtkLightTaggedRadiosity::PatchBasisOn())";
    return false;
  }
  if (!this->Moving)
  {
    this->Moving = new MovingState;
  }
  MovingState& state = *this->Moving;
  const vtkMTimeType sceneTime = scene->GetMTime();
  const vtkMTimeType dynamicTime = dynamic ? dynamic->GetMTime() : 0;
  if (state.Shader && state.SceneTime == sceneTime && state.DynamicTime != dynamicTime &&
    !this->SwapDynamicObjects(dynamic, error))
  {
    return false;
  }
  if ((!state.Shader || state.SceneTime != sceneTime || state.DynamicTime != dynamicTime) &&
    !this->RebuildMovingScene(scene, dynamic, error))
  {
    return false;
  }
  const radiosity::SceneGeometry& g = state.Shader->Geometry();
  radiosity::BasisView basis;
  std::vector<radiosity::MovingLight> movers;
  if (!ReadBasis(scene, static_cast<int>(g.PatchElements.size()), basis, error) ||
    !ReadMovingLights(lights, movers, error))
  {
    return false;
  }
  std::vector<radiosity::Vec3> direct, cells;
  this->LastMovingSceneReused = state.Reused;
  const auto pool = vtkRadiosityAdapter::SharedPool();
  this->LastMovingRays = state.Shader->Direct(movers, *pool, direct);
  radiosity::AddBasisInterreflection(g, direct, basis, *pool, cells);
  if (cellResult->GetNumberOfTuples() == static_cast<vtkIdType>(cells.size()))
  {
    AddTo(cellResult, cells);
  }
  if (pointResult->GetNumberOfTuples() == scene->GetNumberOfPoints())
  {
    const std::vector<radiosity::Vec3> points = radiosity::AverageToPoints(state.Scene, g, cells, 1);
    AddTo(pointResult, points);
  }
  this->LastMovingSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

int vtkRadiosityRelight::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  std::string error;
  if (!this->Lights->ReadScheduleFile(error))
  {
    vtkErrorMacro(<< "Cannot relight: " << error << ".");
    return 0;
  }
  // Time steps: the schedule's keyframes and those of a time-varying moving-light source.
  // Without either, the scene's own (copied by the pipeline) stay as they are.
  std::vector<double> times = this->Lights->Rig().KeyframeTimes();
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    vtkInformation* lights = inputVector[1]->GetInformationObject(0);
    if (lights->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
    {
      const double* steps = lights->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
      times.insert(times.end(), steps, steps + lights->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  if (times.empty())
  {
    return 1;
  }
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), static_cast<int>(times.size()));
  const double range[2] = { times.front(), times.back() };
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkRadiosityRelight::GetNumberOfLights() const
{
  return static_cast<int>(this->Internal->Names.size());
}

int vtkRadiosityRelight::GetNumberOfLightSettings() const
{
  return this->Lights->GetNumberOfLightSettings();
}

const char* vtkRadiosityRelight::GetLightName(int light) const
{
  return light >= 0 && light < this->GetNumberOfLights() ? this->Internal->Names[light].c_str() : nullptr;
}

vtkStringArray* vtkRadiosityRelight::GetLightNames()
{
  this->NamesInfo = vtkSmartPointer<vtkStringArray>::New();
  for (const std::string& name : this->Internal->Names)
  {
    this->NamesInfo->InsertNextValue(name);
  }
  return this->NamesInfo;
}

vtkStringArray* vtkRadiosityRelight::GetLightSettingsInfo()
{
  this->SettingsInfo = vtkSmartPointer<vtkStringArray>::New();
  for (int l = 0; l < this->GetNumberOfLights(); ++l)
  {
    for (const std::string& item : radiosity::SettingRow(this->Internal->Names[l], this->Internal->Effective[l]))
    {
      this->SettingsInfo->InsertNextValue(item);
    }
  }
  return this->SettingsInfo;
}

void vtkRadiosityRelight::GetLightColor(int light, double rgb[3]) const
{
  const bool valid = light >= 0 && light < this->GetNumberOfLights();
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = valid ? this->Internal->Effective[light].Color[c] : 0.0;
  }
}

double vtkRadiosityRelight::GetLightIntensity(int light) const
{
  return light >= 0 && light < this->GetNumberOfLights() ? this->Internal->Effective[light].Intensity : 0.0;
}

bool vtkRadiosityRelight::GetLightEnabled(int light) const
{
  return light >= 0 && light < this->GetNumberOfLights() && this->Internal->Effective[light].Enabled;
}

void vtkRadiosityRelight::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Exposure: " << this->Exposure << "\n";
  for (int l = 0; l < this->GetNumberOfLights(); ++l)
  {
    const radiosity::LightSetting& s = this->Internal->Effective[l];
    os << indent << this->Internal->Names[l] << ": color (" << s.Color.x << ", " << s.Color.y << ", "
       << s.Color.z << ") intensity " << s.Intensity << (s.Enabled ? " on" : " off") << "\n";
  }
}


namespace
{

vtkSmartPointer<vtkUnsignedCharArray> Display(vtkFloatArray* linear, double exposure)
{
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName("DisplayColors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(linear->GetNumberOfTuples());
  static const radiosity::DisplayCurve curve;
  curve.Apply(linear->GetPointer(0), 3 * static_cast<size_t>(linear->GetNumberOfTuples()), exposure,
    colors->GetPointer(0));
  return colors;
}
}

int vtkRadiosityRelight::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  double time = 0;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    time = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  }
  else if (outInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    time = outInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[0];
  }
  vtkPolyData* movers = this->GetNumberOfInputConnections(1) ? vtkPolyData::GetData(inputVector[1], 0) : nullptr;
  vtkPolyData* dynamic = this->GetNumberOfInputConnections(2) ? vtkPolyData::GetData(inputVector[2], 0) : nullptr;
  this->Internal->Names.clear();
  this->Internal->Effective.clear();
  vtkMultiProcessController* parallel = vtkRadiosityPieces::Parallel(outInfo);
  if (parallel && (this->GetNumberOfInputConnections(1) || this->GetNumberOfInputConnections(2)))
  {
    // Moving lights shoot into the whole scene past every occluder: each rank relights
    // the whole (the pieces of all three inputs gathered) and keeps its own piece.
    return vtkRadiosityAdapter::Guarded(this, nullptr, output, [&]() -> int {
      vtkNew<vtkPolyData> allMovers, allDynamic;
      vtkRadiosityPieces::AllGather(parallel, movers, allMovers);
      vtkRadiosityPieces::AllGather(parallel, dynamic, allDynamic);
      vtkNew<vtkTable> unused;
      // The whole scene is kept between frames, so the moving-light shader is too.
      const int ok = vtkRadiosityPieces::SolveTogether(parallel, input, output, unused,
        [&](vtkPolyData* whole, vtkPolyData* result, vtkTable*) {
          return this->Relight(whole, movers ? allMovers.Get() : nullptr, dynamic ? allDynamic.Get() : nullptr, time, result);
        },
        &this->Internal->Gathered);
      if (ok && !this->Lights->Rig().KeyframeTimes().empty())
      {
        output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
      }
      return ok;
    }, parallel);
  }
  return vtkRadiosityAdapter::Guarded(this, input, output, [&]() -> int {
    if (input->GetNumberOfCells() == 0 && parallel)
    {
      output->ShallowCopy(input); // this rank's piece of the scene is empty: nothing to relight
      return 1;
    }
    return this->Relight(input, movers, dynamic, time, output);
  }, parallel);
}

namespace
{
const std::string kPrefix = "Radiosity_";

/// The lights: the solver's LightNames, else every Radiosity_* point or cell array; "" or
/// why the input cannot be relit.
std::string FindLights(vtkPolyData* input, std::vector<std::string>& names)
{
  names = vtkRadiosityLightNames(input->GetFieldData());
  if (!input->GetFieldData()->GetAbstractArray("LightNames"))
  {
    vtkFieldData* source = input->GetPointData()->GetNumberOfArrays() > 0
      ? static_cast<vtkFieldData*>(input->GetPointData())
      : static_cast<vtkFieldData*>(input->GetCellData());
    for (int a = 0; a < source->GetNumberOfArrays(); ++a)
    {
      const char* name = source->GetArrayName(a);
      if (name && std::string(name).compare(0, kPrefix.size(), kPrefix) == 0)
      {
        names.push_back(std::string(name).substr(kPrefix.size()));
      }
    }
  }
  bool perLight = false;
  for (const std::string& name : names)
  {
    perLight = perLight || input->GetCellData()->GetAbstractArray((kPrefix + name).c_str()) ||
      input->GetPointData()->GetAbstractArray((kPrefix + name).c_str());
  }
  if (!perLight && input->GetCellData()->GetAbstractArray("Radiosity"))
  {
    return "the input holds one combined solution (SolutionMode StandardCombined); relighting needs the "
           "per-light solutions of LightTagged or StandardSeparate";
  }
  return names.empty() ? "the input has no lights (no field array 'LightNames' and no 'Radiosity_<name>' "
                         "arrays); run vtkLightTaggedRadiosity first"
                       : "";
}

/// The arrays the weights apply to: Radiosity_<name> per light and, where IndirectScale
/// is not 1, Direct_<name> too (B = s B_total + (1 - s) B_direct over 2k arrays).
std::string SolutionArrays(
  vtkPolyData* input, const std::vector<std::string>& names, bool withDirect, std::vector<std::string>& arrays)
{
  for (const std::string& name : names)
  {
    arrays.push_back(kPrefix + name);
  }
  if (!withDirect)
  {
    return "";
  }
  const std::string direct = "Direct_" + names[0];
  if (!input->GetPointData()->GetAbstractArray(direct.c_str()) && !input->GetCellData()->GetAbstractArray(direct.c_str()))
  {
    return "IndirectScale needs the arrays '" + direct + "' etc.; turn on SeparateDirect in the solver";
  }
  for (const std::string& name : names)
  {
    arrays.push_back("Direct_" + name);
  }
  return "";
}

/// "" when the moving lights left every value finite, else where one is not.
std::string CheckFinite(vtkFloatArray* points, vtkFloatArray* cells)
{
  for (vtkFloatArray* result : { points, cells })
  {
    const vtkIdType bad = result ? vtkRadiosityFirstNonFinite(result) : -1;
    if (bad >= 0)
    {
      return "the result is not finite at item " + std::to_string(bad) +
        " (moving lights included); a light is too strong for float";
    }
  }
  return "";
}
}

std::string vtkRadiosityRelight::ResolveWeights(
  vtkPolyData* input, const std::vector<std::string>& names, double time, std::vector<double>& weights)
{
  // Default colors: the solver's, else the mean Emission of each light's cells.
  const std::vector<radiosity::Vec3> defaultColors =
    vtkRadiosityLights::DefaultColors(input, static_cast<int>(names.size()));
  std::vector<radiosity::LightSetting> effective;
  std::vector<std::string> warnings;
  const std::string invalid = this->Lights->Resolve(names, defaultColors, time, effective, warnings);
  if (!invalid.empty())
  {
    return invalid;
  }
  for (const std::string& warning : this->Internal->Said.New(warnings))
  {
    vtkWarningMacro(<< warning);
  }
  this->Internal->Names = names;
  this->Internal->Effective = effective;
  weights = radiosity::LightWeights(effective, this->IndirectScale);
  return "";
}

std::string vtkRadiosityRelight::Combine(vtkPolyData* input, vtkPolyData* movers, vtkPolyData* dynamic,
  const std::vector<std::string>& arrays, const std::vector<double>& weights, vtkFloatArray* points,
  vtkFloatArray* cells)
{
  std::string error;
  if ((points && !vtkRadiosityCombineSolutions(input->GetPointData(), arrays, weights, input->GetNumberOfPoints(), points, error)) ||
    (cells && !vtkRadiosityCombineSolutions(input->GetCellData(), arrays, weights, input->GetNumberOfCells(), cells, error)))
  {
    return error;
  }
  this->LastMovingRays = 0;
  this->LastMovingSeconds = 0;
  if (!movers || movers->GetNumberOfPoints() == 0)
  {
    return ""; // Combine checked the sum; moving lights may still overflow it
  }
  vtkNew<vtkFloatArray> unusedPoints, unusedCells; // AddMovingLights fills arrays of the right size only
  return this->AddMovingLights(input, movers, dynamic, points ? points : unusedPoints.Get(),
           cells ? cells : unusedCells.Get(), error)
    ? CheckFinite(points, cells)
    : error;
}

double vtkRadiosityRelight::MeterAtDefaults(
  vtkPolyData* input, const std::vector<std::string>& names, bool cells, vtkFloatArray* current)
{
  // A camera meters the scene as its lights are by default (no setting, no schedule, no
  // moving light), once per solution: a light turned up then brightens the picture, one
  // turned off darkens it, and an animation keeps one exposure. Metered on the current
  // picture instead, every change was undone by the meter (all lights at half: the same
  // picture).
  Internals& in = *this->Internal;
  if (in.MeteredFor == input->GetMTime() && in.MeteredCells == cells && in.Metered > 0)
  {
    return in.Metered;
  }
  std::vector<std::string> arrays;
  for (const std::string& name : names)
  {
    arrays.push_back("Radiosity_" + name);
  }
  const std::vector<double> defaults = vtkRadiosityLightDefaultColors(input, static_cast<int>(names.size()));
  vtkDataSetAttributes* data = cells ? static_cast<vtkDataSetAttributes*>(input->GetCellData()) : input->GetPointData();
  vtkNew<vtkFloatArray> sum;
  std::string error;
  const bool summed = !names.empty() &&
    vtkRadiosityCombineSolutions(data, arrays, defaults, cells ? input->GetNumberOfCells() : input->GetNumberOfPoints(), sum, error);
  in.Metered = summed ? vtkRadiosityMeteredExposure(input, sum, cells, 0.0) : 0.0;
  in.MeteredFor = input->GetMTime();
  in.MeteredCells = cells;
  return in.Metered > 0 ? in.Metered : vtkRadiosityMeteredExposure(input, current, cells);
}

void vtkRadiosityRelight::AddSettingsInUse(vtkPolyData* output)
{
  // What the writers and the browser viewer start from: the lights as this filter has them.
  vtkNew<vtkDoubleArray> colors;
  colors->SetName("LightColors");
  colors->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> enabled;
  enabled->SetName("LightEnabled");
  for (const radiosity::LightSetting& s : this->Internal->Effective)
  {
    const radiosity::Vec3 c = s.Color * s.Intensity;
    colors->InsertNextTuple3(c.x, c.y, c.z);
    enabled->InsertNextValue(s.Enabled ? 1 : 0);
  }
  output->GetFieldData()->AddArray(colors);
  output->GetFieldData()->AddArray(enabled);
}

int vtkRadiosityRelight::Relight(
  vtkPolyData* input, vtkPolyData* movers, vtkPolyData* dynamic, double time, vtkPolyData* output)
{
  std::vector<std::string> names, arrays;
  std::vector<double> weights;
  std::string error = !(this->Exposure >= 0 && this->Exposure <= VTK_DOUBLE_MAX) ||
      !(this->IndirectScale >= 0 && this->IndirectScale <= VTK_DOUBLE_MAX)
    ? "Exposure (" + std::to_string(this->Exposure) + ") and IndirectScale (" + std::to_string(this->IndirectScale) +
      ") must be finite and not negative"
    : FindLights(input, names);
  if (error.empty())
  {
    error = this->ResolveWeights(input, names, time, weights);
  }
  if (error.empty())
  {
    error = SolutionArrays(input, names, this->IndirectScale != 1.0, arrays);
  }
  const bool hasPoints = error.empty() && input->GetPointData()->GetAbstractArray(arrays[0].c_str()) != nullptr;
  const bool hasCells = error.empty() && input->GetCellData()->GetAbstractArray(arrays[0].c_str()) != nullptr;
  if (error.empty() && !hasPoints && !hasCells)
  {
    error = "no point or cell array '" + arrays[0] + "'";
  }
  vtkNew<vtkFloatArray> pointResult, cellResult;
  if (error.empty())
  {
    error = this->Combine(input, movers, dynamic, arrays, weights, hasPoints ? pointResult.Get() : nullptr,
      hasCells ? cellResult.Get() : nullptr);
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot relight: " << error << ".");
    return 0;
  }
  output->ShallowCopy(input);
  // Metered on the cells where there are some: they know which ones are lamps.
  this->ExposureInUse = this->Exposure > 0
    ? this->Exposure
    : this->MeterAtDefaults(input, names, hasCells, hasCells ? cellResult.Get() : pointResult.Get());
  vtkNew<vtkDoubleArray> exposure;
  exposure->SetName("Exposure");
  exposure->InsertNextValue(this->ExposureInUse);
  output->GetFieldData()->AddArray(exposure);
  this->AddSettingsInUse(output);
  if (!this->Lights->Rig().KeyframeTimes().empty())
  {
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  }
  for (auto [result, data] : { std::make_pair(hasPoints ? pointResult.Get() : nullptr,
                                 static_cast<vtkDataSetAttributes*>(output->GetPointData())),
         std::make_pair(hasCells ? cellResult.Get() : nullptr, static_cast<vtkDataSetAttributes*>(output->GetCellData())) })
  {
    if (result)
    {
      result->SetName("Radiosity");
      data->AddArray(result);
      data->SetScalars(Display(result, this->ExposureInUse));
    }
  }
  return 1;
}
