// One solution per light or bank (or one combined), the three ways the paper compares.
#ifndef RadiosityCore_LightSolutions_h
#define RadiosityCore_LightSolutions_h

#include "Lights/PointLight.h"
#include "Solve/RadiositySolver.h"

namespace radiosity
{

enum class SolutionMode
{
  LightTagged = 0,      ///< one solution per light or bank, all in one pass (the paper)
  StandardCombined = 1, ///< one ordinary solution with every light at its Emission color
  StandardSeparate = 2  ///< the same solutions as LightTagged, solved one after the other
};

/// Which lights share a solution. A light alone in its solution emits unit exitance (its
/// color is applied when relighting); lights in a shared bank emit their Emission color
/// (white without one), so relighting scales the bank as one (paper 2.1, Dorsey 1995).
struct LightGrouping
{
  std::vector<int> SolutionOfLight; ///< k entries, 0..solutions-1
  int Solutions = 0;

  static LightGrouping OnePerLight(int lights);
  /// Returns an empty string or why `banks` (k bank ids) is not usable.
  static std::string FromBanks(const std::vector<int>& banks, int lights, LightGrouping& out);
};

/// Throws std::invalid_argument naming the problem where `grouping` does not cover every
/// light of `mesh` or names a solution it does not have (SolutionEmission, DefaultColors
/// and SolveLights check it first).
void CheckGrouping(const SceneMesh& mesh, const LightGrouping& grouping);

/// Per-element emission of each solution for the tagged/separate modes.
std::vector<Vec3> SolutionEmission(const SceneMesh& mesh, const LightGrouping& grouping,
  const std::vector<Vec3>& emissionColor);

/// The relight color that reproduces the scene's own Emission: a lone light's mean
/// Emission (white if it has none), white for a bank (its color is inside the solution).
std::vector<Vec3> DefaultColors(const SceneMesh& mesh, const LightGrouping& grouping,
  const std::vector<Vec3>& emissionColor);

/// `emissionColor` (per element, may be empty) is used by StandardCombined and by banks.
/// The solution carries the solver's account of its effects (DescribeEffects); the
/// moving-light basis row says "skipped" until SolvePatchBasis records a basis in it.
/// `pointLights` (luminaires and other lights at points, Solve/PointLightShots.h) take a
/// solution each after the grouping's, white at their Intensity (StandardCombined: all in
/// the one solution at their Color).
Solution SolveLights(const RadiositySolver& solver, const SceneMesh& mesh,
  const LightGrouping& grouping, const std::vector<Vec3>& emissionColor, SolutionMode mode,
  const SolverOptions& options, const std::vector<PointLight>& pointLights = {});

/// Bytes a solve of `solutions` solutions holds at its peak, with the filter's outputs:
/// per element and solution its emission, the solver's radiosity, the solution and the
/// float output; per point and solution the averaged value and its float output; twice
/// for the irradiance (the Illuminance arrays), three times with the direct part kept.
double SolveMemory(long long elements, long long points, int solutions, bool separateDirect);

} // namespace radiosity

#endif
