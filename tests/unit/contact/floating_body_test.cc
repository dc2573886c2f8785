// Floating bodies: a block held only by contact, with equality rows
// G r = e (global equilibrium) and free rigid-mode amplitudes alpha in
// u = A r + D + G^T alpha.
#include "contact_test_tools.h"
#include <gtest/gtest.h>

using namespace dpana_test;

namespace
{
  // A 2D block on n contact elements at x_j in (-1, 1), pressed by a
  // vertical force P at x_P and pushed sideways by H. Rows of G:
  //   0: sum_j N_j = -P           (vertical equilibrium, normal row)
  //   1: sum_j T_j = H            (horizontal equilibrium, tangential row)
  //   2: sum_j x_j N_j = -P x_P   (moment equilibrium, normal row)
  // alpha = (vertical, horizontal translation, rotation) of the block.
  // Compliance: springs a (normal) and c (tangential) per element plus, if
  // coupling > 0, coupling * exp(-|x_i - x_j|) in each direction (the
  // Laplace kernel is positive definite) and an N-T coupling 0.1 between
  // neighbours' normal and tangential unknowns made SPD by construction.
  ContactProblem
  block_2d(const unsigned int n,
           const double       P,
           const double       xP,
           const double       H,
           const double       mu,
           const double       coupling)
  {
    ContactProblem p;
    p.dim = 2;
    p.A   = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    std::vector<double> x(n);
    for (unsigned int j = 0; j < n; ++j)
      x[j] = -1.0 + 2.0 * (j + 0.5) / n;
    for (unsigned int i = 0; i < n; ++i)
      {
        p.A(2 * i, 2 * i) += 1.0;
        p.A(2 * i + 1, 2 * i + 1) += 2.0;
        for (unsigned int j = 0; j < n; ++j)
          {
            const double k = coupling * std::exp(-std::abs(x[i] - x[j]));
            p.A(2 * i, 2 * j) += k;
            p.A(2 * i + 1, 2 * j + 1) += k;
          }
      }
    if (coupling > 0)
      {
        Eigen::MatrixXd B = Eigen::MatrixXd::Zero(2 * n, 2 * n);
        for (unsigned int j = 0; j + 1 < n; ++j)
          B(2 * j, 2 * j + 3) = 0.3;
        p.A += B * B.transpose() + 0.1 * (B + B.transpose());
      }
    p.D  = Eigen::VectorXd::Zero(2 * n);
    p.mu = Eigen::VectorXd::Constant(n, mu);
    p.G  = Eigen::MatrixXd::Zero(3, 2 * n);
    for (unsigned int j = 0; j < n; ++j)
      {
        p.G(0, 2 * j)     = 1.0;
        p.G(1, 2 * j + 1) = 1.0;
        p.G(2, 2 * j)     = x[j];
      }
    p.e = Eigen::Vector3d(-P, H, -P * xP);
    return p;
  }

  // Equilibrium tolerance of each solver: the active-set splitting solves
  // the equality rows exactly (round-off); PGS and NSGS use an augmented
  // Lagrangian and satisfy them to their tolerance.
  double
  equilibrium_tolerance(const SolverType type)
  {
    return type == SolverType::splitting_active_set ? 1e-12 : 1e-9;
  }
} // namespace

TEST(FloatingBody, CentredLoadOnSpringsAnalytic)
{
  // Uncoupled springs, centred load P = 8 on n = 8 elements, H = 1, mu = 0.5.
  // By symmetry and u_N = 0 on every element: N_j = -P/n = -1, and
  // a N_j + alpha_0 + alpha_2 x_j = 0 gives alpha_0 = 1, alpha_2 = 0. All
  // elements stick (|T_j| = H/n = 0.125 < mu |N_j| = 0.5) with u_T = 0:
  // c T_j + alpha_1 = 0, T_j = 1/8, alpha_1 = -0.25.
  const ContactProblem p = block_2d(8, 8.0, 0.0, 1.0, 0.5, 0.0);
  Eigen::VectorXd      expected(16);
  for (unsigned int j = 0; j < 8; ++j)
    expected.segment<2>(2 * j) << -1.0, 0.125;
  for (const SolverType type : all_solvers())
    {
      const SolverResult res = solve(p, options_for(type));
      ASSERT_TRUE(res.converged) << to_string(type) << ": " << res.message;
      EXPECT_LE((res.r - expected).lpNorm<Eigen::Infinity>(), 1e-9)
        << to_string(type) << " " << res.r.transpose();
      EXPECT_LE(res.figures.equilibrium, equilibrium_tolerance(type) * 8.0)
        << to_string(type);
      EXPECT_NEAR(res.alpha[0], 1.0, 1e-8) << to_string(type);
      EXPECT_NEAR(res.alpha[1], -0.25, 1e-8) << to_string(type);
      EXPECT_NEAR(res.alpha[2], 0.0, 1e-8) << to_string(type);
      for (const auto s : res.status)
        EXPECT_EQ(s, ContactStatus::stick);
    }
}

