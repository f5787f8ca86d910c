// Light-tagged progressive refinement radiosity with substructuring
// (Nielsen & Christensen, "Real-time dynamic radiosity relighting", Fig. 2).
#ifndef RadiosityCore_ProgressiveRadiosity_h
#define RadiosityCore_ProgressiveRadiosity_h

#include "Scene.h"
#include "Visibility.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace radiosity
{

struct SolverOptions
{
  int MaximumShots = 2000;
  /// Stop when remaining unshot power / initial power falls below this.
  double ConvergenceThreshold = 1e-3;
  /// Shadow rays from each receiver to stratified points of the shooting patch; 0 treats
  /// every pair as unoccluded.
  int ShadowRays = 16;
  int Threads = 0; ///< 0: all hardware threads
  /// Called between shots with the fraction done; returning false aborts the solve, which
  /// then keeps the valid partial result of the shots made so far.
  std::function<bool(double)> Progress;
};

struct SolverStatistics
{
  int Shots = 0;
  bool Converged = false;
  bool Aborted = false;
  /// Remaining unshot power relative to the initial power, after each shot.
  std::vector<double> RemainingHistory;
  long long ShadowRayCount = 0;
  long long FormFactorCount = 0; ///< receiver-shooter pairs evaluated
  /// Channel-summed power shot by patches and power arriving at receivers (irradiance
  /// times area, before reflection); equal up to discretization in a closed scene.
  double ShotPower = 0;
  double ReceivedPower = 0;
};

/// Holds the per-solve geometry and the Embree scene, so several solves (k separate
/// solutions, or a re-solve with other emissions) reuse them.
class ProgressiveRadiosity
{
public:
  explicit ProgressiveRadiosity(const SceneMesh& mesh);
  ~ProgressiveRadiosity();

  /// Empty when the scene could be prepared.
  const std::string& Error() const;
  const SceneGeometry& Geometry() const { return Geometry_; }

  /// Solves `solutions` independent systems at once. `emission[e * solutions + m]` is the
  /// exitance of element e in solution m. Form factors are computed once per shot and the
  /// shot energy of every solution is distributed with them: this is the light tagging.
  /// The shooter is the patch with the largest unshot power summed over solutions.
  /// On return `radiosity` has the same layout as `emission`.
  SolverStatistics Solve(const std::vector<Vec3>& emission, int solutions,
    const SolverOptions& options, std::vector<Vec3>& radiosity) const;

private:
  /// F(element -> patch) for every element, including shadow-ray visibility.
  void ShootFormFactors(int patch, const SolverOptions& options, std::vector<double>& factors,
    long long& rays) const;

  const SceneMesh& Mesh;
  SceneGeometry Geometry_;
  std::unique_ptr<Visibility> Rays;
  std::vector<Vec3> Loops; ///< element polygons' points, laid out like Mesh.connectivity
  struct SampleTriangle
  {
    Vec3 A, B, C;
    double Cdf; ///< cumulative area fraction within its patch, ending at 1
  };
  std::vector<std::vector<SampleTriangle>> PatchTriangles;
  std::string Error_;
};

} // namespace radiosity

#endif
