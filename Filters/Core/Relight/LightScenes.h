// Light scenes: named sets of settings for groups of lights (a meeting: the downlights at
// 100 %, the wall washers at 30 %), as lighting designers switch them (DIALux's light
// scenes, AGi32's scene manager). A group is a pattern over light names, so a scene names
// "Ovni*" once for every high-bay. The rig applies the active scene under the settings by
// name; the schedule switches and blends scenes over time ("scene:<name>" keyframes).
#ifndef RadiosityCore_LightScenes_h
#define RadiosityCore_LightScenes_h

#include "Relight/LightRig.h"

#include <string>
#include <vector>

namespace radiosity
{

/// A light-scenes file: one row a line, "scene, lights, dimming %, r, g, b, on" (r, g, b
/// may be left empty: the lights keep their colors; '#' starts a comment). Empty, or the
/// problem as "<name>:<line>: <what>".
std::string ParseLightScenes(const std::string& text, const std::string& name, std::vector<LightSceneRow>& rows);

/// The names of the scenes `rows` define, in their first row's order.
std::vector<std::string> LightSceneNames(const std::vector<LightSceneRow>& rows);

/// The setting scene `scene` gives light `name` over `base` (its own setting): the color
/// where a row gives one, the intensity times the row's dimming, on or off (later rows over
/// earlier ones); false where no row of the scene matches the light.
bool SceneSetting(const std::vector<LightSceneRow>& rows, const std::string& scene, const std::string& name,
  const LightSetting& base, LightSetting& out);

/// Empty, or why `scene` cannot be used: no row defines it.
std::string SceneProblem(const std::vector<LightSceneRow>& rows, const std::string& scene);

} // namespace radiosity

#endif
