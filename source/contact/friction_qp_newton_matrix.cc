#include <dpana/contact/friction_qp.h>
#include <dpana/linear_algebra/blas.h>

namespace dpana
{
  namespace contact
  {
    namespace
    {
      // The lower triangle of C <- C - W^T W (BLAS dsyrk).
      void
      subtract_gram(const Eigen::MatrixXd &W, Eigen::MatrixXd &C)
      {
        const int n            = static_cast<int>(W.cols()),
                  k            = static_cast<int>(W.rows());
        const double minus_one = -1.0, one = 1.0;
        if (n > 0 && k > 0)
          dsyrk_(
            "L", "T", &n, &k, &minus_one, W.data(), &k, &one, C.data(), &n);
      }
    } // namespace



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
      const bool same    = (partition == previous_partition);
      previous_partition = partition;
      if (!same)
        return factor_directly();
      if (!cache_valid || partition != cached_partition)
        if (!factor_partition())
          return false;
      blocked = true;
      return factor_slip_schur();
    }



    // Directly: H = Z^T M Z + diag(kappa), lower triangle, Cholesky.
    bool
    FrictionQp::factor_directly()
    {
      const Eigen::Index f = static_cast<Eigen::Index>(directions.size());
      const Eigen::Index q = M.rows();
      blocked              = false;
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
          H(b, b) += kappa(dir);
        }
      return llt.compute(std::move(H));
    }



    // By blocks, the part that depends on the partition only: the index
    // lists of the stick and slip components, the Cholesky factor of M_ss,
    // P = M_ss^{-1} M_sl and Sigma = M_ll - M_ls M_ss^{-1} M_sl.
    bool
    FrictionQp::factor_partition()
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
          if (!llt_stick.compute(std::move(H)))
            return false;
          P.resize(ns, nl);
          for (Eigen::Index b = 0; b < nl; ++b)
            for (Eigen::Index a = 0; a < ns; ++a)
              P(a, b) = M(s_index[a], l_index[b]);
          // W = L^{-1} M_sl, Sigma = M_ll - W^T W, P = L^{-T} W (nothing
          // to do without slip unknowns: Eigen's triangular solve must not
          // see the empty P).
          if (nl > 0)
            {
              llt_stick.solve_lower_in_place(P);
              subtract_gram(P, Sigma);
              Sigma.triangularView<Eigen::StrictlyUpper>() =
                Sigma.transpose().eval();
              llt_stick.solve_upper_in_place(P);
            }
        }
      cached_partition = partition;
      cache_valid      = true;
      return true;
    }



    // By blocks, the part of each step: S = V^T Sigma V + K and its
    // Cholesky factor.
    bool
    FrictionQp::factor_slip_schur()
    {
      const Eigen::Index f = static_cast<Eigen::Index>(directions.size());
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
          S_slip(position[b], position[b]) += kappa(db);
        }
      if (nr > 0)
        {
          return llt_slip.compute(S_slip);
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
      Eigen::MatrixXd Xs = (ns > 0) ? llt_stick.solve(Rs) : Rs;
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
  } // namespace contact
} // namespace dpana
