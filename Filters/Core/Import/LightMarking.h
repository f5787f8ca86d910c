// Making lights in a scene after it is read: cells chosen by material name, and area
// lights (rectangles, disks) added where the file has none.
#ifndef RadiosityCore_LightMarking_h
#define RadiosityCore_LightMarking_h

#include "Base/Text.h" // MatchesPattern, which used to live here
#include "Base/Vec3.h"

#include <string>
#include <vector>

namespace radiosity
{


enum class AreaShape
{
  Rectangle = 0,
  Disk = 1
};

struct AreaLight
{
  std::string Name;
  AreaShape Shape = AreaShape::Rectangle;
  Vec3 Centre;
  Vec3 Normal{ 0, 0, -1 }; ///< the side it emits to
  double Width = 1;        ///< a disk's diameter
  double Height = 1;       ///< a rectangle's other side
  Vec3 Color{ 1, 1, 1 };  ///< its Emission
};

/// The corners of an area light, wound so that its front (right-hand rule) faces Normal:
/// a Width x Height rectangle, or a disk of diameter Width as a 32-gon of the same area.
/// Returns an empty string or what is wrong (zero normal, sizes not positive, non-finite).
std::string AreaLightLoop(const AreaLight& light, std::vector<Vec3>& loop);

/// Renumbers light ids to 0..k-1 in their order, dropping lights left with no cells and
/// their names, so that LightId has no gaps after cells moved to another light.
void CompactLights(std::vector<int>& lightId, std::vector<std::string>& names);

} // namespace radiosity

#endif
