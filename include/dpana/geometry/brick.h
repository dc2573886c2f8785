// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_brick_h
#define dpana_geometry_brick_h

#include <dpana/geometry/shape.h>

#include <deal.II/base/point.h>

#include <vector>

namespace dpana
{
  namespace geometry
  {
    /**
     * The axis-parallel brick of the types `rectangle` (2D, `subsection
     * Rectangle`) and `box` (3D, `subsection Box`) between a lower and an
     * upper corner, with `Subdivisions` cell layers per direction. Each
     * rectangle of the grid is split into 2 triangles, each brick into 5
     * tetrahedra (GridGenerator::subdivided_hyper_rectangle_with_simplices,
     * without colorize, which throws for simplices in deal.II 9.4), and the
     * global refinements act on the simplices. In 2D, `Diagonals =
     * alternating` splits the rectangles along diagonals that alternate as
     * on a checkerboard instead, a mesh mirror-symmetric about every grid
     * line: a half model and its mirror image form one checkerboard,
     * without a seam of the pattern at the axis.
     *
     * The optional grading is a vertex transformation acting on each
     * coordinate separately: with the grading centre $c$, the corners
     * $l < u$ and the exponent $p$ of a direction,
     * @f[
     *   x \mapsto c + (u - c)\left(\frac{x - c}{u - c}\right)^p \quad (x > c),
     *   \qquad
     *   x \mapsto c - (c - l)\left(\frac{c - x}{c - l}\right)^p \quad (x < c).
     * @f]
     * It is monotone and fixes $l$, $c$ and $u$, so it maps the brick onto
     * itself and every boundary face stays on its side. The local cell size
     * is multiplied by the derivative $p\,t^{p-1}$, $t$ the relative distance
     * from $c$, which is small near $c$: with n layers between the plane and
     * a corner, the layer next to the plane becomes n^(p-1) times thinner.
     *
     * Boundary names and ids: `left`/`right` (x = min/max, ids 0/1),
     * `bottom`/`top` (y, 2/3), `front`/`back` (z, 4/5), set from the face
     * centres after the global refinements. With a Load patch half width
     * w > 0, the faces of the top whose centres lie within w of the Load
     * patch centre in every horizontal direction (x, and z in 3D) form the
     * boundary `load patch` (id 6) instead: a pressure on part of the top,
     * e.g. a layer pressed onto a foundation over a square.
     */
    template <int dim>
    class Brick : public Shape<dim>
    {
    public:
      Brick();

      /**
       * Declares Lower corner, Upper corner, Subdivisions, Grading centre,
       * Grading exponents, (in 2D) Diagonals, Load patch centre and Load
       * patch half width.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path) override;

      void
      create_triangulation(
        dealii::Triangulation<dim> &tria,
        const unsigned int          n_global_refinements) const override;

      std::map<std::string, dealii::types::boundary_id>
      boundary_names() const override;

      /**
       * "40 x 40, 16 x 16 subdivisions" (", graded" if graded).
       */
      std::string
      description() const override;

      /**
       * 2 triangles per rectangle (5 tetrahedra per brick) of the
       * Subdivisions, 2^dim children per refinement.
       */
      std::pair<double, std::string>
      estimated_size(const unsigned int n_global_refinements) const override;

    private:
      std::string               parameter;
      dealii::Point<dim>        lower_corner;
      dealii::Point<dim>        upper_corner;
      std::vector<unsigned int> subdivisions;
      dealii::Point<dim>        grading_centre;
      std::vector<double>       grading_exponents;
      dealii::Point<dim>        patch_centre;
      double                    patch_half_width = 0.;
      // Diagonals = alternating (2D only).
      bool alternating = false;

      bool
      graded() const;

      /**
       * The 2D grid split along alternating diagonals (Diagonals =
       * alternating).
       */
      void
      create_alternating_triangles(dealii::Triangulation<dim> &tria) const;

      void
      apply_grading(dealii::Triangulation<dim> &tria) const;

      void
      set_boundary_ids(dealii::Triangulation<dim> &tria) const;

      /**
       * Whether a face centre on the top lies in the load patch.
       */
      bool
      in_load_patch(const dealii::Point<dim> &x) const;
    };
  } // namespace geometry
} // namespace dpana

#endif
