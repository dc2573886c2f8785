// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_circle_h
#define dpana_geometry_circle_h

#include <dpana/geometry/disc.h>

#include <deal.II/base/point.h>

namespace dpana
{
  namespace geometry
  {
    /**
     * The circular body of the Hertz scenes: a whole disc of radius R (the
     * cross-section of a full cylinder), type `disc`, or its half model
     * x >= Centre_x, type `right half disc` (2D only; `subsection Disc`,
     * `subsection Right half disc`). It touches the other body at its
     * lowest point Centre - (0, R) and is loaded along its vertical
     * diameter at the far end, the highest point Centre + (0, R): by a
     * concentrated force there (Loads / Concentrated forces), or by a
     * pressure or traction on the `load patch`, the faces of the upper arc
     * whose centres lie within the Load patch half width w of the axis
     * x = Centre_x.
     *
     * A point force P on the diameter of a disc puts a singular stress
     * field at the load point, which decays over the radius (the disc
     * compressed along a diameter: Timoshenko and Goodier, Theory of
     * Elasticity, 1970); at the far end of the diameter, 2R away, the body
     * is loaded by the contact pressure only, and the pressure there tends
     * to the Hertz pressure of a cylinder as a / R -> 0 (Hertz theory takes
     * each body near the contact as a half-space; Johnson, Contact
     * Mechanics, 1985, chapter 4).
     *
     * The coarse mesh (make_disc_quadrilaterals()) has 12 quadrilaterals
     * (the half model 6): four squares of side R/2 around the centre and
     * eight cells between them and the circle, so that the lowest and the
     * highest points of the circle are vertices. The quadrilaterals are
     * refined towards the contact point (Contact refinements) and towards
     * the load point (Load patch refinements, within w), then split into
     * triangles by CurvedShape. The class is the Disc of the whole circle
     * (its centre, radius and contact refinements), with the load patch.
     *
     * Boundary names: the arc `curved` (id 1), the half model's edge on
     * x = Centre_x `axis` (2), and, if w > 0, `load patch` (3).
     */
    template <int dim>
    class Circle : public Disc<dim>
    {
    public:
      /**
       * The whole disc, or its half x >= Centre_x if @p half.
       */
      explicit Circle(const bool half);

      /**
       * Declares the entries of the half disc (Disc) and the load patch
       * entries.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path) override;

      std::map<std::string, dealii::types::boundary_id>
      boundary_names() const override;

      /**
       * That of the Disc, with the load patch if any.
       */
      std::string
      description() const override;

    private:
      double            patch_half_width;
      ContactRefinement patch_refinement;

      /**
       * The highest point of the circle, refined within the load patch half
       * width.
       */
      std::vector<std::pair<dealii::Point<2>, ContactRefinement>>
      further_refinements() const override;

      std::string
      boundary_name(const dealii::Point<dim> &x) const override;
    };
  } // namespace geometry
} // namespace dpana

#endif
