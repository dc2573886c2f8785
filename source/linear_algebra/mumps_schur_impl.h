// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_source_linear_algebra_mumps_schur_impl_h
#define dpana_source_linear_algebra_mumps_schur_impl_h

// The private state of MumpsSchurFactorization, shared by its two source
// files: mumps_matrix.cc (the matrix K_r handed to PETSc, whole or in
// shares) and mumps_schur.cc (the factorisation, S and the solves).

#include <dpana/linear_algebra/mumps_schur.h>
#include <dpana/parallel/petsc_calls.h>

#include <functional>
#include <string>
#include <vector>

namespace dpana
{
  namespace linear_algebra
  {
    struct MumpsSchurFactorization::Impl
    {
      explicit Impl(const MPI_Comm communicator)
        : communicator(communicator)
      {
        MPI_Comm_rank(communicator, &rank);
      }

      MPI_Comm                                communicator;
      std::function<void(const Statistics &)> analysis_check;
      bool                                    in_shares = false;
      std::string                             out_of_core_directory;
      int                                     rank = 0;
      parallel::RowRange                      rows;
      Mat                                     K = nullptr;
      Mat                                     F = nullptr;

      dealii::AffineConstraints<double> constraints, homogeneous;
      std::vector<unsigned int>         free;
      std::vector<int>                  reduced_index;
      std::vector<PetscInt>             gamma;
      std::vector<unsigned int>         schur;
      Eigen::MatrixXd                   L;

      void
      destroy()
      {
        if (F)
          MatDestroy(&F);
        if (K)
          MatDestroy(&K);
      }

      void
      copy_constraints(const dealii::AffineConstraints<double> &c);
      void
      number_unknowns(const unsigned int               n_rows,
                      const std::vector<unsigned int> &gamma_dofs);
      void
      create_matrix(const dealii::SparseMatrix<double> &K_full);
      void
      create_matrix_from_shares(const dealii::SparseMatrix<double> &K_share);
      void
      insert_distributed(const std::vector<PetscInt>    &row_start,
                         const std::vector<PetscInt>    &columns,
                         const std::vector<PetscScalar> &values);
      void
      factor_interior();
      PetscInt
      try_factor(const PetscInt relaxation);
      void
      factor_schur_complement();

      // y = K_II^{-1} b_I, zero on Gamma.
      Eigen::VectorXd
      solve_interior(const Eigen::VectorXd &b) const;
      // K_r x.
      Eigen::VectorXd
      multiply(const Eigen::VectorXd &x) const;
    };
  } // namespace linear_algebra
} // namespace dpana

#endif
