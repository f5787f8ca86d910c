#include "Relight/LightRig.h"
#include "Relight/LightScenes.h"

#include <cstdio>
#include "Base/Text.h"

#include <algorithm>
#include <iterator>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

namespace radiosity
{
namespace
{
/// A whole cell as a finite number; false for anything else ("1.5x", "", "nan").
bool ParseNumber(const std::string& text, double& value)
{
  char* end = nullptr;
  const std::string cell = Trimmed(text);
  value = std::strtod(cell.c_str(), &end);
  return !cell.empty() && end == cell.c_str() + cell.size() && std::isfinite(value);
}

/// true/false, on/off, yes/no, 1/0 in any case.
bool ParseEnabled(const std::string& text, bool& value)
{
  std::string word = Trimmed(text);
  std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return std::tolower(c); });
  const bool on = word == "1" || word == "true" || word == "on" || word == "yes";
  const bool off = word == "0" || word == "false" || word == "off" || word == "no";
  value = on;
  return on || off;
}

std::string Joined(const std::vector<std::string>& names)
{
  std::string all;
  for (const std::string& name : names)
  {
    all += (all.empty() ? "" : ";") + name;
  }
  return all;
}

} // namespace

std::string InvalidLightValues(double intensity, const Vec3& color)
{
  std::ostringstream why;
  if (!(std::isfinite(intensity) && intensity >= 0))
  {
    why << "has intensity " << intensity << "; it must be a finite number >= 0";
  }
  for (int c = 0; c < 3 && why.str().empty(); ++c)
  {
    if (!(std::isfinite(color[c]) && color[c] >= 0))
    {
      why << "has color component " << c << " = " << color[c] << "; colors must be finite and >= 0";
    }
  }
  return why.str();
}

void LightSetting::ApplyTo(LightSetting& effective) const
{
  if (this->HasColor)
  {
    effective.Color = this->Color;
  }
  if (this->HasIntensity)
  {
    effective.Intensity = this->Intensity;
  }
  if (this->HasEnabled)
  {
    effective.Enabled = this->Enabled;
  }
}

void LightRig::SetColor(int light, const Vec3& color)
{
  LightSetting& s = this->ByIndex[light];
  s.HasColor = true;
  s.Color = color;
}

void LightRig::SetIntensity(int light, double intensity)
{
  LightSetting& s = this->ByIndex[light];
  s.HasIntensity = true;
  s.Intensity = intensity;
}

void LightRig::SetEnabled(int light, bool enabled)
{
  LightSetting& s = this->ByIndex[light];
  s.HasEnabled = true;
  s.Enabled = enabled;
}

void LightRig::SetByName(const std::string& name, const Vec3& color, double intensity, bool enabled)
{
  LightSetting& s = this->ByName[name];
  s.HasColor = !(std::isnan(color.x) || std::isnan(color.y) || std::isnan(color.z));
  s.HasIntensity = !std::isnan(intensity);
  s.HasEnabled = true;
  s.Color = color;
  s.Intensity = intensity;
  s.Enabled = enabled;
}

std::vector<std::string> SettingRow(const std::string& name, const LightSetting& setting)
{
  std::vector<std::string> row{ name };
  for (int c = 1; c < kSettingRowCells; ++c)
  {
    const SettingColumn& column = kSettingRowColumns[c];
    const double value = column.Get(setting);
    char text[32];
    std::snprintf(text, sizeof(text), "%.9g", value);
    row.emplace_back(column.Kind == RowCell::Flag ? (value != 0 ? "1" : "0") : text);
  }
  return row;
}

bool ParseOnOff(const std::string& text, bool& on)
{
  double number = 0;
  if (ParseEnabled(text, on))
  {
    return true;
  }
  const bool numeric = ParseNumber(text, number);
  on = numeric && number != 0;
  return numeric;
}

std::vector<std::string> SettingInputRow(const std::string& name, const LightSetting& setting)
{
  std::vector<std::string> row = SettingRow(name, setting);
  for (int c = 1; c < kSettingRowCells; ++c)
  {
    const SettingColumn& column = kSettingRowColumns[c];
    if (column.Kind != RowCell::Flag && !column.Has(setting))
    {
      row[c] = "nan";
    }
  }
  return row;
}

