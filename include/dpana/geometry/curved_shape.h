// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_curved_shape_h
#define dpana_geometry_curved_shape_h

#include <dpana/geometry/shape.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <string>
#include <utility>
#include <vector>

namespace dpana
{
  namespace geometry
  {
    /**
     * The local refinement of the curved shapes (discs, half cylinder,
     * annuli) around the point where they touch the other body: the entries
     * "Contact refinements" and "Contact refinement radius" of their
     * subsections.
     */
    struct ContactRefinement
    {
      unsigned int n_refinements = 0;
      double       radius        = 0.25;

      /**
       * Declares the two entries; @p point names the point refined around in
       * the help text, e.g. "the lowest point of the circle".
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         const std::string        &point);

      /**
       * Reads them; the radius must be positive when there are refinements
       * (dpana::InputError starting with @p path otherwise).
       */
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /**
       * ", 3 contact refinements within 5", or nothing without refinements.
       */
      std::string
      description() const;
    };



    /**
     * The common part of the curved shapes (Disc, Annulus): the simplex mesh
     * made from a coarse quadrilateral mesh of the cross-section, whose
     * manifolds describe the circles, and the contact refinements around
     * the point where the shape touches the other body.
     *
     * The curved shapes are first meshed with quadrilaterals, because
     * quadrilaterals refine along the manifolds of their coarse cells: every
     * vertex created on the curved boundary lies exactly on the circle, and
     * the interior vertices follow a transfinite interpolation of the
     * boundary, which keeps the cells well shaped. The global refinements
     * and the contact refinements (of the cells that intersect the disc of
     * the refinement radius around contact_point()) are therefore applied
     * to the quadrilaterals. Each new vertex is placed by the closed-form
     * map of its coarse cell at its dyadic reference point, the position
     * deal.II's refinement along the manifolds gives (to rounding) without
     * its Newton iteration per vertex (internal::RefinedQuadrilaterals).
     *
     * The local refinements leave hanging nodes, which
     * GridGenerator::convert_hypercube_to_simplex_mesh does not accept
     * (deal.II 9.4 throws ExcNotImplemented for a mesh with hanging nodes;
     * splitting each cell on its own could not give a conforming mesh
     * anyway). The quadrilaterals are therefore split into triangles here:
     * each active quadrilateral becomes a fan of triangles around its
     * centre, one triangle per edge of its boundary polygon, where the
     * boundary polygon of a cell includes the midpoint of every edge whose
     * neighbour is refined. Both sides of such an edge then use the midpoint
     * as a vertex and the triangle mesh is conforming: a quadrilateral gives
     * 4 triangles plus one per hanging node.
     *
     * In 3D the triangles are extruded along z through the planes
     * z_planes() into prisms, and each prism is split into three
     * tetrahedra. Splitting every quadrilateral side of a prism along the
     * diagonal that joins the lower vertex of smaller index to the upper
     * vertex of larger index is a rule both prisms sharing that side apply
     * identically, so the tetrahedral mesh is conforming as well.
     *
     * Every boundary face then gets the id of boundary_name() of its
     * centre.
     */
    template <int dim>
    class CurvedShape : public Shape<dim>
    {
    public:
      void
      create_triangulation(
        dealii::Triangulation<dim> &tria,
        const unsigned int          n_global_refinements) const override;

      /**
       * 2 triangles per quadrilateral of the coarse mesh, 4 children per
       * refinement; in 3D times 3 tetrahedra per prism of each layer.
       */
      std::pair<double, std::string>
      estimated_size(const unsigned int n_global_refinements) const override;

    protected:
      /**
       * The half shape, or the quarter (x >= Centre_x) if @p quarter.
       */
      explicit CurvedShape(const bool quarter);

      /**
       * The coarse quadrilateral mesh of the cross-section, with its
       * manifolds.
       */
      virtual void
      make_quadrilaterals(dealii::Triangulation<2> &quads) const = 0;

      /**
       * The point the contact refinements refine around.
       */
      virtual dealii::Point<2>
      contact_point() const = 0;

      /**
       * Further zones refined after the contact refinements, each a point
       * and its refinement (e.g. the load patch of Circle); none by default.
       */
      virtual std::vector<std::pair<dealii::Point<2>, ContactRefinement>>
      further_refinements() const;

      /**
       * The planes z_0 < ... < z_n of the extrusion in 3D (not called in
       * 2D).
       */
      virtual std::vector<double>
      z_planes(const unsigned int n_global_refinements) const;

      /**
       * The name of the boundary a face with centre @p x lies on.
       */
      virtual std::string
      boundary_name(const dealii::Point<dim> &x) const = 0;

      const bool         quarter;
      dealii::Point<dim> centre;
      ContactRefinement  refinement;
    };
  } // namespace geometry
} // namespace dpana

#endif
