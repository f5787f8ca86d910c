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

namespace
{
/// Another distribution's shape at another flux.
class Scaled : public LightDistribution
{
public:
  Scaled(std::shared_ptr<const LightDistribution> shape, double factor)
    : Shape(std::move(shape))
    , Factor(factor)
  {
  }
  double Intensity(const Vec3& direction) const override { return Factor * Shape->Intensity(direction); }
  double Flux() const override { return Factor * Shape->Flux(); }
  const char* Kind() const override { return Shape->Kind(); }
  Vec3 Opening() const override { return Shape->Opening(); }

private:
  std::shared_ptr<const LightDistribution> Shape;
  double Factor;
};
} // namespace

std::shared_ptr<const LightDistribution> WithLumens(
  std::shared_ptr<const LightDistribution> made, const LightParameters& parameters, std::string& error)
{
  double lumens, maintenance;
  if (!made || !parameters.Number("lumens", 0, lumens, error) || !parameters.Number("maintenance", 1, maintenance, error))
  {
    return nullptr;
  }
  if (lumens < 0)
  {
    error = "lumens must be 0 or more (0: the light's own), not " + std::to_string(lumens);
    return nullptr;
  }
  if (!(maintenance > 0 && maintenance <= 1))
  {
    error = "a maintenance factor is above 0 and at most 1, not " + std::to_string(maintenance);
    return nullptr;
  }
  const double factor = (lumens > 0 ? lumens / made->Flux() : 1.0) * maintenance;
  return factor != 1.0 ? std::make_shared<const Scaled>(made, factor) : made;
}

const std::vector<LightKind>& LightKinds()
{
  static const std::vector<LightKind> kinds{
    { "point", "lumens (1 W/sr if left out), maintenance (1)", MakeIsotropicLight },
    { "lambertian", "lumens (1 W/sr along its aim if left out), maintenance (1)", MakeLambertianLight },
    { "spot", "cone (degrees, 30), falloff (degrees, 5), lumens (1 W/sr in the cone if left out), maintenance (1)",
      MakeSpotLight },
    { "goniometric", "file (IES or EULUMDAT), lumens (the file's), maintenance (1), tilt (degrees from as measured, 0)",
      MakeGoniometricLight },
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
