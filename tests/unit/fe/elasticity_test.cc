// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Verification of the elastic body on simplices:
// - manufactured solutions in 2D and 3D: the L2 and H1 errors of P1
//   elements must converge at rates 2 and 1 (standard a priori estimates,
//   e.g. Brenner & Scott, The Mathematical Theory of Finite Element Methods,
//   ch. 0 and 5);
// - the patch test: a uniform stress state is reproduced to round-off on an
//   irregular mesh, both with prescribed displacements on the whole boundary
//   and with symmetry planes plus tractions/pressures (which exercises the
//   load assembly and the symmetry constraints).

#include <dpana/body/body.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "mesh_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dealii;

  // A unit square/cube split into simplices, with the boundary ids of the
  // rectangle/box geometry: left 0, right 1, bottom 2, top 3 (, front 4,
  // back 5), set from the face centres.
  template <int dim>
  std::map<std::string, types::boundary_id>
  make_unit_brick(Triangulation<dim> &tria, const unsigned int n)
  {
    return dpana::test::make_named_brick(
      tria, n, dim == 2 ? Point<dim>(1, 1) : Point<dim>(1, 1, 1));
  }

  // The manufactured displacement u_k = sin(a_k . x + b_k), with its
  // gradient, and the body force f = -div sigma(u) that produces it:
  //   f_k = (lambda + mu) sum_i a_ii a_ik sin(theta_i) + mu |a_k|^2
  //   sin(theta_k),   theta_i = a_i . x + b_i,
  // which follows from div sigma = (lambda + mu) grad div u + mu Laplace u.
  template <int dim>
  struct Manufactured
  {
    Tensor<1, dim> a[dim];
    double         b[dim];
    double         lambda, mu;

    Manufactured(const double lambda, const double mu)
      : lambda(lambda)
      , mu(mu)
    {
      const double A[3][3] = {{1.0, 0.5, 0.3},
                              {0.7, 1.2, 0.4},
                              {0.4, 0.9, 1.1}};
      const double B[3]    = {0.3, 0.1, 0.6};
      for (unsigned int k = 0; k < dim; ++k)
        {
          for (unsigned int j = 0; j < dim; ++j)
            a[k][j] = numbers::PI * A[k][j];
          b[k] = B[k];
        }
    }

    double
    theta(const Point<dim> &p, const unsigned int k) const
    {
      return a[k] * p + b[k];
    }
  };

  template <int dim>
  class ExactDisplacement : public Function<dim>
  {
  public:
    ExactDisplacement(const Manufactured<dim> &m)
      : Function<dim>(dim)
      , m(m)
    {
    }
    double
    value(const Point<dim> &p, const unsigned int k) const override
    {
      return std::sin(m.theta(p, k));
    }
    Tensor<1, dim>
    gradient(const Point<dim> &p, const unsigned int k) const override
    {
      return m.a[k] * std::cos(m.theta(p, k));
    }

  private:
    const Manufactured<dim> m;
  };

  template <int dim>
  class ManufacturedBodyForce : public Function<dim>
  {
  public:
    ManufacturedBodyForce(const Manufactured<dim> &m)
      : Function<dim>(dim)
      , m(m)
    {
    }
    double
    value(const Point<dim> &p, const unsigned int k) const override
    {
      double f = m.mu * m.a[k].norm_square() * std::sin(m.theta(p, k));
      for (unsigned int i = 0; i < dim; ++i)
        f +=
          (m.lambda + m.mu) * m.a[i][i] * m.a[i][k] * std::sin(m.theta(p, i));
      return f;
    }

  private:
    const Manufactured<dim> m;
  };

  struct Errors
  {
    double h, L2, H1;
  };

  template <int dim>
  Errors
  manufactured_errors(const unsigned int n)
  {
    dpana::Body<dim> body("Manufactured");
    const auto       names = make_unit_brick(body.triangulation(), n);
    body.set_boundary_names(names);
    body.material() = dpana::Material(1.0, 0.3);
    const Manufactured<dim> m(body.material().lambda(dim),
                              body.material().mu());
    auto                    exact = std::make_shared<ExactDisplacement<dim>>(m);
    for (const auto &[name, id] : names)
      body.boundary_conditions().prescribed.push_back(
        {name, std::vector<bool>(dim, true), exact, "test"});
    body.loads().body_force = std::make_shared<ManufacturedBodyForce<dim>>(m);

    body.setup();
    body.assemble();
    body.solve();

    Vector<float>            cellwise(body.triangulation().n_active_cells());
    const QGaussSimplex<dim> quadrature(4);
    VectorTools::integrate_difference(body.mapping(),
                                      body.dof_handler(),
                                      body.solution(),
                                      *exact,
                                      cellwise,
                                      quadrature,
                                      VectorTools::L2_norm);
    const double L2 = VectorTools::compute_global_error(body.triangulation(),
                                                        cellwise,
                                                        VectorTools::L2_norm);
    VectorTools::integrate_difference(body.mapping(),
                                      body.dof_handler(),
                                      body.solution(),
                                      *exact,
                                      cellwise,
                                      quadrature,
                                      VectorTools::H1_seminorm);
    const double H1 =
      VectorTools::compute_global_error(body.triangulation(),
                                        cellwise,
                                        VectorTools::H1_seminorm);
    return {1.0 / n, L2, H1};
  }

  template <int dim>
  void
  check_convergence(const std::vector<unsigned int> &subdivisions)
  {
    std::vector<Errors> e;
    for (const unsigned int n : subdivisions)
      e.push_back(manufactured_errors<dim>(n));
    std::printf("  %dD manufactured solution, P1 simplices\n", dim);
    std::printf(
      "  %8s %12s %6s %12s %6s\n", "h", "L2 error", "rate", "H1 error", "rate");
    for (unsigned int i = 0; i < e.size(); ++i)
      {
        if (i == 0)
          std::printf("  %8.4f %12.4e %6s %12.4e %6s\n",
                      e[i].h,
                      e[i].L2,
                      "-",
                      e[i].H1,
                      "-");
        else
          {
            const double r  = std::log(e[i - 1].h / e[i].h);
            const double r2 = std::log(e[i - 1].L2 / e[i].L2) / r;
            const double r1 = std::log(e[i - 1].H1 / e[i].H1) / r;
            std::printf("  %8.4f %12.4e %6.2f %12.4e %6.2f\n",
                        e[i].h,
                        e[i].L2,
                        r2,
                        e[i].H1,
                        r1);
            // The asymptotic rates; the first pair of meshes is allowed to
            // be pre-asymptotic.
            if (i >= 2)
              {
                EXPECT_NEAR(r2, 2.0, 0.15) << "L2 rate, h = " << e[i].h;
                EXPECT_NEAR(r1, 1.0, 0.15) << "H1 rate, h = " << e[i].h;
              }
          }
      }
  }

  // The patch test: for an affine displacement u = G x + c the P1 solution
  // is exact, whatever the shape of the cells, so the stress in every cell
  // is C : sym(G) to round-off.
  template <int dim>
  class AffineDisplacement : public Function<dim>
  {
  public:
    AffineDisplacement(const Tensor<2, dim> &G, const Tensor<1, dim> &c)
      : Function<dim>(dim)
      , G(G)
      , c(c)
    {
    }
    double
    value(const Point<dim> &p, const unsigned int k) const override
    {
      return (G * p + c)[k];
    }

  private:
    Tensor<2, dim> G;
    Tensor<1, dim> c;
  };

  template <int dim>
  double
  max_stress_error(const dpana::Body<dim>        &body,
                   const SymmetricTensor<2, dim> &exact_stress)
  {
    double error = 0;
    for (const auto &s : body.cell_stress())
      error = std::max(error, (s - exact_stress).norm());
    return error / exact_stress.norm();
  }

  // An irregular mesh: the interior vertices of a 5 x 5 (x 5) brick moved
  // at random by up to a quarter of the cell size.
  template <int dim>
  std::map<std::string, types::boundary_id>
  make_irregular_brick(Triangulation<dim> &tria)
  {
    const auto names = make_unit_brick(tria, 5);
    GridTools::distort_random(0.25, tria, true, 1234);
    return names;
  }
} // namespace



