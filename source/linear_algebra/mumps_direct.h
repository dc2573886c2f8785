// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_source_linear_algebra_mumps_direct_h
#define dpana_source_linear_algebra_mumps_direct_h

// MUMPS called through its own C interface (dmumps_c) on one process, for
// MumpsSchurFactorization with a given ordering: PETSc's interface cannot
// hand MUMPS an ordering for a Cholesky factorisation, and MUMPS asked for a
// Schur complement without one orders by AMD (doc/parallel.md).

#include <Eigen/Dense>

#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  namespace linear_algebra
  {
    /**
     * One MUMPS instance on MPI_COMM_SELF for a symmetric positive definite
     * matrix (MUMPS' SYM = 1, no pivoting), its unknowns in a given order,
     * with the Schur complement on a given set of them.
     */
    class DirectMumps
    {
    public:
      DirectMumps();
      ~DirectMumps();
      DirectMumps(const DirectMumps &) = delete;
      DirectMumps &
      operator=(const DirectMumps &) = delete;

      /**
       * The upper triangle of the matrix in compressed rows (0-based,
       * increasing columns), @p order the unknowns in elimination order
       * (entry k: the unknown eliminated k-th; @p schur must be its last
       * entries), and MUMPS' analysis of it (JOB = 1), out of core in
       * @p ooc_directory if that is not empty, with the workspace
       * relaxation ICNTL(14) = @p relaxation if it is positive. Returns
       * MUMPS' INFOG(1).
       */
      int
      analyse(const std::vector<int>  &row_start,
              const std::vector<int>  &columns,
              std::vector<double>      values,
              const std::vector<long> &order,
              const std::vector<int>  &schur,
              const std::string       &ooc_directory,
              const int                relaxation);

      /**
       * The numerical factorisation (JOB = 2); MUMPS' INFOG(1). The copy
       * of the matrix made by analyse() is released.
       */
      int
      factorize();

      /**
       * The Schur complement after factorize(), handed over: its lower
       * triangle (the strict upper one zero), row and column k belonging to
       * the k-th unknown of the schur list given to analyse().
       */
      Eigen::MatrixXd
      take_schur_complement();

      /**
       * $K_{II}^{-1} b_I$ (MUMPS' ICNTL(26) = 0), zero on the Schur
       * unknowns.
       */
      Eigen::VectorXd
      solve_interior(const Eigen::VectorXd &b) const;

      /**
       * MUMPS' INFOG(i), RINFOG(i) and ICNTL(i) (1-based, as MUMPS'
       * documentation numbers them).
       */
      int
      infog(const int i) const;
      double
      rinfog(const int i) const;
      int
      icntl(const int i) const;

    private:
      struct Impl;
      std::unique_ptr<Impl> impl;
    };
  } // namespace linear_algebra
} // namespace dpana

#endif
