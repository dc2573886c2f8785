#include <dpana/contact/monitor.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace dpana
{
  namespace contact
  {
    double
    equality_scale(const Eigen::MatrixXd &G,
                   const Eigen::VectorXd &e,
                   const Eigen::VectorXd &x)
    {
      if (G.rows() == 0)
        return 0.0;
      return G.lpNorm<Eigen::Infinity>() * x.lpNorm<Eigen::Infinity>() +
             e.lpNorm<Eigen::Infinity>();
    }



    ConvergenceMonitor::ConvergenceMonitor(const ContactProblem &problem,
                                           const SolverOptions  &options,
                                           const std::string    &name,
                                           const std::string    &unit,
                                           std::vector<double>  &history)
      : tolerance(options.tolerance)
      , stall_iterations(options.stall_iterations)
      , G(problem.G)
      , e(problem.e)
      , name(name)
      , unit(unit)
      , history(history)
      , best(std::numeric_limits<double>::max())
    {
    }



    bool
    ConvergenceMonitor::meets_tolerance(const ResidualFigures &figures,
                                        const Eigen::VectorXd &r) const
    {
      return figures.natural_map <= tolerance &&
             figures.equilibrium <= tolerance * equality_scale(G, e, r);
    }



    ConvergenceMonitor::Verdict
    ConvergenceMonitor::observe(const ResidualFigures &figures,
                                const Eigen::VectorXd &r)
    {
      history.push_back(figures.natural_map);
      if (meets_tolerance(figures, r))
        return Verdict::converged;
      if (!std::isfinite(figures.natural_map))
        return Verdict::diverged;
      return Verdict::iterate;
    }



    bool
    ConvergenceMonitor::stalled(const double residual)
    {
      if (residual < 0.99 * best)
        {
          best       = residual;
          since_best = 0;
          return false;
        }
      return ++since_best >= stall_iterations;
    }



    void
    ConvergenceMonitor::restart_stall_count(const double residual)
    {
      best       = residual;
      since_best = 0;
    }



    std::string
    ConvergenceMonitor::message(const Verdict verdict) const
    {
      switch (verdict)
        {
          case Verdict::converged:
            return "converged";
          case Verdict::diverged:
            return name + " diverged (non-finite residual)";
          case Verdict::iterate:
            break;
        }
      return "";
    }



    bool
    ConvergenceMonitor::stops(const Verdict verdict, SolverResult &result) const
    {
      if (verdict == Verdict::iterate)
        return false;
      result.converged = (verdict == Verdict::converged);
      result.message   = message(verdict);
      return true;
    }



    std::string
    ConvergenceMonitor::stall_message(const std::string &detail) const
    {
      return name + " did not converge: no residual decrease in " +
             std::to_string(stall_iterations) + " " + unit + " (" + detail +
             ")";
    }



    std::string
    ConvergenceMonitor::iteration_limit_message() const
    {
      std::string       message = name + ": iteration limit reached";
      const std::size_t k       = history.size();
      if (k < 2 || !(history.back() > 0.0))
        return message;
      // The mean rate over the last (at most 100) iterations and the
      // iterations it would still need at that rate.
      const std::size_t span  = std::min<std::size_t>(100, k - 1);
      const double      first = history[k - 1 - span];
      const double      rate =
        (first > 0.0) ? std::pow(history.back() / first, 1.0 / span) : 1.0;
      char buffer[160];
      if (rate < 1.0)
        std::snprintf(buffer,
                      sizeof(buffer),
                      " (residual %.2e, falling by a factor %.6f per %s: "
                      "about %.2g more %s needed)",
                      history.back(),
                      rate,
                      unit.substr(0, unit.size() - 1).c_str(),
                      std::log(tolerance / history.back()) / std::log(rate),
                      unit.c_str());
      else
        std::snprintf(buffer,
                      sizeof(buffer),
                      " (residual %.2e, not falling over the last %zu %s)",
                      history.back(),
                      span,
                      unit.c_str());
      return message + buffer;
    }
  } // namespace contact
} // namespace dpana
