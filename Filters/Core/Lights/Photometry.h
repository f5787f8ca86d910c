// A luminaire's candela distribution as photometric files give it (IES LM-63, EULUMDAT),
// in one form for every file type: a table over two angles with the symmetry its angle
// ranges imply, evaluated toward any direction of the luminaire's own frame.
#ifndef RadiosityCore_Photometry_h
#define RadiosityCore_Photometry_h

#include "Base/Vec3.h"

#include <string>
#include <vector>

namespace radiosity
{

/// The goniometer's coordinate systems (LM-63's photometric types, CIE 121's planes).
/// In the luminaire's frame z is the aim (type C's nadir, where gamma = 0), x the C0 plane
/// (the luminaire's length) and y = z x x, so C90 lies a quarter turn clockwise from C0
/// seen from behind the luminaire (from above a downlight), as Radiance's ies2rad reads
/// LM-63. Type B turns about y (floodlights: the plane angle is LM-63's vertical angle, the
/// angle toward y its horizontal one); type A turns about x (the horizontal angle about x,
/// the vertical one toward x).
enum class PhotometricType
{
  C = 1,
  B = 2,
  A = 3
};

/// Candela over directions. The table is indexed by a turning angle ("azimuth": type C's
/// C angle, type B's plane angle, type A's horizontal angle) and an angle within each
/// plane ("polar": type C's gamma from the aim, a latitude in -90..90 for types A and B),
/// each ascending, in degrees. Angles outside the table's ranges are mapped back by the
/// symmetry those ranges imply (LM-63-2002 4.3.1: a single C angle, 0-90, 0-180, 90-270 or
/// a full turn; a 0-90 latitude or plane range mirrored); a direction still outside them
/// gets no light.
struct PhotometricWeb
{
  PhotometricType Type = PhotometricType::C;
  std::vector<double> Azimuth;
  std::vector<double> Polar;
  std::vector<double> Candela; ///< [azimuth * Polar.size() + polar], multipliers applied
  /// What the file says the lamps put out (lumens per lamp times lamps; EULUMDAT: the
  /// lamp sets' flux), 0 where it does not say (LM-63's absolute photometry, -1).
  double LampLumens = 0;
  /// The luminaire's own output where the file gives it (EULUMDAT: lamp flux times the
  /// light output ratio), 0 otherwise.
  double LuminaireLumens = 0;
  /// The luminous opening in metres: width (along y), length (along x), height; a
  /// negative width or length means round (LM-63-2002's convention).
  Vec3 Opening;
  /// TILT=INCLUDE: the lamp's output factor against the angle the lamp is tilted from its
  /// measured position (degrees ascending), and the lamp-to-luminaire geometry (1-3).
  std::vector<double> TiltAngles, TiltFactors;
  int TiltGeometry = 0;
  std::string Source; ///< the file it came from, for messages

  /// Candela toward `direction` (any length) in the luminaire's frame, bilinear in the
  /// table's angles.
  double Intensity(const Vec3& direction) const;
  /// The luminous flux of the distribution, exact for the bilinear interpolation above.
  double Flux() const;
  /// The tilt factor at `degrees` (1 without TILT data; the ends held beyond the table).
  double TiltFactor(double degrees) const;
  /// The largest candela in the table.
  double Peak() const;
};

/// Empty, or why `web` cannot be used (sizes that disagree, angles not ascending or out
/// of their type's range, a range no symmetry covers, negative or non-finite candela).
std::string PhotometricProblem(const PhotometricWeb& web);

/// The table's polar and azimuth angles of a direction in the luminaire's frame, for
/// tests and for anyone drawing the web.
void PhotometricAngles(PhotometricType type, const Vec3& direction, double& azimuth, double& polar);

} // namespace radiosity

#endif
