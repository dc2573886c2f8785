// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/parallel/petsc_calls.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace dpana
{
  namespace parallel
  {
    QuietPetsc::QuietPetsc()
    {
      PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    }



    QuietPetsc::~QuietPetsc()
    {
      PetscPopErrorHandler();
    }



    void
    check(const PetscErrorCode code, const char *call)
    {
      if (code != 0)
        throw std::runtime_error(std::string("MUMPS through PETSc: ") + call +
                                 " failed (PETSc error " +
                                 std::to_string(static_cast<int>(code)) + ")");
    }



    void
    ensure_petsc()
    {
      PetscBool initialized = PETSC_FALSE;
      PetscInitialized(&initialized);
      if (initialized)
        return;
      check(PetscInitializeNoArguments(), "PetscInitializeNoArguments");
      std::atexit([]() {
        PetscBool finalized = PETSC_FALSE;
        PetscFinalized(&finalized);
        if (!finalized)
          PetscFinalize();
      });
    }



    bool
    mumps_available()
    {
      ensure_petsc();
      const QuietPetsc quiet;
      Mat              M         = nullptr;
      PetscBool        available = PETSC_FALSE;
      if (MatCreateSeqSBAIJ(PETSC_COMM_SELF, 1, 1, 1, 1, nullptr, &M) == 0)
        MatGetFactorAvailable(M,
                              MATSOLVERMUMPS,
                              MAT_FACTOR_CHOLESKY,
                              &available);
      if (M)
        MatDestroy(&M);
      return available == PETSC_TRUE;
    }



    RowRange::RowRange(const MPI_Comm communicator, const PetscInt n)
      : communicator(communicator)
      , n(n)
    {
      int size = 1, rank = 0;
      MPI_Comm_size(communicator, &size);
      MPI_Comm_rank(communicator, &rank);
      counts.resize(size);
      offsets.resize(size);
      for (int p = 0, offset = 0; p < size; ++p)
        {
          // PetscSplitOwnership: n / size rows each, the first n % size
          // ranks one more.
          counts[p]  = n / size + (p < n % size ? 1 : 0);
          offsets[p] = offset;
          offset += counts[p];
        }
      begin = offsets[rank];
      end   = begin + counts[rank];
    }



    namespace
    {
      // A PETSc vector on @p values, this rank's part of one distributed by
      // @p rows (sequential on one rank, as the matrix is).
      PetscErrorCode
      wrap(const RowRange &rows, PetscScalar *values, Vec *v)
      {
        if (rows.counts.size() > 1)
          return VecCreateMPIWithArray(
            rows.communicator, 1, rows.n_local(), rows.n, values, v);
        return VecCreateSeqWithArray(PETSC_COMM_SELF, 1, rows.n, values, v);
      }
    } // namespace



    Eigen::VectorXd
    apply(PetscErrorCode (*operation)(Mat, Vec, Vec),
          const Mat              M,
          const RowRange        &rows,
          const Eigen::VectorXd &x,
          const char            *name)
    {
      Eigen::VectorXd x_local = x.segment(rows.begin, rows.n_local());
      Eigen::VectorXd y(x.size());
      Vec             vx, vy;
      check(wrap(rows, x_local.data(), &vx), "VecCreateWithArray");
      check(wrap(rows, y.data() + rows.begin, &vy), "VecCreateWithArray");
      const PetscErrorCode code = operation(M, vx, vy);
      VecDestroy(&vx);
      VecDestroy(&vy);
      check(code, name);
      if (rows.counts.size() > 1)
        MPI_Allgatherv(MPI_IN_PLACE,
                       0,
                       MPI_DATATYPE_NULL,
                       y.data(),
                       rows.counts.data(),
                       rows.offsets.data(),
                       MPI_DOUBLE,
                       rows.communicator);
      return y;
    }



    PetscInt
    infog(const Mat F, const int i)
    {
      PetscInt value = -1;
      if (F)
        MatMumpsGetInfog(F, i, &value);
      return value;
    }



    double
    rinfog(const Mat F, const int i)
    {
      PetscReal value = -1;
      if (F)
        MatMumpsGetRinfog(F, i, &value);
      return value;
    }
  } // namespace parallel
} // namespace dpana
