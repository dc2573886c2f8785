// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_contact_surface_format_point_h
#define dpana_contact_surface_format_point_h

#include <deal.II/base/point.h>

#include <string>

namespace dpana
{
  namespace contact_surface
  {
    namespace internal
    {
      /**
       * A point as "(x, y)" or "(x, y, z)" with six significant digits: how
       * the error messages of the contact surface name a face (by its
       * centroid).
       */
      template <int dim>
      std::string
      format_point(const dealii::Point<dim> &p);
    } // namespace internal
  }   // namespace contact_surface
} // namespace dpana

#endif
