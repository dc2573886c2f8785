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
     * The Hertz solution of two spheres pressed together (the 3D Hertz
     * point contact).
     */
    struct HertzPointContact
    {
      double radius;       // contact radius a (mm)
      double max_pressure; // p0 = -N at the centre (MPa)
      double approach;     // delta, approach of distant points (mm)
    };

    /**
     * Two spheres of radii R1 = @p radius_1 and R2 = @p radius_2 (0: a
     * plane, < 0: a spherical seat of radius |R2| > R1) pressed together by
     * the force P = @p load (N) touch on a disc of radius a, under the
     * pressure p(r) = p0 sqrt(1 - r^2 / a^2), with
     *     a = (3 P R / (4 E*))^(1/3),   1/R = 1/R1 + 1/R2,
     *     p0 = 3 P / (2 pi a^2),        delta = a^2 / R,
     * where @p compliance is 1/E* = (1 - nu1^2) / E1 + (1 - nu2^2) / E2
     * (0 for a rigid body) and delta is the approach of points of the two
     * bodies far from the contact (Hertz 1882; Johnson, Contact Mechanics,
     * 1985, section 4.2). The formulas assume a << R (each body a half-space
     * near the contact, the gap r^2 / (2R) quadratic).
     */
    HertzPointContact
    hertz_point_contact(const double load,
                        const double compliance,
                        const double radius_1,
                        const double radius_2);

    /**
     * One piece of a pressure distribution on a plane: its area A, the
     * integral of r^2 over it (r: the distance from the axis of the contact)
     * and its constant pressure p.
     */
    struct PressurePiece
    {
      double area;
      double r2_integral;
      double pressure;
    };

    /**
     * The moment estimate of the contact radius of an axisymmetric Hertz
     * pressure p0 sqrt(1 - r^2 / a^2) on a disc: the pressure integrates to
     * 2 pi p0 a^2 / 3 and its second moment to 4 pi p0 a^4 / 15, whose ratio
     * is 2 a^2 / 5, so that
     *     a_m = sqrt(5/2 * int r^2 p dA / int p dA)
     * recovers a exactly from the exact profile, from every sector of the
     * disc (a quarter model) alike. Applied to the piecewise constant
     * tractions of a run, the sums over @p pieces replace the integrals.
     * Returns 0 if the pressure integrates to zero.
     */
    double
    moment_contact_radius(const std::vector<PressurePiece> &pieces);

    /**
     * The elliptic fit of an axisymmetric pressure: whether it exists, the
     * fitted peak pressure p0 and the fitted contact radius a_f.
     */
    struct EllipticFit
    {
      bool   available    = false;
      double max_pressure = 0;
      double radius       = 0;
    };

    /**
     * The elliptic fit of @p pieces, the 3D counterpart of the 2D fit of
     * estimate_pressure_profile(): the least squares fit, weighted by the
     * areas, of the Hertz law squared, p^2 = p0^2 (1 - r^2 / a_f^2) =
     * A + C r^2, to the squared pressures of the pressed pieces (p above
     * 1e-9 of the largest), each taken at its mean r^2 (r2_integral /
     * area); then p0 = sqrt(A) and a_f = sqrt(-A / C). Unlike the largest
     * element pressure, which samples the peak with one element, p0 is
     * fitted to every pressed element. It needs two pressed pieces at
     * different radii, C < 0 and A > 0; otherwise it is not available.
     */
    EllipticFit
    elliptic_fit(const std::vector<PressurePiece> &pieces);

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
     * - `hertz sphere` (3D): the Hertz solution of two spheres,
     *   hertz_point_contact(), with the load P of the whole body and 1/E* =
     *   sum (1 - nu_i^2) / E_i. The axis of the contact is the line through
     *   `Candidate centre` along the contact normal; the run's contact
     *   radius is measured as the outer edge, in r, of the elements in
     *   contact (known to one element) and by moment_contact_radius(); its
     *   resultant of -N divided by `Model fraction` (1/4 for a quarter
     *   model) is compared with P; the approach measured by
     *   measure_approach() is compared with delta = a^2 / R and with
     *   delta - sum_i u_B(R_i), where u_B(R_i) is the displacement at the
     *   depth R_i of the sphere's centre under the Hertz load in Hertz's own
     *   half-space model (boussinesq_axial_displacement()): the centre is not
     *   a distant point of a half-space;
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
       * For Type = hertz sphere, measures the approach delta of the bodies
       * (body_approach() of scene/approach.h) into @p summary.estimates:
       * the centre of each sphere, at the distance R_i from the contact
       * point x0 (`Candidate centre`) along the contact normal, relative to
       * x0 on its surface, summed over the bodies; a rigid plane or seat
       * adds nothing. The bodies must hold their displacements. A second
       * body that is no sphere (Radius 2 <= 0) has no centre: then nothing
       * is measured; nor, with a warning, when a centre or the contact point
       * lies outside the mesh of its body (a mesh of a part of the sphere). The
       * plane Hertz solution has no approach (that of an infinite body in plane
       * strain is unbounded), so 2D measures none.
       */
      void
      measure_approach(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
                       const contact_surface::ContactSurface<dim>    &surface,
                       ContactSummary &summary) const;

      /**
       * For the Hertz types, warns when a radius does not match the mesh:
       * when the sphere (circle) fitted to a body's surface about the
       * contact point x0 (`Candidate centre`), its centre on the axis
       * through x0 along the contact normal (fit_axial_sphere() of
       * contact_surface/axial_sphere_fit.h), has a curvature 1/R that
       * differs from that of Radius 1 (Body 1: its candidate faces) or
       * Radius 2 (Body 2: its faces paired with them; a rigid plane is
       * flat) by more than 1 % of the Hertz curvature 1/R1 + 1/R2. The
       * Hertz values would be those of another geometry, and the approach
       * would be measured at points that are not the spheres' centres.
       * @p surfaces are the contact surfaces of the bodies, Body 1's first.
       */
      void
      check_radii(
        const std::vector<std::unique_ptr<contact_surface::ContactSurface<dim>>>
          &surfaces) const;

      /**
       * The comparisons of a run: @p bodies give the elastic constants of
       * the Hertz formulas, @p surface the element positions, @p summary
       * the tractions and the measured half width and pressure.
       */
      std::vector<Comparison>
      compare(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
              const contact_surface::ContactSurface<dim>    &surface,
              const ContactSummary                          &summary) const;

      /**
       * The warnings of the references so far (a comparison file not
       * found, a candidate centre off the sphere's axis, an approach not
       * measured), one line each: the log has them as "dpana: warning:"
       * lines, summary.json in its `warnings`.
       */
      const std::vector<std::string> &
      warnings() const
      {
        return warnings_;
      }

    private:
      std::string type                    = "none";
      double      uniform_normal_traction = 0;
      double      hertz_load = 0, radius_1 = 0, radius_2 = 0;
      double      table_half_width = 0, table_max_pressure = 0;
      double      model_fraction = 1;
      std::string comparison_file;
      // Rows (s, N, T) of the comparison file, sorted by s; empty if none.
      std::vector<std::array<double, 3>> comparison_table;
      mutable std::vector<std::string>   warnings_;

      // Prints @p text (empty: none) as a "dpana: warning:" line (on rank
      // 0) and keeps it for warnings(), once.
      void
      warn(const std::string &text) const;

      // Warns when the load P the contact carries (@p measured says how it
      // was found) is not the Hertz load.
      void
      check_hertz_load(const double P, const std::string &measured) const;

      void
      load_comparison_file();

      Comparison
      uniform(const ContactSummary &summary) const;

      std::vector<Comparison>
      hertz(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
            const ContactSummary                          &summary) const;

      Comparison
      hertz_sphere(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
                   const contact_surface::ContactSurface<dim>    &surface,
                   const ContactSummary &summary) const;

      Comparison
      comparison_run(const contact_surface::ContactSurface<dim> &surface,
                     const ContactSummary                       &summary) const;
    };
  } // namespace scene
} // namespace dpana

#endif
