#include "Image/HdrImage.h"
#include "Base/WorkerPool.h"

#include "Base/AtomicFile.h"

#include <ImfArray.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <exception>
#include <sstream>

namespace radiosity
{

namespace
{

std::string LayerChannel(const std::string& layer, const char* channel)
{
  return layer.empty() ? channel : layer + "." + channel;
}

} // namespace

std::string ValidateCamera(const PinholeCamera& c)
{
  std::ostringstream why;
  auto finite = [](const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  const Vec3 forward = c.FocalPoint - c.Position;
  if (c.Width < 1 || c.Height < 1 || c.Width > MaximumImageSide || c.Height > MaximumImageSide)
  {
    why << "image size " << c.Width << " x " << c.Height << " is outside 1.." << MaximumImageSide << " per side";
  }
  else if (12.0 * c.Width * c.Height > MaximumImageBytes)
  {
    why << "image size " << c.Width << " x " << c.Height << " needs " << 12.0 * c.Width * c.Height / 1073741824.0
        << " GB, more than " << MaximumImageBytes / 1073741824.0;
  }
  else if (!finite(c.Position) || !finite(c.FocalPoint) || !finite(c.ViewUp) || !std::isfinite(c.ViewAngle))
  {
    why << "camera position, focal point, view-up and view angle must be finite";
  }
  else if (!(Norm(forward) > 0))
  {
    why << "camera position equals its focal point, so there is no view direction";
  }
  else if (!(Norm(Cross(Normalized(forward), c.ViewUp)) > 1e-9 * Norm(c.ViewUp)))
  {
    why << "view-up is zero or along the view direction";
  }
  else if (!(c.ViewAngle > 0 && c.ViewAngle < 180))
  {
    why << "view angle " << c.ViewAngle << " is outside (0, 180) degrees";
  }
  return why.str();
}

namespace
{
/// Writes the layers' values at a hit, interpolated over its triangle, into pixel `at`.
void Shade(const Visibility::Hit& hit, const std::vector<const std::vector<Vec3>*>& layers,
  std::vector<std::vector<float>>& images, size_t at)
{
  const double w0 = 1.0 - hit.U - hit.V;
  for (size_t l = 0; l < layers.size(); ++l)
  {
    const std::vector<Vec3>& values = *layers[l];
    const Vec3 value = values[hit.Corner[0]] * w0 + values[hit.Corner[1]] * hit.U + values[hit.Corner[2]] * hit.V;
    float* px = &images[l][at];
    px[0] = static_cast<float>(value.x);
    px[1] = static_cast<float>(value.y);
    px[2] = static_cast<float>(value.z);
  }
}
} // namespace

std::vector<std::vector<float>> RenderLayers(const Visibility& scene,
  const std::vector<const std::vector<Vec3>*>& layers, const PinholeCamera& camera,
  const std::function<bool(double)>& progress, int threads)
{
  const int w = camera.Width, h = camera.Height;
  std::vector<std::vector<float>> images(layers.size(), std::vector<float>(3 * static_cast<size_t>(w) * h, 0.0f));
  const Vec3 forward = Normalized(camera.FocalPoint - camera.Position);
  const Vec3 right = Normalized(Cross(forward, camera.ViewUp));
  const Vec3 up = Cross(right, forward);
  const double halfHeight = std::tan(0.5 * camera.ViewAngle * Pi / 180.0);
  const double halfWidth = halfHeight * w / h;
  // One packet of rays per run of pixels along a row; rows in parallel, a band of 16 rows
  // at a time so that progress and abort are heard from this thread.
  const int run = Visibility::PacketSize;
  const WorkerPool pool(threads);
  auto renderRow = [&](int y) {
    Vec3 directions[Visibility::PacketSize];
    Visibility::Hit hits[Visibility::PacketSize];
    bool found[Visibility::PacketSize];
    const double sy = (1.0 - 2.0 * (y + 0.5) / h) * halfHeight;
    for (int x0 = 0; x0 < w; x0 += run)
    {
      const int count = std::min(run, w - x0);
      for (int i = 0; i < count; ++i)
      {
        const double sx = (2.0 * (x0 + i + 0.5) / w - 1.0) * halfWidth;
        directions[i] = forward + right * sx + up * sy;
      }
      scene.IntersectPacket(camera.Position, directions, count, hits, found);
      for (int i = 0; i < count; ++i)
      {
        if (found[i] && hits[i].Polygon >= 0) // a miss, or a dynamic object: no values there
        {
          Shade(hits[i], layers, images, 3 * (static_cast<size_t>(y) * w + x0 + i));
        }
      }
    }
  };
  for (int band = 0; band < h; band += 16)
  {
    if (progress && !progress(static_cast<double>(band) / h))
    {
      return std::vector<std::vector<float>>(layers.size());
    }
    pool.For(std::min(16, h - band), 1, [&](int begin, int end) {
      for (int y = band + begin; y < band + end; ++y)
      {
        renderRow(y);
      }
    });
  }
  return images;
}

std::vector<float> RenderRadiosity(const Visibility& scene, const std::vector<Vec3>& pointValues,
  const PinholeCamera& camera, const std::function<bool(double)>& progress)
{
  return RenderLayers(scene, { &pointValues }, camera, progress)[0];
}

std::string WriteExr(const std::string& path, int width, int height, const std::vector<float>& rgb)
{
  if (width <= 0 || height <= 0 || rgb.size() != 3 * static_cast<size_t>(width) * height)
  {
    return "WriteExr: image size does not match its pixel data";
  }
  try
  {
    Imf::Array2D<Imf::Rgba> pixels(height, width);
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        const float* p = &rgb[3 * (static_cast<size_t>(y) * width + x)];
        pixels[y][x] = Imf::Rgba(p[0], p[1], p[2], 1.0f);
      }
    }
    const std::string error = WriteAtomically(path, [&](const char* temporary, bool& created) {
      Imf::RgbaOutputFile file(temporary, width, height, Imf::WRITE_RGB);
      created = true;
      file.setFrameBuffer(&pixels[0][0], 1, width);
      file.writePixels(height);
    });
    if (!error.empty())
    {
      return error;
    }
  }
  catch (const std::exception& e)
  {
    return std::string("OpenEXR could not write ") + path + ": " + e.what();
  }
  return std::string();
}

