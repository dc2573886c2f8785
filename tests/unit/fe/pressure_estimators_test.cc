// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Tests of the estimators finer than an element (scene/pressure_estimators.h)
// on synthetic piecewise constant pressures: each element carries the exact
// mean over it of the elliptic Hertz law p(s) = p0 sqrt(1 - (s - c)^2 / a^2),
// computed from the antiderivative of sqrt(1 - u^2),
// F(u) = (u sqrt(1 - u^2) + asin u) / 2. The element edges are not aligned
// with the zone edges s = c -+ a.
//
// Expected accuracies (h the element length):
// - the resultant integrates the means exactly: R = pi p0 a / 2 to round-off,
//   and the centroid of a symmetric law is c;
// - the moment estimate: the piecewise constant pressure adds the variance
//   h^2 / 12 of each element to the second moment, and the means differ from
//   the law by O(h^2) inside the zone, so a_m / a - 1 = O((h / a)^2); the
//   test asserts the bound 0.5 (h / a)^2 (observed 0.24 to 0.31 (h / a)^2);
// - the elliptic fit: the squared mean of the element that holds the zone
//   edge differs from the squared law at its centroid by O(h) on one element
//   of the O(a / h) that are fitted, so a_f / a - 1 = O((h / a)^(3/2)); the
//   test asserts 0.6 (h / a)^(3/2) (observed up to 0.47 (h / a)^(3/2)).

#include <dpana/scene/pressure_estimators.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace
{
  using dpana::scene::estimate_pressure_profile;
  using dpana::scene::PressureElement;
  using dpana::scene::PressureEstimates;

  // The antiderivative of sqrt(1 - u^2), constant outside [-1, 1].
  double
  F(const double u)
  {
    const double v = std::clamp(u, -1., 1.);
    return 0.5 * (v * std::sqrt(1 - v * v) + std::asin(v));
  }

  // n elements of length h from s = first, each with the mean of the
  // elliptic law of half width a, peak p0 and centre c.
  std::vector<PressureElement>
  elliptic_means(const double       first,
                 const double       h,
                 const unsigned int n,
                 const double       a,
                 const double       p0,
                 const double       c)
  {
    std::vector<PressureElement> elements;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double s0 = first + i * h, s1 = s0 + h;
        elements.push_back(
          {s0, s1, p0 * a * (F((s1 - c) / a) - F((s0 - c) / a)) / h});
      }
    return elements;
  }

  const double a  = 8.;     // half width (mm)
  const double p0 = 14681.; // peak pressure (MPa)
  const double L  = 15.;    // candidate half width (mm)
} // namespace



// A half model x >= 0 (mirrored about s0 = 0) refined 8 to 256 elements on
// [0, L].
TEST(PressureEstimators, HalfModelRecoversTheEllipticLaw)
{
  double last_moment_error = 1;
  for (unsigned int n = 8; n <= 256; n *= 2)
    {
      const double            h = L / n;
      const PressureEstimates e =
        estimate_pressure_profile(elliptic_means(0, h, n, a, p0, 0), 0);
      ASSERT_TRUE(e.available);
      EXPECT_TRUE(e.mirrored);
      EXPECT_NEAR(e.resultant, M_PI * p0 * a / 4, 1e-12 * p0 * a);
      EXPECT_EQ(e.centroid, 0.);
      const double moment_error = std::abs(e.moment_half_width / a - 1);
      EXPECT_LT(moment_error, 0.5 * std::pow(h / a, 2)) << n;
      EXPECT_LT(moment_error, last_moment_error) << n;
      last_moment_error = moment_error;
      ASSERT_TRUE(e.fit_available);
      EXPECT_LT(std::abs(e.fit_half_width / a - 1), 0.6 * std::pow(h / a, 1.5))
        << n;
      EXPECT_LT(std::abs(e.fit_max_pressure / p0 - 1),
                0.6 * std::pow(h / a, 1.5))
        << n;
      EXPECT_EQ(e.fit_centre, 0.);
    }
}



// The moment estimate recovers a exactly from the elliptic law itself: the
// error of its element means vanishes as h^2 (each element adds its own
// variance h^2/12 to the second moment), so that it falls 4 times per
// halving of h (3.8 to 4.2 from 64 to 1024 elements), and the Richardson
// extrapolation (4 a_m(h/2) - a_m(h)) / 3 of 512 and 1024 elements lies
// within 1e-7 of a (the computation: 1.5e-8).
TEST(PressureEstimators, MomentEstimateIsExactInTheLimit)
{
  std::vector<double> a_m;
  for (unsigned int n = 64; n <= 1024; n *= 2)
    a_m.push_back(
      estimate_pressure_profile(elliptic_means(0, L / n, n, a, p0, 0), 0)
        .moment_half_width);
  for (unsigned int i = 0; i + 1 < a_m.size(); ++i)
    {
      const double ratio = (a_m[i] - a) / (a_m[i + 1] - a);
      EXPECT_GT(ratio, 3.5) << i;
      EXPECT_LT(ratio, 4.5) << i;
    }
  const double extrapolated = (4 * a_m.back() - a_m[a_m.size() - 2]) / 3;
  EXPECT_NEAR(extrapolated / a, 1.0, 1e-7);
}



// A whole model on [-L, L], shifted off the element edges, with the law
// centred at c = 0.1 mm: the centroid and the fit's centre find c.
TEST(PressureEstimators, WholeModelFindsTheCentre)
{
  const double c = 0.1;
  for (unsigned int n = 8; n <= 256; n *= 2)
    {
      const double            h = L / n;
      const PressureEstimates e = estimate_pressure_profile(
        elliptic_means(-L + 0.37 * h, h, 2 * n, a, p0, c), 0);
      ASSERT_TRUE(e.available);
      EXPECT_FALSE(e.mirrored);
      EXPECT_NEAR(e.resultant, M_PI * p0 * a / 2, 1e-12 * p0 * a);
      // The centroid of the piecewise constant means of a symmetric law is
      // its centre up to the O(h^2) asymmetry of the edge elements.
      EXPECT_NEAR(e.centroid, c, 0.1 * h * h / a) << n;
      EXPECT_LT(std::abs(e.moment_half_width / a - 1), 0.5 * std::pow(h / a, 2))
        << n;
      ASSERT_TRUE(e.fit_available);
      EXPECT_LT(std::abs(e.fit_half_width / a - 1), 0.6 * std::pow(h / a, 1.5))
        << n;
      EXPECT_NEAR(e.fit_centre, c, h) << n;
    }
}



// The moment estimate assumes the elliptic law: a uniform pressure on
// [-b, b] (a flat punch) has a_m = 2 b / sqrt(3), not b, and the elliptic
// fit of a uniform pressure does not exist (C = 0).
TEST(PressureEstimators, WhatTheyAssume)
{
  const double                 b = 3.;
  std::vector<PressureElement> elements;
  for (int i = -10; i < 10; ++i)
    elements.push_back(
      {0.5 * i, 0.5 * (i + 1), std::abs(0.5 * (i + 0.5)) < b ? 1. : 0});
  const PressureEstimates e = estimate_pressure_profile(elements, 0);
  EXPECT_NEAR(e.moment_half_width, 2 * b / std::sqrt(3.), 1e-12);
  EXPECT_NEAR(e.resultant, 2 * b, 1e-12);
  EXPECT_FALSE(e.fit_available);

  // No pressure: no estimate.
  for (auto &el : elements)
    el.pressure = 0;
  EXPECT_FALSE(estimate_pressure_profile(elements, 0).available);
}
