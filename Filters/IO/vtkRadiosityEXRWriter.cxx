#include "vtkRadiosityEXRWriter.h"
#include "vtkRadiosityAbort.h"
#include "vtkRadiosityAdapter.h"
#include "vtkRadiosityLightDefaults.h"
#include "vtkRadiosityPreparedScenes.h"

#include "Image/HdrImage.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <algorithm>

vtkStandardNewMacro(vtkRadiosityEXRWriter);

int vtkRadiosityEXRWriter::GetSizeMaxValue()
{
  return radiosity::MaximumImageSide;
}

vtkRadiosityEXRWriter::vtkRadiosityEXRWriter()
{
  this->SetArrayName("Radiosity");
}

vtkRadiosityEXRWriter::~vtkRadiosityEXRWriter()
{
  this->SetFileName(nullptr);
  this->SetArrayName(nullptr);
}

int vtkRadiosityEXRWriter::GetRaySceneBuilds() const
{
  return this->RaySceneBuilds;
}

int vtkRadiosityEXRWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace
{

std::vector<radiosity::Vec3> PointValues(vtkDataArray* values)
{
  std::vector<radiosity::Vec3> points(values->GetNumberOfTuples());
  for (vtkIdType p = 0; p < values->GetNumberOfTuples(); ++p)
  {
    double v[3];
    values->GetTuple(p, v);
    points[p] = { v[0], v[1], v[2] };
  }
  return points;
}

/// EXR separates layer and channel with '.', so a light's name keeps none; a name taken
/// already (by "Lamp.1" and "Lamp_1", say) gets a number, or one layer would be lost.
std::string LayerName(std::string name, const std::vector<std::string>& taken)
{
  std::replace(name.begin(), name.end(), '.', '_');
  std::string unique = name;
  for (int n = 2; std::find(taken.begin(), taken.end(), unique) != taken.end(); ++n)
  {
    unique = name + "_" + std::to_string(n);
  }
  return unique;
}

} // namespace

std::string vtkRadiosityEXRWriter::CollectLayers(
  vtkPolyData* input, std::vector<std::string>& names, std::vector<std::vector<radiosity::Vec3>>& layers) const
{
  vtkDataArray* values = this->ArrayName ? input->GetPointData()->GetArray(this->ArrayName) : nullptr;
  if (values && values->GetNumberOfComponents() == 3)
  {
    names.push_back(std::string());
    layers.push_back(PointValues(values));
  }
  else if (!this->LightLayers)
  {
    return std::string("the input needs a 3-component point array '") + (this->ArrayName ? this->ArrayName : "") +
      "' (the relight filter's output has 'Radiosity'; on the solver's output set ArrayName to "
      "'Radiosity_<light>' or turn LightLayers on)";
  }
  if (!this->LightLayers)
  {
    return "";
  }
  int lightLayers = 0;
  for (const std::string& name : vtkRadiosityLightNames(input->GetFieldData()))
  {
    vtkDataArray* light = input->GetPointData()->GetArray(("Radiosity_" + name).c_str());
    if (light && light->GetNumberOfComponents() == 3)
    {
      names.push_back(LayerName(name, names));
      layers.push_back(PointValues(light));
      ++lightLayers;
    }
  }
  return lightLayers > 0 ? "" : "light layers: the input has no Radiosity_<light> point arrays for its LightNames "
                                "(the light-tagged solver's output has them)";
}

radiosity::PinholeCamera vtkRadiosityEXRWriter::Camera() const
{
  radiosity::PinholeCamera camera;
  camera.Position = { this->CameraPosition[0], this->CameraPosition[1], this->CameraPosition[2] };
  camera.FocalPoint = { this->FocalPoint[0], this->FocalPoint[1], this->FocalPoint[2] };
  camera.ViewUp = { this->ViewUp[0], this->ViewUp[1], this->ViewUp[2] };
  camera.ViewAngle = this->ViewAngle;
  camera.Width = this->Size[0];
  camera.Height = this->Size[1];
  return camera;
}

