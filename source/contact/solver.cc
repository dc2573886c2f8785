#include <dpana/contact/alart_curnier.h>
#include <dpana/contact/nsgs.h>
#include <dpana/contact/solver.h>
#include <dpana/contact/splitting.h>

#include <stdexcept>

namespace dpana
{
  namespace contact
  {
    SolverType
    solver_type_from_string(const std::string &name)
    {
      if (name == "splitting_pgs")
        return SolverType::splitting_pgs;
      if (name == "splitting_active_set")
        return SolverType::splitting_active_set;
      if (name == "nsgs")
        return SolverType::nsgs;
      if (name == "alart_curnier")
        return SolverType::alart_curnier;
      throw std::invalid_argument(
        "contact solver: unknown solver type '" + name +
        "' (expected splitting_pgs, splitting_active_set, nsgs or "
        "alart_curnier)");
    }



    std::string
    to_string(const SolverType type)
    {
      switch (type)
        {
          case SolverType::splitting_pgs:
            return "splitting_pgs";
          case SolverType::splitting_active_set:
            return "splitting_active_set";
          case SolverType::nsgs:
            return "nsgs";
          case SolverType::alart_curnier:
            return "alart_curnier";
        }
      return "unknown";
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
