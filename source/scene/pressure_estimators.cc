// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/scene/pressure_estimators.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace dpana
{
  namespace scene
  {
    namespace
    {
      // The moments int p, int s p, int s^2 p of the piecewise constant
      // pressure, s measured from s0.
      std::array<double, 3>
      pressure_moments(const std::vector<PressureElement> &elements,
                       const double                        s0)
      {
        std::array<double, 3> m = {{0, 0, 0}};
        for (const auto &e : elements)
          {
            const double p  = std::max(e.pressure, 0.);
            const double x0 = e.s_min - s0, x1 = e.s_max - s0;
            m[0] += p * (x1 - x0);
            m[1] += p * (x1 * x1 - x0 * x0) / 2;
            m[2] += p * (x1 * x1 * x1 - x0 * x0 * x0) / 3;
          }
        return m;
      }



      // Solves the n x n system M c = b (n <= 3) by Gaussian elimination
      // with partial pivoting; false if M is singular.
      bool
      solve(std::array<std::array<double, 3>, 3> M,
            std::array<double, 3>                b,
            const unsigned int                   n,
            std::array<double, 3>               &c)
      {
        for (unsigned int k = 0; k < n; ++k)
          {
            unsigned int pivot = k;
            for (unsigned int i = k + 1; i < n; ++i)
              if (std::abs(M[i][k]) > std::abs(M[pivot][k]))
                pivot = i;
            if (!(std::abs(M[pivot][k]) > 0))
              return false;
            std::swap(M[k], M[pivot]);
            std::swap(b[k], b[pivot]);
            for (unsigned int i = k + 1; i < n; ++i)
              {
                const double f = M[i][k] / M[k][k];
                for (unsigned int j = k; j < n; ++j)
                  M[i][j] -= f * M[k][j];
                b[i] -= f * b[k];
              }
          }
        for (unsigned int k = n; k-- > 0;)
          {
            double r = b[k];
            for (unsigned int j = k + 1; j < n; ++j)
              r -= M[k][j] * c[j];
            c[k] = r / M[k][k];
          }
        return true;
      }



      // The elliptic fit of the header: weighted least squares of p^2 in
      // the basis 1, s^2 (mirrored) or 1, s, s^2 by the normal equations.
      void
      fit_ellipse(const std::vector<PressureElement> &elements,
                  const double                        s0,
                  PressureEstimates                  &est)
      {
        const unsigned int                   n = est.mirrored ? 2 : 3;
        std::array<std::array<double, 3>, 3> M{};
        std::array<double, 3>                b{}, coef{};
        unsigned int                         n_pressed = 0;
        double                               extent    = 0;
        // Pressed: above the round-off of the solver (separated elements
        // carry |N| of that size), relative to the largest pressure.
        double p_max = 0;
        for (const auto &e : elements)
          p_max = std::max(p_max, e.pressure);
        for (const auto &e : elements)
          if (e.pressure > 1e-9 * p_max)
            {
              const double                x = 0.5 * (e.s_min + e.s_max) - s0;
              const double                w = e.s_max - e.s_min;
              const std::array<double, 3> phi =
                est.mirrored ? std::array<double, 3>{{1, x * x, 0}} :
                               std::array<double, 3>{{1, x, x * x}};
              for (unsigned int i = 0; i < n; ++i)
                {
                  for (unsigned int j = 0; j < n; ++j)
                    M[i][j] += w * phi[i] * phi[j];
                  b[i] += w * phi[i] * e.pressure * e.pressure;
                }
              ++n_pressed;
              extent = std::max(
                {extent, std::abs(e.s_min - s0), std::abs(e.s_max - s0)});
            }
        if (n_pressed < n || !solve(M, b, n, coef))
          return;
        const double A = coef[0], B = est.mirrored ? 0 : coef[1];
        const double C = est.mirrored ? coef[1] : coef[2];
        if (!(C < 0))
          return;
        const double p0_squared = A - B * B / (4 * C);
        // A fitted zone more than twice as wide as the pressed one is a
        // flat profile, not an ellipse.
        if (!(p0_squared > 0) || !(-p0_squared / C < 4 * extent * extent))
          return;
        est.fit_available    = true;
        est.fit_centre       = -B / (2 * C);
        est.fit_max_pressure = std::sqrt(p0_squared);
        est.fit_half_width   = std::sqrt(-p0_squared / C);
      }
    } // namespace



    PressureEstimates
    estimate_pressure_profile(const std::vector<PressureElement> &elements,
                              const double                        s0,
                              const bool symmetric_about_s0)
    {
      PressureEstimates est;
      if (elements.empty())
        return est;
      // A surface on one side of s0 (to a round-off of its extent) of a body
      // symmetric about s0 is a half model. Without the symmetry it is a
      // whole model that lies on one side of s0 (a block from x = 0 with
      // nothing held on x = 0): mirrored, its centroid would read 0.
      double lowest = elements[0].s_min, highest = elements[0].s_max;
      for (const auto &e : elements)
        {
          lowest  = std::min(lowest, e.s_min);
          highest = std::max(highest, e.s_max);
        }
      const double tol =
        1e-9 * std::max(std::abs(lowest - s0), std::abs(highest - s0));
      est.mirrored =
        symmetric_about_s0 && (lowest - s0 > -tol || highest - s0 < tol);

      const std::array<double, 3> m = pressure_moments(elements, s0);
      if (!(m[0] > 0))
        return est;
      est.available         = true;
      est.resultant         = m[0];
      est.centroid          = est.mirrored ? 0. : m[1] / m[0];
      const double variance = m[2] / m[0] - est.centroid * est.centroid;
      est.moment_half_width = 2 * std::sqrt(std::max(variance, 0.));
      fit_ellipse(elements, s0, est);
      return est;
    }
  } // namespace scene
} // namespace dpana
