#include <dpana/contact/method_of_multipliers.h>
#include <dpana/contact/monitor.h>
#include <dpana/contact/normal_lcp.h>
#include <dpana/contact/projected_gauss_seidel.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace dpana
{
  namespace contact
  {
    NormalLcp::NormalLcp(const Eigen::MatrixXd &M_,
                         const Eigen::MatrixXd &G_,
                         const InnerOptions    &options_)
      : M(M_)
      , G(G_)
      , options(options_)
    {
      inverse_diagonal = M.diagonal().cwiseInverse();
      if (G.rows() > 0)
        {
          const double g2 = G.squaredNorm();
          penalty = (g2 > 0.0) ? options.augmentation * M.trace() / g2 : 0.0;
          // penalty G^T G as a sum of outer products, one per equality row
          // (there are a few): Eigen's matrix product would size its cache
          // blocks first, which costs more than the update at these sizes.
          M_augmented = M;
          for (Eigen::Index r = 0; r < G.rows(); ++r)
            M_augmented.noalias() +=
              (penalty * G.row(r).transpose()) * G.row(r);
          inverse_diagonal_augmented = M_augmented.diagonal().cwiseInverse();
        }
      w.resize(M.rows());
      rhs.resize(M.rows());
    }



    // @sect4{Projected Gauss-Seidel sweeps}
    //
    // The gradient w = matrix N + rhs is kept current: a change delta of N_j
    // adds delta times column j (contiguous in Eigen's column-major storage).
    // It is recomputed from scratch once the change test passes, and the
    // test is then repeated, so that accumulated round-off cannot fake
    // convergence.
    int
    NormalLcp::pgs(const Eigen::MatrixXd &matrix,
                   const Eigen::VectorXd &inv_diag,
                   const Eigen::VectorXd &right_hand_side,
                   Eigen::VectorXd       &N,
                   const unsigned int     max_sweeps)
    {
      const Eigen::Index n       = N.size();
      const double       omega   = options.over_relaxation;
      auto               refresh = [&]() {
        w.noalias() = matrix * N;
        w += right_hand_side;
      };
      auto sweep = [&](double &change, double &size) {
        for (Eigen::Index j = 0; j < n; ++j)
          {
            const double Nj    = N[j];
            const double Nnew  = std::min(0.0, Nj - omega * w[j] * inv_diag[j]);
            const double delta = Nnew - Nj;
            if (delta != 0.0)
              {
                w += delta * matrix.col(j);
                N[j]   = Nnew;
                change = std::max(change, std::abs(delta));
              }
            size = std::max(size, std::abs(Nnew));
          }
      };
      return projected_gauss_seidel(options.tolerance,
                                    max_sweeps,
                                    refresh,
                                    sweep);
    }



    InnerResult
    NormalLcp::solve_pgs(const Eigen::VectorXd &b,
                         const Eigen::VectorXd &e,
                         Eigen::VectorXd       &N,
                         Eigen::VectorXd       &alpha)
    {
      if (G.rows() == 0)
        return sweeps_result(
          pgs(M, inverse_diagonal, b, N, options.max_iterations), "normal");

      // Method of multipliers for the equality rows.
      return solve_with_multipliers(
        G,
        e,
        penalty,
        b,
        options,
        "normal",
        [&](const Eigen::VectorXd &r, const unsigned int max_sweeps) {
          return pgs(M_augmented, inverse_diagonal_augmented, r, N, max_sweeps);
        },
        rhs,
        N,
        alpha);
    }



    // @sect4{Primal-dual active set}
    //
    // The contact set guessed from the current point: C = { j : N_j - w_j /
    // M_jj < 0 }, w = M N + b + G^T alpha.
    void
    NormalLcp::guess_contact_set(const Eigen::VectorXd &b,
                                 const Eigen::VectorXd &N,
                                 const Eigen::VectorXd &alpha,
                                 std::vector<char>     &in_contact)
    {
      w.noalias() = M * N;
      w += b;
      if (G.rows() > 0)
        w.noalias() += G.transpose() * alpha;
      for (Eigen::Index j = 0; j < N.size(); ++j)
        in_contact[j] = (N[j] - w[j] * inverse_diagonal[j] < 0.0);
    }



    // The factorisation depends on the contact set only. Within a splitting
    // the set settles after a few outer iterations, so the factors of the
    // last set are kept and reused when the set comes back (the solve is
    // then the same to round-off).
    bool
    NormalLcp::factor_contact_set(const std::vector<Eigen::Index> &index)
    {
      if (factor_valid && index == factored_index)
        return true;
      const Eigen::Index k = static_cast<Eigen::Index>(index.size());
      factor_valid         = false;
      Mcc                  = M(index, index);
      direct_flops += static_cast<double>(k) * k * k / 3.0;
      if (!llt.compute(Mcc))
        return false;
      if (G.rows() > 0)
        {
          Gc = G(Eigen::all, index);
          Y  = llt.solve(Eigen::MatrixXd(Gc.transpose())); // M_CC^{-1} G_C^T
          schur.compute(Gc * Y);
        }
      factored_index = index;
      factor_valid   = true;
      return true;
    }



    // @sect4{The reduced problem through the separated set}
    //
    // On the 3D surfaces of 10^3 - 10^4 elements most elements are in
    // contact, and each active-set step factoring M_CC costs |C|^3 / 3 flops
    // (2500 rows of 3364 at 10 092 contact unknowns). The same reduced
    // problem has an equivalent form on the separated set F, the complement
    // of C. With H = M^{-1} and the reaction w = M N + b + G^T alpha, which
    // vanishes on C, the conditions N_F = 0 and G N = e read
    // @f[
    //   N = H (w - b - G^T \alpha), \quad w_C = 0:\qquad
    //   H_{FF} w_F - P_F \alpha = q_F, \quad
    //   P_F^T w_F - G P \alpha = e + G q,
    // @f]
    // with q = H b and P = H G^T. So w_F = z + Y_F alpha, z = H_FF^{-1} q_F,
    // Y_F = H_FF^{-1} P_F, and (P_F^T Y_F - G P) alpha = e + G q - P_F^T z
    // (minus the Schur complement G_C M_CC^{-1} G_C^T of the direct form).
    // H_FF is a principal block of an SPD matrix, hence SPD; a step factors
    // it, |F| rows, and forms H once for all steps of all N-steps of a
    // splitting (M = A_NN does not change). H carries the round-off of the
    // inversion, cond(M) times the machine epsilon; up to three steps of
    // iterative refinement on the KKT rows of C, each a solve of the same
    // form with the residual as data, bring N back to the accuracy of the
    // direct form.
    bool
    NormalLcp::ensure_inverse()
    {
      if (inverse_state == 0)
        {
          DenseCholesky factor;
          inverse_state = factor.compute(M) ? 1 : -1;
          if (inverse_state > 0)
            {
              H = factor.inverse();
              if (G.rows() > 0)
                {
                  P  = H * G.transpose();
                  GP = G * P;
                }
            }
        }
      return inverse_state > 0;
    }



    bool
    NormalLcp::factor_separated_set(const std::vector<Eigen::Index> &free)
    {
      if (free_valid && free == factored_free)
        return true;
      const Eigen::Index f = static_cast<Eigen::Index>(free.size());
      free_valid           = false;
      if (f > 0)
        {
          Eigen::MatrixXd Hff = H(free, free);
          if (!llt_free.compute(std::move(Hff)))
            return false;
        }
      if (G.rows() > 0)
        {
          Pf = P(free, Eigen::all);
          Yf = (f > 0) ? llt_free.solve(Pf) : Pf;
          schur_free.compute(Pf.transpose() * Yf - GP);
        }
      factored_free = free;
      free_valid    = true;
      return true;
    }



    // One solve of the form above for the data (b, e); N_F is set to zero
    // exactly (it is zero up to round-off).
    void
    NormalLcp::solve_through_separated_set(
      const std::vector<Eigen::Index> &free,
      const Eigen::VectorXd           &b,
      const Eigen::VectorXd           &e,
      Eigen::VectorXd                 &N,
      Eigen::VectorXd                 &alpha)
    {
      const Eigen::Index    f  = static_cast<Eigen::Index>(free.size());
      const Eigen::VectorXd q  = H * b;
      const Eigen::VectorXd qf = q(free);
      Eigen::VectorXd       wf = (f > 0) ? llt_free.solve(qf) : qf;
      N                        = -q;
      if (G.rows() > 0)
        {
          Eigen::VectorXd rs = e + G * q;
          rs.noalias() -= Pf.transpose() * wf;
          alpha = schur_free.solve(rs);
          wf.noalias() += Yf * alpha;
          N.noalias() -= P * alpha;
        }
      for (Eigen::Index a = 0; a < f; ++a)
        N += wf[a] * H.col(free[a]);
      for (Eigen::Index a = 0; a < f; ++a)
        N[free[a]] = 0.0;
    }



    bool
    NormalLcp::solve_by_complement(const std::vector<Eigen::Index> &index,
                                   const Eigen::VectorXd           &b,
                                   const Eigen::VectorXd           &e,
                                   Eigen::VectorXd                 &N,
                                   Eigen::VectorXd                 &alpha)
    {
      const Eigen::Index        n = M.rows();
      std::vector<Eigen::Index> free;
      free.reserve(n - index.size());
      std::vector<char> in_c(n, 0);
      for (const Eigen::Index j : index)
        in_c[j] = 1;
      for (Eigen::Index j = 0; j < n; ++j)
        if (!in_c[j])
          free.push_back(j);
      if (!factor_separated_set(free))
        return false;
      solve_through_separated_set(free, b, e, N, alpha);

      // Iterative refinement: the residual of the KKT rows of C (w_C = 0)
      // and of the equality rows, as data of a correction of the same form
      // (only b_C enters the solution, so b' is the residual on C and zero
      // on F), while it falls by at least a half.
      Eigen::VectorXd residual(n), b_correction(n), e_correction, dN, dalpha;
      auto            kkt_residual = [&]() {
        residual.noalias() = M * N;
        residual += b;
        if (G.rows() > 0)
          residual.noalias() += G.transpose() * alpha;
        for (const Eigen::Index j : free)
          residual[j] = 0.0;
        double norm = residual.lpNorm<Eigen::Infinity>();
        if (G.rows() > 0)
          {
            // The equality rows' residual, a traction, made a displacement
            // like the rows of C by the largest compliance per unit of G.
            e_correction = e - G * N;
            norm         = std::max(norm,
                            e_correction.lpNorm<Eigen::Infinity>() *
                              M.diagonal().maxCoeff() /
                              std::max(G.lpNorm<Eigen::Infinity>(), 1e-300));
          }
        return norm;
      };
      double size = kkt_residual();
      for (unsigned int step = 0; step < 3 && size > 0.0; ++step)
        {
          b_correction = residual;
          solve_through_separated_set(
            free, b_correction, e_correction, dN, dalpha);
          const Eigen::VectorXd N_old = N, alpha_old = alpha;
          N += dN;
          if (G.rows() > 0)
            alpha += dalpha;
          const double new_size = kkt_residual();
          if (!(new_size < size))
            {
              N     = N_old;
              alpha = alpha_old;
              break;
            }
          const bool enough = (new_size > 0.5 * size);
          size              = new_size;
          if (enough)
            break;
        }
      return true;
    }



    // The reduced equality-constrained problem on the contact set C,
    // M_CC N_C + G_C^T alpha = -b_C, G_C N_C = e, N = 0 off C; false if
    // M_CC is not positive definite. Through the separated set when that is
    // the smaller one (see above).
    bool
    NormalLcp::solve_on_contact_set(const std::vector<Eigen::Index> &index,
                                    const Eigen::VectorXd           &b,
                                    const Eigen::VectorXd           &e,
                                    Eigen::VectorXd                 &N,
                                    Eigen::VectorXd                 &alpha)
    {
      const Eigen::Index k  = static_cast<Eigen::Index>(index.size());
      const Eigen::Index n  = M.rows();
      const double       n3 = static_cast<double>(n) * n * n;
      if (k > 0 && n >= options.complement_size && n - k < k &&
          (inverse_state != 0 ||
           direct_flops >= options.complement_after * n3) &&
          ensure_inverse())
        {
          ++n_complement_solves;
          return solve_by_complement(index, b, e, N, alpha);
        }
      N.setZero();
      if (k == 0)
        return true;
      if (!factor_contact_set(index))
        return false;
      Eigen::VectorXd bc(k), x;
      for (Eigen::Index a = 0; a < k; ++a)
        bc[a] = b[index[a]];
      if (G.rows() > 0)
        {
          const Eigen::VectorXd z  = llt.solve(Eigen::VectorXd(-bc));
          const Eigen::VectorXd rs = Gc * z - e;
          alpha                    = schur.solve(rs);
          x                        = z - Y * alpha;
        }
      else
        x = llt.solve(Eigen::VectorXd(-bc));
      for (Eigen::Index a = 0; a < k; ++a)
        N[index[a]] = x[a];
      return true;
    }



    InnerResult
    NormalLcp::solve_active_set(const Eigen::VectorXd &b,
                                const Eigen::VectorXd &e,
                                Eigen::VectorXd       &N,
                                Eigen::VectorXd       &alpha)
    {
      const Eigen::Index n = N.size();
      const Eigen::Index m = G.rows();
      InnerResult        result;
      if (alpha.size() != m)
        alpha = Eigen::VectorXd::Zero(m);

      std::vector<char> in_contact(n), next(n);
      guess_contact_set(b, N, alpha, in_contact);
      std::set<std::vector<char>> visited;
      std::vector<Eigen::Index>   index;
      unsigned int                restarts = 0;
      for (unsigned int step = 1; step <= options.max_iterations; ++step)
        {
          result.iterations = step;
          index.clear();
          for (Eigen::Index j = 0; j < n; ++j)
            if (in_contact[j])
              index.push_back(j);
          if (m > 0 && index.empty())
            {
              // Equality rows need contacts to carry them: start from all.
              std::fill(in_contact.begin(), in_contact.end(), 1);
              continue;
            }
          if (!solve_on_contact_set(index, b, e, N, alpha))
            {
              result.message = "normal active set: M_CC not positive definite";
              return result;
            }
          guess_contact_set(b, N, alpha, next);
          const bool equalities_hold =
            (m == 0) || ((G * N - e).lpNorm<Eigen::Infinity>() <=
                         1e-9 * equality_scale(G, e, N));
          if (next == in_contact && equalities_hold)
            {
              result.converged = true;
              return result;
            }
          if (!visited.insert(in_contact).second || next == in_contact)
            {
              // Cycling: a few projected Gauss-Seidel sweeps (the exact
              // solution is a fixed point of both methods) before the set is
              // guessed again.
              if (++restarts > 20)
                {
                  result.message = "normal active set: cycling";
                  return result;
                }
              Eigen::VectorXd a      = alpha;
              InnerOptions    saved  = options;
              options.max_iterations = 20 * restarts;
              solve_pgs(b, e, N, a);
              options = saved;
              alpha   = a;
              guess_contact_set(b, N, alpha, next);
              visited.clear();
            }
          in_contact.swap(next);
        }
      result.iterations = options.max_iterations;
      result.message    = "normal active set: step limit reached";
      return result;
    }
  } // namespace contact
} // namespace dpana
