// "goniometric": a luminaire's measured candela distribution from its IES or EULUMDAT file,
// at the lumens the file gives it or at `lumens`.
#include "Lights/LightKinds.h"

#include "Lights/PhotometricFiles.h"


namespace radiosity
{

namespace
{
class Goniometric : public LightDistribution
{
public:
  explicit Goniometric(PhotometricWeb web)
    : Web(std::move(web))
    , TotalFlux(Web.Flux())
  {
  }
  double Intensity(const Vec3& direction) const override { return Web.Intensity(direction); }
  double Flux() const override { return TotalFlux; }
  const char* Kind() const override { return "goniometric"; }
  Vec3 Opening() const override { return Web.Opening; }

private:
  const PhotometricWeb Web;
  const double TotalFlux;
};
} // namespace

std::shared_ptr<const LightDistribution> MakeGoniometricLight(const LightParameters& parameters, std::string& error)
{
  const std::string file = parameters.Text("file");
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
  if (!(web.Flux() > 0))
  {
    error = file + ": its candela table sends out no light";
    return nullptr;
  }
  // A lamp tilted from the position it was measured in gives what the file's TILT table
  // says for that angle (1 without one): `tilt`, degrees, 0 as measured.
  double tilt;
  if (!parameters.Number("tilt", 0, tilt, error))
  {
    return nullptr;
  }
  const double factor = web.TiltFactor(tilt);
  for (double& cd : web.Candela)
  {
    cd *= factor;
  }
  // At the file's lumens (its table as it stands) or the ones asked for, times the
  // maintenance factor: the shared rule of every kind.
  return WithLumens(std::make_shared<const Goniometric>(std::move(web)), parameters, error);
}

} // namespace radiosity
