#include "Lights/Photometry.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace radiosity
{

namespace
{
constexpr double kDegree = Pi / 180;
constexpr double kAngleSlack = 1e-6; // degrees: files print 89.999 for 90 rarely, 90.0 mostly

bool Near(double a, double b) { return std::fabs(a - b) <= kAngleSlack; }

/// How the turning angles of a table cover the rest of the turn.
enum class Turn
{
  Single,      ///< one angle: the same in every plane
  Quadrant,    ///< type C 0-90: mirrored about the C0-C180 and C90-C270 planes
  HalfC0,      ///< type C 0-180: mirrored about the C0-C180 plane
  HalfC90,     ///< type C 90-270: mirrored about the C90-C270 plane
  Full,        ///< type C: the whole turn, the last angle joined to the first
  Mirrored,    ///< types A, B: 0-x, mirrored to -x-0
  AsGiven,     ///< types A, B: as given, nothing outside
  Unsupported
};

Turn TurnOf(const PhotometricWeb& web)
{
  const std::vector<double>& a = web.Azimuth;
  if (a.size() == 1)
  {
    return Turn::Single;
  }
  const double first = a.front(), last = a.back();
  if (web.Type != PhotometricType::C)
  {
    return Near(first, 0) ? Turn::Mirrored : Turn::AsGiven;
  }
  if (Near(first, 0) && Near(last, 90))
  {
    return Turn::Quadrant;
  }
  if (Near(first, 0) && Near(last, 180))
  {
    return Turn::HalfC0;
  }
  if (Near(first, 90) && Near(last, 270))
  {
    return Turn::HalfC90;
  }
  if (last - first > 180 && last - first <= 360 + kAngleSlack)
  {
    return Turn::Full;
  }
  return Turn::Unsupported;
}

/// A type C angle folded into the table's range (Full: into [first, first + 360)).
double FoldTurn(Turn turn, double c, double first)
{
  if (turn == Turn::Mirrored)
  {
    return std::fabs(c);
  }
  if (turn == Turn::AsGiven)
  {
    return c;
  }
  c = std::fmod(c, 360.0);
  c = c < 0 ? c + 360 : c;
  switch (turn)
  {
    case Turn::Quadrant:
      c = c > 180 ? 360 - c : c;
      return c > 90 ? 180 - c : c;
    case Turn::HalfC0:
      return c > 180 ? 360 - c : c;
    case Turn::HalfC90:
      return c < 90 ? 180 - c : (c > 270 ? 540 - c : c);
    case Turn::Full:
      return c < first - kAngleSlack ? c + 360 : c;
    default:
      return c;
  }
}

/// Where `x` falls in ascending `table`: the index i and weight t of table[i + 1]; false
/// outside it. A one-entry table holds everywhere.
bool Locate(const std::vector<double>& table, double x, size_t& i, double& t)
{
  if (table.size() == 1)
  {
    i = 0;
    t = 0;
    return true;
  }
  if (x < table.front() - kAngleSlack || x > table.back() + kAngleSlack)
  {
    return false;
  }
  const auto upper = std::upper_bound(table.begin(), table.end(), x);
  i = std::min<size_t>(std::max<ptrdiff_t>(upper - table.begin(), 1) - 1, table.size() - 2);
  t = std::min(1.0, std::max(0.0, (x - table[i]) / (table[i + 1] - table[i])));
  return true;
}

/// Candela at table angles (degrees), folded and interpolated.
double TableValue(const PhotometricWeb& web, Turn turn, double azimuth, double polar)
{
  if (web.Type != PhotometricType::C && Near(web.Polar.front(), 0))
  {
    polar = std::fabs(polar); // a latitude table of 0-x is mirrored, as its planes are
  }
  size_t p, a;
  double tp, ta;
  if (!Locate(web.Polar, polar, p, tp))
  {
    return 0;
  }
  const size_t np = web.Polar.size();
  auto column = [&](size_t k) {
    const double* c = web.Candela.data() + k * np;
    return tp > 0 ? c[p] * (1 - tp) + c[p + 1] * tp : c[p];
  };
  const double folded = FoldTurn(turn, azimuth, web.Azimuth.front());
  if (turn == Turn::Full && folded > web.Azimuth.back())
  {
    // Between the last angle and a full turn past the first: joined to the first.
    const double span = web.Azimuth.front() + 360 - web.Azimuth.back();
    const double t = span > 0 ? (folded - web.Azimuth.back()) / span : 0;
    return column(web.Azimuth.size() - 1) * (1 - t) + column(0) * t;
  }
  if (!Locate(web.Azimuth, folded, a, ta))
  {
    return 0;
  }
  return ta > 0 ? column(a) * (1 - ta) + column(a + 1) * ta : column(a);
}

/// The angles of an integration axis at which the interpolated table may bend or jump
/// (its own angles, their mirror images, the domain's ends), ascending, in [lo, hi].
std::vector<double> Knots(const std::vector<double>& angles, double lo, double hi)
{
  std::vector<double> knots{ lo, hi };
  for (double x : angles)
  {
    for (double image : { x, -x, 180 - x, 180 + x, 360 - x, x - 360, x - 180, x + 360 })
    {
      if (image > lo && image < hi)
      {
        knots.push_back(image);
      }
    }
  }
  std::sort(knots.begin(), knots.end());
  knots.erase(std::unique(knots.begin(), knots.end(), [](double a, double b) { return Near(a, b); }), knots.end());
  return knots;
}

/// The integral of a function linear on [a, b], from its values a third and two thirds
/// in: exact, and blind to a jump at either end (the table's edge).
template <typename F>
double LinearPiece(double a, double b, F f)
{
  return 0.5 * (b - a) * (f(a + (b - a) / 3) + f(b - (b - a) / 3));
}

/// The integral over [a, b] (radians) of the linear function through (a, fa), (b, fb)
/// times sin(p) (type C's gamma) or cos(p) (a latitude): exact.
double WeightedPiece(double a, double b, double fa, double fb, bool sine)
{
  const double slope = (fb - fa) / (b - a), start = fa - slope * a;
  // Antiderivatives of sin p, p sin p (sine) or cos p, p cos p (latitude).
  auto flat = [&](double p) { return sine ? -std::cos(p) : std::sin(p); };
  auto ramp = [&](double p) { return sine ? std::sin(p) - p * std::cos(p) : std::cos(p) + p * std::sin(p); };
  return start * (flat(b) - flat(a)) + slope * (ramp(b) - ramp(a));
}
} // namespace

void PhotometricAngles(PhotometricType type, const Vec3& direction, double& azimuth, double& polar)
{
  const Vec3 d = Normalized(direction);
  auto clamped = [](double v) { return std::max(-1.0, std::min(1.0, v)); };
  if (type == PhotometricType::C)
  {
    polar = std::acos(clamped(d.z)) / kDegree;
    azimuth = std::atan2(d.y, d.x) / kDegree;
    azimuth = azimuth < 0 ? azimuth + 360 : azimuth;
  }
  else if (type == PhotometricType::B)
  {
    polar = std::asin(clamped(d.y)) / kDegree;
    azimuth = std::atan2(d.x, d.z) / kDegree;
  }
  else
  {
    polar = std::asin(clamped(d.x)) / kDegree;
    azimuth = std::atan2(d.y, d.z) / kDegree;
  }
}

double PhotometricWeb::Intensity(const Vec3& direction) const
{
  double azimuth, polar;
  PhotometricAngles(Type, direction, azimuth, polar);
  return TableValue(*this, TurnOf(*this), azimuth, polar);
}

double PhotometricWeb::Flux() const
{
  const bool typeC = Type == PhotometricType::C;
  const Turn turn = TurnOf(*this);
  const std::vector<double> turns = Knots(Azimuth, typeC ? 0 : -180, typeC ? 360 : 180);
  const std::vector<double> polars = Knots(Polar, typeC ? 0 : -90, typeC ? 180 : 90);
  auto plane = [&](double azimuth) {
    double sum = 0;
    for (size_t i = 0; i + 1 < polars.size(); ++i)
    {
      const double a = polars[i], b = polars[i + 1], third = (b - a) / 3;
      // The value at each end from the two inner points: the table's edge may jump there.
      const double f1 = TableValue(*this, turn, azimuth, a + third), f2 = TableValue(*this, turn, azimuth, b - third);
      const double fa = 2 * f1 - f2, fb = 2 * f2 - f1;
      sum += WeightedPiece(a * kDegree, b * kDegree, fa, fb, typeC);
    }
    return sum;
  };
  double flux = 0;
  for (size_t i = 0; i + 1 < turns.size(); ++i)
  {
    flux += LinearPiece(turns[i], turns[i + 1], plane) * kDegree;
  }
  return flux;
}

double PhotometricWeb::TiltFactor(double degrees) const
{
  if (TiltAngles.empty())
  {
    return 1;
  }
  if (degrees <= TiltAngles.front())
  {
    return TiltFactors.front();
  }
  if (degrees >= TiltAngles.back())
  {
    return TiltFactors.back();
  }
  size_t i;
  double t;
  Locate(TiltAngles, degrees, i, t);
  return TiltFactors[i] * (1 - t) + TiltFactors[i + 1] * t;
}

double PhotometricWeb::Peak() const
{
  return Candela.empty() ? 0 : *std::max_element(Candela.begin(), Candela.end());
}

namespace
{
std::string AscendingProblem(const std::vector<double>& angles, const char* what, double lo, double hi)
{
  if (angles.empty())
  {
    return std::string("no ") + what + " angles";
  }
  for (size_t i = 0; i < angles.size(); ++i)
  {
    std::ostringstream s;
    if (!std::isfinite(angles[i]) || angles[i] < lo - kAngleSlack || angles[i] > hi + kAngleSlack)
    {
      s << what << " angle " << i + 1 << " is " << angles[i] << ", outside " << lo << " to " << hi;
      return s.str();
    }
    if (i > 0 && !(angles[i] > angles[i - 1]))
    {
      s << what << " angles out of order: " << angles[i - 1] << " then " << angles[i];
      return s.str();
    }
  }
  return {};
}
} // namespace

std::string PhotometricProblem(const PhotometricWeb& web)
{
  const bool typeC = web.Type == PhotometricType::C;
  std::string problem = AscendingProblem(web.Polar, typeC ? "vertical" : "latitude", typeC ? 0 : -90, typeC ? 180 : 90);
  if (problem.empty())
  {
    problem = AscendingProblem(web.Azimuth, typeC ? "horizontal" : "plane", typeC ? 0 : -180, typeC ? 360 : 180);
  }
  if (!problem.empty())
  {
    return problem;
  }
  if (web.Candela.size() != web.Azimuth.size() * web.Polar.size())
  {
    return "the candela table has " + std::to_string(web.Candela.size()) + " values, not " +
      std::to_string(web.Azimuth.size()) + " x " + std::to_string(web.Polar.size());
  }
  if (TurnOf(web) == Turn::Unsupported)
  {
    std::ostringstream s;
    s << "horizontal angles from " << web.Azimuth.front() << " to " << web.Azimuth.back()
      << " imply no symmetry (LM-63 knows 0, 0-90, 0-180, 90-270 and a full turn)";
    return s.str();
  }
  for (size_t i = 0; i < web.Candela.size(); ++i)
  {
    if (!std::isfinite(web.Candela[i]) || web.Candela[i] < 0)
    {
      std::ostringstream s;
      s << "candela value " << i + 1 << " is " << web.Candela[i];
      return s.str();
    }
  }
  if (web.TiltAngles.size() != web.TiltFactors.size())
  {
    return "the tilt table's angles and factors differ in number";
  }
  return AscendingProblem(web.TiltAngles, "tilt", -180, 180).empty() || web.TiltAngles.empty()
    ? std::string()
    : AscendingProblem(web.TiltAngles, "tilt", -180, 180);
}

} // namespace radiosity
