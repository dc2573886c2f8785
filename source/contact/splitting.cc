#include <dpana/contact/friction_qp.h>
#include <dpana/contact/friction_set.h>
#include <dpana/contact/normal_lcp.h>
#include <dpana/contact/splitting.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace dpana
{
  namespace contact
  {
    namespace
    {
      std::string
      scientific(const double x)
      {
        char buffer[32];
        std::snprintf(buffer, sizeof(buffer), "%.3e", x);
        return buffer;
      }
    } // namespace



    SolverResult
    solve_splitting(const ContactProblem  &problem,
                    const SolverOptions   &options,
                    const Eigen::VectorXd *initial_r)
    {
      const unsigned int d    = problem.dim;
      const unsigned int m    = d - 1;
      const unsigned int n    = problem.n_elements();
      const Eigen::Index me   = problem.n_equalities();
      const Eigen::Index size = problem.D.size();
      const FrictionSet  set(problem);
      const double       rho     = residual_rho(problem);
      const bool         use_pgs = options.type == SolverType::splitting_pgs;

      // @sect4{Blocks, extracted once}
      auto nidx = [d](const unsigned int j) { return d * j; };
      auto tidx = [d](const unsigned int j, const unsigned int a) {
        return d * j + 1 + a;
      };
      Eigen::MatrixXd A_NN(n, n), A_TT(m * n, m * n), A_TN(m * n, n);
      Eigen::VectorXd D_N(n), D_T(m * n);
      for (unsigned int k = 0; k < n; ++k)
        {
          for (unsigned int j = 0; j < n; ++j)
            A_NN(j, k) = problem.A(nidx(j), nidx(k));
          for (unsigned int j = 0; j < n; ++j)
            for (unsigned int a = 0; a < m; ++a)
              A_TN(m * j + a, k) = problem.A(tidx(j, a), nidx(k));
          for (unsigned int b = 0; b < m; ++b)
            for (unsigned int j = 0; j < n; ++j)
              for (unsigned int a = 0; a < m; ++a)
                A_TT(m * j + a, m * k + b) = problem.A(tidx(j, a), tidx(k, b));
          D_N[k] = problem.D[nidx(k)];
          for (unsigned int a = 0; a < m; ++a)
            D_T[m * k + a] = problem.D[tidx(k, a)];
        }

      // Equality rows: "normal rows" (with a normal entry) go to the N-step,
      // purely tangential rows to the T-step.
      std::vector<Eigen::Index> normal_rows, tangential_rows;
      for (Eigen::Index i = 0; i < me; ++i)
        {
          bool has_normal = false;
          for (unsigned int j = 0; j < n; ++j)
            has_normal = has_normal || problem.G(i, nidx(j)) != 0.0;
          (has_normal ? normal_rows : tangential_rows).push_back(i);
        }
      const Eigen::Index mN = normal_rows.size(), mT = tangential_rows.size();
      Eigen::MatrixXd    G_NN(mN, n), G_NT(mN, m * n), G_TT(mT, m * n);
      Eigen::VectorXd    e_N(mN), e_T(mT);
      for (Eigen::Index i = 0; i < mN; ++i)
        {
          for (unsigned int j = 0; j < n; ++j)
            {
              G_NN(i, j) = problem.G(normal_rows[i], nidx(j));
              for (unsigned int a = 0; a < m; ++a)
                G_NT(i, m * j + a) = problem.G(normal_rows[i], tidx(j, a));
            }
          e_N[i] = problem.e[normal_rows[i]];
        }
      for (Eigen::Index i = 0; i < mT; ++i)
        {
          for (unsigned int j = 0; j < n; ++j)
            for (unsigned int a = 0; a < m; ++a)
              G_TT(i, m * j + a) = problem.G(tangential_rows[i], tidx(j, a));
          e_T[i] = problem.e[tangential_rows[i]];
        }

      InnerOptions inner;
      inner.tolerance       = options.inner_tolerance;
      inner.max_iterations  = options.inner_max_iterations;
      inner.over_relaxation = options.over_relaxation;
      inner.augmentation    = options.augmentation;
      NormalLcp  normal(A_NN, G_NN, inner);
      FrictionQp friction(A_TT, G_TT, set, inner);

      // @sect4{Start}
      Eigen::VectorXd N = Eigen::VectorXd::Zero(n),
                      T = Eigen::VectorXd::Zero(m * n);
      if (initial_r)
        for (unsigned int j = 0; j < n; ++j)
          {
            N[j] = std::min(0.0, (*initial_r)[nidx(j)]);
            for (unsigned int a = 0; a < m; ++a)
              T[m * j + a] = (*initial_r)[tidx(j, a)];
          }
      Eigen::VectorXd alpha_N = Eigen::VectorXd::Zero(mN),
                      alpha_T = Eigen::VectorXd::Zero(mT);
      Eigen::VectorXd b(n), c(m * n), radius(n), e_shifted(mN), u(size),
        r_old(size);

      SolverResult result;
      result.r      = Eigen::VectorXd::Zero(size);
      result.alpha  = Eigen::VectorXd::Zero(me);
      auto assemble = [&]() {
        for (unsigned int j = 0; j < n; ++j)
          {
            result.r[nidx(j)] = N[j];
            for (unsigned int a = 0; a < m; ++a)
              result.r[tidx(j, a)] = T[m * j + a];
          }
        for (Eigen::Index i = 0; i < mN; ++i)
          result.alpha[normal_rows[i]] = alpha_N[i];
        for (Eigen::Index i = 0; i < mT; ++i)
          result.alpha[tangential_rows[i]] = alpha_T[i];
      };
      assemble();

      // Without a start value, begin with an N-step at T = 0: the
      // frictionless solution, which is what the first T-step (with all
      // friction radii zero) followed by an N-step would give anyway; doing
      // it first also keeps purely tangential equality rows (infeasible with
      // zero radii) out of the first T-step.
      if (!initial_r)
        {
          b = D_N;
          if (mN > 0)
            e_shifted = e_N;
          const InnerResult r0 =
            use_pgs ? normal.solve_pgs(b, e_shifted, N, alpha_N) :
                      normal.solve_active_set(b, e_shifted, N, alpha_N);
          result.inner_iterations += r0.iterations;
        }

      double       best       = std::numeric_limits<double>::max();
      unsigned int since_best = 0;
      std::string  inner_message;
      bool         exact_inner         = false;
      double       inner_tolerance_now = options.inner_tolerance;

      for (unsigned int k = 1; k <= options.max_iterations; ++k)
        {
          result.iterations = k;
          r_old             = result.r;
          inner_message.clear();

          // Inexact inner solves: tolerance 0.1 times the last outer
          // residual, between inner_tolerance and 1e-4 (exact solves of
          // subproblems whose data are still far from converged are wasted).
          if (options.adaptive_inner_tolerance && !exact_inner)
            {
              const double last = result.residual_history.empty() ?
                                    1e-4 :
                                    0.1 * result.residual_history.back();
              const double t =
                std::max(options.inner_tolerance, std::min(1e-4, last));
              normal.set_tolerance(t);
              friction.set_tolerance(t);
              inner_tolerance_now = t;
            }
          else
            {
              normal.set_tolerance(options.inner_tolerance);
              friction.set_tolerance(options.inner_tolerance);
              inner_tolerance_now = options.inner_tolerance;
            }

          // T-step at fixed N.
          for (unsigned int j = 0; j < n; ++j)
            radius[j] = std::max(0.0, -problem.mu[j] * N[j]);
          c = D_T;
          c.noalias() += A_TN * N;
          if (mN > 0)
            c.noalias() += G_NT.transpose() * alpha_N;
          const InnerResult rt =
            use_pgs ? friction.solve_pgs(c, radius, e_T, T, alpha_T) :
                      friction.solve_active_set(c, radius, e_T, T, alpha_T);
          result.inner_iterations += rt.iterations;
          if (!rt.converged)
            {
              inner_message = rt.message;
              // Do not carry multipliers of a failed solve into the next.
              if (!alpha_T.allFinite() || mT > 0)
                alpha_T.setZero();
            }

          // N-step at fixed T.
          b = D_N;
          b.noalias() += A_TN.transpose() * T;
          if (mN > 0)
            {
              e_shifted = e_N;
              e_shifted.noalias() -= G_NT * T;
            }
          const InnerResult rn =
            use_pgs ? normal.solve_pgs(b, e_shifted, N, alpha_N) :
                      normal.solve_active_set(b, e_shifted, N, alpha_N);
          result.inner_iterations += rn.iterations;
          if (!rn.converged)
            {
              inner_message = rn.message;
              if (!alpha_N.allFinite())
                alpha_N.setZero();
            }

          // Shared residual of the full problem.
          assemble();
          u.noalias() = problem.A * result.r;
          u += problem.D;
          if (me > 0)
            u.noalias() += problem.G.transpose() * result.alpha;
          const ResidualFigures figures =
            compute_residual_from_u(problem, set, rho, result.r, u);
          result.residual_history.push_back(figures.natural_map);
          const double r_norm = result.r.lpNorm<Eigen::Infinity>();
          const double change =
            (r_norm > 0.0) ?
              (result.r - r_old).lpNorm<Eigen::Infinity>() / r_norm :
              0.0;

          const double eq_scale =
            (me > 0) ? problem.G.lpNorm<Eigen::Infinity>() * r_norm +
                         problem.e.lpNorm<Eigen::Infinity>() :
                       0.0;
          if (figures.natural_map <= options.tolerance &&
              figures.equilibrium <= options.tolerance * eq_scale)
            {
              result.converged = true;
              result.message   = "converged";
              return result;
            }
          if (!std::isfinite(figures.natural_map))
            {
              result.message = "splitting diverged (non-finite residual)";
              return result;
            }
          if (change <= 1e-15 && inner_tolerance_now > options.inner_tolerance)
            {
              // No progress with inexact inner solves: go on with exact ones.
              exact_inner = true;
              continue;
            }
          if (change <= 1e-15)
            {
              result.message =
                "splitting stagnated: fixed point reached with residual " +
                scientific(figures.natural_map) + " above tolerance (" +
                (inner_message.empty() ?
                   std::string("the inner tolerance limits the residual)") :
                   "inner solver failed: " + inner_message + ")");
              return result;
            }
          if (figures.natural_map < 0.99 * best)
            {
              best       = figures.natural_map;
              since_best = 0;
            }
          else if (++since_best >= options.stall_iterations)
            {
              result.message =
                "splitting did not converge: no residual decrease in " +
                std::to_string(options.stall_iterations) +
                " iterations (cycling or divergence of the fixed point)";
              return result;
            }
        }
      result.message = "splitting: iteration limit reached";
      if (!inner_message.empty())
        result.message += " (" + inner_message + ")";
      return result;
    }
  } // namespace contact
} // namespace dpana
