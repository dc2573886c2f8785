#include <dpana/contact/friction_qp.h>
#include <dpana/contact/friction_set.h>
#include <dpana/contact/monitor.h>
#include <dpana/contact/normal_lcp.h>
#include <dpana/contact/splitting.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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



      // @sect4{The problem as the splitting sees it}
      //
      // The normal and tangential blocks of A and D, extracted once, and the
      // equality rows divided into normal rows (with a normal entry, imposed
      // in the N-step) and purely tangential rows (imposed in the T-step).
      struct SplitProblem
      {
        explicit SplitProblem(const ContactProblem &problem);

        // (N, T) and (alpha_N, alpha_T) written into the interleaved r and
        // the alpha of the full problem.
        void
        assemble(const Eigen::VectorXd &N,
                 const Eigen::VectorXd &T,
                 const Eigen::VectorXd &alpha_N,
                 const Eigen::VectorXd &alpha_T,
                 Eigen::VectorXd       &r,
                 Eigen::VectorXd       &alpha) const;

        // Index of N_j and of T_{j,a} in the interleaved ordering.
        Eigen::Index
        nidx(const unsigned int j) const
        {
          return d * j;
        }
        Eigen::Index
        tidx(const unsigned int j, const unsigned int a) const
        {
          return d * j + 1 + a;
        }

        const unsigned int        d, m, n;
        Eigen::MatrixXd           A_NN, A_TT, A_TN;
        Eigen::VectorXd           D_N, D_T;
        std::vector<Eigen::Index> normal_rows, tangential_rows;
        Eigen::MatrixXd           G_NN, G_NT, G_TT;
        Eigen::VectorXd           e_N, e_T;

      private:
        void
        extract_blocks(const ContactProblem &problem);

        void
        extract_equality_rows(const ContactProblem &problem);
      };



      SplitProblem::SplitProblem(const ContactProblem &problem)
        : d(problem.dim)
        , m(problem.dim - 1)
        , n(problem.n_elements())
      {
        extract_blocks(problem);
        extract_equality_rows(problem);
      }



      void
      SplitProblem::extract_blocks(const ContactProblem &problem)
      {
        A_NN.resize(n, n);
        A_TT.resize(m * n, m * n);
        A_TN.resize(m * n, n);
        D_N.resize(n);
        D_T.resize(m * n);
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
                  A_TT(m * j + a, m * k + b) =
                    problem.A(tidx(j, a), tidx(k, b));
            D_N[k] = problem.D[nidx(k)];
            for (unsigned int a = 0; a < m; ++a)
              D_T[m * k + a] = problem.D[tidx(k, a)];
          }
      }



      void
      SplitProblem::extract_equality_rows(const ContactProblem &problem)
      {
        for (Eigen::Index i = 0; i < problem.n_equalities(); ++i)
          {
            bool has_normal = false;
            for (unsigned int j = 0; j < n; ++j)
              has_normal = has_normal || problem.G(i, nidx(j)) != 0.0;
            (has_normal ? normal_rows : tangential_rows).push_back(i);
          }
        const Eigen::Index mN = normal_rows.size(), mT = tangential_rows.size();
        G_NN.resize(mN, n);
        G_NT.resize(mN, m * n);
        G_TT.resize(mT, m * n);
        e_N.resize(mN);
        e_T.resize(mT);
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
      }



      void
      SplitProblem::assemble(const Eigen::VectorXd &N,
                             const Eigen::VectorXd &T,
                             const Eigen::VectorXd &alpha_N,
                             const Eigen::VectorXd &alpha_T,
                             Eigen::VectorXd       &r,
                             Eigen::VectorXd       &alpha) const
      {
        for (unsigned int j = 0; j < n; ++j)
          {
            r[nidx(j)] = N[j];
            for (unsigned int a = 0; a < m; ++a)
              r[tidx(j, a)] = T[m * j + a];
          }
        for (std::size_t i = 0; i < normal_rows.size(); ++i)
          alpha[normal_rows[i]] = alpha_N[i];
        for (std::size_t i = 0; i < tangential_rows.size(); ++i)
          alpha[tangential_rows[i]] = alpha_T[i];
      }



      // @sect4{The iteration}
      //
      // The iterate (N, T, alpha_N, alpha_T), the two inner solvers and the
      // steps of the splitting; run() is the algorithm of splitting.h.
      class Splitting
      {
      public:
        Splitting(const ContactProblem  &problem,
                  const SolverOptions   &options,
                  const Eigen::VectorXd *initial_r);

        SolverResult
        run();

      private:
        // N_0 and T_0 from initial_r; without it, the frictionless solution.
        void
        start(const Eigen::VectorXd *initial_r);

        // The inner tolerance of the next outer iteration (see splitting.h).
        void
        choose_inner_tolerance();

        // T-step at fixed N, N-step at fixed T.
        void
        friction_step();

        void
        normal_step();

        // The N-step solve of the current b and e_shifted.
        InnerResult
        solve_normal();

        // r and alpha assembled, u = A r + D + G^T alpha and the figures.
        ResidualFigures
        measure();

        // ||r_k - r_{k-1}||_inf / ||r_k||_inf (0 when r_k = 0).
        double
        relative_change() const;

        std::string
        stagnation_message(const double residual) const;

        const ContactProblem &problem;
        const SolverOptions  &options;
        const SplitProblem    split;
        const FrictionSet     set;
        const Eigen::VectorXd rho;
        const bool            use_pgs;
        NormalLcp             normal;
        FrictionQp            friction;
        Eigen::VectorXd       N, T, alpha_N, alpha_T;
        Eigen::VectorXd       b, c, radius, e_shifted, u, r_old;
        SolverResult          result;
        std::string           inner_message;
        bool                  exact_inner         = false;
        double                inner_tolerance_now = 0;
      };



      InnerOptions
      inner_options(const SolverOptions &options)
      {
        InnerOptions inner;
        inner.tolerance             = options.inner_tolerance;
        inner.max_iterations        = options.inner_max_iterations;
        inner.over_relaxation       = options.over_relaxation;
        inner.augmentation          = options.augmentation;
        inner.partition_sweeps      = options.partition_sweeps;
        inner.partition_sweep_size  = options.partition_sweep_size;
        inner.single_precision_size = options.single_precision_size;
        inner.complement_size       = options.normal_complement_size;
        return inner;
      }



      Splitting::Splitting(const ContactProblem  &problem,
                           const SolverOptions   &options,
                           const Eigen::VectorXd *initial_r)
        : problem(problem)
        , options(options)
        , split(problem)
        , set(problem)
        , rho(residual_rho(problem))
        , use_pgs(options.type == SolverType::splitting_pgs)
        , normal(split.A_NN, split.G_NN, inner_options(options))
        , friction(split.A_TT, split.G_TT, set, inner_options(options))
        , inner_tolerance_now(options.inner_tolerance)
      {
        const unsigned int n = split.n, m = split.m;
        b.resize(n);
        c.resize(m * n);
        radius.resize(n);
        e_shifted.resize(split.e_N.size());
        u.resize(problem.D.size());
        r_old.resize(problem.D.size());
        start(initial_r);
      }



      void
      Splitting::start(const Eigen::VectorXd *initial_r)
      {
        const unsigned int n = split.n, m = split.m;
        N = Eigen::VectorXd::Zero(n);
        T = Eigen::VectorXd::Zero(m * n);
        if (initial_r)
          for (unsigned int j = 0; j < n; ++j)
            {
              N[j] = std::min(0.0, (*initial_r)[split.nidx(j)]);
              for (unsigned int a = 0; a < m; ++a)
                T[m * j + a] = (*initial_r)[split.tidx(j, a)];
            }
        alpha_N      = Eigen::VectorXd::Zero(split.e_N.size());
        alpha_T      = Eigen::VectorXd::Zero(split.e_T.size());
        result.r     = Eigen::VectorXd::Zero(problem.D.size());
        result.alpha = Eigen::VectorXd::Zero(problem.n_equalities());
        split.assemble(N, T, alpha_N, alpha_T, result.r, result.alpha);

        // Without a start value, begin with an N-step at T = 0: the
        // frictionless solution, which is what the first T-step (with all
        // friction radii zero) followed by an N-step would give anyway; doing
        // it first also keeps purely tangential equality rows (infeasible
        // with zero radii) out of the first T-step.
        if (!initial_r)
          {
            b = split.D_N;
            if (split.e_N.size() > 0)
              e_shifted = split.e_N;
            result.inner_iterations += solve_normal().iterations;
          }
      }



      void
      Splitting::choose_inner_tolerance()
      {
        // Inexact inner solves: tolerance 0.1 times the last outer
        // residual, between inner_tolerance and 1e-4 (exact solves of
        // subproblems whose data are still far from converged are wasted).
        inner_tolerance_now = options.inner_tolerance;
        if (options.adaptive_inner_tolerance && !exact_inner)
          {
            const double last = result.residual_history.empty() ?
                                  1e-4 :
                                  0.1 * result.residual_history.back();
            inner_tolerance_now =
              std::max(options.inner_tolerance, std::min(1e-4, last));
          }
        normal.set_tolerance(inner_tolerance_now);
        friction.set_tolerance(inner_tolerance_now);
      }



      void
      Splitting::friction_step()
      {
        for (unsigned int j = 0; j < split.n; ++j)
          radius[j] = std::max(0.0, -problem.mu[j] * N[j]);
        c = split.D_T;
        c.noalias() += split.A_TN * N;
        if (split.e_N.size() > 0)
          c.noalias() += split.G_NT.transpose() * alpha_N;
        const InnerResult inner =
          use_pgs ? friction.solve_pgs(c, radius, split.e_T, T, alpha_T) :
                    friction.solve_active_set(c, radius, split.e_T, T, alpha_T);
        result.inner_iterations += inner.iterations;
        if (!inner.converged)
          {
            inner_message = inner.message;
            // Do not carry multipliers of a failed solve into the next.
            if (!alpha_T.allFinite() || split.e_T.size() > 0)
              alpha_T.setZero();
          }
      }



      void
      Splitting::normal_step()
      {
        b = split.D_N;
        b.noalias() += split.A_TN.transpose() * T;
        if (split.e_N.size() > 0)
          {
            e_shifted = split.e_N;
            e_shifted.noalias() -= split.G_NT * T;
          }
        const InnerResult inner = solve_normal();
        result.inner_iterations += inner.iterations;
        if (!inner.converged)
          {
            inner_message = inner.message;
            if (!alpha_N.allFinite())
              alpha_N.setZero();
          }
      }



      InnerResult
      Splitting::solve_normal()
      {
        return use_pgs ? normal.solve_pgs(b, e_shifted, N, alpha_N) :
                         normal.solve_active_set(b, e_shifted, N, alpha_N);
      }



      ResidualFigures
      Splitting::measure()
      {
        split.assemble(N, T, alpha_N, alpha_T, result.r, result.alpha);
        u.noalias() = problem.A * result.r;
        u += problem.D;
        if (problem.n_equalities() > 0)
          u.noalias() += problem.G.transpose() * result.alpha;
        return compute_residual_from_u(problem, set, rho, result.r, u);
      }



      double
      Splitting::relative_change() const
      {
        const double r_norm = result.r.lpNorm<Eigen::Infinity>();
        return (r_norm > 0.0) ?
                 (result.r - r_old).lpNorm<Eigen::Infinity>() / r_norm :
                 0.0;
      }



      std::string
      Splitting::stagnation_message(const double residual) const
      {
        return "splitting stagnated: fixed point reached with residual " +
               scientific(residual) + " above tolerance (" +
               (inner_message.empty() ?
                  std::string("the inner tolerance limits the residual)") :
                  "inner solver failed: " + inner_message + ")");
      }



      SolverResult
      Splitting::run()
      {
        ConvergenceMonitor monitor(
          problem, options, "splitting", "iterations", result.residual_history);
        for (unsigned int k = 1; k <= options.max_iterations; ++k)
          {
            result.iterations = k;
            r_old             = result.r;
            inner_message.clear();
            choose_inner_tolerance();
            friction_step();
            normal_step();

            const ResidualFigures figures = measure();
            if (monitor.stops(monitor.observe(figures, result.r), result))
              return result;
            if (relative_change() <= 1e-15)
              {
                // No progress with inexact inner solves: go on with exact
                // ones; with exact ones, the fixed point is reached.
                if (inner_tolerance_now > options.inner_tolerance)
                  {
                    exact_inner = true;
                    continue;
                  }
                result.message = stagnation_message(figures.natural_map);
                return result;
              }
            if (monitor.stalled(figures.natural_map))
              {
                result.message = monitor.stall_message(
                  "cycling or divergence of the fixed point");
                return result;
              }
          }
        result.message = monitor.iteration_limit_message();
        if (!inner_message.empty())
          result.message += " (" + inner_message + ")";
        return result;
      }
    } // namespace



    SolverResult
    solve_splitting(const ContactProblem  &problem,
                    const SolverOptions   &options,
                    const Eigen::VectorXd *initial_r)
    {
      return Splitting(problem, options, initial_r).run();
    }
  } // namespace contact
} // namespace dpana
