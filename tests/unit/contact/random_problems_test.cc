// Random SPD problems: every solver reaches the shared residual 1e-10 and
// the solvers agree with each other; where the splitting fails it must say
// so, and NSGS must then solve the problem.
#include <iostream>

#include "contact_test_tools.h"
#include <gtest/gtest.h>

using namespace dpana_test;

namespace
{
  struct Case
  {
    unsigned int dim;
    unsigned int n;
    double       mu;
    ConeModel    cone;
  };

  std::string
  name(const Case &c)
  {
    return std::to_string(c.dim) + "D n=" + std::to_string(c.n) +
           " mu=" + std::to_string(c.mu) + " cone=" + to_string(c.cone);
  }

  void
  run_case(const Case &c, const unsigned int seed)
  {
    const ContactProblem p = random_problem(c.dim, c.n, c.mu, seed, c.cone);
    std::vector<SolverResult> results;
    for (const SolverType type : all_solvers())
      {
        const SolverResult res = solve(p, options_for(type));
        std::cout << "[ " << name(c) << " seed " << seed << " ] "
                  << to_string(type) << ": converged " << res.converged
                  << " it " << res.iterations << " inner "
                  << res.inner_iterations << " residual " << res.residual
                  << " (" << res.message << ")" << std::endl;
        // Whatever the outcome, the reported residual must be the true one.
        const ResidualFigures f = compute_residual(p, res.r, res.alpha);
        EXPECT_NEAR(f.natural_map, res.residual, 1e-12 + 1e-6 * res.residual);
        EXPECT_EQ(res.converged, res.residual <= 1e-10) << to_string(type);
        results.push_back(res);
      }
    // NSGS and Alart-Curnier must always solve these problems.
    const SolverResult &nsgs = results[2];
    ASSERT_TRUE(nsgs.converged) << name(c) << ": " << nsgs.message;
    EXPECT_LE(nsgs.residual, 1e-10);
    ASSERT_TRUE(results[3].converged) << name(c) << ": " << results[3].message;
    if (c.mu <= 1.0)
      EXPECT_LE(relative_difference(nsgs.r, results[3].r), 1e-7) << name(c);
    for (unsigned int s = 0; s < 2; ++s)
      if (results[s].converged)
        {
          // Agreement: for mu <= 1 the solutions of these well-conditioned
          // problems are unique; two solutions with residual <= 1e-10 then
          // differ by at most cond(A) * 1e-10, checked as 1e-7 relative.
          if (c.mu <= 1.0)
            EXPECT_LE(relative_difference(nsgs.r, results[s].r), 1e-7)
              << name(c) << " " << to_string(all_solvers()[s]);
        }
      else
        // A failure is allowed only for large friction and must be reported
        // with a reason.
        {
          EXPECT_GE(c.mu, 1.0) << name(c) << " " << results[s].message;
          EXPECT_FALSE(results[s].message.empty());
        }
  }
} // namespace

TEST(RandomProblems, TwoD)
{
  for (const unsigned int n : {5u, 20u, 60u})
    for (const double mu : {0.0, 0.3, 1.0, 2.0})
      run_case({2, n, mu, ConeModel::interval}, 1000 + n);
}

TEST(RandomProblems, ThreeDDisc)
{
  for (const unsigned int n : {5u, 20u, 60u})
    for (const double mu : {0.0, 0.3, 1.0, 2.0})
      run_case({3, n, mu, ConeModel::disc}, 2000 + n);
}

TEST(RandomProblems, ThreeDPolygon)
{
  for (const unsigned int n : {5u, 20u, 60u})
    for (const double mu : {0.0, 0.3, 1.0, 2.0})
      run_case({3, n, mu, ConeModel::polygon}, 3000 + n);
}

TEST(RandomProblems, RelaxationAndWarmStart)
{
  // Over- and under-relaxed PGS / NSGS reach the same solution (1e-7), and
  // every solver started from a converged solution stops at once (one outer
  // iteration for the splitting and NSGS, none for Newton).
  const ContactProblem p = random_problem(3, 20, 0.5, 555, ConeModel::disc);
  const SolverResult   reference = solve(p, options_for(SolverType::nsgs));
  ASSERT_TRUE(reference.converged);
  for (const SolverType type : {SolverType::splitting_pgs, SolverType::nsgs})
    for (const double omega : {0.7, 1.3})
      {
        SolverOptions o        = options_for(type);
        o.over_relaxation      = omega;
        const SolverResult res = solve(p, o);
        ASSERT_TRUE(res.converged) << to_string(type) << " omega " << omega;
        EXPECT_LE(relative_difference(reference.r, res.r), 1e-7);
      }
  for (const SolverType type : all_solvers())
    {
      const SolverResult res = solve(p, options_for(type), &reference.r);
      ASSERT_TRUE(res.converged) << to_string(type);
      EXPECT_LE(res.iterations, 1u) << to_string(type);
      EXPECT_LE(relative_difference(reference.r, res.r), 1e-8);
    }
}
