#include "Relight/LightScenes.h"

#include "Base/Text.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace radiosity
{

namespace
{
std::vector<std::string> Cells(const std::string& line)
{
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ','))
  {
    cells.push_back(Trimmed(cell));
  }
  if (!line.empty() && line.back() == ',')
  {
    cells.emplace_back();
  }
  return cells;
}

bool Number(const std::string& text, double& value)
{
  std::istringstream in(text);
  in.imbue(std::locale::classic());
  in >> value;
  return !in.fail() && in.peek() == std::char_traits<char>::eof() && std::isfinite(value);
}

/// One row's cells into `row`; empty, or what is wrong with them.
std::string ParseRow(const std::vector<std::string>& cells, LightSceneRow& row)
{
  if (cells.size() != 7)
  {
    return std::to_string(cells.size()) + " cells, not 7 (scene, lights, dimming %, r, g, b, on)";
  }
  if (cells[0].empty() || cells[1].empty())
  {
    return "a row needs a scene and the lights it sets";
  }
  row.Scene = cells[0];
  row.Lights = cells[1];
  double dimming;
  if (!Number(cells[2], dimming) || dimming < 0)
  {
    return "the dimming '" + cells[2] + "' is not a percentage of 0 or more";
  }
  row.Setting.HasIntensity = true;
  row.Setting.Intensity = dimming / 100;
  const bool noColor = cells[3].empty() && cells[4].empty() && cells[5].empty();
  for (int c = 0; c < 3 && !noColor; ++c)
  {
    if (!Number(cells[3 + c], row.Setting.Color[c]) || row.Setting.Color[c] < 0)
    {
      return "the color '" + cells[3] + ", " + cells[4] + ", " + cells[5] + "' is not three numbers of 0 or more";
    }
  }
  row.Setting.HasColor = !noColor;
  row.Setting.HasEnabled = true;
  if (!ParseOnOff(cells[6], row.Setting.Enabled))
  {
    return "'" + cells[6] + "' is not on or off";
  }
  return {};
}
} // namespace

std::string ParseLightScenes(const std::string& text, const std::string& name, std::vector<LightSceneRow>& rows)
{
  rows.clear();
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number)
  {
    const std::string content = Trimmed(line.substr(0, line.find('#')));
    if (content.empty())
    {
      continue;
    }
    LightSceneRow row;
    const std::string problem = ParseRow(Cells(content), row);
    if (!problem.empty())
    {
      rows.clear();
      return name + ":" + std::to_string(number) + ": " + ValidUtf8(problem);
    }
    rows.push_back(row);
  }
  return rows.empty() ? name + ": no light scene in it (rows of: scene, lights, dimming %, r, g, b, on)" : std::string();
}

std::vector<std::string> LightSceneNames(const std::vector<LightSceneRow>& rows)
{
  std::vector<std::string> names;
  for (const LightSceneRow& row : rows)
  {
    if (std::find(names.begin(), names.end(), row.Scene) == names.end())
    {
      names.push_back(row.Scene);
    }
  }
  return names;
}

bool SceneSetting(const std::vector<LightSceneRow>& rows, const std::string& scene, const std::string& name,
  const LightSetting& base, LightSetting& out)
{
  out = base;
  bool matched = false;
  for (const LightSceneRow& row : rows)
  {
    if (row.Scene != scene || !MatchesPattern(row.Lights, name))
    {
      continue;
    }
    matched = true;
    out.Color = row.Setting.HasColor ? row.Setting.Color : base.Color;
    out.Intensity = base.Intensity * row.Setting.Intensity; // dimming: a share of its own strength
    out.Enabled = row.Setting.Enabled;
  }
  out.HasColor = out.HasIntensity = out.HasEnabled = matched;
  return matched;
}

std::string SceneProblem(const std::vector<LightSceneRow>& rows, const std::string& scene)
{
  const std::vector<std::string> known = LightSceneNames(rows);
  if (std::find(known.begin(), known.end(), scene) != known.end())
  {
    return {};
  }
  std::string list;
  for (const std::string& s : known)
  {
    list += (list.empty() ? "" : ", ") + s;
  }
  return "no light scene is called '" + scene + "'" + (list.empty() ? " (none are loaded)" : " (there are " + list + ")");
}

} // namespace radiosity
