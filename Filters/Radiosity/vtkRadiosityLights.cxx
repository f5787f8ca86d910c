#include "vtkRadiosityLights.h"

#include "Relight/LightRig.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkRadiosityLights);

vtkRadiosityLights::vtkRadiosityLights()
  : Settings(new radiosity::LightRig)
{
}

vtkRadiosityLights::~vtkRadiosityLights() = default;

void vtkRadiosityLights::SetLightColor(int light, double r, double g, double b)
{
  this->Settings->SetColor(light, { r, g, b });
  this->Modified();
}

void vtkRadiosityLights::SetLightIntensity(int light, double intensity)
{
  this->Settings->SetIntensity(light, intensity);
  this->Modified();
}

void vtkRadiosityLights::SetLightEnabled(int light, bool enabled)
{
  this->Settings->SetEnabled(light, enabled);
  this->Modified();
}

int vtkRadiosityLights::GetNumberOfLightSettings() const
{
  return static_cast<int>(this->Settings->ByName.size());
}

void vtkRadiosityLights::SetLightSetting(const char* name, double r, double g, double b, double intensity, int enabled)
{
  if (!name)
  {
    return;
  }
  this->Settings->SetByName(name, { r, g, b }, intensity, enabled != 0);
  this->Modified();
}

void vtkRadiosityLights::ClearLightSettings()
{
  if (!this->Settings->ByName.empty())
  {
    this->Settings->ByName.clear();
    this->Modified();
  }
}

void vtkRadiosityLights::ResetLights()
{
  this->Settings->ByName.clear();
  this->Settings->ByIndex.clear();
  this->Modified();
}

void vtkRadiosityLights::AddScheduleEntry(
  double time, const char* light, double r, double g, double b, double intensity, int enabled)
{
  if (!light)
  {
    return;
  }
  this->Settings->Schedule.push_back({ time, light, { r, g, b }, intensity, enabled != 0 });
  this->Modified();
}

void vtkRadiosityLights::ClearSchedule()
{
  if (!this->Settings->Schedule.empty())
  {
    this->Settings->Schedule.clear();
    this->Modified();
  }
}

int vtkRadiosityLights::GetNumberOfScheduleEntries() const
{
  return static_cast<int>(this->Settings->Schedule.size());
}

void vtkRadiosityLights::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Settings by index: " << this->Settings->ByIndex.size() << "\n";
  os << indent << "Settings by name: " << this->Settings->ByName.size() << "\n";
  os << indent << "Schedule entries: " << this->Settings->Schedule.size() << " (+" << this->Settings->FileSchedule.size()
     << " from a file)\n";
}
