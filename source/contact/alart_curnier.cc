#include <dpana/contact/alart_curnier.h>
#include <dpana/contact/friction_set.h>
#include <dpana/contact/line_search.h>
#include <dpana/contact/monitor.h>
#include <dpana/contact/nsgs.h>

#include <Eigen/LU>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>

namespace dpana
{
  namespace contact
  {
    namespace
    {
      // State of the Alart-Curnier map at one point.
      struct AlartCurnierMap
      {
        const ContactProblem &problem;
        const FrictionSet    &set;
        Eigen::VectorXd       rho;      // per element
        Eigen::VectorXd       u, yN, c; // per dof / element
        std::vector<double>   yT;       // (d-1) n
        std::vector<int>      region;   // per element

        // F (size d n + m) at (r, alpha); also sets u, yN, yT, c, region.
        void
        evaluate(const Eigen::VectorXd &r,
                 const Eigen::VectorXd &alpha,
                 Eigen::VectorXd       &F)
        {
          const unsigned int d  = problem.dim;
          const unsigned int m  = d - 1;
          const unsigned int n  = problem.n_elements();
          const Eigen::Index me = problem.n_equalities();
          u.noalias()           = problem.A * r;
          u += problem.D;
          if (me > 0)
            u.noalias() += problem.G.transpose() * alpha;
          for (unsigned int j = 0; j < n; ++j)
            {
              const unsigned int iN = d * j;
              yN[j]                 = r[iN] - rho[j] * u[iN];
              F[iN]                 = r[iN] - std::min(0.0, yN[j]);
              c[j]                  = problem.mu[j] * std::max(0.0, -yN[j]);
              double p[2];
              for (unsigned int a = 0; a < m; ++a)
                yT[m * j + a] = r[iN + 1 + a] - rho[j] * u[iN + 1 + a];
              region[j] = set.project_tangential(c[j], yT.data() + m * j, p);
              for (unsigned int a = 0; a < m; ++a)
                F[iN + 1 + a] = r[iN + 1 + a] - p[a];
            }
          if (me > 0)
            F.tail(me).noalias() = problem.G * r - problem.e;
        }
      };



      // The Newton iteration on one problem: the map, the generalised
      // Jacobian J and the step dz; run() is the algorithm of
      // alart_curnier.h.
      class AlartCurnier
      {
      public:
        AlartCurnier(const ContactProblem  &problem,
                     const SolverOptions   &options,
                     const Eigen::VectorXd *initial_r);

        SolverResult
        run();

      private:
        // The generalised Jacobian of F at the point last evaluated.
        void
        assemble_jacobian();

        // The rows of element j (pressed or not, through y_T and the radius).
        void
        assemble_element_rows(const unsigned int j);

        // The Newton step dz solving J dz = -F, after the elimination of the
        // unit rows; false if it is not finite.
        bool
        newton_step();

        // Split the unknowns into the eliminated ones (with dz = -F) and the
        // free ones.
        void
        partition_unknowns();

        // Armijo backtracking along dz; on success the trial point is in
        // rtrial, atrial, Ftrial.
        bool
        line_search();

        // NSGS sweeps from the current point after a failed line search;
        // false after too many failures.
        bool
        globalise();

        const ContactProblem  &problem;
        const SolverOptions   &options;
        const unsigned int     d, m, n;
        const Eigen::Index     me, size;
        const FrictionSet      set;
        const Eigen::MatrixXd &A, &G;
        AlartCurnierMap        map;
        SolverResult           result;
        Eigen::VectorXd       &r, &alpha;
        Eigen::VectorXd        F, Ftrial, dz, rtrial, atrial;
        Eigen::MatrixXd        J;
        std::vector<int>       free_index, fixed_index;
        unsigned int           failures = 0;
      };



