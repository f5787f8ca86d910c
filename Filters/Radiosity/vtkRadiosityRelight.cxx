#include "vtkRadiosityRelight.h"

#include "Relight/LightRig.h"
#include "Base/Text.h"
#include "Relight/Relight.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityLightDefaults.h"
#include "vtkRadiosityMovingScene.h"
#include "vtkRadiosityCombine.h"
#include "vtkRadiosityPieces.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
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

bool vtkRadiosityRelight::AddMovingLights(vtkPolyData* scene, vtkPolyData* lights, vtkPolyData* dynamic,
  vtkFloatArray* pointResult, vtkFloatArray* cellResult, std::string& error)
{
  const auto start = std::chrono::steady_clock::now();
  if (!this->Moving)
  {
    this->Moving = new vtkRadiosityMovingScene;
  }
  if (!this->Moving->Shade(scene, lights, dynamic, pointResult, cellResult, error))
  {
    return false;
  }
  this->LastMovingSceneReused = this->Moving->Reused();
  this->LastMovingRays = this->Moving->Rays();
  this->LastMovingSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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

void vtkRadiosityRelight::BeforeRun(const Run&)
{
  this->Internal->Names.clear();
  this->Internal->Effective.clear();
}

bool vtkRadiosityRelight::GuardsInput(const Run& run)
{
  // Moving lights on ParaView's MPI server: every rank joins the gather of the whole scene.
  return !(run.Parallel && (this->GetNumberOfInputConnections(1) || this->GetNumberOfInputConnections(2)));
}

int vtkRadiosityRelight::Execute(const Run& run)
{
  vtkPolyData* input = run.Input;
  vtkPolyData* output = run.Output;
  vtkInformation* outInfo = run.Outputs->GetInformationObject(0);
  double time = 0;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    time = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  }
  else if (outInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    time = outInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[0];
  }
  vtkPolyData* movers = this->GetNumberOfInputConnections(1) ? vtkPolyData::GetData(run.Inputs[1], 0) : nullptr;
  vtkPolyData* dynamic = this->GetNumberOfInputConnections(2) ? vtkPolyData::GetData(run.Inputs[2], 0) : nullptr;
  vtkMultiProcessController* parallel = run.Parallel;
  if (parallel && (this->GetNumberOfInputConnections(1) || this->GetNumberOfInputConnections(2)))
  {
    // Moving lights shoot into the whole scene past every occluder: each rank relights
    // the whole (the pieces of all three inputs gathered) and keeps its own piece.
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
  }
  if (input->GetNumberOfCells() == 0 && parallel)
  {
    output->ShallowCopy(input); // this rank's piece of the scene is empty: nothing to relight
    return 1;
  }
  return this->Relight(input, movers, dynamic, time, output);
}

namespace
{
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
  const vtkRadiosityRelitInput& relit, double time, std::vector<double>& weights)
{
  std::vector<radiosity::LightSetting> effective;
  std::vector<std::string> warnings;
  const std::string invalid =
    this->Lights->Resolve(relit.GetNames(), relit.GetDefaultColors(), time, effective, warnings);
  if (!invalid.empty())
  {
    return invalid;
  }
  for (const std::string& warning : this->Internal->Said.New(warnings))
  {
    vtkWarningMacro(<< warning);
  }
  this->Internal->Names = relit.GetNames();
  this->Internal->Effective = effective;
  weights = radiosity::LightWeights(effective, this->IndirectScale);
  return "";
}

std::string vtkRadiosityRelight::Combine(const vtkRadiosityRelitInput& relit, vtkPolyData* input,
  vtkPolyData* movers, vtkPolyData* dynamic, const std::vector<double>& weights, vtkFloatArray* points,
  vtkFloatArray* cells)
{
  std::string error;
  if ((points && !relit.Combine(false, weights, points, error)) || (cells && !relit.Combine(true, weights, cells, error)))
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
  const vtkRadiosityRelitInput& relit, vtkPolyData* input, vtkFloatArray* current)
{
  // A camera meters the scene as its lights are by default (no setting, no schedule, no
  // moving light), once per solution: a light turned up then brightens the picture, one
  // turned off darkens it, and an animation keeps one exposure. Metered on the current
  // picture instead, every change was undone by the meter (all lights at half: the same
  // picture).
  Internals& in = *this->Internal;
  const bool cells = relit.HasCells();
  if (in.MeteredFor != input->GetMTime() || in.MeteredCells != cells || !(in.Metered > 0))
  {
    in.Metered = relit.MeterAtDefaults(input);
    in.MeteredFor = input->GetMTime();
    in.MeteredCells = cells;
  }
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
  // Everything the combination needs is read once; then the weights, the sums, the meter.
  vtkRadiosityRelitInput relit;
  std::vector<double> weights;
  std::string error = !(this->Exposure >= 0 && this->Exposure <= VTK_DOUBLE_MAX) ||
      !(this->IndirectScale >= 0 && this->IndirectScale <= VTK_DOUBLE_MAX)
    ? "Exposure (" + std::to_string(this->Exposure) + ") and IndirectScale (" + std::to_string(this->IndirectScale) +
      ") must be finite and not negative"
    : relit.ReadLights(input);
  if (error.empty())
  {
    error = this->ResolveWeights(relit, time, weights);
  }
  if (error.empty())
  {
    error = relit.ReadTables(input, this->IndirectScale != 1.0);
  }
  const bool hasPoints = error.empty() && relit.HasPoints();
  const bool hasCells = error.empty() && relit.HasCells();
  vtkNew<vtkFloatArray> pointResult, cellResult;
  if (error.empty())
  {
    error = this->Combine(relit, input, movers, dynamic, weights, hasPoints ? pointResult.Get() : nullptr,
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
    : this->MeterAtDefaults(relit, input, hasCells ? cellResult.Get() : pointResult.Get());
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
