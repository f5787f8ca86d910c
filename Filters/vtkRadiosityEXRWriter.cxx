#include "vtkRadiosityEXRWriter.h"
#include "vtkRadiosityAdapter.h"

#include "HdrImage.h"

#include "vtkDataArray.h"
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

void vtkRadiosityEXRWriter::WriteData()
{
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "Cannot write: no FileName set.");
    return;
  }
  radiosity::SceneMesh mesh;
  std::string error;
  if (!vtkRadiosityAdapter::CopyPolygons(input, mesh, error))
  {
    vtkErrorMacro(<< "Cannot write: " << error << ".");
    return;
  }
  vtkDataArray* values = this->ArrayName ? input->GetPointData()->GetArray(this->ArrayName) : nullptr;
  if (!values || values->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro(<< "Cannot write: the input needs a 3-component point array '"
                  << (this->ArrayName ? this->ArrayName : "") << "'.");
    return;
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
    vtkErrorMacro(<< "Cannot write: " << scene.Error() << ".");
    return;
  }
  radiosity::PinholeCamera camera;
  camera.Position = { this->CameraPosition[0], this->CameraPosition[1], this->CameraPosition[2] };
  camera.FocalPoint = { this->FocalPoint[0], this->FocalPoint[1], this->FocalPoint[2] };
  camera.ViewUp = { this->ViewUp[0], this->ViewUp[1], this->ViewUp[2] };
  camera.ViewAngle = this->ViewAngle;
  camera.Width = this->Size[0];
  camera.Height = this->Size[1];
  const std::vector<float> rgb = radiosity::RenderRadiosity(scene, pointValues, camera);
  error = radiosity::WriteExr(this->FileName, camera.Width, camera.Height, rgb);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
  }
}

void vtkRadiosityEXRWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
}
