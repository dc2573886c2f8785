#include <dpana/contact/alart_curnier.h>
#include <dpana/contact/nsgs.h>
#include <dpana/contact/solver.h>
#include <dpana/contact/splitting.h>

#include <array>
#include <stdexcept>
#include <utility>

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

      switch (options.type)
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

      // Final displacements, figures and statuses from scratch.
      result.u = problem.A * result.r + problem.D;
      if (problem.n_equalities() > 0)
        result.u.noalias() += problem.G.transpose() * result.alpha;
      const FrictionSet set(problem);
      result.figures = compute_residual_from_u(
        problem, set, residual_rho(problem), result.r, result.u);
      result.residual = result.figures.natural_map;
      result.status =
        classify(problem, result.r, result.u, options.classification_tolerance);
      return result;
    }
  } // namespace contact
} // namespace dpana
