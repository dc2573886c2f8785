// The dense Cholesky factorisation of the contact solvers' symmetric
// positive definite blocks, on the system LAPACK and BLAS.
//
// The active-set inner solvers (friction_qp.h, normal_lcp.h) factor a dense
// block of A every time the contact set or the stick / slip partition
// changes: H = L L^T with L lower triangular (LAPACK dpotrf), solves by
// dpotrs, and the triangular solves L^{-1} R and L^{-T} R by dtrsm. The
// factorisation is the same as Eigen::LLT's up to round-off; it runs on the
// kernels of the system library (OpenBLAS on Debian), which use every core
// and the processor's vector instructions, about four times Eigen's speed
// on a single core for the blocks of 10^3 - 10^4 rows of a 3D contact
// surface. Blocks below 64 rows go to Eigen's LLT, where the call overhead of
// the library would dominate (the result is the same to round-off).
#ifndef dpana_contact_dense_cholesky_h
#define dpana_contact_dense_cholesky_h

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include <limits>

namespace dpana
{
  namespace contact
  {
    class DenseCholesky
    {
    public:
      // Factor H (only its lower triangle is read); false if H is not
      // numerically positive definite (the factor is then invalid).
      bool
      compute(const Eigen::MatrixXd &H);

      // The same, taking H over as the storage of the factor.
      bool
      compute(Eigen::MatrixXd &&H);

      bool
      valid() const
      {
        return ok;
      }

      Eigen::Index
      rows() const
      {
        return single ? factor_single.rows() : factor.rows();
      }

      // R <- H^{-1} R.
      void
      solve_in_place(Eigen::MatrixXd &R) const;

      // H^{-1} R.
      Eigen::MatrixXd
      solve(const Eigen::MatrixXd &R) const;

      Eigen::VectorXd
      solve(const Eigen::VectorXd &r) const;

      // H^{-1}, the whole symmetric matrix (LAPACK dpotri from the factor:
      // n^3 / 3 flops more than the factorisation, a third of what the solve
      // with the n columns of the identity costs).
      Eigen::MatrixXd
      inverse() const;

      // R <- L^{-1} R and R <- L^{-T} R.
      void
      solve_lower_in_place(Eigen::MatrixXd &R) const;

      void
      solve_upper_in_place(Eigen::MatrixXd &R) const;

      // From the next compute() on, factor matrices of at least @p min_rows
      // rows in single precision (LAPACK spotrf): solves are then accurate
      // to about cond(H) 6e-8 relative, and inverse() is not available. A
      // matrix that is not positive definite in single precision is factored
      // in double.
      void
      set_single_precision(const Eigen::Index min_rows)
      {
        single_precision_size = min_rows;
      }

      // Whether the current factor is in single precision.
      bool
      single_precision() const
      {
        return single;
      }

    private:
      bool
      factor_in_place();

      // Whether Eigen's LLT holds the factor (below #small rows).
      bool
      uses_eigen() const
      {
        return factor.size() == 0 && !single;
      }

      // R <- L^{-1} R, or L^{-T} R if transpose.
      void
      triangular_solve(Eigen::MatrixXd &R, bool transpose) const;

      // Below this size Eigen's LLT factors and solves, one column of a
      // right-hand side at a time: a block solve would first size Eigen's
      // cache blocks, a query of the processor that costs more than the
      // solves themselves at these sizes (about 0.07 ms, once per run).
      static constexpr Eigen::Index small = 64;

      Eigen::MatrixXd factor;        // L in the lower triangle
      Eigen::MatrixXf factor_single; // ... in single precision
      Eigen::Index    single_precision_size =
        std::numeric_limits<Eigen::Index>::max();
      bool                        single = false;
      Eigen::LLT<Eigen::MatrixXd> llt;
      bool                        ok = false;
    };
  } // namespace contact
} // namespace dpana

#endif
