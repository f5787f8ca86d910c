// The clustered method's linear solve against Gaussian elimination of the same system, and
// against the bounce-by-bounce iteration it replaced.
#include "Solve/ConjugateBounces.h"
#include "Base/Vec3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using radiosity::ConjugateBounces;
using radiosity::Vec3;

namespace
{
/// A small closed-ish scene in matrix form: areas, a transport F whose A F is symmetric
/// (random couplings, rows scaled to view at most all of the scene), reflectances.
struct System
{
  int n = 0;
  std::vector<double> area, rho;
  std::vector<double> F; // F[i * n + j]: what i receives from j's radiosity

  explicit System(int size, unsigned seed)
    : n(size)
    , area(size)
    , rho(size)
    , F(static_cast<size_t>(size) * size, 0.0)
  {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> coupling(F.size(), 0.0);
    for (int i = 0; i < n; ++i)
    {
      area[i] = 0.2 + u(random);
      rho[i] = 0.95 * u(random);
      for (int j = 0; j < i; ++j)
      {
        coupling[i * n + j] = coupling[j * n + i] = u(random) < 0.4 ? 0.0 : u(random);
      }
    }
    // Symmetric couplings over one common scale keep A F symmetric; the scale makes the
    // largest row sum (the fullest view) 0.98.
    double largest = 0;
    for (int i = 0; i < n; ++i)
    {
      double row = 0;
      for (int j = 0; j < n; ++j)
      {
        row += coupling[i * n + j] / area[i];
      }
      largest = std::max(largest, row);
    }
    for (size_t k = 0; k < F.size(); ++k)
    {
      F[k] = 0.98 * coupling[k] / area[k / n] / largest;
    }
  }

  std::vector<double> Apply(const std::vector<double>& x) const
  {
    std::vector<double> y(n, 0.0);
    for (int i = 0; i < n; ++i)
    {
      for (int j = 0; j < n; ++j)
      {
        y[i] += F[i * n + j] * x[j];
      }
    }
    return y;
  }

  /// X = x0 + R F X by Gaussian elimination with partial pivoting.
  std::vector<double> Exact(const std::vector<double>& x0) const
  {
    std::vector<double> m(F.size()), b = x0;
    for (int i = 0; i < n; ++i)
    {
      for (int j = 0; j < n; ++j)
      {
        m[i * n + j] = (i == j ? 1.0 : 0.0) - rho[i] * F[i * n + j];
      }
    }
    for (int c = 0; c < n; ++c)
    {
      int pivot = c;
      for (int r = c + 1; r < n; ++r)
      {
        pivot = std::fabs(m[r * n + c]) > std::fabs(m[pivot * n + c]) ? r : pivot;
      }
      for (int k = 0; k < n; ++k)
      {
        std::swap(m[c * n + k], m[pivot * n + k]);
      }
      std::swap(b[c], b[pivot]);
      for (int r = c + 1; r < n; ++r)
      {
        const double f = m[r * n + c] / m[c * n + c];
        for (int k = c; k < n; ++k)
        {
          m[r * n + k] -= f * m[c * n + k];
        }
        b[r] -= f * b[c];
      }
    }
    std::vector<double> x(n);
    for (int r = n - 1; r >= 0; --r)
    {
      double s = b[r];
      for (int k = r + 1; k < n; ++k)
      {
        s -= m[r * n + k] * x[k];
      }
      x[r] = s / m[r * n + r];
    }
    return x;
  }
};

std::vector<double> Direct(int n, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> x0(n);
  for (double& v : x0)
  {
    v = u(random) < 0.3 ? 0.0 : u(random);
  }
  return x0;
}
} // namespace

TEST(ConjugateBounces, SolvesTheSystemAsGaussianEliminationDoes)
{
  const System s(40, 7);
  std::vector<double> x0 = Direct(s.n, 11);
  for (int i = 0; i < s.n; ++i)
  {
    x0[i] *= s.rho[i]; // reflected direct light
  }
  const std::vector<double> exact = s.Exact(x0);
  ConjugateBounces<double> solve(s.area, s.rho, 1, 1);
  solve.Start(x0, s.Apply(x0));
  int steps = 0;
  for (; steps < s.n; ++steps)
  {
    double left = 0;
    for (double z : solve.Increment())
    {
      left += std::fabs(z);
    }
    if (left < 1e-13)
    {
      break;
    }
    solve.Step(s.Apply(solve.Direction()));
  }
  EXPECT_LT(steps, s.n); // exact after n steps in exact arithmetic; far fewer here
  for (int i = 0; i < s.n; ++i)
  {
    ASSERT_NEAR(solve.Solution()[i], exact[i], 1e-11) << i;
  }
  // What it keeps of the transport is that of its solution; the increment is the residual.
  const std::vector<double> sent = s.Apply(solve.Solution());
  for (int i = 0; i < s.n; ++i)
  {
    EXPECT_NEAR(solve.Sent()[i], sent[i], 1e-11);
    EXPECT_NEAR(solve.Increment()[i], x0[i] + s.rho[i] * sent[i] - solve.Solution()[i], 1e-11);
  }
}

