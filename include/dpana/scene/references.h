// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_scene_references_h
#define dpana_scene_references_h

#include <dpana/body/body.h>
#include <dpana/contact_surface/contact_surface.h>
#include <dpana/scene/contact_summary.h>

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  namespace scene
  {
    /**
     * The plane Hertz solution of two cylinders pressed together.
     */
    struct HertzLineContact
    {
      double half_width;   // a (mm)
      double max_pressure; // N_max = -N at the centre (MPa)
    };

    /**
     * Two cylinders of radii R1 = @p radius_1 and R2 = @p radius_2 (0: a
     * flat, < 0: a cavity of radius |R2| > R1) pressed together by the load
     * P = @p load per unit length (N/mm) touch on a strip of half width
     *     a = sqrt(4 P k R),   1/R = 1/R1 + 1/R2,   N_max = 2 P / (pi a),
     * where @p compliance is k = k1 + k2, k_i = (1 - nu_i^2) / (pi E_i) in
     * plane strain, 1 / (pi E_i) in plane stress, 0 for a rigid body (Hertz
     * 1882; Johnson, Contact Mechanics, 1985, section 4.2).
     */
    HertzLineContact
    hertz_line_contact(const double load,
                       const double compliance,
                       const double radius_1,
                       const double radius_2);

    /**
     * The references a contact run is compared with, `subsection Contact /
     * subsection Reference`:
     *
     * - `uniform`: the exact solution of a problem whose tractions are
     *   uniform (the frictionless receding block: N = N_ref, T = 0 on every
     *   element);
     * - `hertz`: the plane strain Hertz solution of two cylinders of radii
     *   R1, R2 pressed together by a load P per unit length (Johnson,
     *   Contact Mechanics, 1985, section 4.2):
     *       a = sqrt(4 P (k1 + k2) R),   k_i = (1 - nu_i^2) / (pi E_i),
     *       1/R = 1/R1 + 1/R2,           N_max = 2 P / (pi a),
     *   with R2 = 0 a flat and R2 < 0 a cavity of radius |R2|; in plane stress
     *   the factor 1 - nu^2 drops. With it, the half width and maximum
     *   pressure of a published table (the reference formulation's);
     * - a comparison file: a contact.csv of another run (columns s, N, T),
     *   e.g. the plane solution a 3D run should reproduce on its symmetry
     *   plane, interpolated linearly in s.
     */
    template <int dim>
    class References
    {
    public:
      /**
       * Declares `subsection Reference` inside the current subsection.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * Reads the subsection and the comparison file, so that a bad file
       * stops the run before anything is computed. A comparison file that
       * does not exist yet (the run that writes it has not been made) only
       * disables that comparison, with a warning.
       */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /**
       * The comparisons of a run: @p bodies give the elastic constants of
       * the Hertz formulas, @p surface the element positions, @p summary
       * the tractions and the measured half width and pressure.
       */
      std::vector<Comparison>
      compare(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
              const contact_surface::ContactSurface<dim>    &surface,
              const ContactSummary                          &summary) const;

    private:
      std::string type                    = "none";
      double      uniform_normal_traction = 0;
      double      hertz_load = 0, radius_1 = 0, radius_2 = 0;
      double      table_half_width = 0, table_max_pressure = 0;
      std::string comparison_file;
      // Rows (s, N, T) of the comparison file, sorted by s; empty if none.
      std::vector<std::array<double, 3>> comparison_table;

      void
      load_comparison_file();

      Comparison
      uniform(const ContactSummary &summary) const;

      std::vector<Comparison>
      hertz(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
            const ContactSummary                          &summary) const;

      Comparison
      comparison_run(const contact_surface::ContactSurface<dim> &surface,
                     const ContactSummary                       &summary) const;
    };
  } // namespace scene
} // namespace dpana

#endif
