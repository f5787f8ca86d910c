// The solver's arithmetic on one value: RGB, or one grey channel for a grey scene.
#ifndef RadiosityCore_Channels_h
#define RadiosityCore_Channels_h

#include "Base/Vec3.h"

#include <cstddef>

namespace radiosity
{

/// The solver's arithmetic for an RGB value (Vec3) or a single grey channel (double).
/// A grey scene solved as one channel gives the same numbers with a third of the work.
struct Rgb
{
  using Value = Vec3;
  static Value From(const Vec3& v) { return v; }
  static Vec3 To(const Value& v) { return v; }
  static double Sum(const Value& v) { return v.x + v.y + v.z; }
  static Value Reflect(const Vec3& rho, const Value& u, double f)
  {
    return { rho.x * u.x * f, rho.y * u.y * f, rho.z * u.z * f };
  }
  static constexpr size_t Doubles = 3; ///< what a value takes in a sum over the ranks
  static void Store(const Value& v, double* to)
  {
    to[0] = v.x;
    to[1] = v.y;
    to[2] = v.z;
  }
  static Value Load(const double* from) { return { from[0], from[1], from[2] }; }
};

struct Grey
{
  using Value = double;
  static Value From(const Vec3& v) { return (v.x + v.y + v.z) / 3.0; }
  static Vec3 To(Value v) { return { v, v, v }; }
  static double Sum(Value v) { return 3.0 * v; } // powers stay comparable with RGB runs
  static Value Reflect(const Vec3& rho, Value u, double f) { return (rho.x + rho.y + rho.z) / 3.0 * u * f; }
  static constexpr size_t Doubles = 1;
  static void Store(Value v, double* to) { to[0] = v; }
  static Value Load(const double* from) { return from[0]; }
};

/// Calls body(Grey()) for a single grey channel, body(Rgb()) otherwise: the solver methods
/// are templates on the channel type.
template <typename Body>
void WithChannel(bool grey, const Body& body)
{
  if (grey)
  {
    body(Grey());
  }
  else
  {
    body(Rgb());
  }
}

} // namespace radiosity

#endif
