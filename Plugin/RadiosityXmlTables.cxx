// Writes a plugin XML file from its template in ServerManager/, with the facts that C++
// tables hold filled in at build time: the solver methods, the reader's extensions, the
// columns of a light's row, the accuracy levels. So the XML copies none of them by hand.
// A marker it does not know stops the build.
#include "vtkLightTaggedRadiosity.h"
#include "vtkRadiosityLights.h"
#include "vtkRadiosityMesher.h"
#include "vtkRadiositySceneReader.h"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

namespace
{

std::string Number(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

/// `text` as XML text or an attribute's value.
std::string Escaped(const std::string& text)
{
  std::string out;
  for (char c : text)
  {
    out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '"' ? "&quot;" : std::string(1, c);
  }
  return out;
}

std::string Entry(int value, const std::string& text)
{
  return "<Entry value=\"" + std::to_string(value) + "\" text=\"" + Escaped(text) + "\" />";
}

std::string SolverMethodEntries()
{
  std::string out;
  for (int v = 0; v < vtkLightTaggedRadiosity::GetNumberOfSolverMethods(); ++v)
  {
    out += Entry(v, vtkLightTaggedRadiosity::GetSolverMethodName(v));
  }
  return out;
}

/// ParaView's element type of a row cell (vtkSMVectorProperty: 0 int, 1 double, 2 string).
int ElementType(int vtkType)
{
  return vtkType == VTK_STRING ? 2 : vtkType == VTK_DOUBLE ? 1 : 0;
}

std::string LightRowTypes()
{
  std::string out;
  for (int i = 0; i < vtkRadiosityLights::GetSettingRowCells(); ++i)
  {
    out += (i ? " " : "") + std::to_string(ElementType(vtkRadiosityLights::GetSettingRowColumnType(i)));
  }
  return out;
}

std::string LightRowColumns()
{
  std::string out;
  for (int i = 0; i < vtkRadiosityLights::GetSettingRowCells(); ++i)
  {
    out += (i ? ", " : "") + std::string(vtkRadiosityLights::GetSettingRowColumnName(i));
  }
  return out;
}

std::string Capitalized(std::string name)
{
  if (!name.empty())
  {
    name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
  }
  return name;
}

std::string AccuracyEntries()
{
  std::string out = Entry(-1, "Custom");
  for (int level = 0; level < vtkRadiosityMesher::GetNumberOfAccuracyLevels(); ++level)
  {
    out += Entry(level, Capitalized(vtkRadiosityMesher::GetAccuracyName(level)));
  }
  return out;
}

/// What each level sets, one sentence a level, as the mesher's tooltip gives it.
std::string AccuracyTable()
{
  std::string out;
  for (int level = 0; level < vtkRadiosityMesher::GetNumberOfAccuracyLevels(); ++level)
  {
    const int sweeps = vtkRadiosityMesher::GetAccuracyGatherSweeps(level);
    out += (level ? " " : "") + Capitalized(vtkRadiosityMesher::GetAccuracyName(level)) + ": Element Size \u00d7" +
      Number(vtkRadiosityMesher::GetAccuracyElementScale(level)) + ", Lamp Grading " +
      Number(vtkRadiosityMesher::GetAccuracyLampGrading(level)) + ", Shadow Grading " +
      Number(vtkRadiosityMesher::GetAccuracyShadowGrading(level)) + ", " +
      std::to_string(vtkRadiosityMesher::GetAccuracyGatherRays(level)) + " gather rays, Cluster Separation " +
      Number(vtkRadiosityMesher::GetAccuracyClusterSeparation(level)) + ", " +
      std::to_string(sweeps) + (sweeps == 1 ? " gather sweep." : " gather sweeps.");
  }
  return out;
}

const std::map<std::string, std::function<std::string()>>& Facts()
{
  static const std::map<std::string, std::function<std::string()>> facts = {
    { "SOLVER_METHOD_ENTRIES", SolverMethodEntries },
    { "SCENE_FILE_EXTENSIONS", [] { return Escaped(vtkRadiositySceneReader::GetFileExtensions()); } },
    { "LIGHT_ROW_CELLS", [] { return std::to_string(vtkRadiosityLights::GetSettingRowCells()); } },
    { "LIGHT_ROW_TYPES", LightRowTypes },
    { "LIGHT_ROW_COLUMNS", [] { return Escaped(LightRowColumns()); } },
    { "ACCURACY_LEVEL_ENTRIES", AccuracyEntries },
    { "ACCURACY_LEVEL_TABLE", [] { return Escaped(AccuracyTable()); } },
    { "METHOD_SETTINGS", [] { return Escaped(vtkLightTaggedRadiosity::DescribeMethodSettings()); } },
  };
  return facts;
}

/// `text` with every @NAME@ of Facts() replaced; false (and the name in `unknown`) at an
/// @NAME@ it does not know. An @ not followed by a name and @ is left as it is.
bool FillIn(const std::string& text, std::string& out, std::string& unknown)
{
  size_t at = 0;
  while (at < text.size())
  {
    const size_t open = text.find('@', at);
    const size_t close = open == std::string::npos ? open : text.find('@', open + 1);
    if (close == std::string::npos)
    {
      out.append(text, at, std::string::npos);
      break;
    }
    const std::string name = text.substr(open + 1, close - open - 1);
    const bool marker = !name.empty() && name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ_") == std::string::npos;
    out.append(text, at, (marker ? open : close) - at);
    at = marker ? close + 1 : close;
    if (marker)
    {
      const auto fact = Facts().find(name);
      if (fact == Facts().end())
      {
        unknown = name;
        return false;
      }
      out += fact->second();
    }
  }
  return true;
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: RadiosityXmlTables TEMPLATE.xml OUTPUT.xml\n";
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string filled, unknown;
  if (!in || !FillIn(text.str(), filled, unknown))
  {
    std::cerr << argv[1] << ": " << (in ? "no table gives @" + unknown + "@" : std::string("cannot be read")) << "\n";
    return 1;
  }
  // Unchanged, the file is left as it is (its time too), so that a relinked library does
  // not remake the plugin's XML and everything after it.
  std::ifstream before(argv[2], std::ios::binary);
  std::stringstream written;
  written << before.rdbuf();
  if (before && written.str() == filled)
  {
    return 0;
  }
  std::ofstream out(argv[2], std::ios::binary);
  out << filled;
  return out ? 0 : 1;
}
