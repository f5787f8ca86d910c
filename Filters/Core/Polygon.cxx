#include "Polygon.h"

namespace radiosity
{

Vec3 NewellVector(const Vec3* loop, int count)
{
  Vec3 n;
  for (int i = 0; i < count; ++i)
  {
    const Vec3& a = loop[i];
    const Vec3& b = loop[(i + 1) % count];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

Vec3 PolygonCentroid(const Vec3* loop, int count)
{
  // Area-weighted centroid of the fan triangles, so uneven vertex spacing does not bias it.
  Vec3 weighted;
  double total = 0;
  for (int i = 1; i + 1 < count; ++i)
  {
    const double a = 0.5 * Norm(Cross(loop[i] - loop[0], loop[i + 1] - loop[0]));
    weighted += (loop[0] + loop[i] + loop[i + 1]) * (a / 3.0);
    total += a;
  }
  if (total > 0)
  {
    return weighted * (1.0 / total);
  }
  Vec3 mean;
  for (int i = 0; i < count; ++i)
  {
    mean += loop[i];
  }
  return count > 0 ? mean * (1.0 / count) : mean;
}

void ClipToHalfSpace(const Vec3* loop, int count, const Vec3& origin, const Vec3& normal,
  std::vector<Vec3>& clipped)
{
  clipped.clear();
  for (int i = 0; i < count; ++i)
  {
    const Vec3& a = loop[i];
    const Vec3& b = loop[(i + 1) % count];
    const double da = Dot(normal, a - origin);
    const double db = Dot(normal, b - origin);
    if (da >= 0)
    {
      clipped.push_back(a);
    }
    if ((da >= 0) != (db >= 0))
    {
      const double t = da / (da - db);
      clipped.push_back(a + (b - a) * t);
    }
  }
}

} // namespace radiosity
