// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_source_linear_algebra_mumps_direct_h
#define dpana_source_linear_algebra_mumps_direct_h

// MUMPS called through its own C interface (dmumps_c), for
// MumpsSchurFactorization with a given ordering: PETSc's interface cannot
// hand MUMPS an ordering for a Cholesky factorisation, and MUMPS asked for a
// Schur complement without one orders by AMD (doc/parallel.md).

#include <Eigen/Dense>

#include <memory>
#include <string>
#include <vector>

#include <mpi.h>

namespace dpana
{
  namespace linear_algebra
  {
    /**
     * One MUMPS instance over the ranks of a communicator (the host, rank 0,
     * works too) for a symmetric positive definite matrix (MUMPS' SYM = 1,
     * no pivoting), its unknowns in a given order, with the Schur complement
     * on a given set of them, centralised on rank 0. Every function is
     * collective.
     */
    class DirectMumps
    {
    public:
      explicit DirectMumps(const MPI_Comm communicator);
      ~DirectMumps();
      DirectMumps(const DirectMumps &) = delete;
      DirectMumps &
      operator=(const DirectMumps &) = delete;

      /**
       * MUMPS' analysis (JOB = 1) of the matrix of @p n unknowns whose upper
       * triangle this rank holds in part: the rows @p first_row,
       * @p first_row + 1, ... in compressed rows (0-based global columns);
       * MUMPS sums what the ranks give (distributed input, ICNTL(18) = 3).
       * On rank 0 only (ignored elsewhere): @p order, the unknowns in
       * elimination order (entry k: the unknown eliminated k-th; @p schur
       * must be its last entries), and @p schur, the unknowns of the Schur
       * complement. Out of core in @p ooc_directory if that is not empty,
       * with the workspace relaxation ICNTL(14) = @p relaxation if it is
       * positive. Returns MUMPS' INFOG(1).
       */
      int
      analyse(const int                n,
              const int                first_row,
              const std::vector<int>  &row_start,
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
       * The Schur complement after factorize(), handed over, on rank 0
       * (empty elsewhere): its lower triangle (the strict upper one zero),
       * row and column k belonging to the k-th unknown of the schur list
       * given to analyse().
       */
      Eigen::MatrixXd
      take_schur_complement();

      /**
       * $K_{II}^{-1} b_I$ (MUMPS' ICNTL(26) = 0), zero on the Schur
       * unknowns, on every rank; @p b is read on rank 0.
       */
      Eigen::VectorXd
      solve_interior(const Eigen::VectorXd &b) const;

      /**
       * MUMPS' INFOG(i), RINFOG(i) and ICNTL(i) (1-based, as MUMPS'
       * documentation numbers them), the same on every rank.
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
