// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_parallel_route_h
#define dpana_parallel_route_h

#include <dpana/contact/solver.h>

#include <string>

#include <mpi.h>

namespace dpana
{
  namespace parallel
  {
    /**
     * How a contact run uses the processes it is started on
     * (doc/parallel.md).
     *
     * - <b>serial</b>: one process; each body is factored by the back end
     *   of `Contact / Factorisation back end` (CHOLMOD or MUMPS on
     *   MPI_COMM_SELF). The fast path of a single machine.
     * - <b>mpi</b>: `mpirun -np P dpana scene.prm`. Every rank reads the
     *   scene and builds every body's mesh, and assembles its own cells
     *   (`Parallel assembly = distributed`) or all of them (`replicated`);
     *   each body is factored by MUMPS over MPI_COMM_WORLD (linear_algebra::
     *   MumpsSchurFactorization), each rank holding the rows of the reduced
     *   matrix it owns and its part of the factor; the Schur complement on
     *   Γc and its factor are formed on rank 0, which solves the contact
     *   problem and broadcasts its result (broadcast()); the recovery solves
     *   are distributed. Rank 0 alone prints the log and writes the output.
     *
     * In a parameter file, `subsection Contact / set Parallel route =
     * auto|serial|mpi`; `auto` is `mpi` when the run has more than one
     * rank.
     */
    enum class Route
    {
      serial,
      mpi
    };

    /**
     * The Route of the setting @p name (auto, serial or mpi) on
     * @p n_ranks ranks. Throws InputError for `serial` on more than one
     * rank (it would repeat the same work on every rank).
     */
    Route
    choose_route(const std::string &name, const unsigned int n_ranks);

    /**
     * The number of ranks of MPI_COMM_WORLD, and whether this one is rank 0
     * (true without MPI initialised: a test program without mpirun).
     */
    unsigned int
    n_world_ranks();
    bool
    is_root();

    /**
     * Throws InputError if this PETSc cannot factor with MUMPS
     * (parallel::mumps_available()).
     */
    void
    check_mumps_available();

    /**
     * Throws InputError if a body of @p n_cells cells is to be split over
     * more ranks than it has cells.
     */
    void
    check_ranks(const std::string &body_name,
                const unsigned int n_cells,
                const unsigned int n_ranks);

    /**
     * Replaces the tractions, contact displacements, rigid-mode amplitudes,
     * statuses, convergence, iterations and residual of @p result on every
     * rank of @p communicator by those of rank 0, which alone solved the
     * contact problem. Collective.
     */
    void
    broadcast(contact::SolverResult &result, const MPI_Comm communicator);
  } // namespace parallel
} // namespace dpana

#endif
