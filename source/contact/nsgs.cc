#include <dpana/contact/friction_set.h>
#include <dpana/contact/local_coulomb.h>
#include <dpana/contact/nsgs.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dpana
{
  namespace contact
  {
    SolverResult
    solve_nsgs(const ContactProblem  &problem,
               const SolverOptions   &options,
               const Eigen::VectorXd *initial_r)
    {
      const unsigned int d    = problem.dim;
      const unsigned int n    = problem.n_elements();
      const Eigen::Index me   = problem.n_equalities();
      const Eigen::Index size = problem.D.size();
      const FrictionSet  set(problem);
      const double       rho = residual_rho(problem);

      // With equality rows the sweeps run on the augmented matrix.
      double          penalty = 0.0;
      Eigen::MatrixXd A_augmented;
      if (me > 0)
        {
          const double g2 = problem.G.squaredNorm();
          penalty =
            (g2 > 0.0) ? options.augmentation * problem.A.trace() / g2 : 0.0;
          A_augmented = problem.A;
          A_augmented.noalias() += penalty * problem.G.transpose() * problem.G;
        }
      const Eigen::MatrixXd &A = (me > 0) ? A_augmented : problem.A;

      // Row-major diagonal blocks.
      std::vector<double> W(d * d * n);
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int a = 0; a < d; ++a)
          for (unsigned int b = 0; b < d; ++b)
            W[d * d * j + d * a + b] = A(d * j + a, d * j + b);

      SolverResult result;
      result.r           = initial_r ? *initial_r : Eigen::VectorXd::Zero(size);
      result.alpha       = Eigen::VectorXd::Zero(me);
      Eigen::VectorXd &r = result.r;
      Eigen::VectorXd &alpha = result.alpha;

      // w = A r + D + G^T (alpha - rho e): the displacements seen by the
      // local problems.
      Eigen::VectorXd w(size), u(size), violation(me);
      auto            recompute_w = [&]() {
        w.noalias() = A * r;
        w += problem.D;
        if (me > 0)
          w.noalias() += problem.G.transpose() * (alpha - penalty * problem.e);
      };
      recompute_w();

      std::vector<double> hint(n, 0.0);
      double              best       = std::numeric_limits<double>::max();
      unsigned int        since_best = 0;
      double              omega      = options.over_relaxation;
      unsigned int        reductions = 0;

      for (unsigned int sweep = 1; sweep <= options.max_iterations; ++sweep)
        {
          result.iterations = sweep;
          for (unsigned int j = 0; j < n; ++j)
            {
              const double *Wj = W.data() + d * d * j;
              double       *rj = r.data() + d * j;
              double        q[3], x[3], delta[3];
              for (unsigned int a = 0; a < d; ++a)
                {
                  q[a] = w[d * j + a];
                  for (unsigned int b = 0; b < d; ++b)
                    q[a] -= Wj[d * a + b] * rj[b];
                }
              solve_local_coulomb(set, problem.mu[j], Wj, q, x, hint[j]);
              if (omega != 1.0)
                {
                  double z[3];
                  for (unsigned int a = 0; a < d; ++a)
                    z[a] = (1.0 - omega) * rj[a] + omega * x[a];
                  set.project_cone(problem.mu[j], z, x);
                }
              bool moved = false;
              for (unsigned int a = 0; a < d; ++a)
                {
                  delta[a] = x[a] - rj[a];
                  moved    = moved || delta[a] != 0.0;
                  rj[a]    = x[a];
                }
              if (moved)
                {
                  if (d == 2)
                    w.noalias() += A.middleCols<2>(2 * j) *
                                   Eigen::Vector2d(delta[0], delta[1]);
                  else
                    w.noalias() +=
                      A.middleCols<3>(3 * j) *
                      Eigen::Vector3d(delta[0], delta[1], delta[2]);
                }
            }

          if (sweep % 100 == 0)
            recompute_w();

          // Multiplier update; u is then exactly the current w.
          u = w;
          if (me > 0)
            {
              violation = problem.G * r - problem.e;
              alpha += penalty * violation;
              w.noalias() += penalty * (problem.G.transpose() * violation);
            }
          ResidualFigures figures =
            compute_residual_from_u(problem, set, rho, r, u);
          const double eq_scale = (me > 0) ?
                                    problem.G.lpNorm<Eigen::Infinity>() *
                                        r.lpNorm<Eigen::Infinity>() +
                                      problem.e.lpNorm<Eigen::Infinity>() :
                                    0.0;
          bool         done     = figures.natural_map <= options.tolerance &&
                      figures.equilibrium <= options.tolerance * eq_scale;
          if (done)
            {
              // Confirm with displacements computed from scratch.
              u.noalias() = problem.A * r;
              u += problem.D;
              if (me > 0)
                u.noalias() += problem.G.transpose() * alpha;
              figures = compute_residual_from_u(problem, set, rho, r, u);
              done    = figures.natural_map <= options.tolerance &&
                     figures.equilibrium <= options.tolerance * eq_scale;
              if (!done)
                recompute_w();
            }
          result.residual_history.push_back(figures.natural_map);
          if (done)
            {
              result.converged = true;
              result.message   = "converged";
              if (reductions > 0)
                result.message +=
                  " (relaxation reduced to omega = " + std::to_string(omega) +
                  ")";
              return result;
            }
          if (figures.natural_map < 0.99 * best)
            {
              best       = figures.natural_map;
              since_best = 0;
            }
          else if (++since_best >= options.stall_iterations)
            {
              // Stall or cycling: under-relax (omega halves, at most six
              // times) before giving up.
              if (options.adaptive_relaxation && reductions < 6)
                {
                  omega *= 0.5;
                  ++reductions;
                  since_best = 0;
                  best       = figures.natural_map;
                  continue;
                }
              result.message = "NSGS stalled: no residual decrease in " +
                               std::to_string(options.stall_iterations) +
                               " sweeps (omega = " + std::to_string(omega) +
                               ")";
              return result;
            }
          if (!std::isfinite(figures.natural_map))
            {
              result.message = "NSGS diverged (non-finite residual)";
              return result;
            }
        }
      result.message = "NSGS: iteration limit reached";
      return result;
    }
  } // namespace contact
} // namespace dpana
