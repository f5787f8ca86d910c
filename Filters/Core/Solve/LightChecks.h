// Mistakes in a scene's lights that still solve, but not as meant: a lamp wound the wrong
// way against a nearby surface, or one closed off inside another surface's plane.
#ifndef RadiosityCore_LightChecks_h
#define RadiosityCore_LightChecks_h

#include "Geometry/Scene.h"
#include "Geometry/Visibility.h"

#include <string>
#include <vector>

namespace radiosity
{

/// One message per suspicious light (`names[l]` names light l):
/// - every element closed off (SceneGeometry::Enclosed): it cannot emit at all;
/// - it lies on another surface, in the same plane (a lamp drawn in the ceiling);
/// - most of its probe rays land within 5 % of its own size: it faces a surface right in
///   front of it (a ceiling lamp wound the wrong way), so nearly all its light stays there;
/// - none of its probe rays meets anything: it faces out of the scene (a floor lamp wound
///   the wrong way in an open model), so its light leaves it.
std::vector<std::string> CheckLights(const SceneMesh& mesh, const SceneGeometry& geometry, const Visibility& rays,
  const std::vector<std::string>& names);

} // namespace radiosity

#endif