      AlartCurnier::AlartCurnier(const ContactProblem  &problem,
                                 const SolverOptions   &options,
                                 const Eigen::VectorXd *initial_r)
        : problem(problem)
        , options(options)
        , d(problem.dim)
        , m(problem.dim - 1)
        , n(problem.n_elements())
        , me(problem.n_equalities())
        , size(problem.D.size())
        , set(problem)
        , A(problem.A)
        , G(problem.G)
        , map{problem,
              set,
              Eigen::VectorXd(n),
              Eigen::VectorXd(size),
              Eigen::VectorXd(n),
              Eigen::VectorXd(n),
              std::vector<double>(m * n),
              std::vector<int>(n)}
        , r(result.r)
        , alpha(result.alpha)
        , F(size + me)
        , Ftrial(size + me)
        , dz(size + me)
        , rtrial(size)
        , atrial(me)
        , J(size + me, size + me)
      {
        for (unsigned int j = 0; j < n; ++j)
          map.rho[j] = d / A.block(d * j, d * j, d, d).trace();
        r     = initial_r ? *initial_r : Eigen::VectorXd::Zero(size);
        alpha = Eigen::VectorXd::Zero(me);
      }



      // @sect4{Generalised Jacobian}
      // A is symmetric, so its rows are read as (contiguous) columns.
      void
      AlartCurnier::assemble_jacobian()
      {
        J.setZero();
        for (unsigned int j = 0; j < n; ++j)
          assemble_element_rows(j);
        if (me > 0)
          J.bottomLeftCorner(me, size) = G;
      }



      void
      AlartCurnier::assemble_element_rows(const unsigned int j)
      {
        const unsigned int iN    = d * j;
        const double       rho   = map.rho[j];
        const bool         press = map.yN[j] < 0.0;
        if (press)
          {
            J.row(iN).head(size) = rho * A.col(iN).transpose();
            if (me > 0)
              J.row(iN).tail(me) = rho * G.col(iN).transpose();
          }
        else
          J(iN, iN) = 1.0;

        double        D[4], dc[2];
        const double *yT = map.yT.data() + m * j;
        set.projection_derivative(map.c[j], yT, map.region[j], D);
        set.projection_radius_derivative(map.c[j], yT, map.region[j], dc);
        for (unsigned int a = 0; a < m; ++a)
          {
            const Eigen::Index row = iN + 1 + a;
            J(row, row) += 1.0;
            for (unsigned int b = 0; b < m; ++b)
              {
                const double Dab = D[m * a + b];
                if (Dab == 0.0)
                  continue;
                const Eigen::Index col = iN + 1 + b;
                J(row, col) -= Dab;
                J.row(row).head(size) += (Dab * rho) * A.col(col).transpose();
                if (me > 0)
                  J.row(row).tail(me) += (Dab * rho) * G.col(col).transpose();
              }
            // Through the radius: dc = -mu dy_N when pressed.
            if (press && dc[a] != 0.0)
              {
                const double f = dc[a] * problem.mu[j];
                J(row, iN) += f;
                J.row(row).head(size) -= (f * rho) * A.col(iN).transpose();
                if (me > 0)
                  J.row(row).tail(me) -= (f * rho) * G.col(iN).transpose();
              }
          }
      }



      // Elements that are not pressed (y_N >= 0) and have a zero projection
      // derivative (radius 0) have unit rows: their step is -F outright.
      void
      AlartCurnier::partition_unknowns()
      {
        free_index.clear();
        fixed_index.clear();
        dz.setZero();
        for (unsigned int j = 0; j < n; ++j)
          {
            bool fixed = map.yN[j] >= 0.0;
            for (unsigned int a = 0; a < m && fixed; ++a)
              for (unsigned int b = 0; b < d; ++b)
                fixed = fixed &&
                        J(d * j + 1 + a, d * j + b) == (a + 1 == b ? 1.0 : 0.0);
            for (unsigned int a = 0; a < d; ++a)
              {
                const int i = static_cast<int>(d * j + a);
                if (fixed)
                  {
                    fixed_index.push_back(i);
                    dz[i] = -F[i];
                  }
                else
                  free_index.push_back(i);
              }
          }
        for (Eigen::Index i = 0; i < me; ++i)
          free_index.push_back(static_cast<int>(size + i));
      }



