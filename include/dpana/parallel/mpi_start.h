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
     * when the program was started by mpirun (launched_by_mpirun()), and
     * otherwise by the first use of MUMPS (`Contact / Factorisation back
     * end = mumps`, or `Parallel route = mpi` on one process). A serial
     * run on CHOLMOD never starts it: MPI_Init takes about 0.4 s of every
     * run on one process (OpenMPI spawns its daemon for it), more than the
     * whole solve of a small scene. Without MPI, the ranks and rank 0 of
     * n_world_ranks() and is_root() are 1 and true.
     *
     * The program's main() says how MPI is started (set_mpi_start(), a
     * function that constructs deal.II's MPI_InitFinalize in main()'s
     * scope, so that MPI is finalised when main() returns); start_mpi()
     * starts it once. A program that starts MPI itself before any work
     * (the test programs) need not set anything.
     */
    bool
    launched_by_mpirun();

    void
    set_mpi_start(std::function<void()> start);

    /**
     * Starts MPI unless it is running. Throws std::logic_error if it is
     * not running and no way to start it was set.
     */
    void
    start_mpi();
  } // namespace parallel
} // namespace dpana

#endif
