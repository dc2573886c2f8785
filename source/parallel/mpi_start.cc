// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/parallel/mpi_start.h>

#include <cstdlib>

#include <mpi.h>

namespace dpana
{
  namespace parallel
  {
    namespace
    {
      std::function<void()> &
      mpi_start()
      {
        static std::function<void()> start;
        return start;
      }
    } // namespace



    // The environment that the common launchers give every process they
    // start: OpenMPI's mpirun, PMIx, the PMI of MPICH's Hydra, Slurm; and
    // DPANA_START_MPI for a launcher that sets none of these.
    bool
    launched_by_mpirun()
    {
      for (const char *name : {"DPANA_START_MPI",
                               "OMPI_COMM_WORLD_SIZE",
                               "PMIX_RANK",
                               "PMI_RANK",
                               "PMI_SIZE",
                               "MPI_LOCALNRANKS",
                               "SLURM_PROCID"})
        if (std::getenv(name) != nullptr)
          return true;
      return false;
    }



    void
    set_mpi_start(std::function<void()> start)
    {
      mpi_start() = std::move(start);
    }



    void
    start_mpi()
    {
      int initialized = 0;
      MPI_Initialized(&initialized);
      if (initialized)
        return;
      // A program that set no start (a tutorial step): MUMPS' first use
      // initialises PETSc, and PETSc MPI, as before (petsc_calls.h).
      if (mpi_start())
        mpi_start()();
    }
  } // namespace parallel
} // namespace dpana
