// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_source_linear_algebra_mumps_schur_impl_h
#define dpana_source_linear_algebra_mumps_schur_impl_h

// The private state of MumpsSchurFactorization, shared by its two source
// files: mumps_matrix.cc (the matrix K_r handed to PETSc, whole or in
// shares), mumps_schur.cc (the factorisation, S and the solves) and
// mumps_given_ordering.cc (with a given ordering MUMPS is called directly,
// mumps_direct.h, the rows of K_r taken from PETSc's matrix, which serves
// the products with it).

#include <dpana/linear_algebra/mumps_schur.h>
#include <dpana/parallel/petsc_calls.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mumps_direct.h"

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
      std::optional<LastBlockOrdering>        given_ordering;
      std::unique_ptr<DirectMumps>            direct;
      parallel::RowRange                      rows;
      Mat                                     K = nullptr;
      Mat                                     F = nullptr;

      dealii::AffineConstraints<double> constraints, homogeneous;
      std::vector<unsigned int>         free;
      std::vector<int>                  reduced_index;
      std::vector<PetscInt>             gamma;
      std::vector<unsigned int>         schur;
      Eigen::MatrixXd                   L;

      // Whether MUMPS is called directly: an ordering is given.
      bool
      calls_mumps_directly() const
      {
        return given_ordering.has_value();
      }

      void
      destroy()
      {
        destroy_factor();
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
      PetscInt
      try_factor_directly(const PetscInt relaxation);
      void
      upper_rows(std::vector<PetscInt>    &row_start,
                 std::vector<PetscInt>    &columns,
                 std::vector<PetscScalar> &values) const;
      std::vector<long>
      elimination_order(const std::vector<PetscInt> &row_start,
                        const std::vector<PetscInt> &columns) const;
      void
      factor_schur_complement();
      void
      copy_schur_complement();
      void
      destroy_factor()
      {
        direct.reset();
        if (F)
          MatDestroy(&F);
      }
      Statistics
      statistics() const;
      int
      infog(const int i) const;
      double
      rinfog(const int i) const;
      int
      icntl(const int i) const;

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
