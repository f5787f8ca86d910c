// Moving lights (paper 2.4): the direct part shot per frame; the patch basis
// (PatchBasis.h) carries its interreflection.
#ifndef RadiosityCore_MovingLights_h
#define RadiosityCore_MovingLights_h

#include "Geometry/Scene.h"
#include "Geometry/PreparedScene.h"
#include "Geometry/Visibility.h"
#include "Base/WorkerPool.h"
#include "Lights/PointLight.h"

#include <memory>
#include <vector>

namespace radiosity
{

/// A light that moves between frames: a point light of any kind (Lights/LightKinds.h),
/// isotropic where it has no distribution, a small Lambertian emitter facing its Aim with
/// the "lambertian" one, a luminaire with a "goniometric" one.
using MovingLight = PointLight;

/// The direct part, computed every frame: each element's radiosity rho * irradiance from
/// the moving lights, with Embree shadow rays against the static scene and, optionally,
/// dynamic objects (which cast direct shadows only, as in the paper).
class MovingLightShader
{
public:
  /// Shades `scene` on its prepared scene (PrepareTransport: the solver's, where the caller
  /// kept it, so the shader's patches are the basis's), shared, not copied.
  MovingLightShader(const SceneMesh& scene, const PreparedScene& prepared, const SceneMesh* dynamicObjects);
  const std::string& Error() const { return Error_; }
  const SceneGeometry& Geometry() const { return *Prepared.Geometry; }

  /// Replaces the dynamic objects (null: none): the static scene is instanced as it is and
  /// the objects go beside it, so a moving object costs its own triangles only.
  bool SetDynamicObjects(const SceneMesh* objects);

  /// direct[e] = rho_e * irradiance_e. Returns the number of shadow rays cast.
  long long Direct(const std::vector<MovingLight>& lights, const WorkerPool& pool,
    std::vector<Vec3>& direct) const;

private:
  /// The rays shadows are cast against: the static scene, with the objects where any.
  const Visibility& Rays() const { return WithObjects ? *WithObjects : *Prepared.Rays; }

  const SceneMesh& Scene;
  PreparedScene Prepared;
  std::unique_ptr<Visibility> WithObjects;
  std::string Error_;
};

} // namespace radiosity

#endif
