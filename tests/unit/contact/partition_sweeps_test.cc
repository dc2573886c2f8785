// The partition sweeps of the active-set T-step (friction_qp.h,
// FrictionQp::settle_partition) change the path, not the answer: on 3D
// problems (and 2D ones) with a planted solution that mixes separated, sticking
// and slipping elements (siconos_problems.h), the default solver with the
// sweeps (made at every size here: SolverOptions::partition_sweep_size = 0) and
// without them both converge and both recover the planted tractions.
#include "contact_test_tools.h"
#include "siconos_problems.h"
#include <gtest/gtest.h>

using namespace dpana_test;

namespace
{
  SolverResult
  solve_with_sweeps(const ContactProblem &p, const unsigned int sweeps)
  {
    SolverOptions options    = options_for(SolverType::splitting_active_set);
    options.partition_sweeps = sweeps;
    options.partition_sweep_size = 0;
    options.fallback             = false;
    const SolverResult result    = solve(p, options);
    std::cout << "[ sweeps " << sweeps << " ] converged " << result.converged
              << " it " << result.iterations << " inner "
              << result.inner_iterations << " residual " << result.residual
              << " (" << result.message << ")" << std::endl;
    return result;
  }
} // namespace

TEST(PartitionSweeps, SameSolutionWithAndWithoutSweeps)
{
  const unsigned int n = 60;
  // 2D (one tangential column per element) and 3D (two): the sweeps'
  // single precision column updates take both paths.
  for (const unsigned int dim : {2u, 3u})
    for (const double mu : {0.3, 1.0})
      {
        const auto planted =
          dpana::contact::test_problems::planted_problem(dim, n, mu, 4242);
        const SolverResult with    = solve_with_sweeps(planted.problem, 200);
        const SolverResult without = solve_with_sweeps(planted.problem, 0);
        ASSERT_TRUE(with.converged) << with.message;
        ASSERT_TRUE(without.converged) << without.message;
        // The planted solution is unique for these conditions (cond(A) = 100):
        // two answers of residual 1e-10 lie within cond(A) * 1e-10 of it,
        // checked as 1e-7 relative.
        EXPECT_LE(relative_difference(with.r, planted.r), 1e-7)
          << dim << "D, mu " << mu;
        EXPECT_LE(relative_difference(without.r, planted.r), 1e-7)
          << dim << "D, mu " << mu;
      }
}