std::string ReadExr(const std::string& path, int& width, int& height, std::vector<float>& rgb)
{
  try
  {
    Imf::RgbaInputFile file(path.c_str());
    const Imath::Box2i window = file.dataWindow();
    width = window.max.x - window.min.x + 1;
    height = window.max.y - window.min.y + 1;
    Imf::Array2D<Imf::Rgba> pixels(height, width);
    file.setFrameBuffer(&pixels[0][0] - window.min.x - window.min.y * width, 1, width);
    file.readPixels(window.min.y, window.max.y);
    rgb.resize(3 * static_cast<size_t>(width) * height);
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        float* p = &rgb[3 * (static_cast<size_t>(y) * width + x)];
        p[0] = pixels[y][x].r;
        p[1] = pixels[y][x].g;
        p[2] = pixels[y][x].b;
      }
    }
  }
  catch (const std::exception& e)
  {
    return std::string("OpenEXR could not read ") + path + ": " + e.what();
  }
  return std::string();
}

std::string WriteExrLayers(const std::string& path, int width, int height, const std::vector<std::string>& names,
  const std::vector<std::vector<float>>& images)
{
  const size_t pixels = static_cast<size_t>(std::max(width, 0)) * std::max(height, 0);
  if (width <= 0 || height <= 0 || names.size() != images.size() || names.empty() ||
    std::any_of(images.begin(), images.end(), [&](const std::vector<float>& i) { return i.size() != 3 * pixels; }))
  {
    return "WriteExrLayers: image sizes do not match their pixel data";
  }
  try
  {
    Imf::Header header(width, height);
    Imf::FrameBuffer frames;
    const char* channels[3] = { "R", "G", "B" };
    for (size_t l = 0; l < names.size(); ++l)
    {
      for (int c = 0; c < 3; ++c)
      {
        const std::string name = LayerChannel(names[l], channels[c]);
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        frames.insert(name, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(images[l].data() + c)),
                              3 * sizeof(float), 3 * sizeof(float) * width));
      }
    }
    return WriteAtomically(path, [&](const char* temporary, bool& created) {
      Imf::OutputFile file(temporary, header);
      created = true;
      file.setFrameBuffer(frames);
      file.writePixels(height);
    });
  }
  catch (const std::exception& e)
  {
    return std::string("OpenEXR could not write ") + path + ": " + e.what();
  }
}

std::string ReadExrLayer(const std::string& path, const std::string& name, int& width, int& height,
  std::vector<float>& rgb)
{
  try
  {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    width = window.max.x - window.min.x + 1;
    height = window.max.y - window.min.y + 1;
    rgb.assign(3 * static_cast<size_t>(width) * height, 0.0f);
    Imf::FrameBuffer frames;
    const char* channels[3] = { "R", "G", "B" };
    for (int c = 0; c < 3; ++c)
    {
      const std::string channel = LayerChannel(name, channels[c]);
      if (!file.header().channels().findChannel(channel))
      {
        return path + " has no channel " + channel;
      }
      char* origin = reinterpret_cast<char*>(rgb.data() + c) -
        (static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * width) * 3 * sizeof(float);
      frames.insert(channel, Imf::Slice(Imf::FLOAT, origin, 3 * sizeof(float), 3 * sizeof(float) * width));
    }
    file.setFrameBuffer(frames);
    file.readPixels(window.min.y, window.max.y);
  }
  catch (const std::exception& e)
  {
    return std::string("OpenEXR could not read ") + path + ": " + e.what();
  }
  return std::string();
}

} // namespace radiosity