TEST(ConjugateBounces, TakesFewerStepsThanBouncingToTheSameRemainder)
{
  // Bouncing (each step adds R F of the last one) leaves a remainder that shrinks by the
  // largest eigenvalue of R F per bounce; the solve's shrinks with about its square root's
  // distance from one.
  System s(60, 3);
  for (int i = 0; i < s.n; ++i)
  {
    s.rho[i] = 0.8 + 0.15 * i / s.n; // bright, as a white room is: many bounces
  }
  std::vector<double> x0 = Direct(s.n, 5);
  const auto remainder = [&](const std::vector<double>& v) {
    double sum = 0;
    for (int i = 0; i < s.n; ++i)
    {
      sum += std::fabs(v[i]) * s.area[i];
    }
    return sum;
  };
  const double start = remainder(x0);
  int bounces = 0;
  for (std::vector<double> last = x0; remainder(last) > 1e-6 * start; ++bounces)
  {
    const std::vector<double> next = s.Apply(last);
    for (int i = 0; i < s.n; ++i)
    {
      last[i] = s.rho[i] * next[i];
    }
  }
  ConjugateBounces<double> solve(s.area, s.rho, 1, 1);
  solve.Start(x0, s.Apply(x0));
  int steps = 1; // its start gathers once, as the first bounce does
  for (; remainder(solve.Increment()) > 1e-6 * start; ++steps)
  {
    solve.Step(s.Apply(solve.Direction()));
  }
  std::printf("to 1e-6 of the direct light: %d bounces, %d solve steps\n", bounces, steps);
  EXPECT_LT(2 * steps, bounces);
}

TEST(ConjugateBounces, EveryLaneIsItsOwnSystem)
{
  // Two solutions of three channels each, the channels' reflectances differing: each lane
  // equals a solve of its own.
  const System s(30, 9);
  std::vector<double> weights(3 * s.n);
  for (int i = 0; i < s.n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      weights[3 * i + c] = s.rho[i] * (0.5 + 0.25 * c);
    }
  }
  const std::vector<double> a = Direct(s.n, 1), b = Direct(s.n, 2);
  std::vector<Vec3> x0(2 * s.n);
  for (int i = 0; i < s.n; ++i)
  {
    x0[2 * i] = Vec3{ a[i], 2 * a[i], 0.0 };
    x0[2 * i + 1] = Vec3{ b[i], b[i], b[i] };
  }
  const auto apply = [&](const std::vector<Vec3>& v) {
    std::vector<Vec3> out(v.size());
    for (int i = 0; i < s.n; ++i)
    {
      for (int j = 0; j < s.n; ++j)
      {
        out[2 * i] += v[2 * j] * s.F[i * s.n + j];
        out[2 * i + 1] += v[2 * j + 1] * s.F[i * s.n + j];
      }
    }
    return out;
  };
  ConjugateBounces<Vec3> solve(s.area, weights, 2, 3);
  solve.Start(x0, apply(x0));
  for (int step = 0; step < s.n; ++step)
  {
    solve.Step(apply(solve.Direction()));
  }
  for (int m = 0; m < 2; ++m)
  {
    for (int c = 0; c < 3; ++c)
    {
      System lane = s;
      std::vector<double> start(s.n);
      for (int i = 0; i < s.n; ++i)
      {
        lane.rho[i] = weights[3 * i + c];
        start[i] = reinterpret_cast<const double*>(&x0[2 * i + m])[c];
      }
      const std::vector<double> exact = lane.Exact(start);
      for (int i = 0; i < s.n; ++i)
      {
        ASSERT_NEAR(reinterpret_cast<const double*>(&solve.Solution()[2 * i + m])[c], exact[i], 1e-10)
          << "solution " << m << " channel " << c << " element " << i;
      }
    }
  }
}

TEST(ConjugateBounces, LinksFarFromReciprocalFallBackToBouncing)
{
  // A F far from symmetric (one element sends a hundred times what it gets back): the
  // system is not positive along the first direction (p K p = 2 p1^2 + 2 p2^2 - 10.1 p1 p2
  // at p = (5, 5)), and the lane takes plain bounces instead, which converge here (W F's
  // spectral radius is 0.5). The links are reciprocal, so this guards, not a case met.
  const std::vector<double> area = { 1.0, 1.0 }, weight = { 0.5, 0.5 };
  const double F[2][2] = { { 0.0, 10.0 }, { 0.1, 0.0 } };
  const auto apply = [&](const std::vector<double>& v) {
    return std::vector<double>{ F[0][1] * v[1], F[1][0] * v[0] };
  };
  const std::vector<double> x0 = { 100.0, 1.0 };
  // X = x0 + W F X: X0 = 100 + 5 X1, X1 = 1 + 0.05 X0.
  const double x1 = (1 + 0.05 * 100) / (1 - 0.25), exact[2] = { 100 + 5 * x1, x1 };
  ConjugateBounces<double> solve(area, weight, 1, 1);
  solve.Start(x0, apply(x0));
  for (int step = 0; step < 60; ++step)
  {
    solve.Step(apply(solve.Direction()));
  }
  EXPECT_NEAR(solve.Solution()[0], exact[0], 1e-9 * exact[0]);
  EXPECT_NEAR(solve.Solution()[1], exact[1], 1e-9 * exact[0]);
}
