#include "Lights/LightKinds.h"

#include "Lights/NumberTokens.h"

namespace radiosity
{

bool LightParameters::Number(const std::string& name, double fallback, double& value, std::string& error) const
{
  Read.insert(name);
  const auto it = Values.find(name);
  if (it == Values.end() || it->second.empty())
  {
    value = fallback;
    return true;
  }
  if (!ParseNumber(it->second, value))
  {
    error = "'" + name + "' is '" + it->second + "', not a number";
    return false;
  }
  return true;
}

std::string LightParameters::Text(const std::string& name) const
{
  Read.insert(name);
  const auto it = Values.find(name);
  return it == Values.end() ? std::string() : it->second;
}

std::string LightParameters::Unused() const
{
  std::string unused;
  for (const auto& value : Values)
  {
    if (!Read.count(value.first))
    {
      unused += (unused.empty() ? "" : ", ") + value.first;
    }
  }
  return unused;
}

const std::vector<LightKind>& LightKinds()
{
  static const std::vector<LightKind> kinds{
    { "point", "(none)", MakeIsotropicLight },
    { "lambertian", "(none)", MakeLambertianLight },
    { "spot", "cone (degrees, 30), falloff (degrees, 5)", MakeSpotLight },
    { "goniometric", "file (IES or EULUMDAT), lumens (the file's)", MakeGoniometricLight },
  };
  return kinds;
}

std::shared_ptr<const LightDistribution> MakeLightDistribution(
  const std::string& kind, const LightParameters& parameters, std::string& error)
{
  error.clear();
  for (const LightKind& row : LightKinds())
  {
    if (kind != row.Name)
    {
      continue;
    }
    std::shared_ptr<const LightDistribution> made = row.Make(parameters, error);
    const std::string unused = parameters.Unused();
    if (made && !unused.empty())
    {
      error = std::string("a ") + row.Name + " light does not take " + unused + " (it takes " + row.Parameters + ")";
      made.reset();
    }
    if (!made && error.empty())
    {
      error = std::string("a ") + row.Name + " light could not be made";
    }
    return made;
  }
  std::string names;
  for (const LightKind& row : LightKinds())
  {
    names += (names.empty() ? "" : ", ") + std::string(row.Name);
  }
  error = "no kind of light is called '" + kind + "' (there are " + names + ")";
  return nullptr;
}

} // namespace radiosity
