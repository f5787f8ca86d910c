// Two-level hierarchical shooting: progressive refinement whose per-shot cost follows the
// number of patches, not elements, because far and weakly lit receivers take a shot as
// whole patches (Hanrahan, Salzman & Aupperle 1991, links refined by an energy oracle).
#ifndef RadiosityCore_HierarchicalRadiosity_h
#define RadiosityCore_HierarchicalRadiosity_h

#include "Geometry/Scene.h"
#include "Geometry/Visibility.h"

#include <chrono>
#include <vector>

namespace radiosity
{

struct Solution;      // RadiositySolver.h, which holds this method's settings
struct SolverOptions; // in its options

/// What the hierarchical method alone reads (SolverOptions::Hierarchical).
struct HierarchicalSettings
{
  /// An emitter's first shot (its direct light) reaches every element with its own
  /// shadow rays, as in progressive refinement. Off: it links like any other shooter,
  /// which is much cheaper when many patches emit (the moving-light basis). Off also
  /// keeps Auto from the clustered method, which shoots every emitter first.
  bool DirectToElements = true;
  /// A far link that would carry at least this fraction of a solution's emitted power
  /// at its first shot is resolved element by element. 0 (the default) refines by
  /// geometry alone, so the links, and the light-tagged and combined results, do not
  /// depend on which light shoots; energy refinement gained little (docs/benchmarks.md).
  double RefinementThreshold = 0;
};

/// The SolveFunction for SolverMethod::Hierarchical.
/// - An emitter patch's first shot (direct light) reaches every element, with shadow rays
///   per element, exactly as in progressive refinement: shadows stay sharp.
/// - Every other shooter links once, at its first shot, to each receiver patch: to the
///   patch as a whole (form factors at its corners, visibility from rays between the
///   patches) when it is far (centres more than 2 x the sum of their radii apart) and wholly in
///   front (and, with `Hierarchical.RefinementThreshold`, carries less than that fraction of any
///   solution's emitted power); element by element otherwise. Later shots reuse the links:
///   no rays, no form factors.
/// - A face cluster (a patch of a curved surface, FaceClusters.h) receives node by node
///   through its cluster tree: a node whose elements all face the shooter from far enough
///   takes one factor vector (n_e . v per element); nearer, its children; at the leaves,
///   its elements. A cluster shooter is split the same way through its own tree.
/// - Patch-level energy reaches the elements at the end, interpolated from the corners
///   (mean value coordinates), times each element's reflectance.
/// Each link carries the k-vector of every solution: transport is computed once for all k.
void SolveHierarchical(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<Vec3>& emission, int solutions, bool grey, const SolverOptions& options,
  std::chrono::steady_clock::time_point start, Solution& out);

} // namespace radiosity

#endif
