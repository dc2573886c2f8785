// The normal subproblem of the D-PANA splitting (the N-step): at fixed
// tangential tractions T, find N (and the free multipliers alpha of the
// equality rows, if any) solving the mixed linear complementarity problem
// @f[
//   \min_{N \le 0,\ G N = e} \tfrac12 N^T M N + b^T N
//   \iff
//   w = M N + b + G^T\alpha,\ N \le 0,\ w \le 0,\ N_j w_j = 0,\ G N = e,
// @f]
// with M = A_NN (SPD), b = D_N + A_NT T (+ the fixed part of G^T alpha).
//
// Two solvers:
//   - solve_pgs: projected Gauss-Seidel with over-relaxation omega,
//       N_j <- min(0, N_j - omega w_j / M_jj),
//     keeping w = M N + b up to date by column updates (skipped for elements
//     that stay separated). Stops when the largest change of a sweep is
//     below tolerance * ||N||_inf. Equality rows are handled by the method of
//     multipliers (augmented Lagrangian): PGS runs on M + rho G^T G with
//     b + G^T (alpha - rho e), then alpha += rho (G N - e), until
//     ||G N - e||_inf <= tolerance * (||G||_inf ||N||_inf + ||e||_inf).
//   - solve_active_set: primal-dual active set (a semismooth Newton method
//     for N = min(0, N - w / diag(M))): the contact set
//     C = { j : N_j - w_j / M_jj < 0 } is guessed, the equality-constrained
//     QP on C (N_j = 0 off C, w_j = 0 on C, G N = e) is solved exactly
//     (Cholesky of M_CC on the system LAPACK, dense_cholesky.h, and a Schur
//     complement for alpha), and C is updated
//     until it repeats, which gives the exact solution to round-off. Where
//     most elements are in contact, the reduced problem is solved through
//     the complement F of C instead (see "The reduced problem through the
//     separated set" in normal_lcp.cc): with H = M^{-1}, formed once per
//     NormalLcp, a step factors H_FF, |F| rows instead of |C|. A set
//     that was already visited (cycling, possible for SPD matrices that are
//     not M-matrices) triggers a few PGS sweeps from the current point before
//     the active-set steps resume; the number of steps is capped.
#ifndef dpana_contact_normal_lcp_h
#define dpana_contact_normal_lcp_h

