#include "Import/Wavefront.h"
#include "Base/Text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

namespace radiosity
{
namespace
{
/// The rest of the line after the keyword, trimmed (names may hold spaces).
std::string Rest(std::istringstream& words)
{
  std::string rest;
  std::getline(words, rest);
  return Trimmed(rest);
}

bool Number(const std::string& word, double& value)
{
  char* end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return !word.empty() && end == word.c_str() + word.size();
}

/// "Kd 0.5 0.4 0.3" or "Kd 0.5" (grey) after the keyword; false if not finite numbers.
bool ReadColor(std::istringstream& words, Vec3& color)
{
  std::vector<double> values;
  std::string word;
  double value = 0;
  while (words >> word)
  {
    if (!Number(word, value) || !std::isfinite(value))
    {
      return false;
    }
    values.push_back(value);
  }
  if (values.size() != 1 && values.size() != 3)
  {
    return false;
  }
  color = values.size() == 1 ? Vec3{ value, value, value } : Vec3{ values[0], values[1], values[2] };
  return true;
}

/// A face corner "7", "7/2", "7//3" or "7/2/3" (1-based, negative from the end) as a
/// 0-based point index; -1 if malformed or out of range.
int CornerIndex(const std::string& word, int points)
{
  char* end = nullptr;
  const long index = std::strtol(word.c_str(), &end, 10);
  if (end == word.c_str() || (*end != '\0' && *end != '/'))
  {
    return -1;
  }
  const long zeroBased = index < 0 ? points + index : index - 1;
  return index != 0 && zeroBased >= 0 && zeroBased < points ? static_cast<int>(zeroBased) : -1;
}

/// The index of the named entry, added at the end when new.
int IndexOf(const std::string& name, std::map<std::string, int>& index, std::vector<std::string>& names)
{
  const auto found = index.emplace(name, static_cast<int>(names.size()));
  if (found.second)
  {
    names.push_back(name);
  }
  return found.first->second;
}

/// Calls statement(keyword, words, where) for each line that is not blank or a comment,
/// `where` being "line N: "; stops at the first error it returns.
template <typename Statement>
std::string EachStatement(const std::string& text, Statement statement)
{
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number)
  {
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword) || keyword[0] == '#')
    {
      continue;
    }
    const std::string error = statement(keyword, words, "line " + std::to_string(number) + ": ");
    if (!error.empty())
    {
      return error;
    }
  }
  return std::string();
}

} // namespace

std::string ParseObj(const std::string& text, RawScene& raw, std::vector<std::string>& libraries)
{
  std::map<std::string, int> objects, materials;
  std::vector<std::string> materialNames;
  int object = -1, material = -1;
  const std::string error = EachStatement(text, [&](const std::string& keyword, std::istringstream& words,
                                                   const std::string& where) -> std::string {
    if (keyword == "v")
    {
      std::string word;
      double x[3];
      for (double& value : x)
      {
        if (!(words >> word) || !Number(word, value))
        {
          return where + "a vertex needs three numbers";
        }
        if (!std::isfinite(value))
        {
          return where + "a vertex coordinate is not a finite number ('" + word + "')";
        }
      }
      raw.Points.push_back({ x[0], x[1], x[2] });
    }
    else if (keyword == "f")
    {
      std::string word;
      int corners = 0;
      while (words >> word)
      {
        const int index = CornerIndex(word, static_cast<int>(raw.Points.size()));
        if (index < 0)
        {
          return where + "face corner '" + word + "' is not a vertex defined before it";
        }
        raw.Connectivity.push_back(index);
        ++corners;
      }
      if (corners < 3)
      {
        return where + "a face needs at least three corners";
      }
      raw.Offsets.push_back(static_cast<int>(raw.Connectivity.size()));
      raw.Material.push_back(material);
      raw.Object.push_back(object);
    }
    else if (keyword == "usemtl")
    {
      material = IndexOf(Rest(words), materials, materialNames);
    }
    else if (keyword == "o" || keyword == "g")
    {
      object = IndexOf(Rest(words), objects, raw.ObjectNames);
    }
    else if (keyword == "mtllib")
    {
      libraries.push_back(Rest(words));
    }
    return std::string();
  });
  for (const std::string& name : materialNames)
  {
    raw.Materials.push_back(ImportMaterial{ name });
  }
  return error;
}

std::string ParseMtl(const std::string& text, std::vector<ImportMaterial>& materials)
{
  ImportMaterial* current = nullptr;
  ImportMaterial ignored; // a repeated name's second definition lands here
  return EachStatement(text, [&](const std::string& keyword, std::istringstream& words,
                               const std::string& where) -> std::string {
    if (keyword == "newmtl")
    {
      const std::string name = Rest(words);
      if (name.empty())
      {
        return where + "newmtl without a name";
      }
      const bool known = std::any_of(materials.begin(), materials.end(), [&](const ImportMaterial& m) { return m.Name == name; });
      if (!known)
      {
        materials.push_back(ImportMaterial{ name });
      }
      current = known ? &ignored : &materials.back();
      return std::string();
    }
    if (keyword != "Kd" && keyword != "Ke" && keyword != "map_Kd" && keyword != "map_Ke")
    {
      return std::string();
    }
    if (!current)
    {
      return where + keyword + " before any newmtl";
    }
    if (keyword == "map_Kd" || keyword == "map_Ke")
    {
      // Options (-s, -o, ...) come before the file name; the name is the last word.
      const std::string path = Rest(words);
      const size_t space = path.find_last_of(" \t");
      (keyword == "map_Kd" ? current->DiffuseTexture : current->EmissiveTexture) =
        space == std::string::npos ? path : path.substr(space + 1);
      return std::string();
    }
    Vec3& target = keyword == "Kd" ? current->Diffuse : current->Emissive;
    return ReadColor(words, target) ? std::string()
                                     : where + keyword + " needs one or three finite numbers (material '" + current->Name + "')";
  });
}

} // namespace radiosity
