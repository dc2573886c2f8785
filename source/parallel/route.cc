// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/parallel/petsc_calls.h>
#include <dpana/parallel/route.h>

#include <vector>

namespace dpana
{
  namespace parallel
  {
    Route
    choose_route(const std::string &name, const unsigned int n_ranks)
    {
      if (name == "serial" && n_ranks > 1)
        throw InputError("Contact / Parallel route = serial runs on one "
                         "process, not on " +
                         std::to_string(n_ranks) +
                         " MPI ranks; start it without mpirun or set "
                         "Parallel route = auto or mpi");
      if (name == "mpi" || (name == "auto" && n_ranks > 1))
        return Route::mpi;
      return Route::serial;
    }



    unsigned int
    n_world_ranks()
    {
      int initialized = 0, size = 1;
      MPI_Initialized(&initialized);
      if (initialized)
        MPI_Comm_size(MPI_COMM_WORLD, &size);
      return size;
    }



    bool
    is_root()
    {
      int initialized = 0, rank = 0;
      MPI_Initialized(&initialized);
      if (initialized)
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
      return rank == 0;
    }



    void
    check_mumps_available()
    {
      if (!mumps_available())
        throw InputError("this PETSc has no MUMPS (MatGetFactorAvailable); "
                         "Contact / Parallel route = mpi and Factorisation "
                         "back end = mumps need a PETSc configured with "
                         "MUMPS");
    }



    void
    check_ranks(const std::string &body_name,
                const unsigned int n_cells,
                const unsigned int n_ranks)
    {
      if (n_ranks > n_cells)
        throw InputError(body_name + " has " + std::to_string(n_cells) +
                         " cells, fewer than the " + std::to_string(n_ranks) +
                         " MPI ranks of the run; use fewer ranks or a finer "
                         "mesh");
    }



    namespace
    {
      void
      broadcast(Eigen::VectorXd &v, const MPI_Comm communicator)
      {
        long n = v.size();
        MPI_Bcast(&n, 1, MPI_LONG, 0, communicator);
        v.resize(n);
        MPI_Bcast(v.data(), n, MPI_DOUBLE, 0, communicator);
      }
    } // namespace



    void
    broadcast(contact::SolverResult &result, const MPI_Comm communicator)
    {
      broadcast(result.r, communicator);
      broadcast(result.u, communicator);
      broadcast(result.alpha, communicator);

      std::vector<int> status(result.status.size());
      for (unsigned int j = 0; j < status.size(); ++j)
        status[j] = static_cast<int>(result.status[j]);
      int n = status.size();
      MPI_Bcast(&n, 1, MPI_INT, 0, communicator);
      status.resize(n);
      MPI_Bcast(status.data(), n, MPI_INT, 0, communicator);
      result.status.resize(n);
      for (int j = 0; j < n; ++j)
        result.status[j] = static_cast<contact::ContactStatus>(status[j]);

      int converged = result.converged ? 1 : 0;
      MPI_Bcast(&converged, 1, MPI_INT, 0, communicator);
      result.converged = converged != 0;
      MPI_Bcast(&result.iterations, 1, MPI_UNSIGNED, 0, communicator);
      MPI_Bcast(&result.residual, 1, MPI_DOUBLE, 0, communicator);
    }
  } // namespace parallel
} // namespace dpana
