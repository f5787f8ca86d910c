#include "vtkRadiosityLights.h"

#include "Lights/PhotometricFiles.h" // ReadTextFile
#include "Relight/LightScenes.h"

#include "Relight/LightRig.h"

#include "Base/Text.h"
#include "vtkRadiosityLightDefaults.h"

#include "vtkDelimitedTextReader.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>

vtkStandardNewMacro(vtkRadiosityLights);

vtkRadiosityLights::vtkRadiosityLights()
  : Settings(new radiosity::LightRig)
{
}

vtkRadiosityLights::~vtkRadiosityLights()
{
  this->SetScheduleFileName(nullptr);
  this->SetLightScenesFileName(nullptr);
}

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

void vtkRadiosityLights::AddScheduleRow(
  double time, const char* light, double r, double g, double b, double intensity, const char* enabled)
{
  bool on = true;
  if (!radiosity::ParseOnOff(enabled ? enabled : "", on))
  {
    char when[32];
    std::snprintf(when, sizeof(when), "%g", time);
    this->EntryError = std::string("the schedule's entry at time ") + when + " for '" +
      (light ? light : "") + "' has enabled '" + (enabled ? enabled : "") +
      "', which is not on/off, true/false, yes/no or a number";
    this->Modified();
    return;
  }
  this->AddScheduleEntry(time, light, r, g, b, intensity, on ? 1 : 0);
}

void vtkRadiosityLights::ClearSchedule()
{
  if (!this->Settings->Schedule.empty() || !this->EntryError.empty())
  {
    this->Settings->Schedule.clear();
    this->EntryError.clear();
    this->Modified();
  }
}

int vtkRadiosityLights::GetNumberOfScheduleEntries() const
{
  return static_cast<int>(this->Settings->Schedule.size());
}

namespace
{
/// When the file was last written (0 when it cannot be read): a change re-reads it.
long long WriteStamp(const std::string& file)
{
  std::error_code failed;
  const auto stamp = std::filesystem::last_write_time(file, failed);
  return failed ? 0 : static_cast<long long>(stamp.time_since_epoch().count());
}

/// The keyframes of a schedule CSV file; false with `error` naming the first bad row.
bool ReadKeyframes(const std::string& file, std::vector<radiosity::LightKeyframe>& keys, std::string& error)
{
  // A real CSV reader: quoted names may hold commas and spaces ("Warm, White").
  vtkNew<vtkDelimitedTextReader> reader;
  reader->SetFileName(file.c_str());
  reader->SetFieldDelimiterCharacters(",");
  reader->SetUseStringDelimiter(true);
  reader->SetStringDelimiter('"');
  reader->SetHaveHeaders(false);
  reader->SetDetectNumericColumns(false);
  reader->Update();
  vtkTable* table = reader->GetOutput();
  const vtkIdType columns = table->GetNumberOfColumns();
  for (vtkIdType row = 0; row < table->GetNumberOfRows(); ++row)
  {
    std::vector<std::string> cells;
    for (vtkIdType c = 0; c < columns; ++c)
    {
      cells.push_back(table->GetValue(row, c).ToString());
    }
    while (!cells.empty() && radiosity::Trimmed(cells.back()).empty())
    {
      cells.pop_back();
    }
    std::string first = cells.empty() ? std::string() : radiosity::Trimmed(cells[0]);
    std::transform(first.begin(), first.end(), first.begin(), [](unsigned char c) { return std::tolower(c); });
    if (cells.empty() || (row == 0 && first == "time"))
    {
      continue; // an empty line, or the header (known by its first column's name)
    }
    radiosity::LightKeyframe k;
    if (!radiosity::ParseKeyframe(cells, k))
    {
      error = "row " + std::to_string(row + 1) + " of '" + file +
        "' is not 'time, light, r, g, b, intensity[, enabled]' (numbers; enabled as true/false, on/off, "
        "yes/no or 1/0; quote names with commas)";
      return false;
    }
    keys.push_back(k);
  }
  return true;
}
} // namespace

