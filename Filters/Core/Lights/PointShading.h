// Direct light from a point light of any kind onto the mesh's elements and at single
// points, with shadow rays: the first shot of the solver's luminaires, the moving lights'
// per-frame direct part and the final gather's direct term share it.
#ifndef RadiosityCore_PointShading_h
#define RadiosityCore_PointShading_h

#include "Geometry/Scene.h"
#include "Geometry/Visibility.h"
#include "Lights/PointLight.h"

#include <vector>

namespace radiosity
{

/// Adds the irradiance `light` gives elements [begin, end) (times its Color) to
/// irradiance[e - begin]; returns the shadow rays cast. Where the light is within twice an
/// element's size, cos / r^2 is averaged over the element's fan triangles (one centroid
/// misjudges it there), the light's own distribution taken toward the centroid.
long long AddPointIrradiance(const PointLight& light, const SceneMesh& mesh, const SceneGeometry& g,
  const Visibility& rays, int begin, int end, std::vector<Vec3>& irradiance);

/// The irradiance `light` gives a point on a surface facing `normal` (times its Color),
/// with one shadow ray from the point lifted by `lift` along the normal.
Vec3 PointIrradianceAt(const PointLight& light, const Vec3& point, const Vec3& normal, const Visibility& rays, double lift);

} // namespace radiosity

#endif
