// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_disc_h
#define dpana_geometry_disc_h

#include <dpana/geometry/curved_shape.h>

#include <deal.II/base/point.h>

namespace dpana
{
  namespace geometry
  {
    /**
     * The coarse quadrilateral mesh of a disc of centre @p c and radius @p r
     * described in Disc: the lower half (6 cells), or its part x >= c_x if
     * @p quarter (3 cells); with @p whole also the mirror image above
     * y = c_y (the whole disc, 12 cells, or its half x >= c_x, 6 cells), so
     * that the lowest and the highest point of the circle are vertices.
     * Manifold 0 is the polar manifold of the circle (its faces), manifold
     * 1 a transfinite interpolation (the cells).
     */
    void
    make_disc_quadrilaterals(dealii::Triangulation<2> &quads,
                             const dealii::Point<2>    c,
                             const double              r,
                             const bool                quarter,
                             const bool                whole);



    /**
     * The lower half of a disc, a D-shaped body that touches the ground at
     * its lowest point Centre - (0, Radius) and is loaded on its flat side
     * (a variant of the cylinder of the Hertz scenes, stiffer than the
     * circular body of Circle; see doc/geometry.md): the
     * types `half disc` and `quarter disc` (2D, `subsection Half disc`,
     * `subsection Quarter disc`) and `half cylinder` (3D, `subsection Half
     * cylinder`), the half disc extruded along z from the third coordinate
     * of Centre over the Length.
     *
     * The coarse mesh of the half disc has 6 quadrilaterals (the quarter
     * disc, the part x >= Centre_x, 3): two squares of side R/2 around the
     * centre of the flat side and four cells between them and the circle,
     * so that the lowest point of the circle is a vertex. The curved
     * boundary follows a polar manifold and the cells a transfinite
     * interpolation, so that the refinements put the new boundary vertices
     * on the circle; CurvedShape makes the simplices.
     *
     * Boundary names: the flat side y = Centre_y is `top` (id 0), the arc
     * `curved` (1); the quarter disc's edge on x = Centre_x is `axis` (2);
     * the half cylinder's end faces z = Centre_z and z = Centre_z + Length
     * are `front` (2) and `back` (3).
     */
    template <int dim>
    class Disc : public CurvedShape<dim>
    {
    public:
      /**
       * The half disc (half cylinder in 3D), or the quarter disc if
       * @p quarter (2D only).
       */
      explicit Disc(const bool quarter);

      /**
       * Declares Centre, Radius, the contact refinement entries and, in 3D,
       * Length and Axial subdivisions.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path) override;

      std::map<std::string, dealii::types::boundary_id>
      boundary_names() const override;

      /**
       * "R = 40, centre (0, 40)", with ", L = 8 (2 layers)" in 3D and the
       * contact refinements if any.
       */
      std::string
      description() const override;

    protected:
      /**
       * The shape of Disc(quarter) and, with @p whole, its mirror image
       * above the centre too (the circular body of Circle).
       */
      Disc(const bool quarter, const bool whole);

      const bool   whole;
      double       radius;
      double       length;
      unsigned int n_axial_subdivisions;

      void
      make_quadrilaterals(dealii::Triangulation<2> &quads) const override;

      /**
       * The lowest point of the circle.
       */
      dealii::Point<2>
      contact_point() const override;

      /**
       * Axial subdivisions layers of equal thickness, twice as many after
       * every global refinement.
       */
      std::vector<double>
      z_planes(const unsigned int n_global_refinements) const override;

      std::string
      boundary_name(const dealii::Point<dim> &x) const override;
    };
  } // namespace geometry
} // namespace dpana

#endif