#include <dpana/contact/dense_cholesky.h>

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace dpana
{
  namespace contact
  {
    struct InnerOptions
    {
      double       tolerance       = 1e-12;
      unsigned int max_iterations  = 10000;
      double       over_relaxation = 1.0;
      double       augmentation    = 1.0;
      // Active-set T-step only (friction_qp.h): at most this many projected
      // Gauss-Seidel sweeps before the Newton steps, to find the stick /
      // slip partition; 0: none.
      unsigned int partition_sweeps = 0;
      // ... in T-steps of at least this many tangential unknowns.
      unsigned int partition_sweep_size = 1000;
      // Active-set T-step only: a Newton step whose partition is that of the
      // last factored Newton matrix first tries that matrix's factors (a
      // chord step, kept if it halves ||F||); false: every step is an exact
      // Newton step with its own factorisation.
      bool chord_steps = true;
      // Active-set T-step only: Newton matrices of at least this many rows
      // are factored in single precision, each solve refined in double
      // (friction_qp.cc); 0: all of them.
      unsigned int single_precision_size = 1024;
      // Active-set N-step only: with at least this many normal unknowns, a
      // contact set C with fewer elements outside than inside is solved
      // through H = M^{-1} (formed once, n^3 flops) and a Cholesky factor of
      // H_FF on the separated set F = complement of C, |F| rows instead of
      // the |C| of M_CC; the solution is the same to round-off.
      unsigned int complement_size = 0;
      // ... once the factorisations of M_CC have cost complement_after
      // times the n^3 flops of forming H (so that a solve that needs few
      // steps, a frictionless one, never pays for H, and one that needs many
      // pays at most twice what the better choice made in advance would
      // have cost); 0: at the first step that qualifies.
      double complement_after = 1.0;
    };

    struct InnerResult
    {
      bool         converged  = false;
      unsigned int iterations = 0; // sweeps (PGS) or active-set steps
      std::string  message;
    };

    class NormalLcp
    {
    public:
      // M (n x n, SPD) and G (m x n, m may be 0) are kept by reference and
      // must outlive the object. Precomputes the diagonal and, with equality
      // rows, the augmented matrix.
      NormalLcp(const Eigen::MatrixXd &M,
                const Eigen::MatrixXd &G,
                const InnerOptions    &options);

      // N, alpha: start values on input (warm start), solution on output.
      InnerResult
      solve_pgs(const Eigen::VectorXd &b,
                const Eigen::VectorXd &e,
                Eigen::VectorXd       &N,
                Eigen::VectorXd       &alpha);

      InnerResult
      solve_active_set(const Eigen::VectorXd &b,
                       const Eigen::VectorXd &e,
                       Eigen::VectorXd       &N,
                       Eigen::VectorXd       &alpha);

      // Change the tolerance of the following solves (the splitting tightens
      // it as the outer residual decreases).
      void
      set_tolerance(const double tolerance)
      {
        options.tolerance = tolerance;
      }

      // How many reduced problems were solved through the separated set
      // (InnerOptions::complement_size), over all solves of this object.
      unsigned int
      complement_solves() const
      {
        return n_complement_solves;
      }

    private:
      // PGS sweeps on (matrix, rhs) until the relative change is below the
      // tolerance or max_sweeps; returns the number of sweeps (negative if
      // not converged).
      int
      pgs(const Eigen::MatrixXd &matrix,
          const Eigen::VectorXd &inverse_diagonal,
          const Eigen::VectorXd &rhs,
          Eigen::VectorXd       &N,
          unsigned int           max_sweeps);

      // The steps of solve_active_set: the contact set guessed from
      // (N, alpha), the factors of M_CC (and of the Schur complement of the
      // equality rows) for a set, kept while it repeats, and the solution of
      // the reduced problem on a set (false if M_CC is not positive
      // definite).
      void
      guess_contact_set(const Eigen::VectorXd &b,
                        const Eigen::VectorXd &N,
                        const Eigen::VectorXd &alpha,
                        std::vector<char>     &in_contact);

      bool
      factor_contact_set(const std::vector<Eigen::Index> &index);

      // The reduced problem on C solved through H = M^{-1} and the
      // separated set F (false if M is not positive definite): H formed
      // once, the factors of H_FF kept while F repeats, then the solve and
      // up to three steps of iterative refinement on the KKT rows of C.
      bool
      ensure_inverse();

      bool
      factor_separated_set(const std::vector<Eigen::Index> &free);

      void
      solve_through_separated_set(const std::vector<Eigen::Index> &free,
                                  const Eigen::VectorXd           &b,
                                  const Eigen::VectorXd           &e,
                                  Eigen::VectorXd                 &N,
                                  Eigen::VectorXd                 &alpha);

      bool
      solve_by_complement(const std::vector<Eigen::Index> &index,
                          const Eigen::VectorXd           &b,
                          const Eigen::VectorXd           &e,
                          Eigen::VectorXd                 &N,
                          Eigen::VectorXd                 &alpha);

      bool
      solve_on_contact_set(const std::vector<Eigen::Index> &index,
                           const Eigen::VectorXd           &b,
                           const Eigen::VectorXd           &e,
                           Eigen::VectorXd                 &N,
                           Eigen::VectorXd                 &alpha);

      const Eigen::MatrixXd &M;
      const Eigen::MatrixXd &G;
      InnerOptions           options;
      Eigen::VectorXd        inverse_diagonal;
      double                 penalty = 0;
      Eigen::MatrixXd        M_augmented;
      Eigen::VectorXd        inverse_diagonal_augmented;
      Eigen::VectorXd        w, rhs;

      // Factorisation of the last contact set of solve_active_set (M_CC,
      // and with equality rows M_CC^{-1} G_C^T and the Schur complement),
      // reused while the set repeats.
      std::vector<Eigen::Index> factored_index;
      bool                      factor_valid = false;
      Eigen::MatrixXd           Mcc, Gc, Y;
      DenseCholesky             llt;
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> schur;

      // The same through the separated set: H = M^{-1}, P = H G^T and
      // G P, formed once (inverse_state: 0 not yet, 1 formed, -1 M not
      // positive definite) when the factorisations of M_CC have cost
      // direct_flops >= complement_after n^3; the factor of H_FF of the last
      // separated set F, Y_F = H_FF^{-1} P_F and the Schur complement P_F^T Y_F
      // - G P of the equality rows.
      int                       inverse_state       = 0;
      double                    direct_flops        = 0;
      unsigned int              n_complement_solves = 0;
      Eigen::MatrixXd           H, P, GP;
      std::vector<Eigen::Index> factored_free;
      bool                      free_valid = false;
      Eigen::MatrixXd           Pf, Yf;
      DenseCholesky             llt_free;
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> schur_free;
    };
  } // namespace contact
} // namespace dpana

#endif
