// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_condensation_parameters_h
#define dpana_condensation_parameters_h

#include <dpana/linear_algebra/last_block_ordering.h>
#include <dpana/parallel/route.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace dpana
{
  namespace condensation
  {
    /**
     * The two ways Condenser computes A = V_r^T K_r^{-1} V_r (see
     * Condenser): through the Cholesky factor of the Schur complement of
     * K_r on the contact surface, or by blocked solves with the columns of
     * V.
     */
    enum class Method
    {
      schur,
      blocked_solves
    };

    /**
     * The factorisation of the reduced stiffness matrix behind the Schur
     * route (linear_algebra::SchurFactorization): CHOLMOD's sparse
     * Cholesky with the surface unknowns ordered last, or MUMPS' Schur
     * complement through PETSc. The blocked solves always use CHOLMOD.
     */
    enum class Backend
    {
      cholmod,
      mumps
    };

    /**
     * The parameters of the condensation: the Method, and, for the blocked
     * solves, how many columns of the coupling operator V are handed at once
     * to the sparse Cholesky solves of Condenser::condense(). Neither changes
     * the result beyond round-off; they change the time and the memory of
     * the condensation (the blocked solves hold a dense block of n_dofs x
     * columns, the Schur route one of n_Gamma x n_c, n_Gamma the dofs on the
     * surface). In a parameter file they are the entries
     *
     *     subsection Contact
     *       set Condensation method    = schur
     *       set Factorisation back end = cholmod
     *       set Out-of-core directory  =
     *       set Columns per solve      = 256
     *       set Schur ordering         = automatic
     *       set Memory limit (GB)      = 0
     *       set Parallel route         = auto
     *       set Parallel assembly      = distributed
     *       set Parallel mesh          = distributed
     *       set Concurrent bodies      = true
     *     end
     *
     * declared by declare_parameters() and read by parse_parameters() in
     * the subsection the caller has entered (`Contact`). The back end
     * (Backend) changes only the factorisation of the Schur route;
     * `mumps` with `blocked solves` is an input error.
     */
    struct Parameters
    {
      Method       method            = Method::schur;
      Backend      backend           = Backend::cholmod;
      unsigned int columns_per_solve = 256;
      /**
       * The fill-reducing ordering of the factorisation of the Schur route
       * (linear_algebra::LastBlockOrdering).
       */
      linear_algebra::LastBlockOrdering ordering =
        linear_algebra::LastBlockOrdering::automatic;
      /**
       * Whether MUMPS orders the unknowns itself (`Schur ordering = by
       * MUMPS`, Backend::mumps only) instead of being given #ordering
       * (MumpsSchurFactorization).
       */
      bool mumps_orders_itself = false;
      /**
       * The memory a run may use, in GB; 0: what the machine has (the
       * resident memory of the run plus MemAvailable of /proc/meminfo).
       * A condensation whose estimate (memory_estimate.h) exceeds it is
       * refused before its factorisation.
       */
      double memory_limit_gb = 0;
      /**
       * The parallel::Route of the run, resolved from the setting (auto,
       * serial, mpi) and the number of MPI ranks. The MPI route factors
       * with MUMPS whatever the back end says, and needs Method::schur.
       */
      parallel::Route route = parallel::Route::serial;
      /**
       * Whether each body is partitioned over the ranks and assembled in
       * shares (Body::partition(), setting `Parallel assembly =
       * distributed`, doc/parallel.md): only on the MPI route with more
       * than one rank; otherwise every rank assembles the whole K
       * (`replicated`).
       */
      bool distributed_assembly = false;
      /**
       * Whether the mesh of each body is distributed too (`Parallel mesh =
       * distributed`, the default, Body::partition()): only with
       * #distributed_assembly.
       */
      bool distributed_mesh = false;
      /**
       * Whether the bodies of a two-body scene are assembled, factorised
       * and condensed at the same time, one thread each (`Concurrent bodies =
       * true`, the default of a parameter file; scene::Scene::condense()): only
       * on the serial route with Backend::cholmod.
       */
      bool concurrent_bodies = false;
      /**
       * Where MUMPS writes its factor (out of core, MUMPS' ICNTL(22) = 1);
       * empty: in memory. Only with Backend::mumps (an InputError with
       * CHOLMOD); the directory must exist and be writable. The memory
       * check then uses MUMPS' out-of-core estimate.
       */
      std::string out_of_core_directory;

      /**
       * Declare the entries Condensation method, Factorisation back end,
       * Out-of-core directory, Columns per solve, Schur ordering and Memory
       * limit (GB) in the current subsection of @p prm.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * Read the entries Condensation method, Factorisation back end,
       * Out-of-core directory, Columns per solve, Schur ordering and Memory
       * limit (GB) from the current subsection of @p prm. Throws an
       * InputError for an out-of-core directory that cannot be used
       * (check_out_of_core_directory()) and for the back end
       * mumps with the blocked solves.
       */
      void
      parse_parameters(dealii::ParameterHandler &prm);

    private:
      /**
       * An InputError naming the entry if @p directory cannot hold the
       * factor files: the back end is not MUMPS, or it is not an existing,
       * writable directory.
       */
      static void
      check_out_of_core_directory(const std::string &directory,
                                  const Backend      backend);
    };
  } // namespace condensation
} // namespace dpana

#endif
