// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_parallel_petsc_calls_h
#define dpana_parallel_petsc_calls_h

#include <Eigen/Dense>

#include <vector>

#include <petscmat.h>

namespace dpana
{
  namespace parallel
  {
    /**
     * While an object of this class lives, PETSc returns its errors as
     * codes instead of printing a traceback; check() turns them into
     * exceptions.
     */
    struct QuietPetsc
    {
      QuietPetsc();
      ~QuietPetsc();
    };

    /**
     * Throws a std::runtime_error naming @p call if @p code is an error.
     */
    void
    check(const PetscErrorCode code, const char *call);

    /**
     * Initialises PETSc (and MPI) if no one has (deal.II's
     * Utilities::MPI::MPI_InitFinalize does), and finalises it at exit.
     */
    void
    ensure_petsc();

    /**
     * Whether this PETSc can factor a matrix with MUMPS' Cholesky
     * (MatGetFactorAvailable on a 1 x 1 matrix): Debian's PETSc is
     * configured with MUMPS, a PETSc built by hand may not be.
     */
    bool
    mumps_available();

    /**
     * The rows 0..n-1 of a matrix over the ranks of a communicator as PETSc
     * splits them by default (PetscSplitOwnership): rank p owns the
     * contiguous rows offsets[p] .. offsets[p] + counts[p] - 1, and this
     * rank the rows begin .. end - 1.
     */
    struct RowRange
    {
      RowRange() = default;
      RowRange(const MPI_Comm communicator, const PetscInt n);

      MPI_Comm         communicator = MPI_COMM_SELF;
      PetscInt         n = 0, begin = 0, end = 0;
      std::vector<int> counts, offsets;

      PetscInt
      n_local() const
      {
        return end - begin;
      }
    };

    /**
     * @p operation (MatSolve or MatMult) of the matrix @p M, distributed by
     * @p rows, with a vector @p x that every rank holds in full; the result,
     * which PETSc computes distributed, is gathered so that every rank holds
     * it in full (MPI_Allgatherv). Collective.
     */
    Eigen::VectorXd
    apply(PetscErrorCode (*operation)(Mat, Vec, Vec),
          const Mat              M,
          const RowRange        &rows,
          const Eigen::VectorXd &x,
          const char            *name);

    /**
     * MUMPS' INFOG(i) and RINFOG(i) of the factor @p F (the same on every
     * rank); -1 without a factor.
     */
    PetscInt
    infog(const Mat F, const int i);
    double
    rinfog(const Mat F, const int i);
  } // namespace parallel
} // namespace dpana

#endif
