// High-dynamic-range pictures of a solution: ray-cast view and OpenEXR output.
#ifndef RadiosityCore_HdrImage_h
#define RadiosityCore_HdrImage_h

#include "Geometry/Visibility.h"

#include <functional>
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

/// Largest image side accepted (pixels), and largest image (RGB floats, bytes).
constexpr int MaximumImageSide = 32768;
constexpr double MaximumImageBytes = 4.0 * 1024 * 1024 * 1024;

/// Empty when the camera can make a picture; otherwise which setting is wrong and why:
/// a size out of range, a non-finite vector, a position on its focal point, a view-up
/// along the view direction, an angle outside (0, 180) degrees.
std::string ValidateCamera(const PinholeCamera& camera);

/// Linear RGB, row 0 at the top. Each pixel shows the radiosity interpolated from the
/// point values of the triangle hit at its centre, so no tone mapping or clamping happens.
/// Radiosity is exitance; for a diffuse surface the radiance seen is B / pi, and the image
/// stores B so values compare directly with the solver's arrays. `progress` (optional)
/// hears the fraction done every few rows; when it returns false the render stops and
/// returns an empty image.
std::vector<float> RenderRadiosity(const Visibility& scene, const std::vector<Vec3>& pointValues,
  const PinholeCamera& camera, const std::function<bool(double)>& progress = {});

/// As RenderRadiosity for several point arrays at once (one ray per pixel for all):
/// one image per layer; all empty when stopped. Rows are cast on `threads` threads (0: all).
std::vector<std::vector<float>> RenderLayers(const Visibility& scene,
  const std::vector<const std::vector<Vec3>*>& layers, const PinholeCamera& camera,
  const std::function<bool(double)>& progress = {}, int threads = 0);

/// Writes a 32-bit float OpenEXR file with one RGB layer per image: channels
/// `<name>.R`, `.G`, `.B` (plain R, G, B for an empty name), as OpenEXR's tools and
/// compositors read layers. Written under a temporary name and renamed, as WriteExr.
std::string WriteExrLayers(const std::string& path, int width, int height, const std::vector<std::string>& names,
  const std::vector<std::vector<float>>& images);

/// Reads one layer (`name`, or the plain R, G, B for an empty name) of a layered file.
std::string ReadExrLayer(const std::string& path, const std::string& name, int& width, int& height,
  std::vector<float>& rgb);

/// Writes a half-float RGB OpenEXR file; returns an empty string or the library's error.
/// The file is written beside `path` under a temporary name and renamed over it, so an
/// interrupted write never leaves a truncated file where a good one was.
std::string WriteExr(const std::string& path, int width, int height, const std::vector<float>& rgb);

/// Reads an RGB OpenEXR file back (for tests and tools).
std::string ReadExr(const std::string& path, int& width, int& height, std::vector<float>& rgb);

} // namespace radiosity

#endif