TEST(Elasticity, ManufacturedSolutionConvergence2D)
{
  check_convergence<2>({4, 8, 16, 32, 64});
}



TEST(Elasticity, ManufacturedSolutionConvergence3D)
{
  check_convergence<3>({3, 6, 12, 24});
}



template <int dim>
void
patch_test_dirichlet()
{
  dpana::Body<dim> body("Patch");
  const auto       names = make_irregular_brick(body.triangulation());
  body.set_boundary_names(names);
  body.material() = dpana::Material(200000., 0.3);

  Tensor<2, dim> G;
  Tensor<1, dim> c;
  for (unsigned int i = 0; i < dim; ++i)
    {
      c[i] = 0.01 * (i + 1);
      for (unsigned int j = 0; j < dim; ++j)
        G[i][j] = 1e-3 * (1.0 + i + 2.0 * j) * (i == j ? 1.0 : -0.5);
    }
  auto exact = std::make_shared<AffineDisplacement<dim>>(G, c);
  for (const auto &[name, id] : names)
    body.boundary_conditions().prescribed.push_back(
      {name, std::vector<bool>(dim, true), exact, "test"});
  body.setup();
  body.assemble();
  body.solve();
  body.postprocess();

  const auto exact_stress = body.material().template stress<dim>(symmetrize(G));
  const double error      = max_stress_error(body, exact_stress);
  std::printf("  %dD patch test (Dirichlet): max relative stress error "
              "%.3e\n",
              dim,
              error);
  EXPECT_LT(error, 1e-10);

  // The nodal values are the affine field itself.
  const auto &vertices = body.triangulation().get_vertices();
  double      u_error  = 0;
  for (unsigned int v = 0; v < vertices.size(); ++v)
    for (unsigned int k = 0; k < dim; ++k)
      u_error = std::max(u_error,
                         std::abs(body.solution()[body.vertex_dofs()[v][k]] -
                                  exact->value(vertices[v], k)));
  EXPECT_LT(u_error, 1e-12);
}



