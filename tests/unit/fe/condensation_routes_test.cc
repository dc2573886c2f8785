// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The two routes of the condensation, through the Schur complement on the
// contact surface and by blocked solves, against each other.

#include <dpana/condensation/condenser.h>
#include <dpana/condensation/parameters.h>
#include <dpana/scene/scene.h>

#include <memory>
#include <string>

#include "scene_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dpana;
  using dpana::test::hertz_prm;
  using dpana::test::make_scene;

  // Body b of an assembled scene with a contact surface, condensed anew by
  // the given method (and, for the Schur route, ordering).
  template <int dim>
  std::unique_ptr<condensation::Condenser<dim>>
  condensed(scene::Scene<dim>                      &s,
            const unsigned int                      b,
            const condensation::Method              method,
            const linear_algebra::LastBlockOrdering ordering =
              linear_algebra::LastBlockOrdering::interior_nested_dissection)
  {
    condensation::Parameters parameters;
    parameters.method   = method;
    parameters.ordering = ordering;
    auto c = std::make_unique<condensation::Condenser<dim>>(s.body(b),
                                                            s.surface(b),
                                                            parameters);
    c->factorize();
    c->assemble_coupling();
    c->condense(16);
    return c;
  }



  // The Schur route (the surface dofs ordered last, A = W^T W with W the
  // solve with the factor of the Schur complement) and the blocked solves
  // give the same A, s_o, G and e up to round-off (1e-12 relative), for every
  // body of the scene and every ordering of the Schur route's
  // factorisation, and the same recovered displacement.
  template <int dim>
  void
  expect_routes_agree(scene::Scene<dim> &s)
  {
    s.assemble();
    s.build_contact_surface();
    using linear_algebra::LastBlockOrdering;
    for (unsigned int b = 0; b < s.n_bodies(); ++b)
      for (const auto ordering :
           {LastBlockOrdering::moved_last,
            LastBlockOrdering::constrained_amd,
            LastBlockOrdering::interior_nested_dissection})
        {
          SCOPED_TRACE(linear_algebra::to_string(ordering));
          const auto schur =
            condensed(s, b, condensation::Method::schur, ordering);
          const auto blocked =
            condensed(s, b, condensation::Method::blocked_solves);
          const auto relative = [](const auto &x, const auto &y) {
            return y.norm() > 0 ? (x - y).norm() / y.norm() : x.norm();
          };
          EXPECT_LT(relative(schur->compliance(), blocked->compliance()),
                    1e-12);
          EXPECT_LT(relative(schur->load_term(), blocked->load_term()), 1e-12);
          EXPECT_LT(relative(schur->equilibrium_matrix(),
                             blocked->equilibrium_matrix()),
                    1e-12);
          EXPECT_LT(relative(schur->equilibrium_rhs(),
                             blocked->equilibrium_rhs()),
                    1e-12);
          EXPECT_EQ(schur->fictitious_supports(),
                    blocked->fictitious_supports());
          EXPECT_EQ(schur->asymmetry(), 0.0);
          EXPECT_GT(schur->factorization().schur_dofs().size(), 0u);
          EXPECT_TRUE(schur->compliance() == schur->compliance().transpose());

          const Eigen::VectorXd r =
            Eigen::VectorXd::LinSpaced(schur->compliance().rows(), -1.0, 1.0);
          const Eigen::VectorXd alpha =
            Eigen::VectorXd::Ones(schur->n_free_modes());
          const auto u1 = schur->recover(r, alpha);
          auto       u2 = blocked->recover(r, alpha);
          u2 -= u1;
          EXPECT_LT(u2.l2_norm(), 1e-12 * u1.l2_norm());
        }
  }
} // namespace



// The 2D receding block: held only by its symmetry plane, floating along
// the contact direction (one fictitious support).
TEST(Condensation, SchurRouteEqualsBlockedSolves2DFloatingBody)
{
  auto s = make_scene<2>(dpana::test::receding_block(8, 8, "") +
                         "subsection Contact\n"
                         "  set Boundary 1 = bottom\n"
                         "  set Contact direction = 0, -1\n"
                         "end\n");
  expect_routes_agree(*s);
}



// The Hertz cylinder (locally refined: hanging nodes on the surface,
// floating along its axis) on a floating foundation.
TEST(Condensation, SchurRouteEqualsBlockedSolves2DTwoFloatingBodies)
{
  const std::string foundation = dpana::test::floating_foundation();
  auto              s = make_scene<2>(hertz_prm(2, 15, 0.3, foundation), 2);
  expect_routes_agree(*s);
}



// A 3D block floating along the contact direction (symmetry planes only) on
// a held 3D foundation; and the block alone.
TEST(Condensation, SchurRouteEqualsBlockedSolves3D)
{
  using dpana::test::brick_body;
  const std::string block =
    brick_body("Body 1",
               "box",
               "0, 0, 0",
               "40, 20, 20",
               "8, 4, 4",
               "    set Symmetry = left, front\n",
               "    set Pressure = top: 50; right: 100\n");
  const std::string foundation =
    brick_body("Body 2",
               "box",
               "0, -20, 0",
               "40, 0, 20",
               "8, 4, 4",
               "    set Symmetry = left, front\n    set Fixed = bottom: y\n",
               "");
  const std::string contact = "subsection Contact\n"
                              "  set Boundary 1 = bottom\n"
                              "  set Contact direction = 0, -1, 0\n";
  auto one = make_scene<3>("set Dimension = 3\n" + block + contact + "end\n");
  expect_routes_agree(*one);
  auto two =
    make_scene<3>("set Dimension = 3\nset Number of bodies = 2\n" + block +
                    foundation + contact + "  set Boundary 2 = top\nend\n",
                  2);
  expect_routes_agree(*two);
  EXPECT_EQ(condensed(*two, 0, condensation::Method::schur)->n_free_modes(),
            1u);
  EXPECT_EQ(condensed(*two, 1, condensation::Method::schur)->n_free_modes(),
            0u);
}
