#include <dpana/contact/friction_qp.h>
#include <dpana/contact/line_search.h>
#include <dpana/contact/method_of_multipliers.h>
#include <dpana/contact/monitor.h>
#include <dpana/contact/projected_gauss_seidel.h>

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <type_traits>

#ifdef __SSE2__
#  include <emmintrin.h>
#endif

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

      // w += sum_a delta[a] A(:, a) for the m (1 or 2) single precision
      // columns starting at A. Eigen converts float to double one number at
      // a time, which made a single precision sweep slower than one in
      // double; SSE2 (every x86-64 processor) converts two per instruction.
      // One column (2D) is taken as the pair (A(:, 0), A(:, 0)) with
      // weights (delta[0], 0): the second read hits the cache.
      void
      add_single_columns(const float       *A,
                         const unsigned int m,
                         const Eigen::Index q,
                         const double      *delta,
                         double            *w)
      {
        const float *c0 = A, *c1 = (m == 2) ? A + q : A;
        const double d0 = delta[0], d1 = (m == 2) ? delta[1] : 0.0;
        Eigen::Index i = 0;
#ifdef __SSE2__
        const __m128d D0 = _mm_set1_pd(d0), D1 = _mm_set1_pd(d1);
        for (; i + 4 <= q; i += 4)
          {
            const __m128  a = _mm_loadu_ps(c0 + i), b = _mm_loadu_ps(c1 + i);
            const __m128d low = _mm_add_pd(_mm_mul_pd(D0, _mm_cvtps_pd(a)),
                                           _mm_mul_pd(D1, _mm_cvtps_pd(b)));
            const __m128d high =
              _mm_add_pd(_mm_mul_pd(D0, _mm_cvtps_pd(_mm_movehl_ps(a, a))),
                         _mm_mul_pd(D1, _mm_cvtps_pd(_mm_movehl_ps(b, b))));
            _mm_storeu_pd(w + i, _mm_add_pd(_mm_loadu_pd(w + i), low));
            _mm_storeu_pd(w + i + 2, _mm_add_pd(_mm_loadu_pd(w + i + 2), high));
          }
#endif
        for (; i < q; ++i)
          w[i] +=
            d0 * static_cast<double>(c0[i]) + d1 * static_cast<double>(c1[i]);
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
      llt.set_single_precision(options.single_precision_size);
      llt_stick.set_single_precision(options.single_precision_size);
      llt_slip.set_single_precision(options.single_precision_size);
    }



    // @sect4{Block projected Gauss-Seidel}
    //
    // A sweep reads the whole matrix once, column pair by column pair (the
    // update of w after each block), and at 10^4 contact unknowns that read
    // is most of its time: the partition sweeps (settle_partition) use a
    // single precision copy, which halves it. Their w then carries relative
    // errors of about 1e-7, which can move a block across its boundary
    // only where the Newton steps that follow would move it back: those
    // steps, the stopping test and the fallback sweeps are in double.
    template <typename Matrix>
    int
    FrictionQp::pgs(const Matrix              &matrix,
                    const std::vector<double> &W,
                    const Eigen::VectorXd     &right_hand_side,
                    const Eigen::VectorXd     &radius,
                    Eigen::VectorXd           &T,
                    const unsigned int         max_sweeps)
    {
      auto refresh = [&]() {
        if constexpr (std::is_same_v<typename Matrix::Scalar, double>)
          w.noalias() = matrix * T;
        else
          w = (matrix * T.cast<float>()).template cast<double>();
        w += right_hand_side;
      };
      auto sweep = [&](double &change, double &size) {
        for (unsigned int j = 0; j < n; ++j)
          block_step(matrix, W, radius, j, T, change, size);
      };
      return projected_gauss_seidel(options.tolerance,
                                    max_sweeps,
                                    refresh,
                                    sweep);
    }



    // The exact minimiser of the block problem of element j, relaxed, and
    // the column update of w.
    template <typename Matrix>
    void
    FrictionQp::block_step(const Matrix              &matrix,
                           const std::vector<double> &W,
                           const Eigen::VectorXd     &radius,
                           const unsigned int         j,
                           Eigen::VectorXd           &T,
                           double                    &change,
                           double                    &size)
    {
      const double  omega = options.over_relaxation;
      const double *Wj    = W.data() + m * m * j;
      double       *Tj    = T.data() + m * j;
      double        g[2], t[2], delta[2];
      local_linear_term(m, Wj, w.data() + m * j, Tj, g);
      set.minimise(radius[j], Wj, g, t);
      const bool moved = relaxed_block_update(
        m, omega, Tj, t, delta, [&](const double *z, double *p) {
          set.project_tangential(radius[j], z, p);
        });
      for (unsigned int a = 0; a < m; ++a)
        {
          change = std::max(change, std::abs(delta[a]));
          size   = std::max(size, std::abs(Tj[a]));
        }
      if (!moved)
        return;
      if constexpr (std::is_same_v<typename Matrix::Scalar, double>)
        {
          if (m == 1)
            w += delta[0] * matrix.col(j);
          else
            w +=
              matrix.middleCols(2 * j, 2) * Eigen::Vector2d(delta[0], delta[1]);
        }
      else
        add_single_columns(matrix.data() + matrix.rows() * m * j,
                           m,
                           matrix.rows(),
                           delta,
                           w.data());
    }



    InnerResult
    FrictionQp::solve_pgs(const Eigen::VectorXd &c,
                          const Eigen::VectorXd &radius,
                          const Eigen::VectorXd &e,
                          Eigen::VectorXd       &T,
                          Eigen::VectorXd       &beta)
    {
      if (single_precision_sweeps && M_single.size() == 0)
        M_single = (G.rows() > 0 ? M_augmented : M).cast<float>();
      const auto sweeps = [&](const Eigen::MatrixXd     &matrix,
                              const std::vector<double> &W,
                              const Eigen::VectorXd     &r,
                              const unsigned int         max_sweeps) {
        return single_precision_sweeps ?
                 pgs(M_single, W, r, radius, T, max_sweeps) :
                 pgs(matrix, W, r, radius, T, max_sweeps);
      };
      if (G.rows() == 0)
        return sweeps_result(sweeps(M, blocks, c, options.max_iterations),
                             "friction");
      return solve_with_multipliers(
        G,
        e,
        penalty,
        c,
        options,
        "friction",
        [&](const Eigen::VectorXd &r, const unsigned int max_sweeps) {
          return sweeps(M_augmented, blocks_augmented, r, max_sweeps);
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
      w.noalias() = M * T;
      w += c;
      if (G.rows() > 0)
        w.noalias() += G.transpose() * beta;
      natural_map_of_w(radius, e, T, F);
    }



    // F at T for the w already in place (the line search moves w along
    // the step, w(T + t dT) = w(T) + t (M dT + G^T dbeta), instead of a
    // product with M per trial point).
    void
    FrictionQp::natural_map_of_w(const Eigen::VectorXd &radius,
                                 const Eigen::VectorXd &e,
                                 const Eigen::VectorXd &T,
                                 Eigen::VectorXd       &F)
    {
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
    }


    // Project every T_j onto its set c_j P (the start of the active-set
    // method is feasible).
    void
    FrictionQp::project_onto_sets(const Eigen::VectorXd &radius,
                                  Eigen::VectorXd       &T) const
    {
      for (unsigned int j = 0; j < n; ++j)
        {
          double p[2];
          set.project_tangential(radius[j], T.data() + m * j, p);
          for (unsigned int a = 0; a < m; ++a)
            T[m * j + a] = p[a];
        }
    }



    // The stopping test of the active-set method: ||F_T||_inf <= tolerance
    // max(||T||_inf, max_j c_j) and the equality rows to the tolerance
    // relative to their scale (monitor.h).
    bool
    FrictionQp::active_set_converged(const Eigen::VectorXd &F,
                                     const Eigen::VectorXd &radius,
                                     const Eigen::VectorXd &e,
                                     const Eigen::VectorXd &T) const
    {
      const Eigen::Index q  = T.size();
      const Eigen::Index me = G.rows();
      const double       scale_T =
        std::max(T.lpNorm<Eigen::Infinity>(), radius.lpNorm<Eigen::Infinity>());
      const double err_T = F.head(q).lpNorm<Eigen::Infinity>();
      const double err_e =
        (me > 0) ? F.tail(me).lpNorm<Eigen::Infinity>() : 0.0;
      return err_T <= options.tolerance * scale_T &&
             err_e <= options.tolerance * equality_scale(G, e, T);
    }



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
    //
    // This function sorts the eigenvectors: the fixed part of the step goes
    // to dx, the free directions to the list `directions`, and each block to
    // its partition.
    void
    FrictionQp::newton_directions(const Eigen::VectorXd &radius,
                                  const Eigen::VectorXd &F,
                                  Eigen::VectorXd       &dx)
    {
      dx.setZero();
      directions.clear();
      y_last      = y;
      region_last = region;
      radius_last = radius;
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
    }



    // The amplitudes x of the free directions (and dbeta) for the fixed
    // part of dx already set, then dx completed; returns a failure message,
    // empty on success.
    std::string
    FrictionQp::newton_step(const Eigen::VectorXd &F,
                            Eigen::VectorXd       &dx,
                            const bool             refactor)
    {
      const Eigen::Index q  = M.rows();
      const Eigen::Index me = G.rows();
      const Eigen::Index f  = static_cast<Eigen::Index>(directions.size());
      v.noalias()           = M * dx.head(q);
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
          if (refactor)
            {
              factored_directions = -1;
              if (!factor_newton_matrix())
                return "friction active set: Newton matrix not positive "
                       "definite";
              factored_directions = f;
              n_single_factorisations += factors_in_single_precision();
            }
          x = solve_newton_matrix(g);
          refine_newton_solution(g, x);
        }
      else
        x.resize(0);
      if (me > 0)
        dx.tail(me) = equality_step(F.tail(me), dx);
      for (Eigen::Index a = 0; a < f; ++a)
        {
          const Direction &dir = directions[a];
          for (unsigned int t = 0; t < m; ++t)
            dx[m * dir.block + t] += x[a] * dir.v[t];
        }
      if (!dx.allFinite())
        return "friction active set: singular Jacobian";
      return "";
    }



    // @sect5{Newton matrices in single precision}
    //
    // At 10^4 contact unknowns a T-step factors Newton matrices of up to
    // 6000 rows, f^3/3 flops each, and those factorisations were a third of
    // the contact solve. Matrices of at least
    // InnerOptions::single_precision_size rows are factored in single
    // precision (twice the flops per second of BLAS-3 in double, half the
    // memory); each solve is then followed by up to two steps of iterative
    // refinement whose residual g - H x is computed in double through M (a
    // product with M each), so that the step is accurate to about
    // (cond(H) 6e-8)^2 relative or better, not cond(H) 6e-8. The natural map,
    // the line search and the stopping test stay in double: the factors only
    // choose the direction. A chord step (factors of an earlier matrix of the
    // same partition) is refined against the current matrix the same way.
    void
    FrictionQp::apply_newton_matrix(const Eigen::VectorXd &x,
                                    Eigen::VectorXd       &Hx)
    {
      const Eigen::Index f = static_cast<Eigen::Index>(directions.size());
      z_full.setZero(M.rows());
      for (Eigen::Index a = 0; a < f; ++a)
        {
          const Direction &dir = directions[a];
          for (unsigned int t = 0; t < m; ++t)
            z_full[m * dir.block + t] += x[a] * dir.v[t];
        }
      Mz_full.noalias() = M * z_full;
      Hx.resize(f);
      for (Eigen::Index a = 0; a < f; ++a)
        {
          const Direction &dir = directions[a];
          double           h   = 0.0;
          for (unsigned int t = 0; t < m; ++t)
            h += dir.v[t] * Mz_full[m * dir.block + t];
          Hx[a] = h + kappa(dir) * x[a];
        }
    }



    void
    FrictionQp::refine_newton_solution(const Eigen::VectorXd &rhs,
                                       Eigen::VectorXd       &solution)
    {
      if (!factors_in_single_precision())
        return;
      for (unsigned int step = 0; step < 2; ++step)
        {
          apply_newton_matrix(solution, Hx_refine);
          r_refine = rhs - Hx_refine;
          if (r_refine.norm() <= 1e-10 * rhs.norm())
            return;
          solution += solve_newton_matrix(r_refine);
        }
    }



    bool
    FrictionQp::factors_fit() const
    {
      return factored_directions > 0 && partition == previous_partition &&
             factored_directions ==
               static_cast<Eigen::Index>(directions.size());
    }



    // With equality rows: B = Z^T G^T (f x me), h = -(G T - e) - G dT_fixed,
    // dbeta from the Schur complement S = B^T H^{-1} B, and x corrected.
    Eigen::VectorXd
    FrictionQp::equality_step(const Eigen::VectorXd &violation,
                              const Eigen::VectorXd &dx)
    {
      const Eigen::Index q  = M.rows();
      const Eigen::Index me = G.rows();
      const Eigen::Index f  = static_cast<Eigen::Index>(directions.size());
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
      const Eigen::VectorXd h = -violation - G * dx.head(q);
      Eigen::MatrixXd       Y(f, me);
      if (f > 0)
        Y = solve_newton_matrix(B);
      const Eigen::MatrixXd S = B.transpose() * Y;
      const Eigen::VectorXd dbeta =
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(S).solve(
          B.transpose() * x - h);
      if (f > 0)
        x.noalias() -= Y * dbeta;
      return dbeta;
    }
  } // namespace contact
} // namespace dpana
