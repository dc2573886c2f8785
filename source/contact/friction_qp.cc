#include <dpana/contact/friction_qp.h>
#include <dpana/contact/line_search.h>
#include <dpana/contact/method_of_multipliers.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>

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
      partition.assign(n, 0);
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



    // @sect4{The Newton matrix of solve_active_set}
    //
    // H = Z^T M Z + diag(kappa) over the free directions (see
    // solve_active_set) is factored in one of two ways.
    //
    // Directly: M Z column by column (contiguous columns of M), the lower
    // triangle of H, Cholesky.
    //
    // By blocks, when the partition of the elements into stick blocks s (all
    // directions free, the Cartesian axes, kappa = 0), slip blocks l (some
    // directions free: the tangent of the circle or of a facet) and fixed
    // blocks is the same as at the previous Newton step. With all d - 1
    // components of the slip blocks and V the block-diagonal matrix of their
    // free directions,
    //   H = [ M_ss       M_sl V          ]
    //       [ V^T M_ls   V^T M_ll V + K  ],
    // and eliminating the stick unknowns leaves the Schur complement
    //   S = V^T Sigma V + K,   Sigma = M_ll - M_ls M_ss^{-1} M_sl,
    // in which only V and K (the slip directions and the eigenvalues) change
    // from one step to the next. The Cholesky factor of M_ss, P = M_ss^{-1}
    // M_sl and Sigma depend on the partition only: they are computed once per
    // partition and kept, and each step then factors only S (one unknown per
    // slip direction). Late in a splitting, when the stick and slip zones
    // have settled, every T-step takes this path. It solves the same system
    // as the direct path, up to round-off.
    bool
    FrictionQp::factor_newton_matrix()
    {
      const Eigen::Index f    = static_cast<Eigen::Index>(directions.size());
      const Eigen::Index q    = M.rows();
      const bool         same = (partition == previous_partition);
      previous_partition      = partition;
      if (!same)
        {
          blocked = false;
          MZ.resize(q, f);
          for (Eigen::Index a = 0; a < f; ++a)
            {
              const Direction &dir = directions[a];
              if (m == 1)
                MZ.col(a) = dir.v[0] * M.col(dir.block);
              else
                MZ.col(a) = dir.v[0] * M.col(2 * dir.block) +
                            dir.v[1] * M.col(2 * dir.block + 1);
            }
          H.resize(f, f);
          for (Eigen::Index b = 0; b < f; ++b)
            {
              const double *column = MZ.data() + q * b;
              for (Eigen::Index a = b; a < f; ++a)
                {
                  const Direction &dir = directions[a];
                  const double    *row = column + m * dir.block;
                  double           h   = dir.v[0] * row[0];
                  if (m == 2)
                    h += dir.v[1] * row[1];
                  H(a, b) = h;
                }
              const Direction &dir = directions[b];
              H(b, b) += (1.0 - dir.lambda) / (dir.lambda * rho[dir.block]);
            }
          llt.compute(H);
          return llt.info() == Eigen::Success;
        }

      if (!cache_valid || partition != cached_partition)
        {
          cache_valid = false;
          s_index.clear();
          l_index.clear();
          s_start.assign(n, -1);
          l_start.assign(n, -1);
          for (unsigned int j = 0; j < n; ++j)
            if (partition[j] == 2)
              {
                s_start[j] = static_cast<Eigen::Index>(s_index.size());
                for (unsigned int t = 0; t < m; ++t)
                  s_index.push_back(m * j + t);
              }
            else if (partition[j] == 1)
              {
                l_start[j] = static_cast<Eigen::Index>(l_index.size());
                for (unsigned int t = 0; t < m; ++t)
                  l_index.push_back(m * j + t);
              }
          const Eigen::Index ns = static_cast<Eigen::Index>(s_index.size());
          const Eigen::Index nl = static_cast<Eigen::Index>(l_index.size());
          Sigma.resize(nl, nl);
          for (Eigen::Index b = 0; b < nl; ++b)
            for (Eigen::Index a = 0; a < nl; ++a)
              Sigma(a, b) = M(l_index[a], l_index[b]);
          if (ns > 0)
            {
              H.resize(ns, ns);
              for (Eigen::Index b = 0; b < ns; ++b)
                for (Eigen::Index a = 0; a < ns; ++a)
                  H(a, b) = M(s_index[a], s_index[b]);
              llt_stick.compute(H);
              if (llt_stick.info() != Eigen::Success)
                return false;
              P.resize(ns, nl);
              for (Eigen::Index b = 0; b < nl; ++b)
                for (Eigen::Index a = 0; a < ns; ++a)
                  P(a, b) = M(s_index[a], l_index[b]);
              // W = L^{-1} M_sl, Sigma = M_ll - W^T W, P = L^{-T} W.
              llt_stick.matrixL().solveInPlace(P);
              Sigma.selfadjointView<Eigen::Lower>().rankUpdate(P.transpose(),
                                                               -1.0);
              Sigma.triangularView<Eigen::StrictlyUpper>() =
                Sigma.transpose().eval();
              llt_stick.matrixU().solveInPlace(P);
            }
          cached_partition = partition;
          cache_valid      = true;
        }
      blocked = true;

      // Positions of the directions in the stick unknowns or among the slip
      // directions, and S = V^T Sigma V + K.
      position.resize(f);
      Eigen::Index nr = 0;
      for (Eigen::Index a = 0; a < f; ++a)
        {
          const Direction &dir = directions[a];
          position[a] =
            (partition[dir.block] == 2) ? s_start[dir.block] + dir.axis : nr++;
        }
      S_slip.resize(nr, nr);
      for (Eigen::Index b = 0; b < f; ++b)
        {
          const Direction &db = directions[b];
          if (partition[db.block] == 2)
            continue;
          const Eigen::Index lb = l_start[db.block];
          for (Eigen::Index a = b; a < f; ++a)
            {
              const Direction &da = directions[a];
              if (partition[da.block] == 2)
                continue;
              const Eigen::Index la = l_start[da.block];
              double             s  = 0.0;
              for (unsigned int t = 0; t < m; ++t)
                for (unsigned int u = 0; u < m; ++u)
                  s += da.v[t] * Sigma(la + t, lb + u) * db.v[u];
              S_slip(position[a], position[b]) = s;
            }
          S_slip(position[b], position[b]) +=
            (1.0 - db.lambda) / (db.lambda * rho[db.block]);
        }
      if (nr > 0)
        {
          llt_slip.compute(S_slip);
          return llt_slip.info() == Eigen::Success;
        }
      return true;
    }



    Eigen::MatrixXd
    FrictionQp::solve_newton_matrix(const Eigen::MatrixXd &R) const
    {
      if (!blocked)
        return llt.solve(R);
      const Eigen::Index f = R.rows(), k = R.cols();
      const Eigen::Index ns = static_cast<Eigen::Index>(s_index.size());
      const Eigen::Index nl = static_cast<Eigen::Index>(l_index.size());
      const Eigen::Index nr = S_slip.rows();
      Eigen::MatrixXd    Rs = Eigen::MatrixXd::Zero(ns, k), Rl(nr, k);
      for (Eigen::Index a = 0; a < f; ++a)
        if (partition[directions[a].block] == 2)
          Rs.row(position[a]) = R.row(a);
        else
          Rl.row(position[a]) = R.row(a);
      Eigen::MatrixXd Xs = (ns > 0) ? Eigen::MatrixXd(llt_stick.solve(Rs)) : Rs;
      Eigen::MatrixXd Xl(nr, k);
      if (nr > 0)
        {
          // Slip part: S x_l = r_l - V^T P^T r_s.
          if (ns > 0)
            {
              const Eigen::MatrixXd Q = P.transpose() * Rs;
              for (Eigen::Index a = 0; a < f; ++a)
                {
                  const Direction &dir = directions[a];
                  if (partition[dir.block] == 2)
                    continue;
                  for (unsigned int t = 0; t < m; ++t)
                    Rl.row(position[a]) -=
                      dir.v[t] * Q.row(l_start[dir.block] + t);
                }
            }
          Xl = llt_slip.solve(Rl);
          // Stick part: x_s = M_ss^{-1} r_s - P V x_l.
          if (ns > 0)
            {
              Eigen::MatrixXd VX = Eigen::MatrixXd::Zero(nl, k);
              for (Eigen::Index a = 0; a < f; ++a)
                {
                  const Direction &dir = directions[a];
                  if (partition[dir.block] == 2)
                    continue;
                  for (unsigned int t = 0; t < m; ++t)
                    VX.row(l_start[dir.block] + t) +=
                      dir.v[t] * Xl.row(position[a]);
                }
              Xs.noalias() -= P * VX;
            }
        }
      Eigen::MatrixXd X(f, k);
      for (Eigen::Index a = 0; a < f; ++a)
        if (partition[directions[a].block] == 2)
          X.row(a) = Xs.row(position[a]);
        else
          X.row(a) = Xl.row(position[a]);
      return X;
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
        btrial(me), v(q);
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

          // @sect5{The Newton step as a symmetric positive definite system}
          //
          // The generalised Jacobian of F_j = T_j - Pi(T_j - rho_j w_j),
          // w = M T + c + G^T beta, has the block rows
          //   dF_j = dT_j - D_j (dT_j - rho_j (M dT + G^T dbeta)_j),
          // and the Newton step solves dF = -F (with G dT = -(G T - e)).
          // D_j, the derivative of a projection onto a convex set, is
          // symmetric with eigenvalues in [0, 1]: D_j = sum_i lambda_i v_i
          // v_i^T (FrictionSet::projection_derivative_spectral). Along an
          // eigenvector v with lambda = 0 (the radial direction of a slip
          // disc block, the normal of a polygon facet, a vertex, a zero
          // radius, an interval end) the step is fixed outright,
          // v . dT_j = -v . F_j. Along an eigenvector with lambda > 0 the row,
          // divided by lambda rho_j, reads
          //   v . (M dT + G^T dbeta)_j + kappa v . dT_j
          //     = -v . F_j / (lambda rho_j),   kappa = (1 - lambda)/(lambda
          //     rho_j) >= 0.
          // Writing dT = dT_fixed + Z x, with the columns of Z the
          // eigenvectors with lambda > 0 (placed in their blocks) and x their
          // amplitudes, the unknowns x solve
          //   (Z^T M Z + diag(kappa)) x + Z^T G^T dbeta = g,
          //   G Z x = -(G T - e) - G dT_fixed,
          //   g = -Lambda^{-1} Z^T F / rho - Z^T M dT_fixed.
          // Z has orthonormal columns and M is SPD, so H = Z^T M Z + diag(
          // kappa) is SPD: a Cholesky factorisation replaces the LU of the
          // full nonsymmetric Jacobian. The step is the same (the Jacobian
          // is only reduced, not approximated), the system has one unknown
          // per stick or facet direction instead of d - 1 per free block,
          // and Cholesky takes half the work of LU. Equality rows: Schur
          // complement S = B^T H^{-1} B, B = Z^T G^T.
          dx.setZero();
          directions.clear();
          for (unsigned int j = 0; j < n; ++j)
            {
              double lambda[2], V[4];
              set.projection_derivative_spectral(
                radius[j], y.data() + m * j, region[j], lambda, V);
              unsigned int n_free = 0, n_unit = 0;
              for (unsigned int i = 0; i < m; ++i)
                {
                  const double *vi = V + m * i;
                  double        vF = 0.0;
                  for (unsigned int a = 0; a < m; ++a)
                    vF += vi[a] * F[m * j + a];
                  if (lambda[i] == 0.0)
                    for (unsigned int a = 0; a < m; ++a)
                      dx[m * j + a] -= vF * vi[a];
                  else
                    {
                      Direction dir;
                      dir.block  = j;
                      dir.v[0]   = vi[0];
                      dir.v[1]   = (m == 2) ? vi[1] : 0.0;
                      dir.lambda = lambda[i];
                      dir.vF     = vF;
                      dir.axis   = i;
                      directions.push_back(dir);
                      ++n_free;
                      // Cartesian axis i with eigenvalue 1?
                      n_unit += (lambda[i] == 1.0 && vi[i] == 1.0 &&
                                 (m == 1 || vi[1 - i] == 0.0));
                    }
                }
              // 2: every direction free, Cartesian, eigenvalue 1 (stick);
              // 1: some directions free (slip on the circle or a facet);
              // 0: none (vertex, interval end, radius 0).
              partition[j] = (n_unit == m) ? 2 : (n_free > 0 ? 1 : 0);
            }
          const Eigen::Index f = static_cast<Eigen::Index>(directions.size());
          v.noalias()          = M * dx.head(q);
          g.resize(f);
          for (Eigen::Index a = 0; a < f; ++a)
            {
              const Direction &dir = directions[a];
              double           zv  = dir.v[0] * v[m * dir.block];
              if (m == 2)
                zv += dir.v[1] * v[m * dir.block + 1];
              g[a] = -dir.vF / (dir.lambda * rho[dir.block]) - zv;
            }
          if (f > 0)
            {
              if (!factor_newton_matrix())
                {
                  result.iterations = step;
                  result.message =
                    "friction active set: Newton matrix not positive definite";
                  return result;
                }
              x = solve_newton_matrix(g);
            }
          else
            x.resize(0);
          if (me > 0)
            {
              // B = Z^T G^T (f x me), h = -(G T - e) - G dT_fixed.
              B.resize(f, me);
              for (Eigen::Index a = 0; a < f; ++a)
                {
                  const Direction &dir = directions[a];
                  for (Eigen::Index i = 0; i < me; ++i)
                    {
                      double bi = dir.v[0] * G(i, m * dir.block);
                      if (m == 2)
                        bi += dir.v[1] * G(i, m * dir.block + 1);
                      B(a, i) = bi;
                    }
                }
              const Eigen::VectorXd h = -F.tail(me) - G * dx.head(q);
              Eigen::MatrixXd       Y(f, me);
              if (f > 0)
                Y = solve_newton_matrix(B);
              const Eigen::MatrixXd S = B.transpose() * Y;
              const Eigen::VectorXd dbeta =
                Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(S)
                  .solve(B.transpose() * x - h);
              if (f > 0)
                x.noalias() -= Y * dbeta;
              dx.tail(me) = dbeta;
            }
          for (Eigen::Index a = 0; a < f; ++a)
            {
              const Direction &dir = directions[a];
              for (unsigned int t = 0; t < m; ++t)
                dx[m * dir.block + t] += x[a] * dir.v[t];
            }
          if (!dx.allFinite())
            {
              result.iterations = step;
              result.message    = "friction active set: singular Jacobian";
              return result;
            }

          // Armijo backtracking on 1/2 ||F||^2.
          const bool accepted =
            armijo_backtracking(0.5 * F.squaredNorm(), 40, [&](const double t) {
              Ttrial = T + t * dx.head(q);
              if (me > 0)
                btrial = beta + t * dx.tail(me);
              natural_map(c, radius, e, Ttrial, btrial, Ftrial);
              return 0.5 * Ftrial.squaredNorm();
            });
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