namespace
{
/// Cells [first, end) of a row that share column `first`'s heading: one part of a setting.
int PartEnd(int first)
{
  int end = first + 1;
  while (end < kSettingRowCells && std::string(kSettingRowColumns[end].Heading) == kSettingRowColumns[first].Heading)
  {
    ++end;
  }
  return end;
}

/// Reads cells [first, end) of `row` into `setting` where every one of them reads (a Flag
/// as ParseOnOff takes it); false, leaving the part unset, where one does not.
bool ReadPart(const std::string* row, int first, int end, LightSetting& setting)
{
  std::vector<double> values;
  for (int c = first; c < end; ++c)
  {
    double value = 0;
    bool on = false;
    const bool flag = kSettingRowColumns[c].Kind == RowCell::Flag;
    if (!(flag ? ParseOnOff(row[c], on) : ParseNumber(row[c], value)))
    {
      return false;
    }
    values.push_back(flag ? (on ? 1.0 : 0.0) : value);
  }
  for (int c = first; c < end; ++c)
  {
    kSettingRowColumns[c].Set(setting, values[c - first]);
  }
  return true;
}
} // namespace

std::vector<NamedSetting> ParseSettingRows(const std::vector<std::string>& flat)
{
  std::vector<NamedSetting> rows;
  for (size_t i = 0; i + kSettingRowCells <= flat.size(); i += kSettingRowCells)
  {
    NamedSetting row;
    row.Name = flat[i];
    bool readable = !row.Name.empty();
    for (int first = 1; first < kSettingRowCells; first = PartEnd(first))
    {
      // A number that does not read leaves its part to what lies below; an on/off that does
      // not read leaves the row out.
      const bool read = ReadPart(&flat[i], first, PartEnd(first), row.Setting);
      readable = readable && (read || kSettingRowColumns[first].Kind != RowCell::Flag);
    }
    if (readable)
    {
      rows.push_back(row);
    }
  }
  return rows;
}

bool ParseKeyframe(const std::vector<std::string>& cells, LightKeyframe& key)
{
  key = LightKeyframe();
  key.Light = Trimmed(cells.size() > 1 ? cells[1] : "");
  return (cells.size() == 6 || cells.size() == 7) && ParseNumber(cells[0], key.Time) && !key.Light.empty() &&
    ParseNumber(cells[2], key.Color.x) && ParseNumber(cells[3], key.Color.y) && ParseNumber(cells[4], key.Color.z) &&
    ParseNumber(cells[5], key.Intensity) && (cells.size() == 6 || ParseEnabled(cells[6], key.Enabled));
}

bool LightRig::Scheduled(const std::string& name, int index, double time, const LightSetting& base, LightSetting& out) const
{
  // The keyframes that speak of this light: by name, by index, or through a scene that
  // sets it (taken as the setting the scene gives it then).
  LightKeyframe before, after;
  bool hasBefore = false, hasAfter = false;
  for (const auto* list : { &this->FileSchedule, &this->Schedule })
  {
    for (const LightKeyframe& given : *list)
    {
      LightKeyframe k = given;
      LightSetting scened;
      const bool scene = k.Light.rfind("scene:", 0) == 0;
      if (scene && SceneSetting(this->Scenes, k.Light.substr(6), name, base, scened))
      {
        k.Color = scened.Color;
        k.Intensity = scened.Intensity;
        k.Enabled = scened.Enabled;
      }
      else if (scene || (k.Light != name && k.Light != std::to_string(index)))
      {
        continue;
      }
      if (k.Time <= time && (!hasBefore || k.Time >= before.Time))
      {
        before = k;
        hasBefore = true;
      }
      if (k.Time >= time && (!hasAfter || k.Time < after.Time))
      {
        after = k;
        hasAfter = true;
      }
    }
  }
  if (!hasBefore && !hasAfter)
  {
    return false;
  }
  const LightKeyframe& a = hasBefore ? before : after;
  const LightKeyframe& b = hasAfter ? after : before;
  const double w = b.Time > a.Time ? (time - a.Time) / (b.Time - a.Time) : 0.0;
  out.HasColor = out.HasIntensity = out.HasEnabled = true;
  out.Color = a.Color + (b.Color - a.Color) * w;
  out.Intensity = a.Intensity + w * (b.Intensity - a.Intensity);
  out.Enabled = a.Enabled;
  return true;
}

