// The shared stopping and stall tests of the contact solvers (monitor.h).
#include <dpana/contact/monitor.h>

#include <limits>

#include "contact_test_tools.h"
#include <gtest/gtest.h>

using namespace dpana_test;

namespace
{
  ResidualFigures
  figures(const double natural_map, const double equilibrium = 0.0)
  {
    ResidualFigures f;
    f.natural_map = natural_map;
    f.equilibrium = equilibrium;
    return f;
  }

  // The monitor of an NSGS solve with tolerance 1e-8 on a small problem,
  // its history and an iterate r.
  class NsgsMonitor : public ::testing::Test
  {
  protected:
    NsgsMonitor()
      : p(random_problem(2, 3, 0.3, 1))
      , o(tolerance(1e-8))
      , monitor(p, o, "NSGS", "sweeps", history)
      , r(Eigen::VectorXd::Ones(6))
    {
    }

    static SolverOptions
    tolerance(const double value)
    {
      SolverOptions options;
      options.tolerance = value;
      return options;
    }

    const ContactProblem  p;
    const SolverOptions   o;
    std::vector<double>   history;
    ConvergenceMonitor    monitor;
    const Eigen::VectorXd r;
  };
} // namespace



// Converged at the tolerance, diverged on a non-finite residual, and every
// observed residual in the history.
TEST_F(NsgsMonitor, Verdicts)
{
  using Verdict = ConvergenceMonitor::Verdict;
  EXPECT_EQ(monitor.observe(figures(1e-3), r), Verdict::iterate);
  EXPECT_EQ(monitor.observe(figures(1e-8), r), Verdict::converged);
  EXPECT_EQ(monitor.observe(figures(std::nan("")), r), Verdict::diverged);
  EXPECT_EQ(history.size(), 3u);
  SolverResult result;
  EXPECT_TRUE(monitor.stops(Verdict::diverged, result));
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.message, "NSGS diverged (non-finite residual)");
  EXPECT_FALSE(monitor.stops(Verdict::iterate, result));
  EXPECT_EQ(monitor.iteration_limit_message(), "NSGS: iteration limit reached");
}



// With equality rows, the violation is measured against ||G|| ||r|| + ||e||.
TEST(Monitor, EqualityRows)
{
  ContactProblem p = random_problem(2, 2, 0.3, 1);
  p.G              = Eigen::MatrixXd::Zero(1, 4);
  p.G(0, 0)        = 2.0;
  p.e              = Eigen::VectorXd::Constant(1, -1.0);
  SolverOptions o;
  o.tolerance = 1e-6;
  std::vector<double>   history;
  ConvergenceMonitor    monitor(p, o, "splitting", "iterations", history);
  const Eigen::VectorXd r = Eigen::VectorXd::Constant(4, -0.5);
  EXPECT_DOUBLE_EQ(equality_scale(p.G, p.e, r), 2.0 * 0.5 + 1.0);
  EXPECT_TRUE(monitor.meets_tolerance(figures(1e-7, 1.9e-6), r));
  EXPECT_FALSE(monitor.meets_tolerance(figures(1e-7, 2.1e-6), r));
}



// A stall is stall_iterations observations without a new minimum by a
// factor 0.99; a restart counts again from the given residual.
TEST(Monitor, Stall)
{
  const ContactProblem p = random_problem(2, 3, 0.3, 1);
  SolverOptions        o;
  o.stall_iterations = 3;
  std::vector<double> history;
  ConvergenceMonitor  monitor(p, o, "splitting", "iterations", history);
  EXPECT_FALSE(monitor.stalled(1.0));
  EXPECT_FALSE(monitor.stalled(0.995)); // not 1 % below the minimum
  EXPECT_FALSE(monitor.stalled(0.98));  // new minimum
  EXPECT_FALSE(monitor.stalled(0.98));
  EXPECT_FALSE(monitor.stalled(0.98));
  EXPECT_TRUE(monitor.stalled(0.98));
  monitor.restart_stall_count(0.98);
  EXPECT_FALSE(monitor.stalled(0.975));
  EXPECT_EQ(monitor.stall_message("cycling"),
            "splitting did not converge: no residual decrease in 3 "
            "iterations (cycling)");
}



// At the iteration cap the message says how far the solver is: the
// residual, its mean rate per iteration and the iterations still needed at
// that rate (residuals 1e-2, 1e-3, 1e-4: a factor 0.1 per sweep, 4 more to
// 1e-8), or that it is not falling.
TEST_F(NsgsMonitor, IterationLimitMessageGivesTheRate)
{
  for (const double x : {1e-2, 1e-3, 1e-4})
    monitor.observe(figures(x), r);
  EXPECT_EQ(monitor.iteration_limit_message(),
            "NSGS: iteration limit reached (residual 1.00e-04, falling by a "
            "factor 0.100000 per sweep: about 4 more sweeps needed)");
  monitor.observe(figures(1e-2), r);
  EXPECT_EQ(monitor.iteration_limit_message(),
            "NSGS: iteration limit reached (residual 1.00e-02, not falling "
            "over the last 3 sweeps)");
}
