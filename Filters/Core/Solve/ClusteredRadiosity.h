// Hierarchical radiosity with clustering, in gathering order (Smits, Arvo & Greenberg
// 1994; Sillion 1995): links between groups of elements of any size, found once for the
// scene, carry every light's solution at once.
#ifndef RadiosityCore_ClusteredRadiosity_h
#define RadiosityCore_ClusteredRadiosity_h

#include "Geometry/Scene.h"
#include "Geometry/Visibility.h"

#include <chrono>
#include <vector>

namespace radiosity
{

struct Solution;      // RadiositySolver.h, which holds this method's settings
struct SolverOptions; // in its options

/// What the clustered method alone reads (SolverOptions::Clustered).
struct ClusteredSettings
{
  /// Two groups of elements exchange light as a whole when their centres are farther
  /// apart than this many times the sum of their radii (1.5 times it where one side
  /// does not all face the other). Larger is more accurate and slower (what each costs
  /// and buys on the FZK-Haus: docs/benchmarks.md; the accuracy levels set it, and this
  /// default is the default level's, as the solver filter's is).
  double Separation = 3.0;
  /// Bytes the links, and then the links and per-node sums, may take (0: 90 % of the
  /// memory the system has free when they are made). A solve that would need more stops
  /// with the direct light, the reason in SolverStatistics::OutOfMemory.
  double MemoryLimit = 0;
};

/// The SolveFunction for SolverMethod::Clustered.
/// - Direct light: each emitter patch shoots once to every element, with shadow rays per
///   element, as in progressive refinement: shadows stay sharp.
/// - The interreflection: an element tree (ElementTree.h) whose node pairs are linked
///   (ClusterLinks.h) where they are far apart for their size and face each other wholly;
///   nearer pairs split, down to element pairs, which take Lambert's formula. The links do
///   not depend on the lights, so their cost follows the scene's surfaces, not its polygons
///   times its shooters.
/// - The interreflection is one linear system, solved by conjugate gradients
///   (ConjugateBounces.h): each step gathers along every link (sums of radiosity x area x
///   normal pulled up the tree, irradiance vectors pushed down) until what one more bounce
///   would add is below the threshold of each solution's emitted power: about half the
///   gathers of bouncing (the FZK-Haus: 7 instead of 13). Each element's gathering is
///   scaled so that it views exactly a whole closed scene where it sees one.
void SolveClustered(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, int solutions, bool grey, const SolverOptions& options,
  std::chrono::steady_clock::time_point start, Solution& out);

} // namespace radiosity

#endif
