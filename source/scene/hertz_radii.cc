// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The radii of the Hertz references against the mesh: a radius that is not
// the body's compares the run with the contact of other bodies, which the
// relative errors alone do not show (References::check_radii()).
#include <dpana/contact_surface/axial_sphere_fit.h>
#include <dpana/contact_surface/format_point.h>
#include <dpana/scene/references.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace dpana
{
  namespace scene
  {
    namespace
    {
      // 1/R of a Reference radius: 0 for a flat surface (R = 0).
      double
      curvature_of(const double radius)
      {
        return radius != 0 ? 1 / radius : 0.;
      }



      // How the warning names a fitted curvature: as a radius, or flat.
      std::string
      describe(const double curvature, const double scale)
      {
        std::ostringstream s;
        if (std::abs(curvature) <= 1e-6 * scale)
          s << "is flat";
        else
          s << "has the radius " << std::setprecision(6)
            << (curvature > 0 ? "" : "-") << 1 / std::abs(curvature)
            << (curvature > 0 ? "" : " (concave)");
        return s.str();
      }
    } // namespace



    template <int dim>
    void
    References<dim>::check_radii(
      const std::vector<std::unique_ptr<contact_surface::ContactSurface<dim>>>
        &surfaces) const
    {
      if ((type != "hertz" && type != "hertz sphere") || surfaces.empty())
        return;
      const auto                  &first = *surfaces[0];
      const dealii::Point<dim>     x0    = first.options().region_centre;
      const dealii::Tensor<1, dim> n     = first.surface_normal();
      const double                 scale =
        std::abs(curvature_of(radius_1) + curvature_of(radius_2));
      const std::string where = " about Candidate centre " +
                                contact_surface::internal::format_point(x0);
      if (surfaces.size() == 1 && radius_2 != 0)
        {
          std::ostringstream s;
          s << "Contact / Reference / Radius 2 = " << radius_2
            << ", but the obstacle of this run is the rigid plane, which is "
               "flat: the Hertz values compared are those of another geometry";
          warn(s.str());
        }
      // Body 2's faces are compared within the reach of Body 1's
      // candidate faces, where the contact is.
      double reach = 0;
      for (const auto &face : first.get_faces())
        for (const auto &x : face.points)
          reach = std::max(reach, x.distance(x0));
      for (unsigned int b = 0; b < surfaces.size() && b < 2; ++b)
        {
          const auto fit = contact_surface::fit_axial_sphere(
            surfaces[b]->get_faces(), x0, b == 0 ? n : -n, reach);
          const double given = curvature_of(b == 0 ? radius_1 : radius_2);
          if (!fit.available || std::abs(fit.curvature - given) <= 1e-2 * scale)
            continue;
          std::ostringstream s;
          s << "Contact / Reference / Radius " << b + 1 << " = "
            << (b == 0 ? radius_1 : radius_2) << ", but the surface of Body "
            << b + 1 << where << " " << describe(fit.curvature, scale)
            << ": the Hertz values compared are those of another geometry";
          if (type == "hertz sphere")
            s << ", and the approach is not measured at the spheres' centres";
          warn(s.str());
        }
    }



    template void
    References<2>::check_radii(
      const std::vector<std::unique_ptr<contact_surface::ContactSurface<2>>> &)
      const;
    template void
    References<3>::check_radii(
      const std::vector<std::unique_ptr<contact_surface::ContactSurface<3>>> &)
      const;
  } // namespace scene
} // namespace dpana
