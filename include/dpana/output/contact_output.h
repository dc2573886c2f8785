// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_output_contact_output_h
#define dpana_output_contact_output_h

#include <dpana/contact_surface/contact_surface.h>
#include <dpana/scene/contact_summary.h>

#include <string>

namespace dpana
{
  namespace output
  {
    /**
     * Writes contact.csv: one row per contact element of Body 1, sorted
     * along the surface coordinate s (then t), with the columns
     *   element, s, (t,) x, y, (z,) area, gap, N, T (T1, T2), u_N, u_T
     *   (u_T1, u_T2), status, residual
     * (tractions in MPa, relative displacements in mm, residual: the
     * element's natural-map residual in MPa).
     */
    template <int dim>
    void
    write_contact_csv(const contact_surface::ContactSurface<dim> &surface,
                      const scene::ContactSummary                &summary,
                      const std::string                          &filename);

    /**
     * Writes the contact surface of Body 1 as a VTU file (deal.II DataOut on
     * a mesh of its faces: lines in 2D, triangles in 3D), with the values of
     * each face's contact element: element, N, T (T1, T2), u_N, u_T (u_T1,
     * u_T2), gap, status (0 separated, 1 stick, 2 slip), residual, and the
     * traction vector N n + T tau in global coordinates.
     */
    template <int dim>
    void
    write_contact_surface_vtu(
      const contact_surface::ContactSurface<dim> &surface,
      const scene::ContactSummary                &summary,
      const std::string                          &filename);

    /**
     * Draws @p png from @p csv with the plot script of this build
     * (scripts/plot_contact.py, its path set by CMake) and the system's
     * python3. Returns a warning text if no plot could be drawn, empty
     * otherwise.
     */
    std::string
    plot_contact(const std::string &csv, const std::string &png);
  } // namespace output
} // namespace dpana

#endif
