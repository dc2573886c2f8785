// Cases where the D-PANA splitting does not converge: alone (fallback off)
// it must say so (converged = false, a message, a residual that is the true
// one); NSGS must solve the problem, and so must the default (robust) mode
// of the splitting, by its fallback, saying which solver answered.
#include "contact_test_tools.h"
#include <gtest/gtest.h>

using namespace dpana_test;

namespace
{
  // The default mode of the splitting solves the problem by a fallback
  // solver, to the tolerance, and says so in the result and its message.
  void
  expect_fallback_solves(const ContactProblem &p, const SolverType type)
  {
    const SolverResult res = solve(p, options_for(type));
    ASSERT_TRUE(res.converged) << to_string(type) << ": " << res.message;
    EXPECT_LE(res.residual, 1e-10);
    EXPECT_NE(res.solver, type);
    ASSERT_FALSE(res.fallbacks.empty());
    EXPECT_EQ(res.fallbacks.front().rfind(to_string(type) + ": ", 0), 0u)
      << res.fallbacks.front();
    EXPECT_NE(res.message.find("fallback after " + to_string(type)),
              std::string::npos)
      << res.message;
  }
} // namespace

// One 2D element, A = [[1, 0.5], [0.5, 1]], D = (1, 10), mu = 3.
// Exact solution (derived by hand): backward slip s = -1, T = mu N, and
// u_N = N + 0.5 T + 1 = 0 gives N = -1 / (1 + 0.5 * 3) = -0.4, T = -1.2;
// u_T = 0.5 N + T + 10 = 8.6 > 0 = -lambda T with lambda > 0.
// The splitting from N = 0: T = 0, N = -1 (frictionless); then the stick
// trial T = -(10 - 0.5) = -9.5 is clipped to -mu |N| = -3, and the N-step
// gives N = min(0, -(1 + 0.5 * (-3))) = 0; then T = 0 and N = -1 again: an
// exact two-cycle (the fixed-point map of N on the slip branch has slope
// s mu A_NT / A_NN = -1.5, of modulus > 1).
TEST(SplittingFailure, TwoCycleOnOneElement)
{
  ContactProblem p;
  p.dim = 2;
  p.A.resize(2, 2);
  p.A << 1.0, 0.5, 0.5, 1.0;
  p.D  = Eigen::Vector2d(1.0, 10.0);
  p.mu = Eigen::VectorXd::Constant(1, 3.0);
  const Eigen::Vector2d exact(-0.4, -1.2);

  for (const SolverType type :
       {SolverType::splitting_pgs, SolverType::splitting_active_set})
    {
      SolverOptions o        = options_for(type);
      o.max_iterations       = 500;
      o.fallback             = false;
      const SolverResult res = solve(p, o);
      EXPECT_FALSE(res.converged) << to_string(type);
      EXPECT_NE(res.message.find("did not converge"), std::string::npos)
        << res.message;
      EXPECT_GT(res.residual, 1e-2);
      // The reported residual is the true one.
      EXPECT_DOUBLE_EQ(
        res.residual,
        compute_residual(p, res.r, Eigen::VectorXd()).natural_map);
      // The iterates alternate between the two points of the cycle.
      const double N = res.r[0];
      EXPECT_TRUE(std::abs(N) < 1e-12 || std::abs(N + 1.0) < 1e-12) << N;
      expect_fallback_solves(p, type);
      EXPECT_LE(
        (solve(p, options_for(type)).r - exact).lpNorm<Eigen::Infinity>(),
        1e-12);
    }
  for (const SolverType type : {SolverType::nsgs, SolverType::alart_curnier})
    {
      const SolverResult res = solve(p, options_for(type));
      ASSERT_TRUE(res.converged) << res.message;
      EXPECT_LE((res.r - exact).lpNorm<Eigen::Infinity>(), 1e-12);
      EXPECT_EQ(res.status[0], ContactStatus::slip);
    }
}

// Many copies of the cycling element, weakly coupled: the splitting still
// fails and says so; NSGS solves it (residual <= 1e-10).
TEST(SplittingFailure, CoupledCopies)
{
  const unsigned int n = 10;
  ContactProblem     p;
  p.dim = 2;
  p.A   = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  p.D.resize(2 * n);
  for (unsigned int j = 0; j < n; ++j)
    {
      p.A.block<2, 2>(2 * j, 2 * j) << 1.0, 0.5, 0.5, 1.0;
      p.D.segment<2>(2 * j) << 1.0 + 0.05 * j, 10.0 - 0.3 * j;
      if (j + 1 < n)
        {
          // Weak normal-normal coupling keeps A SPD (diagonally dominant
          // blocks).
          p.A(2 * j, 2 * j + 2) = p.A(2 * j + 2, 2 * j) = 0.05;
        }
    }
  p.mu = Eigen::VectorXd::Constant(n, 3.0);
  for (const SolverType type :
       {SolverType::splitting_pgs, SolverType::splitting_active_set})
    {
      SolverOptions o        = options_for(type);
      o.fallback             = false;
      const SolverResult res = solve(p, o);
      EXPECT_FALSE(res.converged) << to_string(type);
      EXPECT_FALSE(res.message.empty());
      expect_fallback_solves(p, type);
    }
  const SolverResult res = solve(p, options_for(SolverType::nsgs));
  ASSERT_TRUE(res.converged) << res.message;
  EXPECT_LE(res.residual, 1e-10);
}

// A 4-element random problem with mu = 2 (the one found by the brute-force
// test) on which the splitting cycles and plain NSGS (omega = 1) cycles too;
// the enumeration shows that the solution exists and is unique. NSGS with
// adaptive relaxation finds it.
TEST(SplittingFailure, HardRandomProblem)
{
  const ContactProblem p   = random_problem(2, 4, 2.0, 100 * 4 + 3 + 7919);
  const auto           ref = enumerate_2d(p);
  ASSERT_EQ(ref.size(), 1u);
  for (const SolverType type :
       {SolverType::splitting_pgs, SolverType::splitting_active_set})
    {
      SolverOptions o        = options_for(type);
      o.fallback             = false;
      const SolverResult res = solve(p, o);
      EXPECT_FALSE(res.converged) << to_string(type);
      EXPECT_FALSE(res.message.empty());
      expect_fallback_solves(p, type);
    }
  SolverOptions plain             = options_for(SolverType::nsgs);
  plain.adaptive_relaxation       = false;
  const SolverResult plain_result = solve(p, plain);
  EXPECT_FALSE(plain_result.converged);
  const SolverResult res = solve(p, options_for(SolverType::nsgs));
  ASSERT_TRUE(res.converged) << res.message;
  EXPECT_LE(relative_difference(ref[0], res.r), 1e-8);
  // The semismooth Newton method solves it too, from r = 0.
  const SolverResult ac = solve(p, options_for(SolverType::alart_curnier));
  ASSERT_TRUE(ac.converged) << ac.message;
  EXPECT_LE(relative_difference(ref[0], ac.r), 1e-8);
}
