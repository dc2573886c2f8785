#include <dpana/contact/alart_curnier.h>
#include <dpana/contact/friction_set.h>
#include <dpana/contact/line_search.h>
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
    } // namespace



    SolverResult
    solve_alart_curnier(const ContactProblem  &problem,
                        const SolverOptions   &options,
                        const Eigen::VectorXd *initial_r)
    {
      const unsigned int     d    = problem.dim;
      const unsigned int     m    = d - 1;
      const unsigned int     n    = problem.n_elements();
      const Eigen::Index     me   = problem.n_equalities();
      const Eigen::Index     size = problem.D.size();
      const Eigen::Index     q    = size + me;
      const FrictionSet      set(problem);
      const double           rho_residual = residual_rho(problem);
      const Eigen::MatrixXd &A            = problem.A;
      const Eigen::MatrixXd &G            = problem.G;

      AlartCurnierMap map{problem,
                          set,
                          Eigen::VectorXd(n),
                          Eigen::VectorXd(size),
                          Eigen::VectorXd(n),
                          Eigen::VectorXd(n),
                          std::vector<double>(m * n),
                          std::vector<int>(n)};
      for (unsigned int j = 0; j < n; ++j)
        map.rho[j] = d / A.block(d * j, d * j, d, d).trace();

      SolverResult result;
      result.r           = initial_r ? *initial_r : Eigen::VectorXd::Zero(size);
      result.alpha       = Eigen::VectorXd::Zero(me);
      Eigen::VectorXd &r = result.r;
      Eigen::VectorXd &alpha = result.alpha;

      Eigen::VectorXd  F(q), Ftrial(q), dz(q), rtrial(size), atrial(me);
      Eigen::MatrixXd  J(q, q), Jr;
      std::vector<int> free_index, fixed_index;
      Eigen::PartialPivLU<Eigen::MatrixXd> lu;
      const double                         eq_norm_e =
        (me > 0) ? problem.e.lpNorm<Eigen::Infinity>() : 0.0;
      const double eq_norm_G = (me > 0) ? G.lpNorm<Eigen::Infinity>() : 0.0;

      unsigned int failures = 0;
      map.evaluate(r, alpha, F);
      for (unsigned int k = 0; k <= options.max_iterations; ++k)
        {
          result.iterations = k;
          const ResidualFigures figures =
            compute_residual_from_u(problem, set, rho_residual, r, map.u);
          result.residual_history.push_back(figures.natural_map);
          if (figures.natural_map <= options.tolerance &&
              figures.equilibrium <=
                options.tolerance *
                  (eq_norm_G * r.lpNorm<Eigen::Infinity>() + eq_norm_e))
            {
              result.converged = true;
              result.message   = "converged";
              return result;
            }
          if (k == options.max_iterations)
            break;

          // @sect4{Generalised Jacobian}
          // A is symmetric, so its rows are read as (contiguous) columns.
          J.setZero();
          for (unsigned int j = 0; j < n; ++j)
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

              double D[4], dc[2];
              set.projection_derivative(map.c[j],
                                        map.yT.data() + m * j,
                                        map.region[j],
                                        D);
              set.projection_radius_derivative(map.c[j],
                                               map.yT.data() + m * j,
                                               map.region[j],
                                               dc);
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
                      J.row(row).head(size) +=
                        (Dab * rho) * A.col(col).transpose();
                      if (me > 0)
                        J.row(row).tail(me) +=
                          (Dab * rho) * G.col(col).transpose();
                    }
                  // Through the radius: dc = -mu dy_N when pressed.
                  if (press && dc[a] != 0.0)
                    {
                      const double f = dc[a] * problem.mu[j];
                      J(row, iN) += f;
                      J.row(row).head(size) -=
                        (f * rho) * A.col(iN).transpose();
                      if (me > 0)
                        J.row(row).tail(me) -=
                          (f * rho) * G.col(iN).transpose();
                    }
                }
            }
          if (me > 0)
            J.bottomLeftCorner(me, size) = G;

          // Elements that are not pressed (y_N >= 0) and have a zero
          // projection derivative (radius 0) have unit rows: their step is
          // -F outright. Eliminate them and factor only the rest.
          free_index.clear();
          fixed_index.clear();
          dz.setZero();
          for (unsigned int j = 0; j < n; ++j)
            {
              bool fixed = map.yN[j] >= 0.0;
              for (unsigned int a = 0; a < m && fixed; ++a)
                for (unsigned int b = 0; b < d; ++b)
                  fixed = fixed && J(d * j + 1 + a, d * j + b) ==
                                     (a + 1 == b ? 1.0 : 0.0);
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
              Jr = J(free_index, free_index);
              lu.compute(Jr);
              Eigen::VectorXd z = lu.solve(rhs);
              if (!z.allFinite() || lu.rcond() < 1e-14)
                {
                  // Singular generalised Jacobian (e.g. at r = 0 with
                  // equality rows: no element pressed, so alpha does not
                  // enter yet): take the minimum-norm least-squares step.
                  z =
                    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(Jr)
                      .solve(rhs);
                }
              for (Eigen::Index a = 0; a < nf; ++a)
                dz[free_index[a]] = z[a];
            }
          if (!dz.allFinite())
            {
              result.message = "Alart-Curnier: singular Jacobian";
              return result;
            }

          // Armijo backtracking on 1/2 ||F||^2.
          const bool accepted =
            armijo_backtracking(0.5 * F.squaredNorm(), 30, [&](const double t) {
              rtrial = r + t * dz.head(size);
              if (me > 0)
                atrial = alpha + t * dz.tail(me);
              map.evaluate(rtrial, atrial, Ftrial);
              return 0.5 * Ftrial.squaredNorm();
            });
          if (!accepted)
            {
              // Globalisation: a few NSGS sweeps from the current point
              // (20, 40, ... sweeps), then Newton resumes.
              if (++failures > 10)
                {
                  map.evaluate(r, alpha, F);
                  result.message =
                    "Alart-Curnier: line search failed 10 times (no descent "
                    "of ||F|| even after NSGS sweeps); try nsgs";
                  return result;
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
              continue;
            }
          r.swap(rtrial);
          if (me > 0)
            alpha.swap(atrial);
          F.swap(Ftrial);
        }
      result.message = "Alart-Curnier: iteration limit reached";
      return result;
    }
  } // namespace contact
} // namespace dpana
