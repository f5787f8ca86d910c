// Small 3-vector used throughout the VTK-free core.
#ifndef RadiosityCore_Vec3_h
#define RadiosityCore_Vec3_h

#include <cmath>

namespace radiosity
{

constexpr double Pi = 3.14159265358979323846;

struct Vec3
{
  double x = 0, y = 0, z = 0;

  Vec3() = default;
  constexpr Vec3(double a, double b, double c)
    : x(a)
    , y(b)
    , z(c)
  {
  }
  double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return { a.x + b.x, a.y + b.y, a.z + b.z }; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return { a.x - b.x, a.y - b.y, a.z - b.z }; }
inline Vec3 operator*(const Vec3& a, double s) { return { a.x * s, a.y * s, a.z * s }; }
inline Vec3 operator*(double s, const Vec3& a) { return a * s; }
inline Vec3& operator+=(Vec3& a, const Vec3& b)
{
  a.x += b.x;
  a.y += b.y;
  a.z += b.z;
  return a;
}
/// Channel by channel: a color times a filter (a reflectance, a texture's mean).
inline Vec3 Times(const Vec3& a, const Vec3& b) { return { a.x * b.x, a.y * b.y, a.z * b.z }; }
inline double Dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}
inline double Norm(const Vec3& a) { return std::sqrt(Dot(a, a)); }
inline Vec3 Normalized(const Vec3& a)
{
  const double n = Norm(a);
  return n > 0 ? a * (1.0 / n) : Vec3{ 0, 0, 0 };
}

/// Unit tangents t, b with (t, b, n) right-handed, for a unit normal n; built from a world
/// axis, so use it where directions only need to cover the hemisphere evenly.
inline void TangentFrame(const Vec3& n, Vec3& t, Vec3& b)
{
  const Vec3 helper = std::fabs(n.x) < 0.6 ? Vec3{ 1, 0, 0 } : Vec3{ 0, 1, 0 };
  t = Normalized(Cross(helper, n));
  b = Cross(n, t);
}

} // namespace radiosity

#endif
