// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/contact_surface/axial_sphere_fit.h>

#include <cmath>

namespace dpana
{
  namespace contact_surface
  {
    template <int dim>
    AxialSphereFit
    fit_axial_sphere(const std::vector<Face<dim>> &faces,
                     const dealii::Point<dim>     &x0,
                     const dealii::Tensor<1, dim> &m,
                     const double                  reach)
    {
      // The normal equations of z = alpha q + beta, q = |d|^2, in sums
      // over the vertices (a vertex shared by faces counts once per face).
      double n = 0, sq = 0, sqq = 0, sz = 0, sqz = 0;
      for (const auto &face : faces)
        for (const auto &x : face.points)
          {
            const dealii::Tensor<1, dim> d = x - x0;
            const double                 q = d.norm_square();
            if (q > reach * reach)
              continue;
            const double z = d * m;
            n += 1;
            sq += q;
            sqq += q * q;
            sz += z;
            sqz += q * z;
          }
      AxialSphereFit fit;
      const double   det = n * sqq - sq * sq;
      // The distances must differ: det is the sum over pairs of
      // (q_i - q_j)^2, small against (sum q)^2 only if they all agree.
      if (n < 2 || !(det > 1e-12 * sq * sq))
        return fit;
      const double alpha = (n * sqz - sq * sz) / det;
      const double beta  = (sqq * sz - sq * sqz) / det;
      const double s     = 1 - 4 * alpha * beta;
      if (!(s > 0))
        return fit;
      fit.available = true;
      fit.curvature = -2 * alpha / std::sqrt(s);
      fit.offset    = beta;
      return fit;
    }



    template AxialSphereFit
    fit_axial_sphere(const std::vector<Face<2>> &,
                     const dealii::Point<2> &,
                     const dealii::Tensor<1, 2> &,
                     const double);
    template AxialSphereFit
    fit_axial_sphere(const std::vector<Face<3>> &,
                     const dealii::Point<3> &,
                     const dealii::Tensor<1, 3> &,
                     const double);
  } // namespace contact_surface
} // namespace dpana
