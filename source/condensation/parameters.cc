// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/condensation/parameters.h>
#include <dpana/parallel/mpi_start.h>

#include <deal.II/base/patterns.h>

#include <sys/stat.h>
#include <unistd.h>

namespace dpana
{
  namespace condensation
  {
    void
    Parameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Condensation method",
        "schur",
        dealii::Patterns::Selection("schur|blocked solves"),
        "How A = V^T K^-1 V is formed: 'schur' through the "
        "Cholesky factor of the Schur complement of K on the "
        "contact surface (the surface dofs ordered last in "
        "the factorisation), 'blocked solves' by solving for "
        "the columns of V. The Schur route is usually the faster; it "
        "holds a dense block of n_Gamma^2 numbers for the "
        "n_Gamma surface unknowns. On a large candidate "
        "surface of a 3D body the blocked solves need far "
        "less memory (a factor with CHOLMOD's own ordering "
        "and no such block), at the cost of n_c solves: the "
        "memory check names them when the block matters.");
      prm.declare_entry("Factorisation back end",
                        "cholmod",
                        dealii::Patterns::Selection("cholmod|mumps"),
                        "The sparse factorisation behind Condensation "
                        "method = schur: 'cholmod' (CHOLMOD's sparse "
                        "Cholesky, the surface dofs ordered last) or 'mumps' "
                        "(MUMPS' Schur complement on the surface dofs, "
                        "through PETSc). The blocked solves use CHOLMOD.");
      prm.declare_entry(
        "Out-of-core directory",
        "",
        dealii::Patterns::Anything(),
        "Empty (the default): MUMPS holds its factor in memory. A directory "
        "(absolute, or relative to where dpana runs; it must exist and be "
        "writable): MUMPS writes its factor to files there (out of core, "
        "its ICNTL(22) = 1) and reads them back for each solve; the memory "
        "check then uses MUMPS' out-of-core estimate. The files are removed "
        "when the factorisation ends. Needs the MUMPS back end "
        "(Factorisation back end = mumps, or the MPI route).");
      prm.declare_entry("Columns per solve",
                        "256",
                        dealii::Patterns::Integer(1),
                        "Columns of V handed at once to the blocked sparse "
                        "Cholesky solves of the condensation (Condensation "
                        "method = blocked solves).");
      prm.declare_entry(
        "Schur ordering",
        "automatic",
        dealii::Patterns::Selection("automatic|interior nested "
                                    "dissection|constrained AMD|moved "
                                    "last|by MUMPS"),
        "The fill-reducing ordering of the factorisation of the Schur route, "
        "the surface dofs last: 'automatic' (constrained AMD where CHOLMOD's "
        "own test finds a minimum degree ordering good: fewer than 500 flops "
        "per factor entry, or fewer than 5 factor entries per matrix entry; "
        "interior nested dissection otherwise: in practice AMD in 2D and for "
        "3D bodies of a few thousand dofs), 'interior nested dissection' "
        "(METIS on the "
        "graph of the other dofs' mesh vertices), 'constrained AMD' (CAMD "
        "on the whole graph, the surface a second constraint set) or 'moved "
        "last' "
        "(CHOLMOD's ordering of the whole matrix, the surface dofs moved to "
        "the end). The MUMPS back end is given the same ordering, on one "
        "process and on the MPI route; 'by MUMPS' lets MUMPS order (AMD when "
        "it computes a Schur complement). The result is the same up to "
        "round-off; the time and memory of the factorisation differ "
        "(benchmarks/condensation).");
      prm.declare_entry("Memory limit (GB)",
                        "0",
                        dealii::Patterns::Double(0),
                        "The memory the run may use, in GB; 0: what the "
                        "machine has (the run's resident memory plus "
                        "MemAvailable of /proc/meminfo). After the symbolic "
                        "analysis of each body's factorisation the memory of "
                        "the factor, of the dense blocks of the condensation "
                        "and of the contact solve is estimated; a run whose "
                        "estimate exceeds the limit stops there with an "
                        "error.");
      prm.declare_entry("Parallel route",
                        "auto",
                        dealii::Patterns::Selection("auto|serial|mpi"),
                        "How the run uses its MPI ranks (doc/parallel.md): "
                        "'serial' one process, each body factored by the "
                        "Factorisation back end; 'mpi' each body factored by "
                        "MUMPS over all ranks (mpirun -np P dpana FILE.prm), "
                        "the contact problem solved on rank 0; 'auto' mpi "
                        "on more than one rank, serial on one.");
      prm.declare_entry(
        "Parallel assembly",
        "distributed",
        dealii::Patterns::Selection("replicated|distributed"),
        "How the MPI route on more than one rank assembles each body "
        "(doc/parallel.md): 'distributed' the cells partitioned over the "
        "ranks by METIS, each rank assembling its own cells into the "
        "distributed matrix that MUMPS factors (no rank holds the whole "
        "stiffness matrix; the mesh is still whole on every rank); "
        "'replicated' every rank assembles the whole body and hands its "
        "rows to MUMPS. One process ignores it.");
      prm.declare_entry(
        "Parallel mesh",
        "distributed",
        dealii::Patterns::Selection("whole|distributed"),
        "With Parallel assembly = distributed on more than one rank: "
        "'distributed' each rank keeps only its cells of each body and a "
        "layer of ghost cells around them (a "
        "parallel::fullydistributed::Triangulation; rank 0 builds the whole "
        "mesh for the set-up and releases it; doc/parallel.md); 'whole' "
        "every rank keeps the whole mesh. The replicated assembly keeps the "
        "whole mesh. One process ignores it.");
      prm.declare_entry(
        "Concurrent bodies",
        "true",
        dealii::Patterns::Bool(),
        "With two bodies, on the serial route with Factorisation back end = "
        "cholmod: 'true' assembles, factorises and condenses the bodies at the "
        "same time, one thread each, the BLAS on one thread per body meanwhile "
        "(the same compliance and load term up to round-off; a body whose "
        "memory check fails only because of the other's is factorised after "
        "it); 'false' one body after the other, the BLAS on every core. "
        "The MPI route and the MUMPS back end take the bodies one after the "
        "other. Starting the threads costs a fraction of a millisecond: on "
        "two cores 'true' is about as fast from about 700 dofs in all and "
        "faster from a few thousand (doc/parameters.md).");
    }



    // The out-of-core directory must be one MUMPS can write to: it is
    // checked here, before any work, rather than by MUMPS in the middle of
    // a factorisation. MUMPS keeps at most 255 characters of its name.
    void
    Parameters::check_out_of_core_directory(const std::string &directory,
                                            const Backend      backend)
    {
      const std::string entry =
        "Contact / Out-of-core directory = '" + directory + "'";
      if (backend != Backend::mumps)
        throw InputError(entry +
                         " needs Contact / Factorisation back end = mumps "
                         "(or the MPI route): CHOLMOD factors in memory only");
      if (directory.size() > 255)
        throw InputError(entry + ": longer than the 255 characters MUMPS "
                                 "keeps of a directory name");
      struct stat status;
      if (stat(directory.c_str(), &status) != 0 || !S_ISDIR(status.st_mode))
        throw InputError(entry + ": not an existing directory");
      if (access(directory.c_str(), W_OK | X_OK) != 0)
        throw InputError(entry + ": not writable");
    }



    void
    Parameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      method            = prm.get("Condensation method") == "schur" ?
                            Method::schur :
                            Method::blocked_solves;
      columns_per_solve = prm.get_integer("Columns per solve");
      backend = prm.get("Factorisation back end") == "mumps" ? Backend::mumps :
                                                               Backend::cholmod;
      if (backend == Backend::mumps && method != Method::schur)
        throw InputError("Contact / Factorisation back end = mumps needs "
                         "Contact / Condensation method = schur");
      route = parallel::choose_route(prm.get("Parallel route"),
                                     parallel::n_world_ranks());
      if (route == parallel::Route::mpi)
        {
          if (method != Method::schur)
            throw InputError("Contact / Condensation method = blocked "
                             "solves is not supported by the MPI route "
                             "(Contact / Parallel route = mpi, or auto on "
                             "more than one rank); use schur");
          backend = Backend::mumps;
        }
      distributed_assembly = route == parallel::Route::mpi &&
                             parallel::n_world_ranks() > 1 &&
                             prm.get("Parallel assembly") == "distributed";
      distributed_mesh =
        distributed_assembly && prm.get("Parallel mesh") == "distributed";
      concurrent_bodies = prm.get_bool("Concurrent bodies") &&
                          route == parallel::Route::serial &&
                          backend == Backend::cholmod;
      // MUMPS runs on MPI (on MPI_COMM_SELF on one process): MPI starts
      // here if it is not running yet (parallel/mpi_start.h).
      if (backend == Backend::mumps)
        {
          parallel::start_mpi();
          parallel::check_mumps_available();
        }
      out_of_core_directory = prm.get("Out-of-core directory");
      if (!out_of_core_directory.empty())
        check_out_of_core_directory(out_of_core_directory, backend);
      memory_limit_gb        = prm.get_double("Memory limit (GB)");
      const std::string name = prm.get("Schur ordering");
      mumps_orders_itself    = name == "by MUMPS";
      if (mumps_orders_itself && backend != Backend::mumps)
        throw InputError("Contact / Schur ordering = by MUMPS needs Contact / "
                         "Factorisation back end = mumps (or the MPI route)");
      for (const auto o :
           {linear_algebra::LastBlockOrdering::moved_last,
            linear_algebra::LastBlockOrdering::constrained_amd,
            linear_algebra::LastBlockOrdering::interior_nested_dissection,
            linear_algebra::LastBlockOrdering::automatic})
        if (linear_algebra::to_string(o) == name)
          ordering = o;
    }
  } // namespace condensation
} // namespace dpana
