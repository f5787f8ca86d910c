#include "vtkRadiosityEXRWriter.h"
#include "vtkRadiosityAbort.h"
#include "vtkRadiosityAdapter.h"

#include "HdrImage.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkRadiosityEXRWriter);

vtkRadiosityEXRWriter::vtkRadiosityEXRWriter()
{
  this->SetArrayName("Radiosity");
}

vtkRadiosityEXRWriter::~vtkRadiosityEXRWriter()
{
  this->SetFileName(nullptr);
  this->SetArrayName(nullptr);
}

int vtkRadiosityEXRWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

bool vtkRadiosityEXRWriter::Render(std::vector<float>& rgb)
{
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  radiosity::SceneMesh mesh;
  std::string error;
  if (vtkRadiosityAdapter::FailedUpstream(input))
  {
    vtkErrorMacro(<< "Cannot render: a filter upstream failed (see its error).");
    return false;
  }
  if (!vtkRadiosityAdapter::CopyPolygons(input, mesh, error))
  {
    vtkErrorMacro(<< "Cannot render: " << error << ".");
    return false;
  }
  vtkDataArray* values = this->ArrayName ? input->GetPointData()->GetArray(this->ArrayName) : nullptr;
  if (!values || values->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro(<< "Cannot render: the input needs a 3-component point array '"
                  << (this->ArrayName ? this->ArrayName : "") << "'.");
    return false;
  }
  std::vector<radiosity::Vec3> pointValues(input->GetNumberOfPoints());
  for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
  {
    double v[3];
    values->GetTuple(p, v);
    pointValues[p] = { v[0], v[1], v[2] };
  }
  radiosity::Visibility scene(mesh);
  if (!scene.Error().empty())
  {
    vtkErrorMacro(<< "Cannot render: " << scene.Error() << ".");
    return false;
  }
  radiosity::PinholeCamera camera;
  camera.Position = { this->CameraPosition[0], this->CameraPosition[1], this->CameraPosition[2] };
  camera.FocalPoint = { this->FocalPoint[0], this->FocalPoint[1], this->FocalPoint[2] };
  camera.ViewUp = { this->ViewUp[0], this->ViewUp[1], this->ViewUp[2] };
  camera.ViewAngle = this->ViewAngle;
  camera.Width = this->Size[0];
  camera.Height = this->Size[1];
  if (!(error = radiosity::ValidateCamera(camera)).empty())
  {
    vtkErrorMacro(<< "Cannot render: " << error << ".");
    return false;
  }
  const vtkRadiosityAbortWatch abort(this);
  rgb = radiosity::RenderRadiosity(scene, pointValues, camera, [this, &abort](double f) {
    this->UpdateProgress(f);
    return !abort.Stop();
  });
  if (rgb.empty())
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
  std::vector<float> pixels;
  if (!rgb || !this->GetInput() || !this->Render(pixels))
  {
    return false;
  }
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(pixels.size() / 3));
  std::copy(pixels.begin(), pixels.end(), rgb->GetPointer(0));
  return true;
}

void vtkRadiosityEXRWriter::WriteData()
{
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "Cannot write: no FileName set.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  std::vector<float> rgb;
  if (!this->Render(rgb))
  {
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  const std::string error = radiosity::WriteExr(this->FileName, this->Size[0], this->Size[1], rgb);
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
