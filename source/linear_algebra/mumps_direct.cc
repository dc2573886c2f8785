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
      // MUMPS keeps the instance's state in this structure; its solves
      // write to it, hence mutable.
      mutable DMUMPS_STRUC_C id;

      // The matrix in MUMPS' coordinate format (1-based), the position of
      // each unknown in the elimination order (MUMPS' PERM_IN), the Schur
      // unknowns (1-based) and the Schur complement.
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



    // A MUMPS instance on this process alone (PAR = 1: the host works), for
    // a symmetric positive definite matrix (SYM = 1), silent.
    DirectMumps::DirectMumps()
      : impl(std::make_unique<Impl>())
    {
      auto &id = impl->id;
      std::memset(&id, 0, sizeof(id));
      id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_SELF));
      id.par          = 1;
      id.sym          = 1;
      impl->call(-1);
      id.icntl[0] = -1;
      id.icntl[1] = -1;
      id.icntl[2] = -1;
      id.icntl[3] = 0;
    }



    // JOB = -2 frees MUMPS' memory and removes its out-of-core files.
    DirectMumps::~DirectMumps()
    {
      impl->call(-2);
    }



    // MUMPS' user ordering (ICNTL(7) = 1) takes the position of each unknown;
    // the centralised Schur complement (ICNTL(19) = 2) of a symmetric matrix
    // is its lower triangle by columns, which is LAPACK's column-major lower
    // triangle.
    int
    DirectMumps::analyse(const std::vector<int>  &row_start,
                         const std::vector<int>  &columns,
                         std::vector<double>      values,
                         const std::vector<long> &order,
                         const std::vector<int>  &schur,
                         const std::string       &ooc_directory,
                         const int                relaxation)
    {
      const long n = row_start.size() - 1;
      impl->irn.resize(columns.size());
      impl->jcn.resize(columns.size());
      for (long r = 0; r < n; ++r)
        for (long p = row_start[r]; p < row_start[r + 1]; ++p)
          {
            impl->irn[p] = r + 1;
            impl->jcn[p] = columns[p] + 1;
          }
      impl->a = std::move(values);
      impl->position.resize(n);
      for (long k = 0; k < n; ++k)
        impl->position[order[k]] = k + 1;
      impl->schur_list.resize(schur.size());
      for (std::size_t k = 0; k < schur.size(); ++k)
        impl->schur_list[k] = schur[k] + 1;
      const long m = schur.size();
      impl->S.setZero(m, m);

      auto &id    = impl->id;
      id.n        = n;
      id.nnz      = columns.size();
      id.irn      = impl->irn.data();
      id.jcn      = impl->jcn.data();
      id.a        = impl->a.data();
      id.icntl[6] = 1;
      id.perm_in  = impl->position.data();
      if (m > 0)
        {
          id.icntl[18]     = 2;
          id.size_schur    = m;
          id.listvar_schur = impl->schur_list.data();
          id.schur         = impl->S.data();
          id.schur_lld     = m;
        }
      if (relaxation > 0)
        id.icntl[13] = relaxation;
      if (!ooc_directory.empty())
        {
          id.icntl[21] = 1;
          std::strncpy(id.ooc_tmpdir,
                       ooc_directory.c_str(),
                       sizeof(id.ooc_tmpdir) - 1);
        }
      impl->call(1);
      return id.infog[0];
    }



    // MUMPS copies the matrix into its own structures here; without
    // iterative refinement (ICNTL(10) = 0) its solves do not read it again.
    int
    DirectMumps::factorize()
    {
      impl->call(2);
      impl->id.irn = nullptr;
      impl->id.jcn = nullptr;
      impl->id.a   = nullptr;
      std::vector<MUMPS_INT>().swap(impl->irn);
      std::vector<MUMPS_INT>().swap(impl->jcn);
      std::vector<double>().swap(impl->a);
      return impl->id.infog[0];
    }



    Eigen::MatrixXd
    DirectMumps::take_schur_complement()
    {
      impl->id.schur = nullptr;
      return std::move(impl->S);
    }



    // One dense right-hand side, centralised (ICNTL(20) = 0), solution in
    // its place (ICNTL(21) = 0).
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
