// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_parallel_mpi_start_h
#define dpana_parallel_mpi_start_h

#include <functional>

namespace dpana
{
  namespace parallel
  {
    /**
     * MPI is started when a run first needs it (doc/parallel.md): at once
     * when the program was started by a launcher (launched_by_mpirun():
     * the variables of OpenMPI's mpirun, PMIx, PMI, Slurm, or
     * DPANA_START_MPI), and otherwise when the contact parameters ask for
     * MUMPS (`Contact / Factorisation back end = mumps`, or `Parallel route
     * = mpi` on one process). A serial run on CHOLMOD does not start it:
     * MPI_Init takes about 0.4 s of every run on one process (OpenMPI
     * spawns its daemon for it), more than the whole solve of a small
     * scene. Without MPI, n_world_ranks() and is_root() are 1 and true.
     *
     * The program's main() says how MPI is started (set_mpi_start(), a
     * function that constructs deal.II's MPI_InitFinalize in main()'s
     * scope, so that MPI is finalised when main() returns); start_mpi()
     * starts it once. A program that sets nothing either starts MPI
     * itself (the test programs) or leaves it to PETSc, which MUMPS'
     * first use initialises (the tutorial steps).
     */
    bool
    launched_by_mpirun();

    void
    set_mpi_start(std::function<void()> start);

    /**
     * Starts MPI unless it is running, by the function of set_mpi_start()
     * if one was set.
     */
    void
    start_mpi();
  } // namespace parallel
} // namespace dpana

#endif