void vtkRadiosityLights::SetLightScene(const char* scene)
{
  const std::string name = scene ? scene : "";
  if (name != this->Settings->ActiveScene)
  {
    this->Settings->ActiveScene = name;
    this->Modified();
  }
}

const char* vtkRadiosityLights::GetLightScene() const
{
  return this->Settings->ActiveScene.c_str();
}

int vtkRadiosityLights::GetNumberOfLightScenes() const
{
  return static_cast<int>(this->SceneNames.size());
}

const char* vtkRadiosityLights::GetLightSceneName(int i) const
{
  return i >= 0 && i < static_cast<int>(this->SceneNames.size()) ? this->SceneNames[i].c_str() : "";
}

bool vtkRadiosityLights::ReadScenesFile(std::string& error)
{
  const std::string file = this->LightScenesFileName ? this->LightScenesFileName : "";
  const long long stamp = file.empty() ? 0 : WriteStamp(file);
  if (file == this->ScenesFile && stamp == this->ScenesStamp)
  {
    return true;
  }
  this->Settings->Scenes.clear();
  this->SceneNames.clear();
  this->ScenesFile.clear();
  std::string text;
  if (file.empty())
  {
    return true;
  }
  if (!radiosity::ReadTextFile(file, text))
  {
    error = "cannot open the light-scenes file '" + file + "'";
    return false;
  }
  error = radiosity::ParseLightScenes(text, file, this->Settings->Scenes);
  if (!error.empty())
  {
    return false;
  }
  this->SceneNames = radiosity::LightSceneNames(this->Settings->Scenes);
  this->ScenesFile = file;
  this->ScenesStamp = stamp;
  return true;
}

bool vtkRadiosityLights::ReadScheduleFile(std::string& error)
{
  if (!this->ReadScenesFile(error))
  {
    return false;
  }
  const std::string file = this->ScheduleFileName ? this->ScheduleFileName : "";
  const long long stamp = file.empty() ? 0 : WriteStamp(file);
  if (file == this->ReadFile && stamp == this->ReadStamp)
  {
    return true;
  }
  std::vector<radiosity::LightKeyframe>& keys = this->Settings->FileSchedule;
  keys.clear();
  this->ReadFile.clear();
  if (file.empty())
  {
    return true;
  }
  if (!std::ifstream(file))
  {
    error = "cannot open the schedule file '" + file + "'";
    return false;
  }
  if (!ReadKeyframes(file, keys, error))
  {
    keys.clear();
    return false;
  }
  this->ReadFile = file;
  this->ReadStamp = stamp;
  return true;
}

std::string vtkRadiosityLights::Resolve(const std::vector<std::string>& names,
  const std::vector<radiosity::Vec3>& defaults, double time, std::vector<radiosity::LightSetting>& effective,
  std::vector<std::string>& warnings)
{
  std::string error = this->EntryError;
  return error.empty() && this->ReadScheduleFile(error) ? this->Settings->Resolve(names, defaults, time, effective, warnings)
                                                        : error;
}

int vtkRadiosityLights::GetSettingRowCells()
{
  return radiosity::kSettingRowCells;
}

const char* vtkRadiosityLights::GetSettingRowColumnName(int i)
{
  return i >= 0 && i < radiosity::kSettingRowCells ? radiosity::kSettingRowColumns[i].Name : nullptr;
}

int vtkRadiosityLights::GetSettingRowColumnType(int i)
{
  if (i < 0 || i >= radiosity::kSettingRowCells)
  {
    return 0;
  }
  switch (radiosity::kSettingRowColumns[i].Kind)
  {
    case radiosity::RowCell::Text:
      return VTK_STRING;
    case radiosity::RowCell::Color:
    case radiosity::RowCell::Number:
      return VTK_DOUBLE;
    case radiosity::RowCell::Flag:
      return VTK_INT;
  }
  return 0;
}

