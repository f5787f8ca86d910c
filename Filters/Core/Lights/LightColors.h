// A light's default colour: the one rule the solver's output, the relight paths and the
// writers share.
#ifndef RadiosityCore_LightColors_h
#define RadiosityCore_LightColors_h

#include "Base/Vec3.h"

#include <vector>

namespace radiosity
{

/// The lights' default colors: `given` (the solver's LightDefaultColors, 3 values per
/// light) when it holds one per light, else each light's mean Emission over its cells
/// (`lightId`, `emission` per cell; zero Emission stays zero, a light without cells or
/// without an Emission array is white).
std::vector<Vec3> LightDefaultColors(int lights, const std::vector<double>& given, const std::vector<int>& lightId,
  const std::vector<Vec3>& emission);

} // namespace radiosity

#endif
