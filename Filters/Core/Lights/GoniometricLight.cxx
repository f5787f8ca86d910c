// "goniometric": a luminaire's measured candela distribution from its IES or EULUMDAT file,
// at the lumens the file gives it or at `lumens`.
#include "Lights/LightKinds.h"

#include "Lights/PhotometricFiles.h"

#include <sstream>

namespace radiosity
{

namespace
{
class Goniometric : public LightDistribution
{
public:
  Goniometric(PhotometricWeb web, double scale)
    : Web(std::move(web))
    , Scale(scale)
    , TotalFlux(Web.Flux() * scale)
  {
  }
  double Intensity(const Vec3& direction) const override { return Scale * Web.Intensity(direction); }
  double Flux() const override { return TotalFlux; }
  const char* Kind() const override { return "goniometric"; }

private:
  const PhotometricWeb Web;
  const double Scale, TotalFlux;
};
} // namespace

std::shared_ptr<const LightDistribution> MakeGoniometricLight(const LightParameters& parameters, std::string& error)
{
  const std::string file = parameters.Text("file");
  double lumens;
  if (!parameters.Number("lumens", 0, lumens, error))
  {
    return nullptr;
  }
  if (file.empty())
  {
    error = "a goniometric light needs its photometric file ('file')";
    return nullptr;
  }
  PhotometricWeb web;
  error = ReadPhotometricFile(file, web);
  if (!error.empty())
  {
    return nullptr;
  }
  const double flux = web.Flux();
  if (!(flux > 0))
  {
    error = file + ": its candela table sends out no light";
    return nullptr;
  }
  if (lumens < 0)
  {
    std::ostringstream s;
    s << "a goniometric light's lumens must be above 0 (0: the file's own), not " << lumens;
    error = s.str();
    return nullptr;
  }
  return std::make_shared<const Goniometric>(std::move(web), lumens > 0 ? lumens / flux : 1.0);
}

} // namespace radiosity
