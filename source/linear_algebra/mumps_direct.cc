// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include "mumps_direct.h"

#include <cstring>
#include <stdexcept>
#include <string>

#include <dmumps_c.h>
#include <mpi.h>

namespace dpana
{
  namespace linear_algebra
  {
    struct DirectMumps::Impl
    {
      explicit Impl(const MPI_Comm communicator)
        : communicator(communicator)
      {
        MPI_Comm_rank(communicator, &rank);
      }

      MPI_Comm communicator;
      int      rank = 0;

      // MUMPS keeps the instance's state in this structure; its solves
      // write to it, hence mutable.
      mutable DMUMPS_STRUC_C id;

      // This rank's part of the matrix in MUMPS' coordinate format
      // (1-based), the Schur unknowns (1-based), and on rank 0 the position
      // of each unknown in the elimination order (MUMPS' PERM_IN) and the
      // Schur complement.
      std::vector<MUMPS_INT> irn, jcn, position, schur_list;
      std::vector<double>    a;
      Eigen::MatrixXd        S;

      void
      call(const int job) const
      {
        id.job = job;
        dmumps_c(&id);
      }
    };



    // A MUMPS instance over the ranks of @p communicator (PAR = 1: the host
    // works), for a symmetric positive definite matrix (SYM = 1), silent.
    DirectMumps::DirectMumps(const MPI_Comm communicator)
      : impl(std::make_unique<Impl>(communicator))
    {
      auto &id = impl->id;
      std::memset(&id, 0, sizeof(id));
      id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(communicator));
      id.par          = 1;
      id.sym          = 1;
      impl->call(-1);
      if (id.infog[0] < 0)
        throw std::runtime_error("MUMPS could not be started (INFOG(1) = " +
                                 std::to_string(id.infog[0]) + ")");
      id.icntl[0] = -1;
      id.icntl[1] = -1;
      id.icntl[2] = -1;
      id.icntl[3] = 0;
      // No iterative refinement (ICNTL(10)) and no error analysis
      // (ICNTL(11)): the solves then do not read the matrix, which
      // factorize() releases.
      id.icntl[9]  = 0;
      id.icntl[10] = 0;
    }



    // JOB = -2 frees MUMPS' memory and removes its out-of-core files.
    DirectMumps::~DirectMumps()
    {
      impl->call(-2);
    }



    // The matrix distributed (ICNTL(18) = 3), MUMPS' user ordering
    // (ICNTL(7) = 1: the position of each unknown, on the host), the Schur
    // complement centralised on the host (ICNTL(19) = 1: for a symmetric
    // matrix its lower triangle by rows, the upper one of the column-major
    // array).
    int
    DirectMumps::analyse(const int                n,
                         const int                first_row,
                         const std::vector<int>  &row_start,
                         const std::vector<int>  &columns,
                         std::vector<double>      values,
                         const std::vector<long> &order,
                         const std::vector<int>  &schur,
                         const std::string       &ooc_directory,
                         const int                relaxation)
    {
      const long n_rows = row_start.size() - 1;
      impl->irn.resize(columns.size());
      impl->jcn.resize(columns.size());
      for (long r = 0; r < n_rows; ++r)
        for (long p = row_start[r]; p < row_start[r + 1]; ++p)
          {
            impl->irn[p] = first_row + r + 1;
            impl->jcn[p] = columns[p] + 1;
          }
      impl->a = std::move(values);

      auto &id      = impl->id;
      id.n          = n;
      id.icntl[17]  = 3;
      id.nnz_loc    = columns.size();
      id.irn_loc    = impl->irn.data();
      id.jcn_loc    = impl->jcn.data();
      id.a_loc      = impl->a.data();
      id.icntl[6]   = 1;
      id.size_schur = schur.size();
      impl->schur_list.resize(schur.size());
      for (std::size_t k = 0; k < schur.size(); ++k)
        impl->schur_list[k] = schur[k] + 1;
      if (impl->rank == 0)
        {
          impl->position.resize(n);
          for (long k = 0; k < n; ++k)
            impl->position[order[k]] = k + 1;
          id.perm_in = impl->position.data();
          impl->S.setZero(schur.size(), schur.size());
        }
      if (!schur.empty())
        {
          id.icntl[18]     = 1;
          id.listvar_schur = impl->schur_list.data();
          id.schur         = impl->S.data();
          id.schur_lld     = schur.size();
        }
      if (relaxation > 0)
        id.icntl[13] = relaxation;
      if (!ooc_directory.empty())
        {
          if (ooc_directory.size() >= sizeof(id.ooc_tmpdir))
            throw std::runtime_error("the out-of-core directory name is "
                                     "longer than MUMPS keeps");
          id.icntl[21] = 1;
          std::strncpy(id.ooc_tmpdir,
                       ooc_directory.c_str(),
                       sizeof(id.ooc_tmpdir) - 1);
        }
      impl->call(1);
      return id.infog[0];
    }



    // MUMPS copies the matrix into its own structures here; without
    // iterative refinement and error analysis (ICNTL(10) = ICNTL(11) = 0,
    // set by the constructor) its solves do not read it again.
    int
    DirectMumps::factorize()
    {
      impl->call(2);
      impl->id.irn_loc = nullptr;
      impl->id.jcn_loc = nullptr;
      impl->id.a_loc   = nullptr;
      std::vector<MUMPS_INT>().swap(impl->irn);
      std::vector<MUMPS_INT>().swap(impl->jcn);
      std::vector<double>().swap(impl->a);
      return impl->id.infog[0];
    }



    Eigen::MatrixXd
    DirectMumps::take_schur_complement()
    {
      impl->id.schur    = nullptr;
      Eigen::MatrixXd S = std::move(impl->S);
      S.transposeInPlace();
      return S;
    }



    // One dense right-hand side and its solution, centralised on the host
    // (ICNTL(20) = 0, ICNTL(21) = 0), the solution then sent to every rank.
    Eigen::VectorXd
    DirectMumps::solve_interior(const Eigen::VectorXd &b) const
    {
      Eigen::VectorXd x  = b;
      auto           &id = impl->id;
      id.icntl[19]       = 0;
      id.icntl[20]       = 0;
      id.icntl[25]       = 0;
      id.nrhs            = 1;
      id.lrhs            = x.size();
      id.rhs             = x.data();
      impl->call(3);
      id.rhs = nullptr;
      if (id.infog[0] < 0)
        throw std::runtime_error("MUMPS' solve failed (INFOG(1) = " +
                                 std::to_string(id.infog[0]) + ")");
      MPI_Bcast(x.data(), x.size(), MPI_DOUBLE, 0, impl->communicator);
      for (const MUMPS_INT k : impl->schur_list)
        x(k - 1) = 0.0;
      return x;
    }



    int
    DirectMumps::infog(const int i) const
    {
      return impl->id.infog[i - 1];
    }



    double
    DirectMumps::rinfog(const int i) const
    {
      return impl->id.rinfog[i - 1];
    }



    int
    DirectMumps::icntl(const int i) const
    {
      return impl->id.icntl[i - 1];
    }
  } // namespace linear_algebra
} // namespace dpana