std::vector<double> LightRig::KeyframeTimes() const
{
  std::vector<double> times;
  for (const auto* list : { &this->FileSchedule, &this->Schedule })
  {
    for (const LightKeyframe& k : *list)
    {
      times.push_back(k.Time);
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

std::string LightRig::Resolve(const std::vector<std::string>& names, const std::vector<Vec3>& defaults, double time,
  std::vector<LightSetting>& effective, std::vector<std::string>& warnings) const
{
  effective.clear();
  const std::string scene = this->ActiveScene.empty() ? std::string() : SceneProblem(this->Scenes, this->ActiveScene);
  if (!scene.empty())
  {
    return scene;
  }
  const int k = static_cast<int>(names.size());
  for (int i = 0; i < k; ++i)
  {
    LightSetting s;
    // A default (the lamp's Emission) is its hue, brightest channel 1, times its strength:
    // an intensity set replaces the strength and a color set keeps it (an area light of
    // intensity 20 set to 40 shone at 800, and set to white dropped to 1).
    const Vec3 given = i < static_cast<int>(defaults.size()) ? defaults[i] : Vec3{ 1, 1, 1 };
    const double peak = std::max({ given.x, given.y, given.z });
    s.Color = peak > 0 ? given * (1.0 / peak) : given;
    s.Intensity = peak > 0 ? peak : 1.0;
    const LightSetting own = s;
    LightSetting scened;
    if (!this->ActiveScene.empty() && SceneSetting(this->Scenes, this->ActiveScene, names[i], own, scened))
    {
      s = scened;
    }
    const auto byName = this->ByName.find(names[i]);
    if (byName != this->ByName.end())
    {
      byName->second.ApplyTo(s);
    }
    LightSetting scheduled;
    if (this->Scheduled(names[i], i, time, own, scheduled))
    {
      scheduled.ApplyTo(s);
    }
    const auto byIndex = this->ByIndex.find(i);
    if (byIndex != this->ByIndex.end())
    {
      byIndex->second.ApplyTo(s);
    }
    const std::string invalid = s.Enabled ? InvalidLightValues(s.Intensity, s.Color) : std::string();
    if (!invalid.empty())
    {
      return "light '" + names[i] + "' " + invalid;
    }
    effective.push_back(s);
  }
  const auto known = [&](const std::string& light) { return std::find(names.begin(), names.end(), light) != names.end(); };
  for (const auto& entry : this->ByName)
  {
    if (!known(entry.first))
    {
      warnings.push_back("No light is named '" + entry.first + "'; lights are: " + Joined(names));
    }
  }
  std::set<std::string> unknown;
  for (const auto* list : { &this->FileSchedule, &this->Schedule })
  {
    for (const LightKeyframe& key : *list)
    {
      bool index = false;
      for (int i = 0; i < k && !index; ++i)
      {
        index = key.Light == std::to_string(i);
      }
      const bool scene = key.Light.rfind("scene:", 0) == 0;
      if (scene && !SceneProblem(this->Scenes, key.Light.substr(6)).empty())
      {
        warnings.push_back("The light schedule's '" + key.Light + "': " + SceneProblem(this->Scenes, key.Light.substr(6)));
      }
      else if (!scene && !index && !known(key.Light))
      {
        unknown.insert(key.Light);
      }
    }
  }
  for (const std::string& light : unknown)
  {
    warnings.push_back("The light schedule names '" + light + "', which is no light; lights are: " + Joined(names));
  }
  for (const auto& entry : this->ByIndex)
  {
    if (entry.first < 0 || entry.first >= k)
    {
      warnings.push_back("Light index " + std::to_string(entry.first) + " is out of range; there are " +
        std::to_string(k) + " lights.");
    }
  }
  return std::string();
}

std::vector<double> LightWeights(const std::vector<LightSetting>& effective, double indirectScale)
{
  std::vector<double> weights;
  for (const LightSetting& s : effective)
  {
    const Vec3 w = s.Weight();
    weights.insert(weights.end(), { w.x, w.y, w.z });
  }
  if (indirectScale != 1.0)
  {
    const size_t total = weights.size();
    for (size_t w = 0; w < total; ++w)
    {
      weights.push_back(weights[w] * (1.0 - indirectScale));
      weights[w] *= indirectScale;
    }
  }
  return weights;
}

std::vector<std::string> SaidOnce::New(const std::vector<std::string>& warnings)
{
  std::vector<std::string> fresh;
  std::copy_if(warnings.begin(), warnings.end(), std::back_inserter(fresh),
    [&](const std::string& w) { return std::find(Said.begin(), Said.end(), w) == Said.end(); });
  Said = warnings;
  return fresh;
}

} // namespace radiosity
