// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The estimators of an axisymmetric contact pressure on a plane, from its
// piecewise constant pieces (references.h): the moment estimate of the
// contact radius and the elliptic fit of the Hertz law.
#include <dpana/scene/references.h>

#include <algorithm>
#include <cmath>

namespace dpana
{
  namespace scene
  {
    double
    moment_contact_radius(const std::vector<PressurePiece> &pieces)
    {
      double force = 0, moment = 0;
      for (const PressurePiece &p : pieces)
        {
          force += p.pressure * p.area;
          moment += p.pressure * p.r2_integral;
        }
      return force != 0 ? std::sqrt(2.5 * moment / force) : 0.0;
    }



    EllipticFit
    elliptic_fit(const std::vector<PressurePiece> &pieces)
    {
      double p_max = 0;
      for (const PressurePiece &p : pieces)
        p_max = std::max(p_max, p.pressure);
      // The normal equations of the weighted least squares in the basis
      // 1, r^2: [sum w, sum w r2; sum w r2, sum w r2^2] (A, C) =
      // (sum w p^2, sum w r2 p^2).
      double m00 = 0, m01 = 0, m11 = 0, b0 = 0, b1 = 0;
      for (const PressurePiece &p : pieces)
        if (p.pressure > 1e-9 * p_max && p.area > 0)
          {
            const double r2 = p.r2_integral / p.area,
                         p2 = p.pressure * p.pressure;
            m00 += p.area;
            m01 += p.area * r2;
            m11 += p.area * r2 * r2;
            b0 += p.area * p2;
            b1 += p.area * r2 * p2;
          }
      EllipticFit  fit;
      const double det = m00 * m11 - m01 * m01;
      // Pieces at one radius only leave the normal matrix singular (to the
      // round-off of its entries).
      if (!(det > 1e-12 * m00 * m11))
        return fit;
      const double A = (b0 * m11 - m01 * b1) / det;
      const double C = (m00 * b1 - m01 * b0) / det;
      if (!(A > 0) || !(C < 0))
        return fit;
      fit.available    = true;
      fit.max_pressure = std::sqrt(A);
      fit.radius       = std::sqrt(-A / C);
      return fit;
    }
  } // namespace scene
} // namespace dpana
