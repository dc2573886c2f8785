// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include "refined_quadrilaterals.h"

#include <deal.II/base/array_view.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/tensor.h>

#include <deal.II/grid/manifold_lib.h>

namespace dpana
{
  namespace geometry
  {
    namespace internal
    {
      void
      flag_cells_near(dealii::Triangulation<2> &tria,
                      const dealii::Point<2>   &p,
                      const double              rho)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->center().distance(p) < rho + 0.5 * cell->diameter())
            cell->set_refine_flag();
      }



      RefinedQuadrilaterals::RefinedQuadrilaterals(
        const dealii::Triangulation<2> &curved)
        : curved(curved)
        , flat(dealii::Triangulation<2>::limit_level_difference_at_vertices)
      {
        Assert(curved.n_levels() == 1, dealii::ExcInternalError());
        flat.copy_triangulation(curved);
        flat.reset_all_manifolds();
        flat.set_all_manifold_ids(dealii::numbers::flat_manifold_id);
        // The coarse vertices stay where the shape put them.
        placed = flat.get_used_vertices();
        place_new_vertices();
      }



      const dealii::Triangulation<2> &
      RefinedQuadrilaterals::mesh() const
      {
        return flat;
      }



      void
      RefinedQuadrilaterals::refine_global(const unsigned int n)
      {
        for (unsigned int cycle = 0; cycle < n; ++cycle)
          {
            flat.refine_global(1);
            place_new_vertices();
          }
      }



      void
      RefinedQuadrilaterals::refine_near(const dealii::Point<2> &p,
                                         const double            rho,
                                         const unsigned int      n)
      {
        for (unsigned int cycle = 0; cycle < n; ++cycle)
          {
            flag_cells_near(flat, p, rho);
            flat.execute_coarsening_and_refinement();
            place_new_vertices();
          }
      }



      dealii::Point<2>
      RefinedQuadrilaterals::centre(
        const dealii::Triangulation<2>::active_cell_iterator &cell) const
      {
        const Square &s = squares[cell->level()][cell->index()];
        return coarse_map(s.coarse,
                          dealii::Point<2>(s.u0 + 0.5 * s.side,
                                           s.v0 + 0.5 * s.side));
      }



      // The children of a quadrilateral are numbered like its vertices:
      // child c shares vertex c of its parent, and vertex i of a cell sits
      // at (i % 2, i / 2) of its square.
      void
      RefinedQuadrilaterals::place_new_vertices()
      {
        squares.resize(flat.n_levels());
        squares[0].resize(flat.n_cells(0));
        for (const auto &cell : flat.cell_iterators_on_level(0))
          squares[0][cell->index()] = {static_cast<unsigned int>(cell->index()),
                                       0.,
                                       0.,
                                       1.};
        for (unsigned int level = 0; level + 1 < flat.n_levels(); ++level)
          {
            squares[level + 1].resize(flat.n_raw_cells(level + 1));
            for (const auto &cell : flat.cell_iterators_on_level(level))
              if (cell->has_children())
                {
                  const Square &s    = squares[level][cell->index()];
                  const double  half = 0.5 * s.side;
                  for (unsigned int c = 0; c < 4; ++c)
                    squares[level + 1][cell->child(c)->index()] = {
                      s.coarse,
                      s.u0 + (c % 2) * half,
                      s.v0 + (c / 2) * half,
                      half};
                }
          }

        // A new vertex takes a slot that no vertex used before or is
        // appended: either way it is not placed yet.
        placed.resize(flat.n_vertices(), false);
        for (const auto &cell : flat.active_cell_iterators())
          for (const unsigned int i : cell->vertex_indices())
            if (!placed[cell->vertex_index(i)])
              {
                const Square &s = squares[cell->level()][cell->index()];
                cell->vertex(i) =
                  coarse_map(s.coarse,
                             dealii::Point<2>(s.u0 + (i % 2) * s.side,
                                              s.v0 + (i / 2) * s.side));
                placed[cell->vertex_index(i)] = true;
              }
      }



      // The Coons patch of a transfinite interpolation cell: the sum of the
      // four lines, each weighted by the distance from the opposite one,
      // minus the bilinear interpolation of the vertices. Line l runs from
      // vertex line_to_cell_vertices(l, 0) to line_to_cell_vertices(l, 1)
      // along coordinate 1 - l / 2; its weight is u_{l/2} or 1 - u_{l/2}.
      dealii::Point<2>
      RefinedQuadrilaterals::coarse_map(const unsigned int      k,
                                        const dealii::Point<2> &uv) const
      {
        const dealii::Triangulation<2>::cell_iterator K(&curved, 0, k);
        const std::array<dealii::Point<2>, 4>         x = {
                  {K->vertex(0), K->vertex(1), K->vertex(2), K->vertex(3)}};
        const double                u = uv[0], v = uv[1];
        const std::array<double, 4> bilinear = {
          {(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v}};

        const auto &manifold = K->get_manifold();
        if (dynamic_cast<const dealii::TransfiniteInterpolationManifold<2> *>(
              &manifold) == nullptr)
          return manifold.get_new_point(
            dealii::ArrayView<const dealii::Point<2>>(x.data(), 4),
            dealii::ArrayView<const double>(bilinear.data(), 4));

        dealii::Tensor<1, 2> p;
        for (unsigned int i = 0; i < 4; ++i)
          p -= bilinear[i] * x[i];
        for (unsigned int l = 0; l < 4; ++l)
          {
            const double weight = (l % 2) ? uv[l / 2] : 1 - uv[l / 2];
            const double t      = uv[1 - l / 2];
            const dealii::Point<2> &a =
              x[dealii::GeometryInfo<2>::line_to_cell_vertices(l, 0)];
            const dealii::Point<2> &b =
              x[dealii::GeometryInfo<2>::line_to_cell_vertices(l, 1)];
            const auto id = K->line(l)->manifold_id();
            if (id == K->manifold_id() ||
                id == dealii::numbers::flat_manifold_id)
              p += weight * ((1 - t) * a + t * b);
            else
              p += weight *
                   K->line(l)->get_manifold().get_intermediate_point(a, b, t);
          }
        return dealii::Point<2>(p);
      }
    } // namespace internal
  }   // namespace geometry
} // namespace dpana
