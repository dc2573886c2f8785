// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
// MumpsSchurFactorization with a given ordering: the unknowns of K_r ordered
// as SparseCholesky orders them (last_block_ordering.h, the unknowns of
// Gamma last) and handed to MUMPS through its own interface (mumps_direct.h),
// each rank giving MUMPS the rows of PETSc's matrix it owns.

#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "mumps_schur_impl.h"

namespace dpana
{
  namespace linear_algebra
  {
    using parallel::check;



    // The upper triangle of the rows of K_r this rank owns (rows.begin to
    // rows.end), in compressed rows with global columns, as PETSc holds them
    // (a symmetric matrix of PETSc gives its rows' upper triangle between
    // MatGetRowUpperTriangular and MatRestoreRowUpperTriangular).
    void
    MumpsSchurFactorization::Impl::upper_rows(
      std::vector<PetscInt>    &row_start,
      std::vector<PetscInt>    &columns,
      std::vector<PetscScalar> &values) const
    {
      row_start.assign(1, 0);
      columns.clear();
      values.clear();
      check(MatGetRowUpperTriangular(K), "MatGetRowUpperTriangular");
      for (PetscInt r = rows.begin; r < rows.end; ++r)
        {
          PetscInt           n_columns;
          const PetscInt    *c;
          const PetscScalar *v;
          check(MatGetRow(K, r, &n_columns, &c, &v), "MatGetRow");
          for (PetscInt k = 0; k < n_columns; ++k)
            if (c[k] >= r)
              {
                columns.push_back(c[k]);
                values.push_back(v[k]);
              }
          MatRestoreRow(K, r, &n_columns, &c, &v);
          row_start.push_back(columns.size());
        }
      check(MatRestoreRowUpperTriangular(K), "MatRestoreRowUpperTriangular");
    }



    // The ordering, computed on rank 0 (empty on the others) on the pattern
    // of K_r: the ranks' rows, contiguous and in the order of the ranks,
    // gathered there make its upper triangle by rows, which is its lower
    // triangle by columns, the layout CHOLMOD takes.
    std::vector<long>
    MumpsSchurFactorization::Impl::elimination_order(
      const std::vector<PetscInt> &row_start,
      const std::vector<PetscInt> &columns) const
    {
      const int        n_local = columns.size();
      const int        n_ranks = rows.counts.size();
      std::vector<int> sizes(n_ranks), offsets(n_ranks, 0);
      MPI_Gather(
        &n_local, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, communicator);
      std::partial_sum(sizes.begin(), sizes.end() - 1, offsets.begin() + 1);
      const CholmodIndex        n = free.size();
      std::vector<CholmodIndex> outer, inner;
      std::vector<PetscInt>     all_columns(
        rank == 0 ? offsets.back() + sizes.back() : 0);
      MPI_Gatherv(columns.data(),
                  n_local,
                  MPIU_INT,
                  all_columns.data(),
                  sizes.data(),
                  offsets.data(),
                  MPIU_INT,
                  0,
                  communicator);
      // The row starts: each rank's counts of columns per row.
      std::vector<PetscInt> counts(row_start.size() - 1);
      for (std::size_t r = 0; r + 1 < row_start.size(); ++r)
        counts[r] = row_start[r + 1] - row_start[r];
      std::vector<PetscInt> all_counts(rank == 0 ? n : 0);
      MPI_Gatherv(counts.data(),
                  counts.size(),
                  MPIU_INT,
                  all_counts.data(),
                  rows.counts.data(),
                  rows.offsets.data(),
                  MPIU_INT,
                  0,
                  communicator);
      if (rank != 0)
        return {};
      outer.assign(1, 0);
      for (const PetscInt c : all_counts)
        outer.push_back(outer.back() + c);
      inner.assign(all_columns.begin(), all_columns.end());
      const std::vector<double>             pattern(inner.size(), 1.0);
      const Eigen::Map<const CholmodMatrix> K_lower(
        n, n, inner.size(), outer.data(), inner.data(), pattern.data());
      std::vector<bool> is_last(n, false);
      for (const PetscInt k : gamma)
        is_last[k] = true;
      cholmod_common common;
      cholmod_l_start(&common);
      const std::vector<CholmodIndex> order =
        order_last_block(K_lower, is_last, *given_ordering, common);
      cholmod_l_finish(&common);
      // MUMPS takes the Schur unknowns last in the order of its list.
      std::vector<long> interior_then_gamma;
      interior_then_gamma.reserve(n);
      for (const CholmodIndex k : order)
        if (!is_last[k])
          interior_then_gamma.push_back(k);
      interior_then_gamma.insert(interior_then_gamma.end(),
                                 gamma.begin(),
                                 gamma.end());
      return interior_then_gamma;
    }



    // As try_factor(), MUMPS called directly: the analysis with the given
    // order, the memory check, the factorisation. A negative pivot (MUMPS'
    // INFOG(12) counts them; SYM = 1 does not pivot) is reported as -10.
    PetscInt
    MumpsSchurFactorization::Impl::try_factor_directly(
      const PetscInt relaxation)
    {
      static_assert(std::is_same_v<PetscInt, int>,
                    "MUMPS' C interface takes 32-bit indices");
      direct       = std::make_unique<DirectMumps>(communicator);
      int analysis = 0;
      {
        // This rank's rows, released once MUMPS holds its copy.
        std::vector<PetscInt>    row_start, columns;
        std::vector<PetscScalar> values;
        upper_rows(row_start, columns, values);
        const std::vector<long> order = elimination_order(row_start, columns);
        analysis                      = direct->analyse(rows.n,
                                   rows.begin,
                                   row_start,
                                   columns,
                                   std::move(values),
                                   order,
                                   gamma,
                                   out_of_core_directory,
                                   relaxation);
      }
      // An analysis that fails is not a question of the matrix' values.
      if (analysis < 0)
        throw std::runtime_error(
          "MUMPS' analysis failed (INFOG(1) = " + std::to_string(analysis) +
          ", INFOG(2) = " + std::to_string(direct->infog(2)) +
          ") on a matrix of " + std::to_string(rows.n) + " unknowns");
      if (analysis_check)
        analysis_check(statistics());
      const int status = direct->factorize();
      if (direct->infog(12) > 0)
        return -10;
      return status;
    }
  } // namespace linear_algebra
} // namespace dpana
