// The tangential subproblem of the D-PANA splitting (the T-step): at fixed
// normal tractions N, find T (and the multipliers beta of the purely
// tangential equality rows, if any) solving
// @f[
//   \min_{T_j \in c_j P,\ G T = e} \tfrac12 T^T M T + c^T T ,
// @f]
// with M = A_TT (SPD), c = D_T + A_TN N (+ the fixed part of G^T alpha), the
// radii c_j = -mu_j N_j >= 0, and P the unit interval, disc or polygon
// (friction_set.h). Stationarity: w = M T + c + G^T beta, -w_j in the normal
// cone of c_j P at T_j.
//
// Two solvers:
//   - solve_pgs: block projected Gauss-Seidel. The local step is the EXACT
//     minimiser of the (d-1)-dimensional block problem over c_j P with the
//     diagonal block W_j = M_jj (FrictionSet::minimise: clipping, secular
//     equation for the disc, facet/vertex enumeration for the polygon), not a
//     Euclidean projection. With omega != 1 the relaxed point
//     (1 - omega) T_j + omega T_j^loc is projected (Euclidean) back onto
//     c_j P. Equality rows: method of multipliers, as in normal_lcp.h.
//   - solve_active_set: a semismooth Newton method on the natural map
//       F_j(T) = T_j - Pi_{c_j P}(T_j - rho_j w_j),   rho_j = (d-1)/tr W_j,
//     (plus the rows G T - e when present, with beta as unknowns), using the
//     derivative of the projection (identity inside, the tangent projector
//     on a facet / (c/|y|)(I - yy^T/|y|^2) on the circle, zero at a vertex or
//     an interval end). For the interval and the polygon the projection is
//     piecewise linear and a full Newton step solves the QP restricted to the
//     current faces exactly: this is the primal-dual active set method, and
//     it stops as soon as the faces repeat. For the disc it converges
//     locally quadratically. Globalised by an Armijo backtracking on
//     1/2 ||F||^2; if the line search fails, a few PGS sweeps are made before
//     Newton resumes. The Newton system is reduced exactly to a symmetric
//     positive definite one (the projection derivative is symmetric with
//     eigenvalues in [0, 1]): directions with eigenvalue 0 (radius 0,
//     interval end, polygon vertex, the radial direction of a disc slip
//     block, the normal of a facet) have their step outright, the others
//     (stick, the facet or circle tangent) enter a Cholesky factorisation,
//     with a Schur complement for the equality rows (dense_cholesky.h: on
//     the system LAPACK). Warm started (the T-steps of a splitting), the
//     solve begins with a predictor: one Newton step of the new data on the
//     partition of the previous solve's last step, kept if it passes the
//     Armijo test (friction_qp.cc). The line search moves w = M T + c along
//     the step instead of multiplying by M at every trial point.
//     On large problems (InnerOptions::partition_sweep_size tangential
//     unknowns and more)
//     the Newton steps are preceded by projected Gauss-Seidel sweeps that
//     find the stick / slip partition (settle_partition in friction_qp.cc):
//     a Newton step whose partition differs from the last one's costs a
//     Cholesky factorisation of H (f^3/3 flops, f up to the number of
//     tangential unknowns q), a sweep a few q^2, and a semismooth Newton
//     method moves the boundary between stick and slip by a few blocks per
//     step, where the sweeps move it at no factorisation's cost.
#ifndef dpana_contact_friction_qp_h
#define dpana_contact_friction_qp_h

