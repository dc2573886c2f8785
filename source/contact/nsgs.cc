#include <dpana/contact/friction_set.h>
#include <dpana/contact/local_coulomb.h>
#include <dpana/contact/monitor.h>
#include <dpana/contact/nsgs.h>
#include <dpana/contact/projected_gauss_seidel.h>

#include <string>
#include <vector>

namespace dpana
{
  namespace contact
  {
    namespace
    {
      // The sweeps of NSGS on one problem: the (augmented) matrix, its
      // diagonal blocks, the iterate and the displacements w seen by the
      // local problems; run() is the algorithm of nsgs.h.
      class Nsgs
      {
      public:
        Nsgs(const ContactProblem  &problem,
             const SolverOptions   &options,
             const Eigen::VectorXd *initial_r);

        SolverResult
        run();

      private:
        // One sweep over the elements with relaxation omega.
        void
        sweep(const double omega);

        // The exact local solve of element j, relaxed, and the column update
        // of w.
        void
        local_step(const unsigned int j, const double omega);

        // w = A r + D + G^T (alpha - penalty e) from scratch.
        void
        recompute_w();

        // The multiplier update after a sweep and the figures at u = w
        // (exact for the new alpha and the sweep just made).
        ResidualFigures
        update_multipliers();

        // The figures with u computed from scratch, to confirm convergence
        // (w is recomputed as well if they miss the tolerance).
        ResidualFigures
        confirm(const ConvergenceMonitor &monitor);

        const ContactProblem  &problem;
        const SolverOptions   &options;
        const unsigned int     d, n;
        const FrictionSet      set;
        const Eigen::VectorXd  rho;
        double                 penalty = 0.0;
        Eigen::MatrixXd        A_augmented;
        const Eigen::MatrixXd &A; // A, or A + penalty G^T G
        std::vector<double>    W; // row-major diagonal blocks of A
        std::vector<double>    hint;
        SolverResult           result;
        Eigen::VectorXd       &r, &alpha;
        Eigen::VectorXd        w, u, violation;
      };



      Nsgs::Nsgs(const ContactProblem  &problem,
                 const SolverOptions   &options,
                 const Eigen::VectorXd *initial_r)
        : problem(problem)
        , options(options)
        , d(problem.dim)
        , n(problem.n_elements())
        , set(problem)
        , rho(residual_rho(problem))
        , A((problem.n_equalities() > 0) ? A_augmented : problem.A)
        , hint(n, 0.0)
        , r(result.r)
        , alpha(result.alpha)
      {
        // With equality rows the sweeps run on the augmented matrix.
        const Eigen::Index me = problem.n_equalities();
        if (me > 0)
          {
            const double g2 = problem.G.squaredNorm();
            penalty =
              (g2 > 0.0) ? options.augmentation * problem.A.trace() / g2 : 0.0;
            A_augmented = problem.A;
            A_augmented.noalias() +=
              penalty * problem.G.transpose() * problem.G;
          }
        W.resize(d * d * n);
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int a = 0; a < d; ++a)
            for (unsigned int b = 0; b < d; ++b)
              W[d * d * j + d * a + b] = A(d * j + a, d * j + b);

        const Eigen::Index size = problem.D.size();
        r     = initial_r ? *initial_r : Eigen::VectorXd::Zero(size);
        alpha = Eigen::VectorXd::Zero(me);
        w.resize(size);
        u.resize(size);
        violation.resize(me);
        recompute_w();
      }



      void
      Nsgs::recompute_w()
      {
        w.noalias() = A * r;
        w += problem.D;
        if (problem.n_equalities() > 0)
          w.noalias() += problem.G.transpose() * (alpha - penalty * problem.e);
      }



      void
      Nsgs::local_step(const unsigned int j, const double omega)
      {
        const double *Wj = W.data() + d * d * j;
        double       *rj = r.data() + d * j;
        double        q[3], x[3], delta[3];
        // q_j = w_j - A_jj r_j: the displacement due to the other elements.
        local_linear_term(d, Wj, w.data() + d * j, rj, q);
        solve_local_coulomb(set, problem.mu[j], Wj, q, x, hint[j]);
        const bool moved = relaxed_block_update(
          d, omega, rj, x, delta, [&](const double *z, double *p) {
            set.project_cone(problem.mu[j], z, p);
          });
        if (!moved)
          return;
        if (d == 2)
          w.noalias() +=
            A.middleCols<2>(2 * j) * Eigen::Vector2d(delta[0], delta[1]);
        else
          w.noalias() += A.middleCols<3>(3 * j) *
                         Eigen::Vector3d(delta[0], delta[1], delta[2]);
      }



      void
      Nsgs::sweep(const double omega)
      {
        for (unsigned int j = 0; j < n; ++j)
          local_step(j, omega);
      }



      ResidualFigures
      Nsgs::update_multipliers()
      {
        u = w;
        if (problem.n_equalities() > 0)
          {
            violation = problem.G * r - problem.e;
            alpha += penalty * violation;
            w.noalias() += penalty * (problem.G.transpose() * violation);
          }
        return compute_residual_from_u(problem, set, rho, r, u);
      }



      ResidualFigures
      Nsgs::confirm(const ConvergenceMonitor &monitor)
      {
        u.noalias() = problem.A * r;
        u += problem.D;
        if (problem.n_equalities() > 0)
          u.noalias() += problem.G.transpose() * alpha;
        const ResidualFigures figures =
          compute_residual_from_u(problem, set, rho, r, u);
        if (!monitor.meets_tolerance(figures, r))
          recompute_w();
        return figures;
      }



      SolverResult
      Nsgs::run()
      {
        ConvergenceMonitor monitor(
          problem, options, "NSGS", "sweeps", result.residual_history);
        double       omega      = options.over_relaxation;
        unsigned int reductions = 0;
        for (unsigned int k = 1; k <= options.max_iterations; ++k)
          {
            result.iterations = k;
            sweep(omega);
            if (k % 100 == 0)
              recompute_w();

            ResidualFigures figures = update_multipliers();
            if (monitor.meets_tolerance(figures, r))
              figures = confirm(monitor);
            if (monitor.stops(monitor.observe(figures, r), result))
              {
                if (result.converged && reductions > 0)
                  result.message +=
                    " (relaxation reduced to omega = " + std::to_string(omega) +
                    ")";
                return result;
              }
            if (monitor.stalled(figures.natural_map))
              {
                // Stall or cycling: under-relax (omega halves, at most six
                // times) before giving up.
                if (options.adaptive_relaxation && reductions < 6)
                  {
                    omega *= 0.5;
                    ++reductions;
                    monitor.restart_stall_count(figures.natural_map);
                    continue;
                  }
                result.message =
                  monitor.stall_message("omega = " + std::to_string(omega));
                return result;
              }
          }
        result.message = monitor.iteration_limit_message();
        return result;
      }
    } // namespace



    SolverResult
    solve_nsgs(const ContactProblem  &problem,
               const SolverOptions   &options,
               const Eigen::VectorXd *initial_r)
    {
      return Nsgs(problem, options, initial_r).run();
    }
  } // namespace contact
} // namespace dpana
