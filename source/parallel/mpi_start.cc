// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/parallel/mpi_start.h>

#include <cstdlib>
#include <stdexcept>

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
    // start: OpenMPI's mpirun, PMIx, the PMI of MPICH's Hydra, Slurm.
    bool
    launched_by_mpirun()
    {
      for (const char *name : {"OMPI_COMM_WORLD_SIZE",
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
      if (!mpi_start())
        throw std::logic_error("MPI is needed (MUMPS) but not running, and "
                               "the program set no way to start it "
                               "(parallel::set_mpi_start)");
      mpi_start()();
    }
  } // namespace parallel
} // namespace dpana
