// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The P1 simplex geometry that the assembly and the stresses use
// (include/dpana/body/p1_simplex.h) against deal.II's own FEValues with
// FE_SimplexP(1) and its MappingFE: on every cell of randomly distorted
// triangle and tetrahedron meshes, the measure must equal the sum of the
// JxW values and the gradients of the barycentric coordinates must equal
// the shape gradients, to round-off. A triangle with known gradients
// checks the formula itself. The use of these gradients in the assembly
// and the stresses (the dof of each component and vertex) is checked by
// the patch tests and the manufactured solutions of elasticity_test.cc.

#include <dpana/body/p1_simplex.h>

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

namespace
{
  using namespace dealii;

  // The triangle (0,0), (2,0), (1,1): area 1, J = [[2, 1], [0, 1]] (not
  // diagonal, so a transposed inverse would fail), barycentric coordinates
  // lambda_1 = (x - y)/2, lambda_2 = y, lambda_0 = 1 - x/2 - y/2.
  TEST(P1Simplex, Triangle)
  {
    const auto s =
      dpana::p1_simplex<2>({{Point<2>(0, 0), Point<2>(2, 0), Point<2>(1, 1)}});
    EXPECT_DOUBLE_EQ(s.measure, 1.0);
    EXPECT_DOUBLE_EQ(s.gradients[0][0], -0.5);
    EXPECT_DOUBLE_EQ(s.gradients[0][1], -0.5);
    EXPECT_DOUBLE_EQ(s.gradients[1][0], 0.5);
    EXPECT_DOUBLE_EQ(s.gradients[1][1], -0.5);
    EXPECT_DOUBLE_EQ(s.gradients[2][0], 0.0);
    EXPECT_DOUBLE_EQ(s.gradients[2][1], 1.0);
  }



  template <int dim>
  void
  check_against_fe_values(const unsigned int n_subdivisions)
  {
    Triangulation<dim> hypercube, tria;
    GridGenerator::subdivided_hyper_cube(hypercube, n_subdivisions);
    GridGenerator::convert_hypercube_to_simplex_mesh(hypercube, tria);
    // Distort every interior vertex by up to 30 % of the shortest edge at
    // it (deterministic: deal.II's generator is seeded).
    const std::vector<Point<dim>> undistorted = tria.get_vertices();
    GridTools::distort_random(0.3, tria, true, 1);
    ASSERT_NE(undistorted, tria.get_vertices());

    const FE_SimplexP<dim>   fe(1);
    const MappingFE<dim>     mapping(fe);
    const QGaussSimplex<dim> quadrature(2);
    FEValues<dim>            fe_values(mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    double                   largest_gradient_error = 0, largest_gradient = 0;
    double                   largest_measure_error = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        fe_values.reinit(cell);
        const auto s       = dpana::p1_simplex<dim>(cell);
        double     sum_jxw = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          sum_jxw += fe_values.JxW(q);
        largest_measure_error =
          std::max(largest_measure_error,
                   std::abs(s.measure - sum_jxw) / sum_jxw);
        for (unsigned int v = 0; v <= dim; ++v)
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              largest_gradient =
                std::max(largest_gradient, fe_values.shape_grad(v, q).norm());
              largest_gradient_error =
                std::max(largest_gradient_error,
                         (s.gradients[v] - fe_values.shape_grad(v, q)).norm());
            }
      }
    EXPECT_LT(largest_measure_error, 1e-12);
    EXPECT_LT(largest_gradient_error, 1e-12 * largest_gradient);
  }

  TEST(P1Simplex, MatchesFEValuesOnDistortedTriangles)
  {
    check_against_fe_values<2>(6);
  }

  TEST(P1Simplex, MatchesFEValuesOnDistortedTetrahedra)
  {
    check_against_fe_values<3>(3);
  }
} // namespace
