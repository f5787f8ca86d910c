// High-dynamic-range pictures of a solution: ray-cast view and OpenEXR output.
#ifndef RadiosityCore_HdrImage_h
#define RadiosityCore_HdrImage_h

#include "Visibility.h"

#include <string>
#include <vector>

namespace radiosity
{

struct PinholeCamera
{
  Vec3 Position{ 0, 0, 1 };
  Vec3 FocalPoint{ 0, 0, 0 };
  Vec3 ViewUp{ 0, 1, 0 };
  double ViewAngle = 30; ///< vertical, degrees (VTK's convention)
  int Width = 640;
  int Height = 480;
};

/// Linear RGB, row 0 at the top. Each pixel shows the radiosity interpolated from the
/// point values of the triangle hit at its centre, so no tone mapping or clamping happens.
/// Radiosity is exitance; for a diffuse surface the radiance seen is B / pi, and the image
/// stores B so values compare directly with the solver's arrays.
std::vector<float> RenderRadiosity(
  const Visibility& scene, const std::vector<Vec3>& pointValues, const PinholeCamera& camera);

/// Writes a half-float RGB OpenEXR file; returns an empty string or the library's error.
std::string WriteExr(const std::string& path, int width, int height, const std::vector<float>& rgb);

/// Reads an RGB OpenEXR file back (for tests and tools).
std::string ReadExr(const std::string& path, int& width, int& height, std::vector<float>& rgb);

} // namespace radiosity

#endif