TEST(Elasticity, PatchTestDirichlet2D)
{
  patch_test_dirichlet<2>();
}



TEST(Elasticity, PatchTestDirichlet3D)
{
  patch_test_dirichlet<3>();
}



// The traction version: symmetry planes x = 0, y = 0 (, z = 0) and a
// uniform normal stress diag(s_1, ..., s_dim) applied as a traction on
// the right face, a pressure on the top face (p = -s_2, so that -p n =
// s_2 e_y) and, in 3D, a traction on the back face. The exact solution is
// the uniform stress; the reactions on the symmetry planes must balance
// the loads.
template <int dim>
void
patch_test_tractions()
{
  dpana::Body<dim> body("Patch");
  const auto       names = make_irregular_brick(body.triangulation());
  body.set_boundary_names(names);
  body.material() = dpana::Material(130000., 0.2);

  const double s[3]                   = {30.0, -50.0, 20.0};
  body.boundary_conditions().symmetry = {{"left", "test"}, {"bottom", "test"}};
  if (dim == 3)
    body.boundary_conditions().symmetry.push_back({"front", "test"});
  Tensor<1, dim> t_right;
  t_right[0] = s[0];
  body.loads().traction.push_back({"right", t_right, "test"});
  body.loads().pressure.push_back({"top", -s[1], "test"});
  if (dim == 3)
    {
      Tensor<1, dim> t_back;
      t_back[2] = s[2];
      body.loads().traction.push_back({"back", t_back, "test"});
    }
  body.setup();
  EXPECT_TRUE(body.free_rigid_modes().empty());
  body.assemble();
  body.solve();
  body.postprocess();

  SymmetricTensor<2, dim> exact_stress;
  for (unsigned int d = 0; d < dim; ++d)
    exact_stress[d][d] = s[d];
  const double error = max_stress_error(body, exact_stress);
  std::printf("  %dD patch test (symmetry + tractions): max relative stress "
              "error %.3e\n",
              dim,
              error);
  EXPECT_LT(error, 1e-10);

  // Reactions: the left face carries -s_x times its area (1), etc.
  EXPECT_NEAR(body.reactions().at("left")[0], -s[0], 1e-9 * std::abs(s[0]));
  EXPECT_NEAR(body.reactions().at("bottom")[1], -s[1], 1e-9 * std::abs(s[1]));
  EXPECT_NEAR(body.applied_load_resultant()[0], s[0], 1e-9 * std::abs(s[0]));
}



TEST(Elasticity, PatchTestTractions2D)
{
  patch_test_tractions<2>();
}



TEST(Elasticity, PatchTestTractions3D)
{
  patch_test_tractions<3>();
}



// Symmetry on inclined planes (the general-normal branch: u_k tied to the
// other components): the traction patch test of above on the square rotated
// by 30 degrees. The exact stress is the rotated uniform stress
// Q diag(s_1, s_2) Q^T, the reactions of the two inclined symmetry planes
// are minus the loads on the opposite faces.
TEST(Elasticity, PatchTestInclinedSymmetry2D)
{
  dpana::Body<2> body("Patch");
  const auto     names = make_irregular_brick(body.triangulation());
  const double   angle = numbers::PI / 6.0;
  GridTools::rotate(angle, body.triangulation());
  body.set_boundary_names(names);
  body.material() = dpana::Material(130000., 0.2);

  const double s1 = 30.0, s2 = -50.0;
  body.boundary_conditions().symmetry = {{"left", "test"}, {"bottom", "test"}};
  // Outward normals of the rotated right and top faces.
  const Tensor<1, 2> n_right({std::cos(angle), std::sin(angle)});
  const Tensor<1, 2> n_top({-std::sin(angle), std::cos(angle)});
  body.loads().traction.push_back({"right", s1 * n_right, "test"});
  body.loads().pressure.push_back({"top", -s2, "test"});
  body.setup();
  EXPECT_TRUE(body.free_rigid_modes().empty());
  body.assemble();
  body.solve();
  body.postprocess();

  const SymmetricTensor<2, 2> exact_stress =
    s1 * symmetrize(outer_product(n_right, n_right)) +
    s2 * symmetrize(outer_product(n_top, n_top));
  const double error = max_stress_error(body, exact_stress);
  std::printf("  2D patch test (inclined symmetry planes): max relative "
              "stress error %.3e\n",
              error);
  EXPECT_LT(error, 1e-10);
  const Tensor<1, 2> R_left   = body.reactions().at("left");
  const Tensor<1, 2> R_bottom = body.reactions().at("bottom");
  EXPECT_LT((R_left + s1 * n_right).norm(), 1e-9 * std::abs(s1));
  EXPECT_LT((R_bottom + s2 * n_top).norm(), 1e-9 * std::abs(s2));
}
