#include <dpana/contact/alart_curnier.h>
#include <dpana/contact/nsgs.h>
#include <dpana/contact/solver.h>
#include <dpana/contact/splitting.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>
#include <vector>

namespace dpana
{
  namespace contact
  {
    namespace
    {
      // The one list of the solvers and their names, the default first.
      const std::array<std::pair<SolverType, const char *>, 4> solver_names = {
        {{SolverType::splitting_active_set, "splitting_active_set"},
         {SolverType::splitting_pgs, "splitting_pgs"},
         {SolverType::nsgs, "nsgs"},
         {SolverType::alart_curnier, "alart_curnier"}}};



      // The final displacements, figures and statuses, from scratch.
      void
      finish(const ContactProblem &problem,
             const SolverOptions  &options,
             SolverResult         &result)
      {
        result.u = problem.A * result.r + problem.D;
        if (problem.n_equalities() > 0)
          result.u.noalias() += problem.G.transpose() * result.alpha;
        const FrictionSet set(problem);
        result.figures = compute_residual_from_u(
          problem, set, residual_rho(problem), result.r, result.u);
        result.residual = result.figures.natural_map;
        // A solution to the relative residual tol has a sticking element
        // slide by up to tol S(r) / rho_j: below tau = tol it is told from
        // a slipping one (residual.h), so tau is at least tol; the traction
        // threshold of separation grows with it.
        result.status = classify(problem,
                                 result.r,
                                 result.u,
                                 std::max(options.classification_tolerance,
                                          options.tolerance));
      }



      // One solver, without fallback.
      SolverResult
      solve_with(const ContactProblem  &problem,
                 const SolverType       type,
                 const SolverOptions   &options,
                 const Eigen::VectorXd *initial_r)
      {
        SolverResult result;
        switch (type)
          {
            case SolverType::nsgs:
              result = solve_nsgs(problem, options, initial_r);
              break;
            case SolverType::alart_curnier:
              result = solve_alart_curnier(problem, options, initial_r);
              break;
            default:
              result = solve_splitting(problem, options, initial_r);
              break;
          }
        result.solver = type;
        finish(problem, options, result);
        return result;
      }



      // The options of a fallback solver: NSGS, the last resort, converges
      // linearly at a rate set by the conditioning of A and may need tens of
      // thousands of sweeps (the 3D block: 2e4 - 3.5e4), so it gets 100
      // times the iteration cap; its stall test still stops it early where
      // it cycles or the problem has no solution.
      SolverOptions
      fallback_options(const SolverOptions &options, const SolverType type)
      {
        SolverOptions o = options;
        if (type == SolverType::nsgs)
          o.max_iterations = options.max_iterations >= 100000000u ?
                               options.max_iterations :
                               100 * options.max_iterations;
        return o;
      }



      // The robust mode of the splitting (SolverOptions::fallback):
      // Alart-Curnier from the splitting's last iterate, then NSGS from the
      // best iterate so far. The answer with the smallest residual is
      // returned, with the stop messages of the solvers tried before it.
      SolverResult
      fall_back(const ContactProblem &problem,
                const SolverOptions  &options,
                SolverResult          first)
      {
        std::vector<SolverResult> attempts;
        attempts.push_back(std::move(first));
        std::size_t best = 0;
        for (const SolverType next :
             {SolverType::alart_curnier, SolverType::nsgs})
          {
            const Eigen::VectorXd &r_best = attempts[best].r;
            const Eigen::VectorXd  start =
              r_best.allFinite() ? r_best :
                                    Eigen::VectorXd::Zero(problem.D.size());
            attempts.push_back(solve_with(
              problem, next, fallback_options(options, next), &start));
            const SolverResult &last = attempts.back();
            if (last.converged || last.residual < attempts[best].residual)
              best = attempts.size() - 1;
            if (last.converged)
              break;
          }
        // The history of every outer iteration of every solver, in order.
        std::vector<double> history;
        for (const SolverResult &attempt : attempts)
          history.insert(history.end(),
                         attempt.residual_history.begin(),
                         attempt.residual_history.end());
        SolverResult result     = std::move(attempts[best]);
        result.residual_history = std::move(history);
        for (std::size_t i = 0; i < attempts.size(); ++i)
          if (i != best)
            {
              result.fallbacks.push_back(to_string(attempts[i].solver) + ": " +
                                         attempts[i].message);
              result.inner_iterations += attempts[i].inner_iterations;
            }
        std::string before;
        for (const std::string &entry : result.fallbacks)
          before += (before.empty() ? "" : "; ") + entry;
        if (result.converged)
          result.message += " by " + to_string(result.solver) +
                            " (fallback after " + before + ")";
        else
          result.message = "no solver converged; the answer of " +
                           to_string(result.solver) + " (" + result.message +
                           ") has the smallest residual; the others: " + before;
        return result;
      }
    } // namespace



