// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_annulus_h
#define dpana_geometry_annulus_h

#include <dpana/geometry/curved_shape.h>

#include <deal.II/base/point.h>

namespace dpana
{
  namespace geometry
  {
    /**
     * The lower half (or the lower right quarter) of the annulus of centre
     * Centre and radii Inner radius < Outer radius: the types `half annulus`
     * (the cavity of the cylinder-in-a-cavity scenes) and `quarter annulus`
     * (the thick cylinder of Lamé), 2D only, `subsection Half annulus` and
     * `subsection Quarter annulus`.
     *
     * The coarse mesh is a polar grid of quadrilaterals: n_theta cells along
     * the angle, at least 4 on the half and 2 on the quarter and about one
     * per angle ln(Ro/Ri), and n_r = round(ln(Ro/Ri) / dtheta) layers with
     * radii growing geometrically, so that all cells are similar with an
     * aspect ratio close to one. A polar manifold everywhere keeps the
     * refined vertices on the circles; CurvedShape makes the simplices. The
     * contact refinements act around the lowest point Centre - (0, Ri) of the
     * inner circle.
     *
     * Boundary names: `inner` (id 0), `outer` (1), and the straight edges
     * on y = Centre_y, `left` (2) and `right` (3) of the half annulus; the
     * quarter annulus (x >= Centre_x) has `x_axis` (2) on y = Centre_y and
     * `y_axis` (3) on x = Centre_x.
     */
    template <int dim>
    class Annulus : public CurvedShape<dim>
    {
    public:
      /**
       * The half annulus, or the quarter annulus if @p quarter. Only
       * dim = 2 is implemented.
       */
      explicit Annulus(const bool quarter);

      /**
       * Declares Centre, Inner radius, Outer radius and the contact
       * refinement entries.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path) override;

      std::map<std::string, dealii::types::boundary_id>
      boundary_names() const override;

      /**
       * "Ri = 120, Ro = 360, centre (0, 120)" and the contact refinements
       * if any.
       */
      std::string
      description() const override;

    private:
      double inner_radius;
      double outer_radius;

      void
      make_quadrilaterals(dealii::Triangulation<2> &quads) const override;

      /**
       * The lowest point of the inner circle.
       */
      dealii::Point<2>
      contact_point() const override;

      std::string
      boundary_name(const dealii::Point<dim> &x) const override;
    };
  } // namespace geometry
} // namespace dpana

#endif
