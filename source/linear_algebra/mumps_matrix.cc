// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
// The matrix K_r that MumpsSchurFactorization hands to PETSc and MUMPS:
// the rows a rank owns of the whole matrix, or every rank's share of it.

#include <algorithm>

#include "mumps_schur_impl.h"

namespace dpana
{
  namespace linear_algebra
  {
    using parallel::check;



    // The upper triangle of the rows of K_r this rank owns, in compressed
    // rows with global column indices. A row of a deal.II SparseMatrix holds
    // its diagonal first and then the other columns in increasing order, so
    // the kept columns are in increasing order. On one rank the matrix is
    // sequential (MATSBAIJ becomes MATSEQSBAIJ), on several distributed by
    // contiguous blocks of rows (MATMPISBAIJ).
    void
    MumpsSchurFactorization::Impl::create_matrix(
      const dealii::SparseMatrix<double> &K_full)
    {
      rows = parallel::RowRange(communicator, free.size());
      std::vector<PetscInt>    row_start(1, 0), columns;
      std::vector<PetscScalar> values;
      for (PetscInt r = rows.begin; r < rows.end; ++r)
        {
          const unsigned int i = free[r];
          for (auto it = K_full.begin(i); it != K_full.end(i); ++it)
            {
              const int c = reduced_index[it->column()];
              if (c >= r && it->value() != 0.0)
                {
                  columns.push_back(c);
                  values.push_back(it->value());
                }
            }
          row_start.push_back(columns.size());
        }
      const PetscInt n = rows.n, n_local = rows.n_local();
      check(MatCreate(communicator, &K), "MatCreate");
      check(MatSetSizes(K, n_local, n_local, n, n), "MatSetSizes");
      check(MatSetType(K, MATSBAIJ), "MatSetType");
      if (rows.counts.size() > 1)
        insert_distributed(row_start, columns, values);
      else
        check(MatSeqSBAIJSetPreallocationCSR(
                K, 1, row_start.data(), columns.data(), values.data()),
              "MatSeqSBAIJSetPreallocationCSR");
      check(MatSetOption(K, MAT_SPD, PETSC_TRUE), "MatSetOption(MAT_SPD)");
    }



    // A matrix in shares (the cells of each rank): every rank adds the upper
    // triangle of all the nonzero rows of its share of K_r, whoever owns
    // them. The preallocation of a row counts its columns in the diagonal
    // block (the rows its owner holds) and right of it, summed over the
    // shares (an entry that two shares hold is counted twice: a little too
    // much memory reserved on the rows between subdomains), then cut to
    // the size of each block.
    void
    MumpsSchurFactorization::Impl::create_matrix_from_shares(
      const dealii::SparseMatrix<double> &K_share)
    {
      rows              = parallel::RowRange(communicator, free.size());
      const PetscInt n  = rows.n;
      const int      nr = rows.counts.size();
      // The owner of each reduced row: offsets are increasing.
      const auto owner_end = [this, nr](const PetscInt r) {
        const auto p =
          std::upper_bound(rows.offsets.begin(), rows.offsets.end(), r) -
          rows.offsets.begin() - 1;
        return p + 1 < nr ? PetscInt(rows.offsets[p + 1]) : rows.n;
      };
      std::vector<PetscInt> counts(2 * n, 0);
      for (PetscInt r = 0; r < n; ++r)
        {
          const unsigned int i   = free[r];
          const PetscInt     end = owner_end(r);
          for (auto it = K_share.begin(i); it != K_share.end(i); ++it)
            {
              const int c = reduced_index[it->column()];
              if (c >= r && it->value() != 0.0)
                ++counts[2 * r + (c < end ? 0 : 1)];
            }
        }
      MPI_Allreduce(MPI_IN_PLACE,
                    counts.data(),
                    counts.size(),
                    MPIU_INT,
                    MPI_SUM,
                    communicator);
      const PetscInt        n_local = rows.n_local();
      std::vector<PetscInt> diagonal(n_local), off_diagonal(n_local);
      for (PetscInt k = 0; k < n_local; ++k)
        {
          const PetscInt r = rows.begin + k;
          diagonal[k]      = std::min(counts[2 * r], rows.end - r);
          off_diagonal[k]  = std::min(counts[2 * r + 1], n - rows.end);
        }
      counts.clear();
      counts.shrink_to_fit();

      check(MatCreate(communicator, &K), "MatCreate");
      check(MatSetSizes(K, n_local, n_local, n, n), "MatSetSizes");
      check(MatSetType(K, MATSBAIJ), "MatSetType");
      if (nr > 1)
        check(MatMPISBAIJSetPreallocation(
                K, 1, 0, diagonal.data(), 0, off_diagonal.data()),
              "MatMPISBAIJSetPreallocation");
      else
        check(MatSeqSBAIJSetPreallocation(K, 1, 0, diagonal.data()),
              "MatSeqSBAIJSetPreallocation");
      std::vector<PetscInt>    columns;
      std::vector<PetscScalar> values;
      for (PetscInt r = 0; r < n; ++r)
        {
          const unsigned int i = free[r];
          columns.clear();
          values.clear();
          for (auto it = K_share.begin(i); it != K_share.end(i); ++it)
            {
              const int c = reduced_index[it->column()];
              if (c >= r && it->value() != 0.0)
                {
                  columns.push_back(c);
                  values.push_back(it->value());
                }
            }
          if (!columns.empty())
            check(MatSetValues(K,
                               1,
                               &r,
                               columns.size(),
                               columns.data(),
                               values.data(),
                               ADD_VALUES),
                  "MatSetValues");
        }
      check(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
      check(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
      check(MatSetOption(K, MAT_SPD, PETSC_TRUE), "MatSetOption(MAT_SPD)");
    }



    // The rows of this rank into the distributed matrix, preallocated by
    // the counts of their columns in the diagonal block (those this rank
    // owns) and right of it.
    void
    MumpsSchurFactorization::Impl::insert_distributed(
      const std::vector<PetscInt>    &row_start,
      const std::vector<PetscInt>    &columns,
      const std::vector<PetscScalar> &values)
    {
      const PetscInt        n_local = rows.n_local();
      std::vector<PetscInt> diagonal(n_local, 0), off_diagonal(n_local, 0);
      for (PetscInt r = 0; r < n_local; ++r)
        for (PetscInt k = row_start[r]; k < row_start[r + 1]; ++k)
          ++(columns[k] < rows.end ? diagonal[r] : off_diagonal[r]);
      check(MatMPISBAIJSetPreallocation(
              K, 1, 0, diagonal.data(), 0, off_diagonal.data()),
            "MatMPISBAIJSetPreallocation");
      for (PetscInt r = 0; r < n_local; ++r)
        {
          const PetscInt row = rows.begin + r;
          check(MatSetValues(K,
                             1,
                             &row,
                             row_start[r + 1] - row_start[r],
                             columns.data() + row_start[r],
                             values.data() + row_start[r],
                             INSERT_VALUES),
                "MatSetValues");
        }
      check(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
      check(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    }
  } // namespace linear_algebra
} // namespace dpana
