// A light at a point, of any kind (LightKinds.h): placed, aimed, turned, colored, scaled.
#ifndef RadiosityCore_PointLight_h
#define RadiosityCore_PointLight_h

#include "Lights/LightKinds.h"

#include <memory>
#include <string>
#include <vector>

namespace radiosity
{

/// Radiant (or luminous) intensity toward a direction d of the world:
/// Intensity * Color * Distribution(d in the light's frame); an isotropic light where no
/// distribution is given, so a surface at distance r receives Intensity * Color * cos / r^2.
/// The frame: z along Aim; x (the C0 plane of a photometric file) the world's x axis
/// projected across the aim (the world's y where the aim is within 8 degrees of x), then
/// turned by Rotation degrees about the aim; y = z x x.
struct PointLight
{
  Vec3 Position;
  Vec3 Aim{ 0, 0, -1 };
  double Rotation = 0;
  Vec3 Color{ 1, 1, 1 };
  double Intensity = 1;
  std::shared_ptr<const LightDistribution> Distribution;

  /// The light's strength toward world direction `d` (any length), before Color.
  double Toward(const Vec3& d) const;
  /// The flux it sends out per color channel's unit: Intensity times the distribution's.
  double Flux() const;
  /// Unit axes of the light's frame in world coordinates.
  void Frame(Vec3& x, Vec3& y, Vec3& z) const;
  /// The largest side (or diameter) of the light's luminous opening; 0 for a point.
  double OpeningSize() const;
  /// `count` points spread evenly over the luminous opening (a 4 x 4 grid of cells over a
  /// rectangle, rings of equal area over a disk; `count` a square), in world coordinates:
  /// where a surface is within a few opening sizes, the light comes from all of them.
  std::vector<Vec3> OpeningPoints(int count) const;
};

/// Empty, or what makes `light` unusable (a non-finite or zero aim, position or strength,
/// a negative color), prefixed by `what` ("luminaire 'Desk'").
std::string PointLightProblem(const PointLight& light, const std::string& what);

} // namespace radiosity

#endif
