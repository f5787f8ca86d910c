// Point lights (luminaires, spots, bulbs: Lights/LightKinds.h) as light-tagged solutions
// of the solver: each takes a solution of its own, its first shot is its direct light on
// every element with shadow rays, and from there the transport carries it as it carries
// the emitters' light: the reflected direct light enters the solve as the receivers'
// unshot radiosity, so every method (and the final gather) treats it alike.
#ifndef RadiosityCore_PointLightShots_h
#define RadiosityCore_PointLightShots_h

#include "Geometry/Scene.h"
#include "Geometry/Visibility.h"
#include "Lights/PointLight.h"
#include "Solve/RadiositySolver.h"

#include <vector>

namespace radiosity
{

/// The irradiance each light gives each element, [e * lights + k], white (the solution is
/// the light's at unit color; relighting applies its color) and with its Intensity.
std::vector<Vec3> PointLightIrradiance(const SceneMesh& mesh, const SceneGeometry& g, const Visibility& rays,
  const std::vector<PointLight>& lights, int threads);

/// `emission` ([e * solutions + m]) with light k's reflected direct light added to solution
/// first + k: what the element sends on after the light's first shot.
void AddReflectedDirect(const SceneMesh& mesh, const std::vector<Vec3>& irradiance, int lights,
  std::vector<Vec3>& emission, int solutions, int first);

/// Sets what the solve made of the lights right: their direct part (SeparateDirect) is the
/// reflected direct light alone, and the ledger counts their whole flux as emitted and
/// what reached no element as escaped (the solve saw only the reflected part). `first`
/// -1: StandardCombined, every light at its color in the one solution.
void SettlePointLights(const SceneMesh& mesh, const SceneGeometry& g, const std::vector<PointLight>& lights,
  const std::vector<Vec3>& irradiance, int first, Solution& out);

} // namespace radiosity

#endif
