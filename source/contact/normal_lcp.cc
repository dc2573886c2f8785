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
          M_augmented = M;
          M_augmented.noalias() += penalty * G.transpose() * G;
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
      Mcc.resize(k, k);
      for (Eigen::Index c = 0; c < k; ++c)
        for (Eigen::Index a = 0; a < k; ++a)
          Mcc(a, c) = M(index[a], index[c]);
      if (!llt.compute(Mcc))
        return false;
      if (G.rows() > 0)
        {
          Gc.resize(G.rows(), k);
          for (Eigen::Index a = 0; a < k; ++a)
            Gc.col(a) = G.col(index[a]);
          Y = llt.solve(Eigen::MatrixXd(Gc.transpose())); // M_CC^{-1} G_C^T
          schur.compute(Gc * Y);
        }
      factored_index = index;
      factor_valid   = true;
      return true;
    }



    // The reduced equality-constrained problem on the contact set C,
    // M_CC N_C + G_C^T alpha = -b_C, G_C N_C = e, N = 0 off C; false if
    // M_CC is not positive definite.
    bool
    NormalLcp::solve_on_contact_set(const std::vector<Eigen::Index> &index,
                                    const Eigen::VectorXd           &b,
                                    const Eigen::VectorXd           &e,
                                    Eigen::VectorXd                 &N,
                                    Eigen::VectorXd                 &alpha)
    {
      const Eigen::Index k = static_cast<Eigen::Index>(index.size());
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
