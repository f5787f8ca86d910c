// Progressive refinement with substructuring: every shot evaluates a form factor, with
// shadow rays, to every element (the paper's method).
#ifndef RadiosityCore_ProgressiveRadiosity_h
#define RadiosityCore_ProgressiveRadiosity_h

#include "Solve/RadiositySolver.h"

namespace radiosity
{

/// The SolveFunction for SolverMethod::ProgressiveRefinement.
void SolveProgressive(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, int solutions, bool grey, const SolverOptions& options,
  std::chrono::steady_clock::time_point start, Solution& out);

} // namespace radiosity

#endif
