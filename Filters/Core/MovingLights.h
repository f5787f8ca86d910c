// Moving lights through a patch basis (paper 2.4): direct light per frame, interreflection
// from precomputed per-patch solutions.
#ifndef RadiosityCore_MovingLights_h
#define RadiosityCore_MovingLights_h

#include "RadiositySolver.h"
#include "Scene.h"
#include "Visibility.h"
#include "WorkerPool.h"

#include <memory>
#include <vector>

namespace radiosity
{

/// A light that moves between frames. Isotropic when Normal is zero: radiant intensity
/// Intensity * Color in every direction, so a surface at distance r receives irradiance
/// Intensity * Color * cos(theta) / r^2. With a Normal it is a small Lambertian emitter:
/// intensity Intensity * Color * cos(angle to Normal), nothing behind it.
struct MovingLight
{
  Vec3 Position;
  Vec3 Color{ 1, 1, 1 };
  double Intensity = 1;
  Vec3 Normal;
};

/// The direct part, computed every frame: each element's radiosity rho * irradiance from
/// the moving lights, with Embree shadow rays against the static scene and, optionally,
/// dynamic objects (which cast direct shadows only, as in the paper).
class MovingLightShader
{
public:
  MovingLightShader(const SceneMesh& scene, const SceneMesh* dynamicObjects);
  const std::string& Error() const { return Rays->Error(); }
  const SceneGeometry& Geometry() const { return Geometry_; }

  /// direct[e] = rho_e * irradiance_e. Returns the number of shadow rays cast.
  long long Direct(const std::vector<MovingLight>& lights, const WorkerPool& pool,
    std::vector<Vec3>& direct) const;

private:
  const SceneMesh& Scene;
  SceneGeometry Geometry_;
  std::unique_ptr<Visibility> Rays;
};

/// The basis convention: basis[e * 3P + 3q + c] is element e's radiosity in channel c when
/// patch q emits unit exitance, WITHOUT q's own emission (only light reflected by the
/// scene, including by q's elements). So the frame's result is
///   B_e = D_e + sum_q E_q * basis_q(e),  E_q = area mean of D over patch q,
/// where D (the direct part) already contains each patch's first reflection.
void AddBasisInterreflection(const SceneGeometry& geometry, const std::vector<Vec3>& direct,
  const float* basis, int patches, const WorkerPool& pool, std::vector<Vec3>& result);

/// Solves the basis: every patch a unit emitter (all P solutions in one light-tagged
/// pass), its own emission then removed. Returns n * 3P floats in the layout above.
std::vector<float> SolvePatchBasis(
  const RadiositySolver& solver, const SceneMesh& mesh, const SolverOptions& options, SolverStatistics& stats);

} // namespace radiosity

#endif