bool vtkRadiosityEXRWriter::Render(std::vector<std::string>& names, std::vector<std::vector<float>>& images)
{
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  radiosity::SceneMesh mesh;
  std::string error = vtkRadiosityAdapter::FailedUpstream(input) ? "a filter upstream failed (see its error)" : "";
  // A mesh kept prepared (an animation's earlier frame, the solver's output) was copied and
  // checked when it was prepared: each frame's write skips the copy.
  const vtkRadiosityPreparedScenes::MeshKey key =
    error.empty() ? vtkRadiosityPreparedScenes::KeyOf(input) : vtkRadiosityPreparedScenes::MeshKey();
  radiosity::PreparedScene prepared = error.empty() ? vtkRadiosityPreparedScenes::Find(input, key, false) : radiosity::PreparedScene();
  if (error.empty() && !prepared.Rays)
  {
    vtkRadiosityAdapter::CopyPolygons(input, mesh, error);
  }
  std::vector<std::vector<radiosity::Vec3>> layers;
  if (error.empty())
  {
    error = this->CollectLayers(input, names, layers);
  }
  if (error.empty() && !prepared.Rays)
  {
    ++this->RaySceneBuilds;
    if ((error = radiosity::PrepareRays(mesh, vtkRadiosityAdapter::Threads(0), prepared)).empty())
    {
      vtkRadiosityPreparedScenes::Keep(input, key, prepared);
    }
  }
  const radiosity::PinholeCamera camera = this->Camera();
  if (error.empty())
  {
    error = radiosity::ValidateCamera(camera);
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot render: " << error << ".");
    return false;
  }
  std::vector<const std::vector<radiosity::Vec3>*> pointers;
  for (const auto& layer : layers)
  {
    pointers.push_back(&layer);
  }
  const vtkRadiosityAbortWatch abort(this);
  images = radiosity::RenderLayers(
    *prepared.Rays, pointers, camera,
    [this, &abort](double f) {
      this->UpdateProgress(f);
      return !abort.Stop();
    },
    vtkRadiosityAdapter::Threads(0));
  if (images.empty() || images[0].empty())
  {
    vtkWarningMacro(<< "Render aborted: no image made, nothing written (a file already there is kept).");
    return false;
  }
  return true;
}

bool vtkRadiosityEXRWriter::RenderImage(vtkFloatArray* rgb)
{
  if (vtkAlgorithm* source = this->GetInputAlgorithm())
  {
    source->Update();
  }
  std::vector<std::string> names;
  std::vector<std::vector<float>> images;
  if (!rgb || !this->GetInput() || !this->Render(names, images))
  {
    return false;
  }
  if (!names[0].empty())
  {
    vtkErrorMacro(<< "Cannot render: the input has no 3-component point array '"
                  << (this->ArrayName ? this->ArrayName : "") << "' (RenderImage shows ArrayName only).");
    return false;
  }
  const std::vector<float>& pixels = images[0];
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(pixels.size() / 3));
  std::copy(pixels.begin(), pixels.end(), rgb->GetPointer(0));
  return true;
}

int vtkRadiosityEXRWriter::Write()
{
  // Where it went through, WriteData has set the code.
  this->SetErrorCode(vtkRadiosityAdapter::UpdateForWriting(this) ? this->GetErrorCode() : vtkErrorCode::UserError);
  return this->GetErrorCode() == vtkErrorCode::NoError;
}

void vtkRadiosityEXRWriter::WriteData()
{
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "Cannot write: no FileName set.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  std::vector<std::string> names;
  std::vector<std::vector<float>> images;
  if (!this->Render(names, images))
  {
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  const std::string error = this->LightLayers
    ? radiosity::WriteExrLayers(this->FileName, this->Size[0], this->Size[1], names, images)
    : radiosity::WriteExr(this->FileName, this->Size[0], this->Size[1], images[0]);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
  }
}

void vtkRadiosityEXRWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
}

bool vtkRadiosityEXRWriter::ReadLayer(const char* fileName, const char* layer, vtkFloatArray* rgb, int size[2])
{
  if (!fileName || !rgb)
  {
    vtkGenericWarningMacro(<< "Cannot read an EXR layer: no file name or no output array.");
    return false;
  }
  std::vector<float> values;
  const std::string error = radiosity::ReadExrLayer(fileName, layer ? layer : "", size[0], size[1], values);
  if (!error.empty())
  {
    vtkGenericWarningMacro(<< "Cannot read layer '" << (layer ? layer : "") << "' of " << fileName << ": " << error);
    return false;
  }
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / 3));
  std::copy(values.begin(), values.end(), rgb->GetPointer(0));
  return true;
}