#include <dpana/contact/dense_cholesky.h>
#include <dpana/contact/friction_set.h>
#include <dpana/contact/normal_lcp.h>

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace dpana
{
  namespace contact
  {
    class FrictionQp
    {
    public:
      // M ((d-1) n square, SPD) and G (m x (d-1) n, m may be 0) are kept by
      // reference and must outlive the object.
      FrictionQp(const Eigen::MatrixXd &M,
                 const Eigen::MatrixXd &G,
                 const FrictionSet     &set,
                 const InnerOptions    &options);

      // radius[j] = c_j >= 0. T, beta: warm start on input, solution on
      // output.
      InnerResult
      solve_pgs(const Eigen::VectorXd &c,
                const Eigen::VectorXd &radius,
                const Eigen::VectorXd &e,
                Eigen::VectorXd       &T,
                Eigen::VectorXd       &beta);

      InnerResult
      solve_active_set(const Eigen::VectorXd &c,
                       const Eigen::VectorXd &radius,
                       const Eigen::VectorXd &e,
                       Eigen::VectorXd       &T,
                       Eigen::VectorXd       &beta);

      // Change the tolerance of the following solves (the splitting tightens
      // it as the outer residual decreases).
      void
      set_tolerance(const double tolerance)
      {
        options.tolerance = tolerance;
      }

      // Newton matrices factored in single precision so far
      // (InnerOptions::single_precision_size).
      unsigned int
      single_precision_factorisations() const
      {
        return n_single_factorisations;
      }

    private:
      // Sweeps over a matrix in double (Eigen::MatrixXd) or, for the
      // partition sweeps, single precision (Eigen::MatrixXf).
      template <typename Matrix>
      int
      pgs(const Matrix              &matrix,
          const std::vector<double> &blocks,
          const Eigen::VectorXd     &rhs,
          const Eigen::VectorXd     &radius,
          Eigen::VectorXd           &T,
          unsigned int               max_sweeps);

      // One block of a sweep (the exact local minimiser, relaxed, and the
      // column update of w), raising change and size.
      template <typename Matrix>
      void
      block_step(const Matrix              &matrix,
                 const std::vector<double> &blocks,
                 const Eigen::VectorXd     &radius,
                 const unsigned int         j,
                 Eigen::VectorXd           &T,
                 double                    &change,
                 double                    &size);

      // Natural map F (size q + m) at (T, beta); records the regions.
      void
      natural_map(const Eigen::VectorXd &c,
                  const Eigen::VectorXd &radius,
                  const Eigen::VectorXd &e,
                  const Eigen::VectorXd &T,
                  const Eigen::VectorXd &beta,
                  Eigen::VectorXd       &F);

      // The same for the w = M T + c + G^T beta already in place.
      void
      natural_map_of_w(const Eigen::VectorXd &radius,
                       const Eigen::VectorXd &e,
                       const Eigen::VectorXd &T,
                       Eigen::VectorXd       &F);

      const Eigen::MatrixXd &M;
      const Eigen::MatrixXd &G;
      const FrictionSet     &set;
      InnerOptions           options;
      unsigned int           m; // d - 1
      unsigned int           n;
      std::vector<double>    blocks, blocks_augmented; // row-major W_j
      Eigen::VectorXd        rho;
      double                 penalty = 0;
      Eigen::MatrixXd        M_augmented;
      // The matrix of the sweeps (M, or M_augmented with equality rows) in
      // single precision, made at the first partition sweep; the sweeps
      // of solve_pgs use it while single_precision_sweeps is set.
      Eigen::MatrixXf  M_single;
      bool             single_precision_sweeps = false;
      Eigen::VectorXd  w, rhs, y;
      std::vector<int> region;

      // The steps of solve_active_set (friction_qp.cc): a feasible start,
      // the stopping test, the eigen-directions of the projection
      // derivatives and the Newton step on the free ones, with the Schur
      // complement of the equality rows (returns dbeta).
      void
      project_onto_sets(const Eigen::VectorXd &radius,
                        Eigen::VectorXd       &T) const;

      // PGS sweeps, in chunks, until two chunks in a row leave the regions
      // of the natural map unchanged or options.partition_sweeps are made; F
      // and the regions are those of the final (T, beta). Returns the sweeps.
      unsigned int
      settle_partition(const Eigen::VectorXd &c,
                       const Eigen::VectorXd &radius,
                       const Eigen::VectorXd &e,
                       Eigen::VectorXd       &T,
                       Eigen::VectorXd       &beta,
                       Eigen::VectorXd       &F);

      // The start of solve_active_set: the predictor and the partition
      // sweeps (friction_qp_active_set.cc); (T, beta, F) move.
      void
      start_active_set(const Eigen::VectorXd &c,
                       const Eigen::VectorXd &radius,
                       const Eigen::VectorXd &e,
                       Eigen::VectorXd       &T,
                       Eigen::VectorXd       &beta,
                       Eigen::VectorXd       &F,
                       Eigen::VectorXd       &dx);

      // Along dx: non-monotone Armijo backtracking (at most max_steps
      // halvings) or, with contraction > 0, the full step if it brings
      // 1/2 ||F||^2 below contraction times its value. An accepted step
      // moves (T, beta, F); returns whether one was accepted.
      bool
      line_search(const Eigen::VectorXd &radius,
                  const Eigen::VectorXd &e,
                  const Eigen::VectorXd &dx,
                  Eigen::VectorXd       &T,
                  Eigen::VectorXd       &beta,
                  Eigen::VectorXd       &F,
                  const unsigned int     max_steps,
                  const double           contraction = 0.0);

      bool
      active_set_converged(const Eigen::VectorXd &F,
                           const Eigen::VectorXd &radius,
                           const Eigen::VectorXd &e,
                           const Eigen::VectorXd &T) const;

      void
      newton_directions(const Eigen::VectorXd &radius,
                        const Eigen::VectorXd &F,
                        Eigen::VectorXd       &dx);

      // With refactor = false the factors of the last Newton matrix are
      // used as they are (a chord step; same partition, hence the same
      // number of directions).
      std::string
      newton_step(const Eigen::VectorXd &F,
                  Eigen::VectorXd       &dx,
                  const bool             refactor = true);

      // Whether the factors of the last Newton matrix can serve the
      // directions just found: same partition, same number of directions.
      bool
      factors_fit() const;

      // The first step of a warm started solve, with the Jacobian of the
      // last Newton step of the previous solve (friction_qp_active_set.cc).
      bool
      predictor_step(const Eigen::VectorXd &F, Eigen::VectorXd &dx);

      Eigen::VectorXd
      equality_step(const Eigen::VectorXd &violation,
                    const Eigen::VectorXd &dx);

      // Factor the Newton matrix H of the current directions (directly,
      // or by blocks with the factors kept per partition; see
      // friction_qp_newton_matrix.cc); false if it is not numerically
      // positive definite.
      bool
      factor_newton_matrix();

      bool
      factor_directly();

      bool
      factor_partition();

      bool
      factor_slip_schur();

      // H^{-1} R for a right-hand side R with one row per direction.
      Eigen::MatrixXd
      solve_newton_matrix(const Eigen::MatrixXd &R) const;

      // Work space of the Newton step of solve_active_set: the directions
      // with a nonzero eigenvalue of the projection derivative (block,
      // eigenvector, eigenvalue, v . F_j, index of the eigenvector), the
      // partition of the blocks (2 stick, 1 slip, 0 fixed), the right-hand
      // side g and the amplitudes x.
      struct Direction
      {
        unsigned int block;
        double       v[2];
        double       lambda;
        double       vF;
        unsigned int axis;
      };
      std::vector<Direction> directions;

      // The diagonal term (1 - lambda) / (lambda rho_j) of H for a direction.
      double
      kappa(const Direction &dir) const
      {
        return (1.0 - dir.lambda) / (dir.lambda * rho[dir.block]);
      }

      std::vector<char> partition, previous_partition;
      // y, the regions and the radii of the last Newton step (predictor).
      Eigen::VectorXd  y_last, radius_last;
      std::vector<int> region_last;
      Eigen::VectorXd  g, x, v; // v = M dT_fixed
      // The line search: w and M dx at its start, the trial point, and the
      // merits of the last accepted iterates.
      Eigen::VectorXd     w0, dw, T_trial, beta_trial, F_trial;
      std::vector<double> recent_merits;
      Eigen::MatrixXd     B;
      // Direct factorisation: M Z, H, Cholesky of H.
      Eigen::MatrixXd MZ, H;
      DenseCholesky   llt;
      // Number of directions of the factored Newton matrix (-1: none).
      Eigen::Index factored_directions = -1;
      // Blocked factorisation: components of the stick and the slip blocks,
      // the first component of each block among them (-1: none), Cholesky
      // of M_ss, P = M_ss^{-1} M_sl and Sigma (kept for cached_partition),
      // the positions of the directions, S and its Cholesky factor.
      bool                      blocked = false, cache_valid = false;
      std::vector<char>         cached_partition;
      std::vector<Eigen::Index> s_index, l_index, s_start, l_start, position;
      DenseCholesky             llt_stick, llt_slip;
      Eigen::MatrixXd           P, Sigma, S_slip;
      // Iterative refinement of a solve with single precision factors: Z x
      // and M Z x over all tangential unknowns, H x and the residual.
      Eigen::VectorXd z_full, Mz_full, Hx_refine, r_refine;
      unsigned int    n_single_factorisations = 0;

      // Whether the factors solve_newton_matrix() uses are in single
      // precision.
      bool
      factors_in_single_precision() const
      {
        return blocked ?
                 llt_stick.single_precision() || llt_slip.single_precision() :
                 llt.single_precision();
      }

      // H x through M, in double.
      void
      apply_newton_matrix(const Eigen::VectorXd &x, Eigen::VectorXd &Hx);

      // Iterative refinement of H x = rhs (two steps at most), if the factors
      // are in single precision.
      void
      refine_newton_solution(const Eigen::VectorXd &rhs,
                             Eigen::VectorXd       &solution);
    };
  } // namespace contact
} // namespace dpana

#endif