      bool
      AlartCurnier::newton_step()
      {
        partition_unknowns();
        if (!free_index.empty())
          {
            const Eigen::Index nf = free_index.size();
            Eigen::VectorXd    rhs(nf);
            for (Eigen::Index a = 0; a < nf; ++a)
              rhs[a] = -F[free_index[a]];
            if (!fixed_index.empty())
              {
                Eigen::VectorXd dfixed(fixed_index.size());
                for (std::size_t a = 0; a < fixed_index.size(); ++a)
                  dfixed[a] = dz[fixed_index[a]];
                rhs.noalias() -= J(free_index, fixed_index) * dfixed;
              }
            const Eigen::MatrixXd                Jr = J(free_index, free_index);
            Eigen::PartialPivLU<Eigen::MatrixXd> lu(Jr);
            Eigen::VectorXd                      z = lu.solve(rhs);
            if (!z.allFinite() || lu.rcond() < 1e-14)
              {
                // Singular generalised Jacobian (e.g. at r = 0 with equality
                // rows: no element pressed, so alpha does not enter yet):
                // take the minimum-norm least-squares step.
                z = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(Jr)
                      .solve(rhs);
              }
            for (Eigen::Index a = 0; a < nf; ++a)
              dz[free_index[a]] = z[a];
          }
        return dz.allFinite();
      }



      bool
      AlartCurnier::line_search()
      {
        return armijo_backtracking(0.5 * F.squaredNorm(),
                                   30,
                                   [&](const double t) {
                                     rtrial = r + t * dz.head(size);
                                     if (me > 0)
                                       atrial = alpha + t * dz.tail(me);
                                     map.evaluate(rtrial, atrial, Ftrial);
                                     return 0.5 * Ftrial.squaredNorm();
                                   });
      }



      bool
      AlartCurnier::globalise()
      {
        // A few NSGS sweeps from the current point (20, 40, ... sweeps),
        // then Newton resumes.
        if (++failures > 10)
          {
            map.evaluate(r, alpha, F);
            return false;
          }
        SolverOptions sweeps    = options;
        sweeps.type             = SolverType::nsgs;
        sweeps.max_iterations   = 20 * failures;
        const SolverResult warm = solve_nsgs(problem, sweeps, &r);
        result.inner_iterations += warm.iterations;
        r = warm.r;
        if (me > 0)
          alpha = warm.alpha;
        map.evaluate(r, alpha, F);
        return true;
      }



      SolverResult
      AlartCurnier::run()
      {
        ConvergenceMonitor    monitor(problem,
                                   options,
                                   "Alart-Curnier",
                                   "iterations",
                                   result.residual_history);
        const Eigen::VectorXd rho_residual = residual_rho(problem);
        map.evaluate(r, alpha, F);
        for (unsigned int k = 0; k <= options.max_iterations; ++k)
          {
            result.iterations = k;
            const ResidualFigures figures =
              compute_residual_from_u(problem, set, rho_residual, r, map.u);
            if (monitor.stops(monitor.observe(figures, r), result))
              return result;
            if (k == options.max_iterations)
              break;

            assemble_jacobian();
            if (!newton_step())
              {
                result.message = "Alart-Curnier: singular Jacobian";
                return result;
              }
            if (line_search())
              {
                r.swap(rtrial);
                if (me > 0)
                  alpha.swap(atrial);
                F.swap(Ftrial);
              }
            else if (!globalise())
              {
                result.message =
                  "Alart-Curnier: line search failed 10 times (no descent "
                  "of ||F|| even after NSGS sweeps); try nsgs";
                return result;
              }
          }
        result.message = monitor.iteration_limit_message();
        return result;
      }
    } // namespace



    SolverResult
    solve_alart_curnier(const ContactProblem  &problem,
                        const SolverOptions   &options,
                        const Eigen::VectorXd *initial_r)
    {
      return AlartCurnier(problem, options, initial_r).run();
    }
  } // namespace contact
} // namespace dpana
