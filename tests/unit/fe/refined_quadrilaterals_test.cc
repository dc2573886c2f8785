// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Tests of the refinement of the curved shapes' quadrilaterals with every
// vertex placed by its coarse cell's map (RefinedQuadrilaterals). The
// reference is deal.II itself: the same coarse mesh refined the same way
// along its manifolds (the transfinite interpolation of the disc, the polar
// manifold of an annulus), whose new vertices deal.II places by pulling
// their neighbours back to the coarse cell (a Newton iteration) and pushing
// the average forward. Both meshes must have the same vertices in the same
// order, and the cell centres (cell->center(true) on deal.II's mesh), to
// 1e-11 of the radius (they differ by 7e-14 of it): deal.II's Newton
// iteration stops at a small tolerance, and a few such steps add up.

#include <dpana/geometry/disc.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include "../../../source/geometry/refined_quadrilaterals.h"
#include <gtest/gtest.h>

namespace
{
  using dpana::geometry::internal::RefinedQuadrilaterals;

  // deal.II's refinement of the curved mesh with the flags
  // RefinedQuadrilaterals::refine_near sets.
  void
  refine_near(dealii::Triangulation<2> &tria,
              const dealii::Point<2>    p,
              const double              rho,
              const unsigned int        n)
  {
    for (unsigned int cycle = 0; cycle < n; ++cycle)
      {
        dpana::geometry::internal::flag_cells_near(tria, p, rho);
        tria.execute_coarsening_and_refinement();
      }
  }



  // Refines the coarse mesh that @p make builds twice globally and three
  // times near @p p in both ways and compares the vertices and the cell
  // centres. (Each mesh is built by @p make: a copied transfinite
  // interpolation manifold would still describe the original mesh.)
  template <typename MakeCoarse>
  void
  expect_same_as_deal_ii(const MakeCoarse      &make,
                         const dealii::Point<2> p,
                         const double           rho,
                         const double           length)
  {
    dealii::Triangulation<2> reference(
      dealii::Triangulation<2>::limit_level_difference_at_vertices);
    make(reference);
    reference.refine_global(2);
    refine_near(reference, p, rho, 3);

    dealii::Triangulation<2> coarse(
      dealii::Triangulation<2>::limit_level_difference_at_vertices);
    make(coarse);
    RefinedQuadrilaterals refined(coarse);
    refined.refine_global(2);
    refined.refine_near(p, rho, 3);
    const auto &mesh = refined.mesh();

    ASSERT_EQ(mesh.n_active_cells(), reference.n_active_cells());
    ASSERT_EQ(mesh.n_vertices(), reference.n_vertices());
    // The local refinements left hanging nodes: the test covers them.
    EXPECT_GT(mesh.n_levels(), 3u);
    const double tolerance    = 1e-11 * length;
    double       max_distance = 0;
    for (unsigned int i = 0; i < mesh.n_vertices(); ++i)
      max_distance =
        std::max(max_distance,
                 mesh.get_vertices()[i].distance(reference.get_vertices()[i]));
    EXPECT_LT(max_distance, tolerance);

    max_distance = 0;
    auto ref     = reference.begin_active();
    for (const auto &cell : mesh.active_cell_iterators())
      {
        max_distance =
          std::max(max_distance,
                   refined.centre(cell).distance(ref->center(true)));
        ++ref;
      }
    EXPECT_LT(max_distance, tolerance);
  }
} // namespace



// The half disc x >= 0 of the circular body: transfinite interpolation in
// the cells, the polar manifold on the circle, flat on the axis.
TEST(RefinedQuadrilaterals, TransfiniteDiscAsDealIiRefinesIt)
{
  const auto make = [](dealii::Triangulation<2> &coarse) {
    dpana::geometry::make_disc_quadrilaterals(
      coarse, dealii::Point<2>(0, 40), 40., /*quarter=*/true, /*whole=*/true);
  };
  expect_same_as_deal_ii(make, dealii::Point<2>(0, 0), 6., 40.);
}



// A half annulus whose cells and faces all follow one polar manifold.
TEST(RefinedQuadrilaterals, PolarAnnulusAsDealIiRefinesIt)
{
  const dealii::Point<2> centre(1, 2);
  const auto             make = [&centre](dealii::Triangulation<2> &coarse) {
    dealii::GridGenerator::half_hyper_shell(coarse, centre, 10., 25., 4);
    coarse.set_all_manifold_ids(0);
    coarse.set_manifold(0, dealii::PolarManifold<2>(centre));
  };
  expect_same_as_deal_ii(make, centre + dealii::Point<2>(10, 0), 3., 25.);
}
