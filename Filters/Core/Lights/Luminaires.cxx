#include "Lights/Luminaires.h"

#include "Base/Text.h"

#include <set>

namespace radiosity
{

std::string ParseLightParameters(const std::string& text, LightParameters& out)
{
  std::set<std::string> seen;
  size_t start = 0;
  while (start <= text.size())
  {
    const size_t end = std::min(text.find(';', start), text.size());
    const std::string pair = Trimmed(text.substr(start, end - start));
    start = end + 1;
    if (pair.empty())
    {
      continue;
    }
    const size_t equals = pair.find('=');
    if (equals == std::string::npos)
    {
      return "'" + pair + "' is not name=value";
    }
    const std::string name = Trimmed(pair.substr(0, equals));
    if (!seen.insert(name).second)
    {
      return "'" + name + "' is given twice";
    }
    out.Set(name, Trimmed(pair.substr(equals + 1)));
  }
  return {};
}

std::string MakePointLight(const LuminaireRow& row, PointLight& out)
{
  const std::string what = "luminaire '" + row.Name + "'";
  LightParameters parameters;
  std::string error = ParseLightParameters(row.Parameters, parameters);
  if (error.empty())
  {
    out = PointLight();
    out.Distribution = MakeLightDistribution(row.Kind, parameters, error);
  }
  if (!error.empty())
  {
    return what + ": " + error;
  }
  out.Position = row.Position;
  out.Aim = row.Aim;
  out.Rotation = row.Rotation;
  out.Color = row.Color;
  return PointLightProblem(out, what);
}

std::string LuminaireNamesProblem(const std::vector<LuminaireRow>& rows, const std::vector<std::string>& taken)
{
  std::set<std::string> names(taken.begin(), taken.end());
  for (const LuminaireRow& row : rows)
  {
    if (row.Name.empty() || row.Name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_") !=
        std::string::npos)
    {
      return "luminaire name '" + ValidUtf8(row.Name) + "' is not made of letters, digits and '_' only";
    }
    if (!names.insert(row.Name).second)
    {
      return "luminaire name '" + row.Name + "' is taken by another light";
    }
  }
  return {};
}

} // namespace radiosity
