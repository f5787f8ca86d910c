// The clustered method's interreflection as one linear solve by conjugate gradients,
// instead of one bounce after another: about half the gathers for the same remainder.
#ifndef RadiosityCore_ConjugateBounces_h
#define RadiosityCore_ConjugateBounces_h

#include <cstddef>
#include <vector>

namespace radiosity
{

/// Solves X = x0 + W F X for the reflected radiosity X, where x0 is the reflected direct
/// light, F the links' transport (what an element receives from the others' radiosity)
/// and W per element and channel its reflectance times its receiver scale. With A the
/// areas, A F is symmetric (the links couple each pair both ways alike), so
/// (A / W - A F) X = A x0 / W is a symmetric positive definite system: conjugate gradients
/// preconditioned by its diagonal. Each step's residual, scaled by that diagonal, is what
/// one more bounce would add (the increment), so the remainder reads as the bouncing one's.
/// Every lane (solution x channel) is its own system with its own step lengths; lanes are
/// side by side per element, as ClusterGather lays them out. Values are `Value`s (Vec3 or
/// double) read as doubles.
template <typename Value>
class ConjugateBounces
{
public:
  /// `weight[e * channels + c]`: W of element e in channel c; lanes = solutions x channels.
  ConjugateBounces(const std::vector<double>& area, std::vector<double> weight, int solutions, int channels)
    : Area(area)
    , Weight(std::move(weight))
    , Channels(channels)
    , Lanes(solutions * channels)
  {
  }

  /// From the reflected direct light and what it sends (F x0, gathered).
  void Start(const std::vector<Value>& x0, const std::vector<Value>& sent)
  {
    X = x0;
    Carried = sent;
    Z = sent;
    double* z = Doubles(Z);
    ForEachLane([&](std::size_t, std::size_t i, double w) { z[i] *= w; });
    P = Z;
    RZ = ResidualDotIncrement();
    Bouncing.assign(Lanes, 0);
  }

  /// The direction whose transport Step needs next.
  const std::vector<Value>& Direction() const { return P; }

  /// One step, from what the direction sends (F p, gathered). The residual r of the
  /// symmetric system is kept as the increment z = W r / A (r itself where W > 0), which
  /// saves a vector; K p = A (p - W F p) / W.
  void Step(const std::vector<Value>& sent)
  {
    const double* g = Doubles(sent);
    double* p = Doubles(P);
    std::vector<double> pKp(Lanes, 0.0);
    ForEachLane([&](std::size_t e, std::size_t i, double w) {
      pKp[i % Lanes] += w > 0 ? Area[e] * p[i] * (p[i] - w * g[i]) / w : 0.0;
    });
    std::vector<double> alpha(Lanes, 0.0);
    for (int j = 0; j < Lanes; ++j)
    {
      if (Bouncing[j])
      {
        alpha[j] = 1.0; // along the increment, whole: one bounce
      }
      else if (RZ[j] > 0 && !(pKp[j] > 0))
      {
        Bouncing[j] = 1; // the system is not positive along p (links far from reciprocal): bounce from here
      }
      else
      {
        alpha[j] = RZ[j] > 0 ? RZ[j] / pKp[j] : 0.0; // a lane with nothing left stays
      }
    }
    double* x = Doubles(X);
    double* t = Doubles(Carried);
    double* z = Doubles(Z);
    ForEachLane([&](std::size_t, std::size_t i, double w) {
      const double a = alpha[i % Lanes];
      x[i] += a * p[i];
      t[i] += a * g[i];
      z[i] -= w > 0 ? a * (p[i] - w * g[i]) : 0.0;
    });
    const std::vector<double> rz = ResidualDotIncrement();
    ForEachLane([&](std::size_t, std::size_t i, double) {
      const int j = static_cast<int>(i % Lanes);
      p[i] = z[i] + (RZ[j] > 0 && !Bouncing[j] ? rz[j] / RZ[j] : 0.0) * p[i];
    });
    RZ = rz;
  }

  const std::vector<Value>& Solution() const { return X; }
  /// F X: what the solution sends, kept up to date without a gather of its own.
  const std::vector<Value>& Sent() const { return Carried; }
  /// What one more bounce would add to each element and lane.
  const std::vector<Value>& Increment() const { return Z; }

private:
  static double* Doubles(std::vector<Value>& v) { return reinterpret_cast<double*>(v.data()); }
  static const double* Doubles(const std::vector<Value>& v) { return reinterpret_cast<const double*>(v.data()); }

  /// body(element, index, W) over every element and lane, in order.
  template <typename Body>
  void ForEachLane(const Body& body) const
  {
    for (std::size_t e = 0; e < Area.size(); ++e)
    {
      const double* w = Weight.data() + e * Channels;
      for (int j = 0; j < Lanes; ++j)
      {
        body(e, e * Lanes + j, w[j % Channels]);
      }
    }
  }

  /// Per lane, r . z = sum of A z^2 / W (in element order: the same on any thread count).
  std::vector<double> ResidualDotIncrement() const
  {
    std::vector<double> sums(Lanes, 0.0);
    const double* z = Doubles(Z);
    ForEachLane([&](std::size_t e, std::size_t i, double w) { sums[i % Lanes] += w > 0 ? Area[e] * z[i] * z[i] / w : 0.0; });
    return sums;
  }

  const std::vector<double>& Area;
  const std::vector<double> Weight;
  const int Channels, Lanes;
  std::vector<Value> X, Carried, Z, P;
  std::vector<double> RZ;
  /// Lanes whose system turned out not positive definite: they take plain bounces (Jacobi
  /// steps along the increment), which converge wherever bouncing did.
  std::vector<char> Bouncing;
};

} // namespace radiosity

#endif
