// One solution per light (or one combined), the three ways the paper compares.
#ifndef RadiosityCore_LightSolutions_h
#define RadiosityCore_LightSolutions_h

#include "ProgressiveRadiosity.h"

namespace radiosity
{

enum class SolutionMode
{
  LightTagged = 0,      ///< k unit-emission solutions in one pass (the paper's method)
  StandardCombined = 1, ///< one ordinary solution with every light at its Emission colour
  StandardSeparate = 2  ///< k unit-emission solutions, solved one after the other
};

struct LightSolutions
{
  int Solutions = 0;             ///< k, or 1 for StandardCombined
  std::vector<Vec3> Radiosity;   ///< [element * Solutions + m]
  SolverStatistics Statistics;   ///< summed over the solves of StandardSeparate
};

/// `lights` is k from ValidateScene; `emissionColor` (per element) is used only by
/// StandardCombined. Unit emission means exitance 1 in every channel on a light's cells.
LightSolutions SolveLights(const ProgressiveRadiosity& solver, const SceneMesh& mesh, int lights,
  const std::vector<Vec3>& emissionColor, SolutionMode mode, const SolverOptions& options);

/// Vertex values as the area-weighted mean of the cells around each vertex. Vertices are
/// shared only within a flat surface of one material, so nothing bleeds across corners.
std::vector<Vec3> AverageToPoints(
  const SceneMesh& mesh, const SceneGeometry& geometry, const std::vector<Vec3>& cells, int columns);

} // namespace radiosity

#endif
