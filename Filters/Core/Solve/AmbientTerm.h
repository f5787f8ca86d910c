// Cohen et al. 1988's ambient term, shared by every solver method: the power still to
// travel, spread evenly over the scene and interreflected in closed form.
#ifndef RadiosityCore_AmbientTerm_h
#define RadiosityCore_AmbientTerm_h

#include "Geometry/Scene.h"

#include <algorithm>

namespace radiosity
{

class AmbientTerm
{
public:
  /// The scene's area and its area-weighted mean reflectance, over `elements` elements.
  AmbientTerm(const SceneMesh& mesh, const SceneGeometry& g, int elements)
  {
    Vec3 meanRho;
    for (int e = 0; e < elements; ++e)
    {
      meanRho += mesh.Reflectance[e] * g.Area[e];
      Area += g.Area[e];
    }
    meanRho = meanRho * (1.0 / Area);
    for (int c = 0; c < 3; ++c)
    {
      // Capped: a closed scene of perfect reflectors has no finite ambient.
      Interreflection[c] = 1.0 / std::max(1.0 - meanRho[c], 1e-6);
    }
  }

  /// The ambient radiosity for `power` (per channel) still to travel.
  Vec3 Of(const Vec3& power) const
  {
    const Vec3 a = power * (1.0 / Area);
    return { Interreflection.x * a.x, Interreflection.y * a.y, Interreflection.z * a.z };
  }

private:
  double Area = 0;
  Vec3 Interreflection;
};

} // namespace radiosity

#endif
