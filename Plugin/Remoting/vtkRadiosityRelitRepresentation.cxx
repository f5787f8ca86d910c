#include "vtkRadiosityRelitRepresentation.h"
#include "vtkRadiosityLights.h"

#include "vtkRadiosityRelightMapper.h"

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkStringArray.h"

vtkStandardNewMacro(vtkRadiosityRelitRepresentation);

vtkRadiosityRelitRepresentation::vtkRadiosityRelitRepresentation()
  : Mapper(vtkSmartPointer<vtkRadiosityRelightMapper>::New())
  , ColorsMapper(vtkSmartPointer<vtkPolyDataMapper>::New())
  , Actor(vtkSmartPointer<vtkActor>::New())
  , Data(vtkSmartPointer<vtkPolyData>::New())
  , NamesInfo(vtkSmartPointer<vtkStringArray>::New())
  , SettingsInfo(vtkSmartPointer<vtkStringArray>::New())
{
  this->Actor->SetMapper(this->Mapper);
  // The shader draws the relit colors unlit; the actor's lighting plays no part.
  this->Actor->GetProperty()->LightingOff();
  // Unsigned char colors pass through unmapped in the default color mode.
  this->ColorsMapper->SetScalarModeToUsePointFieldData();
  this->ColorsMapper->SelectColorArray("DisplayColors");
  this->ColorsMapper->SetColorModeToDefault();
  this->ColorsMapper->ScalarVisibilityOn();
}

void vtkRadiosityRelitRepresentation::SetComputedColors(int computed)
{
  vtkMapper* wanted = computed ? static_cast<vtkMapper*>(this->ColorsMapper) : this->Mapper;
  if (this->Actor->GetMapper() != wanted)
  {
    this->Actor->SetMapper(wanted);
    this->Modified();
  }
}

vtkRadiosityRelitRepresentation::~vtkRadiosityRelitRepresentation() = default;

// Light settings reach the mapper directly: no MarkModified, so no pipeline update and no
// new delivery of the data; the view's next render uses them.
void vtkRadiosityRelitRepresentation::SetLightSetting(
  const char* name, double r, double g, double b, double intensity, int enabled)
{
  this->Mapper->GetLights()->SetLightSetting(name, r, g, b, intensity, enabled);
}

void vtkRadiosityRelitRepresentation::ClearLightSettings()
{
  this->Mapper->GetLights()->ClearLightSettings();
}

void vtkRadiosityRelitRepresentation::AddScheduleEntry(
  double time, const char* light, double r, double g, double b, double intensity, int enabled)
{
  this->Mapper->GetLights()->AddScheduleEntry(time, light, r, g, b, intensity, enabled);
}

void vtkRadiosityRelitRepresentation::AddScheduleRow(
  double time, const char* light, double r, double g, double b, double intensity, const char* enabled)
{
  this->Mapper->GetLights()->AddScheduleRow(time, light, r, g, b, intensity, enabled);
}

void vtkRadiosityRelitRepresentation::ClearSchedule()
{
  this->Mapper->GetLights()->ClearSchedule();
}

void vtkRadiosityRelitRepresentation::SetScheduleFileName(const char* file)
{
  this->Mapper->GetLights()->SetScheduleFileName(file);
}

void vtkRadiosityRelitRepresentation::SetLightScenesFileName(const char* file)
{
  this->Mapper->GetLights()->SetLightScenesFileName(file);
}

void vtkRadiosityRelitRepresentation::SetLightScene(const char* scene)
{
  this->Mapper->GetLights()->SetLightScene(scene);
}

void vtkRadiosityRelitRepresentation::SetUpdateTime(double time)
{
  this->Mapper->SetTime(time);
  this->Superclass::SetUpdateTime(time);
}

void vtkRadiosityRelitRepresentation::SetRelightExposure(double exposure)
{
  this->Mapper->SetExposure(exposure);
}

vtkStringArray* vtkRadiosityRelitRepresentation::GetLightNames()
{
  this->Mapper->DescribeLights(this->Data, this->NamesInfo, this->SettingsInfo);
  return this->NamesInfo;
}

vtkStringArray* vtkRadiosityRelitRepresentation::GetLightSettingsInfo()
{
  this->Mapper->DescribeLights(this->Data, this->NamesInfo, this->SettingsInfo);
  return this->SettingsInfo;
}

vtkRadiosityRelightMapper* vtkRadiosityRelitRepresentation::GetMapper()
{
  return this->Mapper;
}

int vtkRadiosityRelitRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkRadiosityRelitRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  auto* input = inputVector[0]->GetNumberOfInformationObjects() ? vtkPolyData::GetData(inputVector[0], 0) : nullptr;
  this->Data = vtkSmartPointer<vtkPolyData>::New();
  if (input)
  {
    this->Data->ShallowCopy(input);
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

int vtkRadiosityRelitRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request, inInfo, outInfo))
  {
    return 0;
  }
  if (request == vtkPVView::REQUEST_UPDATE())
  {
    vtkPVView::SetPiece(inInfo, this, this->Data);
    vtkPVRenderView::SetGeometryBounds(inInfo, this, this->Data->GetBounds());
  }
  else if (request == vtkPVView::REQUEST_RENDER())
  {
    if (vtkAlgorithmOutput* producer = vtkPVRenderView::GetPieceProducer(inInfo, this))
    {
      this->Mapper->SetInputConnection(producer);
      this->ColorsMapper->SetInputConnection(producer);
    }
  }
  return 1;
}

bool vtkRadiosityRelitRepresentation::AddToView(vtkView* view)
{
  if (auto* render = vtkPVRenderView::SafeDownCast(view))
  {
    render->GetRenderer()->AddActor(this->Actor);
    return this->Superclass::AddToView(view);
  }
  return false;
}

bool vtkRadiosityRelitRepresentation::RemoveFromView(vtkView* view)
{
  if (auto* render = vtkPVRenderView::SafeDownCast(view))
  {
    render->GetRenderer()->RemoveActor(this->Actor);
    return this->Superclass::RemoveFromView(view);
  }
  return false;
}

void vtkRadiosityRelitRepresentation::SetVisibility(bool visible)
{
  this->Actor->SetVisibility(visible ? 1 : 0);
  this->Superclass::SetVisibility(visible);
}

void vtkRadiosityRelitRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
