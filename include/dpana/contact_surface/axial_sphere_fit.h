// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_contact_surface_axial_sphere_fit_h
#define dpana_contact_surface_axial_sphere_fit_h

#include <dpana/contact_surface/contact_surface.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace dpana
{
  namespace contact_surface
  {
    /**
     * The sphere (a circle in 2D) that best fits a body's surface about a
     * point, with its centre on the axis through that point.
     */
    struct AxialSphereFit
    {
      // False if the vertices do not determine a fit (fewer than two
      // distinct distances from the point).
      bool available = false;
      // 1/R: > 0 convex (the centre inside the body), < 0 concave (a cavity),
      // 0 flat.
      double curvature = 0;
      // beta below: 0 if the surface passes through the point, the height
      // of a plane above it along the outward normal.
      double offset = 0;
    };

    /**
     * Fits a sphere whose centre lies on the axis through @p x0 along the
     * body's outward unit normal @p m to the vertices of @p faces within the
     * distance @p reach of x0. With d = x - x0 and z = d . m, every point of
     * the sphere of centre x0 + c m and radius R satisfies
     *     |d|^2 - 2 c z + c^2 - R^2 = 0,  i.e.  z = alpha |d|^2 + beta,
     *     alpha = 1 / (2c),  beta = (c^2 - R^2) / (2c),
     * and a plane at the height beta (c infinite) has alpha = 0. The fit
     * solves this for alpha and beta by least squares over the vertices,
     * which is exact when they lie on such a sphere or plane; then
     *     1/R = -2 alpha / sqrt(1 - 4 alpha beta)
     * with the sign of a convex surface (centre at c < 0, inside the body)
     * positive. The Hertz references compare it with their radii
     * (References::check_radii()).
     */
    template <int dim>
    AxialSphereFit
    fit_axial_sphere(const std::vector<Face<dim>> &faces,
                     const dealii::Point<dim>     &x0,
                     const dealii::Tensor<1, dim> &m,
                     const double                  reach);
  } // namespace contact_surface
} // namespace dpana

#endif
