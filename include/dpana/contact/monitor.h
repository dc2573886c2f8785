// The stopping and stall tests shared by the iterative contact solvers of
// dpana (the D-PANA splitting, NSGS, Alart-Curnier), next to the residual
// they test (residual.h).
//
// @sect3{The stopping test}
//
// An iterate (r, alpha) with figures computed by compute_residual_from_u()
// is converged when
// @f[
//   \mathrm{natural\_map} \le \mathrm{tol}
//   \quad\text{and}\quad
//   \|G r - e\|_\infty \le \mathrm{tol}\,
//     \big(\|G\|_\infty \|r\|_\infty + \|e\|_\infty\big),
// @f]
// the second condition being void without equality rows. A non-finite
// residual stops the solver as diverged.
//
// @sect3{The stall test}
//
// The solver has stalled (it cycles, or the fixed point diverges slowly)
// when the residual has not reached a new minimum, by a factor 0.99, for
// SolverOptions::stall_iterations consecutive iterations. A solver that has
// a remedy (NSGS halves its relaxation) applies it and restarts the count
// from the current residual.
//
// @sect3{Messages}
//
// All the stop messages are formed here, from the solver's name and the name
// of its iterations: "converged", "NAME diverged (non-finite residual)",
// "NAME did not converge: no residual decrease in K UNIT (DETAIL)" and
// "NAME: iteration limit reached".
#ifndef dpana_contact_monitor_h
#define dpana_contact_monitor_h

#include <dpana/contact/residual.h>
#include <dpana/contact/solver.h>

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace dpana
{
  namespace contact
  {
    // The scale ||G||_inf ||x||_inf + ||e||_inf of the equality rows G x = e
    // (||G||_inf the largest entry in absolute value), against which their
    // violation is measured; 0 when there are no rows.
    double
    equality_scale(const Eigen::MatrixXd &G,
                   const Eigen::VectorXd &e,
                   const Eigen::VectorXd &x);

    class ConvergenceMonitor
    {
    public:
      // What an observed iterate means for the iteration.
      enum class Verdict
      {
        iterate,   // go on
        converged, // the stopping test holds
        diverged   // non-finite residual
      };

      // name: the solver in the messages ("splitting", "NSGS", ...); unit:
      // its iterations ("iterations", "sweeps"). The residual history is
      // appended to @p history (SolverResult::residual_history).
      ConvergenceMonitor(const ContactProblem &problem,
                         const SolverOptions  &options,
                         const std::string    &name,
                         const std::string    &unit,
                         std::vector<double>  &history);

      // The stopping test alone (see above) for the figures of tractions r.
      bool
      meets_tolerance(const ResidualFigures &figures,
                      const Eigen::VectorXd &r) const;

      // Record the residual of the iterate in the history, then apply the
      // stopping test and the divergence test.
      Verdict
      observe(const ResidualFigures &figures, const Eigen::VectorXd &r);

      // The stall test: true when the residual has not reached a new
      // minimum (by a factor 0.99) for stall_iterations calls.
      bool
      stalled(const double residual);

      // Start the stall count again from @p residual (after a remedy).
      void
      restart_stall_count(const double residual);

      // The message of a verdict that stops the solver (converged or
      // diverged); empty for iterate.
      std::string
      message(const Verdict verdict) const;

      // For a verdict that stops the solver (converged or diverged): set
      // result.converged and result.message and return true; otherwise
      // return false.
      bool
      stops(const Verdict verdict, SolverResult &result) const;

      // The message of a stall; detail: the solver's explanation.
      std::string
      stall_message(const std::string &detail) const;

      // "NAME: iteration limit reached (residual R, falling by a factor q
      // per UNIT: about K more UNITs needed)", q the mean rate of the last
      // 100 iterations (or "not falling" when q >= 1): where a linearly
      // converging solver (NSGS on an ill-conditioned A) cannot get within
      // its iteration cap, the message says how far it is.
      std::string
      iteration_limit_message() const;

    private:
      const double           tolerance;
      const unsigned int     stall_iterations;
      const Eigen::MatrixXd &G; // equality rows G r = e
      const Eigen::VectorXd &e;
      const std::string      name, unit;
      std::vector<double>   &history;
      double                 best;
      unsigned int           since_best = 0;
    };
  } // namespace contact
} // namespace dpana

#endif