TEST(FloatingBody, EccentricLoadCoupled)
{
  // Eccentric load with a coupled compliance: part of the base lifts off,
  // part slips. Reference: the solvers must agree with each other (1e-7)
  // and each must satisfy the law (residual) and the equilibrium rows.
  const ContactProblem      p = block_2d(12, 10.0, 0.55, 3.0, 0.4, 0.5);
  std::vector<SolverResult> results;
  for (const SolverType type : all_solvers())
    {
      const SolverResult res = solve(p, options_for(type));
      ASSERT_TRUE(res.converged) << to_string(type) << ": " << res.message;
      EXPECT_LE(res.residual, 1e-10);
      EXPECT_LE(res.figures.equilibrium, equilibrium_tolerance(type) * 10.0)
        << to_string(type);
      // Independent check of G r = e.
      EXPECT_LE((p.G * res.r - p.e).lpNorm<Eigen::Infinity>(),
                equilibrium_tolerance(type) * 10.0);
      results.push_back(res);
    }
  unsigned int separated = 0;
  for (const auto s : results[1].status)
    separated += (s == ContactStatus::separated);
  EXPECT_GE(separated, 1u);
  EXPECT_LE(relative_difference(results[1].r, results[0].r), 1e-7);
  EXPECT_LE(relative_difference(results[1].r, results[2].r), 1e-7);
  EXPECT_LE(relative_difference(results[1].alpha, results[2].alpha), 1e-6);
}

TEST(FloatingBody, ThreeDBlockOnGrid)
{
  // 3D block on a 3 x 3 grid of contact elements (spacing 1, centred), disc
  // friction, uncoupled springs diag(1, 2, 2). Rows: sum N = -P,
  // sum T_x = Hx, sum T_y = Hy, sum x N = 0, sum y N = 0 (centred load).
  // Analytic: N_j = -P/9, T_j = (Hx, Hy)/9 (stick: |H|/9 < mu P/9).
  const double   P = 9.0, Hx = 0.9, Hy = -1.8, mu = 0.3;
  ContactProblem p;
  p.dim  = 3;
  p.cone = ConeModel::disc;
  p.A    = Eigen::MatrixXd::Zero(27, 27);
  p.G    = Eigen::MatrixXd::Zero(5, 27);
  for (unsigned int j = 0; j < 9; ++j)
    {
      const double x = double(j % 3) - 1.0, y = double(j / 3) - 1.0;
      p.A(3 * j, 3 * j)         = 1.0;
      p.A(3 * j + 1, 3 * j + 1) = p.A(3 * j + 2, 3 * j + 2) = 2.0;
      p.G(0, 3 * j)                                         = 1.0;
      p.G(1, 3 * j + 1)                                     = 1.0;
      p.G(2, 3 * j + 2)                                     = 1.0;
      p.G(3, 3 * j)                                         = x;
      p.G(4, 3 * j)                                         = y;
    }
  p.D  = Eigen::VectorXd::Zero(27);
  p.mu = Eigen::VectorXd::Constant(9, mu);
  p.e.resize(5);
  p.e << -P, Hx, Hy, 0.0, 0.0;
  for (const ConeModel cone : {ConeModel::disc, ConeModel::polygon})
    for (const SolverType type : all_solvers())
      {
        p.cone                 = cone;
        const SolverResult res = solve(p, options_for(type));
        ASSERT_TRUE(res.converged) << to_string(type) << ": " << res.message;
        for (unsigned int j = 0; j < 9; ++j)
          {
            EXPECT_NEAR(res.r[3 * j], -1.0, 1e-8) << to_string(type);
            EXPECT_NEAR(res.r[3 * j + 1], 0.1, 1e-8) << to_string(type);
            EXPECT_NEAR(res.r[3 * j + 2], -0.2, 1e-8) << to_string(type);
          }
        EXPECT_LE(res.figures.equilibrium, equilibrium_tolerance(type) * 9.0);
      }
}

TEST(FloatingBody, InfeasibleSidewaysLoadIsReported)
{
  // H = 5 > mu P = 0.5 * 8: friction cannot hold the block, there is no
  // static solution. Every solver must stop with converged = false and a
  // message, quickly.
  const ContactProblem p = block_2d(8, 8.0, 0.0, 5.0, 0.5, 0.0);
  for (const SolverType type : all_solvers())
    {
      const SolverResult res = solve(p, options_for(type));
      EXPECT_FALSE(res.converged) << to_string(type);
      EXPECT_FALSE(res.message.empty()) << to_string(type);
      // The equilibrium rows cannot all hold with a law-abiding r.
      EXPECT_TRUE(res.residual > 1e-10 || res.figures.equilibrium > 1e-6)
        << to_string(type);
    }
}
