// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_scene_contact_summary_h
#define dpana_scene_contact_summary_h

#include <dpana/contact/problem.h>
#include <dpana/contact/solver.h>
#include <dpana/contact_surface/contact_surface.h>
#include <dpana/scene/pressure_estimators.h>

#include <deal.II/base/point.h>

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace dpana
{
  namespace scene
  {
    /**
     * A zone of equal contact status: in 2D a run of neighbouring elements
     * along s, in 3D the bounding box in (s, t) of all elements of the
     * status.
     */
    struct Zone
    {
      contact::ContactStatus status;
      double                 from, to;             // along s
      double                 t_from = 0, t_to = 0; // 3D: along t
      unsigned int           n_elements = 0;
    };

    /**
     * The comparison of a run with one of its references: the kind
     * ("uniform", "hertz", "published table", "comparison file"), the log
     * line, and the named numbers (reference values and relative errors)
     * that summary.json lists.
     */
    struct Comparison
    {
      std::string                                 type;
      std::string                                 text;
      std::vector<std::pair<std::string, double>> values;
      std::string                                 file; // a comparison file
    };

    /**
     * What a contact run reports of its answer besides the tractions: the
     * solver's result, the contact half width and maximum pressure, the
     * zones, the per-element residual, and the comparisons with the
     * references.
     */
    struct ContactSummary
    {
      contact::SolverResult result;
      unsigned int          n_elements = 0;
      // Outer edge of the last element in contact, measured along s from the
      // candidate centre, and the centroid of that element.
      double half_width          = 0;
      double half_width_centroid = 0;
      // Tangential size of the element that ends the contact zone: with
      // piecewise constant tractions, a is known to this size.
      double            half_width_element     = 0;
      double            max_pressure           = 0; // max(-N)
      double            normal_resultant       = 0; // sum(-N area)
      bool              candidate_edge_warning = false;
      double            asymmetry              = 0; // of A, before symmetrising
      std::vector<Zone> zones;
      // 2D: the half width to less than one element, the resultant and
      // the centroid of the pressure.
      PressureEstimates       estimates;
      std::vector<double>     element_residual; // ||F_j||, MPa
      std::vector<Comparison> comparisons;
    };

    /**
     * Fills @p summary (whose result is set) from the contact surface of
     * Body 1 and the contact problem: the per-element natural-map residual,
     * the half width measured from @p centre, the maximum pressure, the
     * normal resultant, the zones and, in 2D, the pressure estimates
     * (mirrored about the centre if @p symmetric_about_centre and the
     * surface lies on one side of it).
     */
    template <int dim>
    void
    summarise(const contact_surface::ContactSurface<dim> &surface,
              const contact::ContactProblem              &problem,
              const dealii::Point<dim>                   &centre,
              ContactSummary                             &summary,
              const bool symmetric_about_centre = true);

    /**
     * The warning of a contact zone that reaches an edge of the candidate
     * surface beyond which the body goes on towards the obstacle (the log's
     * WARNING line and an entry of summary.json's warnings).
     */
    std::string
    candidate_edge_warning();

    /**
     * The lines of the log: half width, pressure, zones, the warning of a
     * contact zone that reaches the edge of the candidate surface, and the
     * comparisons.
     */
    void
    print(const ContactSummary &summary,
          const unsigned int    dim,
          std::ostream         &out);
  } // namespace scene
} // namespace dpana

#endif