namespace
{
const radiosity::SettingColumn* Column(int i)
{
  return i >= 0 && i < radiosity::kSettingRowCells ? &radiosity::kSettingRowColumns[i] : nullptr;
}
} // namespace

const char* vtkRadiosityLights::GetSettingRowColumnHeading(int i)
{
  return Column(i) ? Column(i)->Heading : nullptr;
}

int vtkRadiosityLights::GetSettingRowColumnEditor(int i)
{
  switch (Column(i) ? Column(i)->Kind : radiosity::RowCell::Text)
  {
    case radiosity::RowCell::Color:
      return COLOR_CELL;
    case radiosity::RowCell::Number:
      return NUMBER_CELL;
    case radiosity::RowCell::Flag:
      return FLAG_CELL;
    default:
      return NAME_CELL;
  }
}

double vtkRadiosityLights::GetSettingRowColumnLow(int i)
{
  return Column(i) ? Column(i)->Low : 0.0;
}

double vtkRadiosityLights::GetSettingRowColumnHigh(int i)
{
  return Column(i) ? Column(i)->High : 0.0;
}

void vtkRadiosityLights::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Settings by index: " << this->Settings->ByIndex.size() << "\n";
  os << indent << "Settings by name: " << this->Settings->ByName.size() << "\n";
  os << indent << "Light scenes file: " << (this->LightScenesFileName ? this->LightScenesFileName : "(none)")
     << ", scene: " << (this->Settings->ActiveScene.empty() ? "(none)" : this->Settings->ActiveScene) << "\n";
  os << indent << "Schedule entries: " << this->Settings->Schedule.size() << " (+" << this->Settings->FileSchedule.size()
     << " from a file)\n";
}

std::vector<vtkRadiosityLights::ShownLight> vtkRadiosityLights::ShownLights(
  const std::vector<std::string>& inEffect, const std::vector<std::string>& edited)
{
  const std::vector<radiosity::NamedSetting> mine = radiosity::ParseSettingRows(edited);
  std::vector<ShownLight> lights;
  for (const radiosity::NamedSetting& now : radiosity::ParseSettingRows(inEffect))
  {
    ShownLight light;
    light.Name = now.Name;
    light.Cells.assign(radiosity::kSettingRowCells, 0.0);
    light.CellEdited.assign(radiosity::kSettingRowCells, 0);
    radiosity::LightSetting shown = now.Setting;
    for (const radiosity::NamedSetting& row : mine)
    {
      if (row.Name == now.Name)
      {
        row.Setting.ApplyTo(shown); // a 'nan' part keeps what is in effect
        light.Edited = true;
        for (int c = 1; c < radiosity::kSettingRowCells; ++c)
        {
          light.CellEdited[c] = light.CellEdited[c] || radiosity::kSettingRowColumns[c].Has(row.Setting);
        }
      }
    }
    for (int c = 1; c < radiosity::kSettingRowCells; ++c)
    {
      light.Cells[c] = radiosity::kSettingRowColumns[c].Get(shown);
    }
    lights.push_back(light);
  }
  return lights;
}

std::vector<std::string> vtkRadiosityLights::EditedRow(const ShownLight& light)
{
  radiosity::LightSetting setting;
  for (int c = 1; c < radiosity::kSettingRowCells && c < static_cast<int>(light.Cells.size()); ++c)
  {
    const radiosity::SettingColumn& column = radiosity::kSettingRowColumns[c];
    if (column.Kind == radiosity::RowCell::Flag || (c < static_cast<int>(light.CellEdited.size()) && light.CellEdited[c]))
    {
      column.Set(setting, light.Cells[c]);
    }
  }
  return radiosity::SettingInputRow(light.Name, setting);
}

bool vtkRadiosityLights::ReadScheduleRow(const std::vector<std::string>& cells, std::string& light, bool& enabled)
{
  radiosity::LightKeyframe key;
  if (!radiosity::ParseKeyframe(cells, key))
  {
    return false;
  }
  light = key.Light;
  enabled = key.Enabled;
  return true;
}