    SolverType
    solver_type_from_string(const std::string &name)
    {
      for (const auto &entry : solver_names)
        if (name == entry.second)
          return entry.first;
      std::string expected;
      for (std::size_t i = 0; i < solver_names.size(); ++i)
        expected += std::string(i == 0                       ? "" :
                                i + 1 == solver_names.size() ? " or " :
                                                               ", ") +
                    solver_names[i].second;
      throw std::invalid_argument("contact solver: unknown solver type '" +
                                  name + "' (expected " + expected + ")");
    }



    std::string
    to_string(const SolverType type)
    {
      for (const auto &entry : solver_names)
        if (type == entry.first)
          return entry.second;
      return "unknown";
    }



    std::string
    solver_type_names()
    {
      std::string names;
      for (const auto &entry : solver_names)
        names += (names.empty() ? "" : "|") + std::string(entry.second);
      return names;
    }



    void
    validate(const SolverOptions &options)
    {
      auto fail = [](const std::string &message) {
        throw std::invalid_argument("contact solver options: " + message);
      };
      if (!(options.tolerance > 0.0))
        fail("tolerance must be positive");
      if (!(options.inner_tolerance > 0.0))
        fail("inner_tolerance must be positive");
      if (options.max_iterations == 0)
        fail("max_iterations must be positive");
      if (options.inner_max_iterations == 0)
        fail("inner_max_iterations must be positive");
      if (!(options.over_relaxation > 0.0 && options.over_relaxation < 2.0))
        fail("over_relaxation must lie in (0, 2)");
      if (options.stall_iterations == 0)
        fail("stall_iterations must be positive");
      if (!(options.classification_tolerance >= 0.0))
        fail("classification_tolerance must be >= 0");
      if (!(options.augmentation > 0.0))
        fail("augmentation must be positive");
    }



    SolverResult
    solve(const ContactProblem  &problem,
          const SolverOptions   &options,
          const Eigen::VectorXd *initial_r)
    {
      problem.validate();
      validate(options);
      if (initial_r && initial_r->size() != problem.D.size())
        throw std::invalid_argument(
          "contact solver: initial_r must have size " +
          std::to_string(problem.D.size()));
      if (initial_r && !initial_r->allFinite())
        throw std::invalid_argument(
          "contact solver: initial_r has a non-finite entry");

      SolverResult result;
      if (problem.n_elements() == 0)
        {
          result.alpha     = Eigen::VectorXd::Zero(problem.n_equalities());
          result.converged = true;
          result.message   = "empty problem";
          return result;
        }

      result = solve_with(problem, options.type, options, initial_r);
      const bool splitting = options.type == SolverType::splitting_pgs ||
                             options.type == SolverType::splitting_active_set;
      if (!result.converged && splitting && options.fallback)
        result = fall_back(problem, options, std::move(result));
      return result;
    }
  } // namespace contact
} // namespace dpana
