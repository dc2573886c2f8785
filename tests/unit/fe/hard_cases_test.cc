// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Hard cases of whole contact runs: nearly incompressible bodies and
// extreme stiffness ratios between two bodies, solved by every contact
// solver. Each solver must converge to the shared residual tolerance, or
// the run must say that it did not; on these cases all of them converge,
// and they must agree with each other.

#include <dpana/scene/scene.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "scene_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using dpana::test::make_scene;

  const std::vector<std::string> solvers = {"splitting_active_set",
                                            "splitting_pgs",
                                            "nsgs",
                                            "alart_curnier"};

  using dpana::test::receding_block;

  // The contact subsection: candidate surface the base, contact direction
  // (0, -1), friction coefficient mu, contact solver `solver`; `extra`
  // holds more entries.
  std::string
  contact(const double mu, const std::string &solver, const std::string &extra)
  {
    return "subsection Contact\n"
           "  set Boundary 1 = bottom\n"
           "  set Contact direction = 0, -1\n"
           "  set Friction coefficient = " +
           std::to_string(mu) + "\n  set Solver = " + solver + "\n" + extra +
           "end\n";
  }

  // The receding block of the reference formulation, section 4.2.1 (16 x 16
  // cells, rigid foundation) with Poisson's ratio nu.
  std::string
  block_prm(const double nu, const double mu, const std::string &solver)
  {
    return "set Dimension = 2\n" +
           receding_block(
             16, 16, "    set Poisson's ratio = " + std::to_string(nu) + "\n") +
           contact(mu, solver, "");
  }

  // The block of section 4.2.3 on an elastic foundation (half model
  // [0, 80] x [-80, 0], 32 x 32 cells, matching edges of 2.5 mm) with
  // Young's moduli E1 (block) and E2 (foundation), mu = 1.
  std::string
  two_body_prm(const double E1, const double E2, const std::string &solver)
  {
    return "set Dimension = 2\n"
           "set Number of bodies = 2\n" +
           receding_block(
             16, 16, "    set Young's modulus = " + std::to_string(E1) + "\n") +
           "subsection Body 2\n"
           "  subsection Geometry\n"
           "    subsection Rectangle\n"
           "      set Lower corner = 0, -80\n"
           "      set Upper corner = 80, 0\n"
           "      set Subdivisions = 32, 32\n"
           "    end\n"
           "  end\n"
           "  subsection Material\n"
           "    set Young's modulus = " +
           std::to_string(E2) +
           "\n"
           "  end\n"
           "  subsection Boundary conditions\n"
           "    set Symmetry = left\n"
           "    set Fixed = bottom: x, y\n"
           "  end\n"
           "end\n" +
           contact(1,
                   solver,
                   "  set Boundary 2 = top\n"
                   "  set Candidate centre = 0, 0\n"
                   "  set Candidate half width = 40\n");
  }

  // Runs `text` with every solver: each must converge, and the tractions
  // of each must agree with those of the first solver to 1e-6 of the
  // largest traction (the solvers stop at the residual 1e-10).
  void
  all_solvers_agree(const std::function<std::string(const std::string &)> &text,
                    const unsigned int n_bodies,
                    const std::string &what)
  {
    Eigen::VectorXd first;
    for (const auto &solver : solvers)
      {
        auto s = make_scene<2>(text(solver), n_bodies);
        s->run(false);
        const auto &r = s->summary().result;
        EXPECT_TRUE(r.converged) << what << ", " << solver << ": " << r.message;
        std::cout << what << ", " << solver << ": " << r.iterations
                  << " iterations, residual " << r.residual << std::endl;
        if (first.size() == 0)
          first = r.r;
        else
          EXPECT_LT((r.r - first).lpNorm<Eigen::Infinity>(),
                    1e-6 * first.lpNorm<Eigen::Infinity>())
            << what << ", " << solver;
      }
  }
} // namespace



// A nearly incompressible block, nu = 0.4999 (lambda / mu = 5000): the
// stiffness matrix is badly conditioned, but the frictionless receding
// block keeps its exact uniform solution N = -50 MPa, T = 0 (a linear
// displacement, which P1 elements represent exactly whatever nu; see
// ContactRun.FrictionlessRecedingBlockIsUniform). With mu = 1 there is no
// closed form: all solvers must converge and agree.
TEST(HardCases, NearlyIncompressibleBlock)
{
  auto s = make_scene<2>(block_prm(0.4999, 0, "splitting_active_set"));
  s->run(false);
  ASSERT_TRUE(s->summary().result.converged);
  double eN = 0, eT = 0;
  for (unsigned int j = 0; j < s->summary().n_elements; ++j)
    {
      eN = std::max(eN, std::abs(s->normal_traction(j) + 50.0));
      eT = std::max(eT, std::abs(s->tangential_traction(j)));
    }
  std::cout << "nu = 0.4999, mu = 0: max |N + 50| = " << eN
            << " MPa, max |T| = " << eT << " MPa" << std::endl;
  EXPECT_LT(eN, 50.0 * 1e-7);
  EXPECT_LT(eT, 50.0 * 1e-7);

  all_solvers_agree(
    [](const std::string &solver) { return block_prm(0.4999, 1, solver); },
    1,
    "nu = 0.4999, mu = 1");
}



// Stiffness ratios E1/E2 = 1e-3 (a soft block on a nearly rigid
// foundation) and 1e3 (a nearly rigid flat punch), mu = 1: A = A1 + A2 is
// dominated by one body, and the floating block's equality row couples
// every element. Every solver must converge, and they must agree.
TEST(HardCases, ExtremeStiffnessRatios)
{
  for (const double ratio : {1e-3, 1e3})
    all_solvers_agree(
      [ratio](const std::string &solver) {
        return two_body_prm(130000 * std::sqrt(ratio),
                            130000 / std::sqrt(ratio),
                            solver);
      },
      2,
      std::string("E1/E2 = ") + (ratio < 1 ? "1e-3" : "1e3"));
}
