#include <dpana/contact/friction_qp.h>
#include <dpana/contact/method_of_multipliers.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace dpana
{
  namespace contact
  {
    namespace
    {
      // Row-major copies of the diagonal (d-1)x(d-1) blocks of a matrix.
      std::vector<double>
      diagonal_blocks(const Eigen::MatrixXd &matrix,
                      const unsigned int     m,
                      const unsigned int     n)
      {
        std::vector<double> b(m * m * n);
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int a = 0; a < m; ++a)
            for (unsigned int c = 0; c < m; ++c)
              b[m * m * j + m * a + c] = matrix(m * j + a, m * j + c);
        return b;
      }
    } // namespace



    FrictionQp::FrictionQp(const Eigen::MatrixXd &M_,
                           const Eigen::MatrixXd &G_,
                           const FrictionSet     &set_,
                           const InnerOptions    &options_)
      : M(M_)
      , G(G_)
      , set(set_)
      , options(options_)
      , m(set_.tangential_dim())
      , n(static_cast<unsigned int>(M_.rows()) / set_.tangential_dim())
    {
      blocks = diagonal_blocks(M, m, n);
      rho.resize(n);
      for (unsigned int j = 0; j < n; ++j)
        {
          double tr = 0.0;
          for (unsigned int a = 0; a < m; ++a)
            tr += blocks[m * m * j + m * a + a];
          rho[j] = m / tr;
        }
      if (G.rows() > 0)
        {
          const double g2 = G.squaredNorm();
          penalty = (g2 > 0.0) ? options.augmentation * M.trace() / g2 : 0.0;
          M_augmented = M;
          M_augmented.noalias() += penalty * G.transpose() * G;
          blocks_augmented = diagonal_blocks(M_augmented, m, n);
        }
      w.resize(M.rows());
      rhs.resize(M.rows());
      y.resize(M.rows());
      region.resize(n);
    }



    // @sect4{Block projected Gauss-Seidel}
    int
    FrictionQp::pgs(const Eigen::MatrixXd     &matrix,
                    const std::vector<double> &W,
                    const Eigen::VectorXd     &right_hand_side,
                    const Eigen::VectorXd     &radius,
                    Eigen::VectorXd           &T,
                    const unsigned int         max_sweeps)
    {
      const double omega = options.over_relaxation;
      w.noalias()        = matrix * T;
      w += right_hand_side;
      bool fresh = true;
      for (unsigned int sweep = 1; sweep <= max_sweeps; ++sweep)
        {
          double change = 0.0, size = 0.0;
          for (unsigned int j = 0; j < n; ++j)
            {
              const double *Wj = W.data() + m * m * j;
              double       *Tj = T.data() + m * j;
              double        g[2], t[2], delta[2];
              // Linear term of the block problem: w_j - W_j T_j.
              for (unsigned int a = 0; a < m; ++a)
                {
                  g[a] = w[m * j + a];
                  for (unsigned int c = 0; c < m; ++c)
                    g[a] -= Wj[m * a + c] * Tj[c];
                }
              set.minimise(radius[j], Wj, g, t);
              if (omega != 1.0)
                {
                  double z[2];
                  for (unsigned int a = 0; a < m; ++a)
                    z[a] = (1.0 - omega) * Tj[a] + omega * t[a];
                  set.project_tangential(radius[j], z, t);
                }
              bool moved = false;
              for (unsigned int a = 0; a < m; ++a)
                {
                  delta[a] = t[a] - Tj[a];
                  moved    = moved || (delta[a] != 0.0);
                  change   = std::max(change, std::abs(delta[a]));
                  size     = std::max(size, std::abs(t[a]));
                  Tj[a]    = t[a];
                }
              if (moved)
                {
                  if (m == 1)
                    w += delta[0] * matrix.col(j);
                  else
                    w += matrix.middleCols(2 * j, 2) *
                         Eigen::Vector2d(delta[0], delta[1]);
                }
            }
          if (change <= options.tolerance * size)
            {
              if (fresh)
                return static_cast<int>(sweep);
              w.noalias() = matrix * T;
              w += right_hand_side;
              fresh = true;
            }
          else
            fresh = false;
        }
      return -static_cast<int>(max_sweeps);
    }



    InnerResult
    FrictionQp::solve_pgs(const Eigen::VectorXd &c,
                          const Eigen::VectorXd &radius,
                          const Eigen::VectorXd &e,
                          Eigen::VectorXd       &T,
                          Eigen::VectorXd       &beta)
    {
      InnerResult result;
      if (G.rows() == 0)
        {
          const int s = pgs(M, blocks, c, radius, T, options.max_iterations);
          result.converged  = s > 0;
          result.iterations = static_cast<unsigned int>(std::abs(s));
          if (!result.converged)
            result.message = "friction PGS: sweep limit reached";
          return result;
        }
      return solve_with_multipliers(
        G,
        e,
        penalty,
        c,
        options,
        "friction",
        [&](const Eigen::VectorXd &r, const unsigned int max_sweeps) {
          return pgs(M_augmented, blocks_augmented, r, radius, T, max_sweeps);
        },
        rhs,
        T,
        beta);
    }



    // @sect4{Semismooth Newton / active set}
    void
    FrictionQp::natural_map(const Eigen::VectorXd &c,
                            const Eigen::VectorXd &radius,
                            const Eigen::VectorXd &e,
                            const Eigen::VectorXd &T,
                            const Eigen::VectorXd &beta,
                            Eigen::VectorXd       &F)
    {
      const Eigen::Index q = T.size();
      w.noalias()          = M * T;
      w += c;
      if (G.rows() > 0)
        w.noalias() += G.transpose() * beta;
      for (unsigned int j = 0; j < n; ++j)
        {
          double p[2];
          for (unsigned int a = 0; a < m; ++a)
            y[m * j + a] = T[m * j + a] - rho[j] * w[m * j + a];
          region[j] = set.project_tangential(radius[j], y.data() + m * j, p);
          for (unsigned int a = 0; a < m; ++a)
            F[m * j + a] = T[m * j + a] - p[a];
        }
      if (G.rows() > 0)
        F.tail(G.rows()).noalias() = G * T - e;
      (void)q;
    }



    InnerResult
    FrictionQp::solve_active_set(const Eigen::VectorXd &c,
                                 const Eigen::VectorXd &radius,
                                 const Eigen::VectorXd &e,
                                 Eigen::VectorXd       &T,
                                 Eigen::VectorXd       &beta)
    {
      const Eigen::Index q  = T.size();
      const Eigen::Index me = G.rows();
      InnerResult        result;
      if (beta.size() != me)
        beta = Eigen::VectorXd::Zero(me);
      // Start from a feasible point.
      for (unsigned int j = 0; j < n; ++j)
        {
          double p[2];
          set.project_tangential(radius[j], T.data() + m * j, p);
          for (unsigned int a = 0; a < m; ++a)
            T[m * j + a] = p[a];
        }

      Eigen::VectorXd F(q + me), Ftrial(q + me), dx(q + me), Ttrial(q),
        btrial(me), v(q), rhs_reduced;
      std::vector<unsigned int>            free_blocks;
      std::vector<double>                  derivatives(m * m * n);
      Eigen::PartialPivLU<Eigen::MatrixXd> lu;
      const double e_norm   = (me > 0) ? e.lpNorm<Eigen::Infinity>() : 0.0;
      const double G_norm   = (me > 0) ? G.lpNorm<Eigen::Infinity>() : 0.0;
      unsigned int failures = 0;

      natural_map(c, radius, e, T, beta, F);
      for (unsigned int step = 0; step <= options.max_iterations; ++step)
        {
          const double scale_T = std::max(T.lpNorm<Eigen::Infinity>(),
                                          radius.lpNorm<Eigen::Infinity>());
          const double err_T   = F.head(q).lpNorm<Eigen::Infinity>();
          const double err_e =
            (me > 0) ? F.tail(me).lpNorm<Eigen::Infinity>() : 0.0;
          if (err_T <= options.tolerance * scale_T &&
              err_e <= options.tolerance *
                         (G_norm * T.lpNorm<Eigen::Infinity>() + e_norm))
            {
              result.converged  = true;
              result.iterations = step;
              return result;
            }
          if (step == options.max_iterations)
            break;

          // Generalised Jacobian, block row j:
          //   (I - D_j) e_j + rho_j D_j M_j,:  |  rho_j D_j G_j^T,
          // equality rows: G | 0. A block with D_j = 0 (friction radius
          // zero, interval end, polygon vertex) has the row e_j: its step is
          // dx_j = -F_j outright. Those blocks are eliminated, and only the
          // remaining "free" blocks (stick, facet or circle slip) enter the
          // dense LU, which makes the step much cheaper when many elements
          // are separated or at a vertex.
          free_blocks.clear();
          dx.setZero();
          for (unsigned int j = 0; j < n; ++j)
            {
              double *D = derivatives.data() + m * m * j;
              set.projection_derivative(radius[j],
                                        y.data() + m * j,
                                        region[j],
                                        D);
              bool nonzero = false;
              for (unsigned int a = 0; a < m * m; ++a)
                nonzero = nonzero || D[a] != 0.0;
              if (nonzero)
                free_blocks.push_back(j);
              else
                dx.segment(m * j, m) = -F.segment(m * j, m);
            }
          const Eigen::Index nf = static_cast<Eigen::Index>(free_blocks.size());
          const Eigen::Index f  = m * nf;
          v.noalias()           = M * dx.head(q);
          J.resize(f + me, f + me);
          rhs_reduced.resize(f + me);
          for (Eigen::Index bk = 0; bk < nf; ++bk)
            {
              const unsigned int k = free_blocks[bk];
              for (unsigned int t = 0; t < m; ++t)
                {
                  const Eigen::Index col  = m * bk + t;
                  const Eigen::Index gcol = m * k + t;
                  for (Eigen::Index bj = 0; bj < nf; ++bj)
                    {
                      const unsigned int j = free_blocks[bj];
                      const double      *D = derivatives.data() + m * m * j;
                      for (unsigned int a = 0; a < m; ++a)
                        {
                          double value = 0.0;
                          for (unsigned int b = 0; b < m; ++b)
                            value += D[m * a + b] * M(m * j + b, gcol);
                          value *= rho[j];
                          if (j == k)
                            value += (a == t ? 1.0 : 0.0) - D[m * a + t];
                          J(m * bj + a, col) = value;
                        }
                    }
                  for (Eigen::Index i = 0; i < me; ++i)
                    J(f + i, col) = G(i, gcol);
                }
            }
          for (Eigen::Index bj = 0; bj < nf; ++bj)
            {
              const unsigned int j = free_blocks[bj];
              const double      *D = derivatives.data() + m * m * j;
              for (unsigned int a = 0; a < m; ++a)
                {
                  double value = 0.0;
                  for (unsigned int b = 0; b < m; ++b)
                    value += D[m * a + b] * v[m * j + b];
                  rhs_reduced[m * bj + a] = -F[m * j + a] - rho[j] * value;
                  for (Eigen::Index i = 0; i < me; ++i)
                    {
                      double g = 0.0;
                      for (unsigned int b = 0; b < m; ++b)
                        g += D[m * a + b] * G(i, m * j + b);
                      J(m * bj + a, f + i) = rho[j] * g;
                    }
                }
            }
          if (me > 0)
            {
              J.bottomRightCorner(me, me).setZero();
              rhs_reduced.tail(me) = -F.tail(me) - G * dx.head(q);
            }
          if (f + me > 0)
            {
              lu.compute(J);
              const Eigen::VectorXd z = lu.solve(rhs_reduced);
              for (Eigen::Index bj = 0; bj < nf; ++bj)
                dx.segment(m * free_blocks[bj], m) = z.segment(m * bj, m);
              if (me > 0)
                dx.tail(me) = z.tail(me);
            }
          if (!dx.allFinite())
            {
              result.iterations = step;
              result.message    = "friction active set: singular Jacobian";
              return result;
            }

          // Armijo backtracking on 1/2 ||F||^2.
          const double phi      = 0.5 * F.squaredNorm();
          double       t        = 1.0;
          bool         accepted = false;
          for (unsigned int ls = 0; ls < 40; ++ls, t *= 0.5)
            {
              Ttrial = T + t * dx.head(q);
              if (me > 0)
                btrial = beta + t * dx.tail(me);
              natural_map(c, radius, e, Ttrial, btrial, Ftrial);
              if (0.5 * Ftrial.squaredNorm() <= (1.0 - 2e-4 * t) * phi)
                {
                  accepted = true;
                  break;
                }
            }
          if (accepted)
            {
              T.swap(Ttrial);
              if (me > 0)
                beta.swap(btrial);
              F.swap(Ftrial);
            }
          else
            {
              // Globalisation fallback: a few PGS sweeps.
              if (++failures > 50)
                {
                  result.iterations = step;
                  result.message    = "friction active set: line search failed";
                  return result;
                }
              InnerOptions saved     = options;
              options.max_iterations = 10 * failures;
              solve_pgs(c, radius, e, T, beta);
              options = saved;
              natural_map(c, radius, e, T, beta, F);
            }
        }
      result.iterations = options.max_iterations;
      result.message    = "friction active set: step limit reached";
      return result;
    }
  } // namespace contact
} // namespace dpana
