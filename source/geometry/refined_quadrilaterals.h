// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_refined_quadrilaterals_h
#define dpana_geometry_refined_quadrilaterals_h

#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <array>
#include <vector>

namespace dpana
{
  namespace geometry
  {
    namespace internal
    {
      /**
       * Flags for refinement the active cells of @p tria that intersect the
       * disc of radius @p rho around @p p (a cell's centre, the mean of its
       * vertices, closer than rho plus half its diameter).
       */
      void
      flag_cells_near(dealii::Triangulation<2> &tria,
                      const dealii::Point<2>   &p,
                      const double              rho);



      /**
       * A quadrilateral mesh refined as deal.II refines it along the
       * manifolds of its coarse cells, with every vertex placed by a closed
       * formula instead of by the manifolds.
       *
       * deal.II places the vertex it creates at a refinement by pulling the
       * neighbouring vertices back to the reference square of their coarse
       * cell, averaging there and pushing the average forward. Every vertex
       * of the refined mesh is therefore the image F_K(u, v) of a dyadic
       * point (u, v) of the unit square under the map F_K of its coarse
       * cell K. For the transfinite interpolation of a disc that pull-back
       * is a Newton iteration per vertex, and it took half of the assembly
       * phase of a circular body of 3·10⁵ unknowns.
       *
       * Here the mesh is refined without manifolds, every cell keeps its
       * square [u0, u0 + l] x [v0, v0 + l] in its coarse cell, and each new
       * vertex is moved to F_K of its corner. F_K is
       *  - for a cell of a transfinite interpolation manifold, the Coons
       *    patch of its four lines: each line is straight when it carries
       *    that manifold's id or the flat one, and otherwise follows its own
       *    manifold (get_intermediate_point), the formula of deal.II's
       *    TransfiniteInterpolationManifold;
       *  - for any other cell, the cell's manifold applied to its vertices
       *    with the bilinear weights of (u, v) (the chart's bilinear
       *    interpolation for the polar manifold of an annulus).
       *
       * The positions agree with deal.II's to the tolerance of its Newton
       * iteration, and the refinement flags set from them (cell centres and
       * diameters) are the same.
       */
      class RefinedQuadrilaterals
      {
      public:
        /**
         * Takes the coarse mesh with its manifolds; @p curved must outlive
         * this object and stay unrefined.
         */
        explicit RefinedQuadrilaterals(const dealii::Triangulation<2> &curved);

        /**
         * The refined mesh, without manifolds (read only: refine through
         * the functions below).
         */
        const dealii::Triangulation<2> &
        mesh() const;

        void
        refine_global(const unsigned int n);

        /**
         * Refines, n times, the cells that intersect the disc of radius rho
         * around p. deal.II keeps at most one hanging node per face.
         */
        void
        refine_near(const dealii::Point<2> &p,
                    const double            rho,
                    const unsigned int      n);

        /**
         * The image of the centre of an active cell's square: the point
         * deal.II's cell->center(true) gives on the curved mesh.
         */
        dealii::Point<2>
        centre(
          const dealii::Triangulation<2>::active_cell_iterator &cell) const;

      private:
        /**
         * A cell's square in its coarse cell (of index coarse): the corner
         * (u0, v0) and the side.
         */
        struct Square
        {
          unsigned int coarse;
          double       u0, v0, side;
        };

        /** F_K(u, v) of the coarse cell K of index k. */
        dealii::Point<2>
        coarse_map(const unsigned int k, const dealii::Point<2> &uv) const;

        /** The squares of all cells, then every new vertex placed. */
        void
        place_new_vertices();

        const dealii::Triangulation<2> &curved;
        dealii::Triangulation<2>        flat;
        // squares[level][index]
        std::vector<std::vector<Square>> squares;
        std::vector<bool>                placed;
      };
    } // namespace internal
  }   // namespace geometry
} // namespace dpana

#endif
