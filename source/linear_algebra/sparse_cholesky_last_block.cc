// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// SparseCholesky with a given set of unknowns last: the ordering
// (last_block_ordering.h), CHOLMOD's symbolic analysis with it, and the
// unknowns of the last block in the order of the factor's columns.

#include <dpana/linear_algebra/last_block_ordering.h>
#include <dpana/linear_algebra/schur_factorization.h>
#include <dpana/linear_algebra/sparse_cholesky.h>

#include "sparse_cholesky_impl.h"

namespace dpana
{
  namespace linear_algebra
  {
    // @sect3{The surface unknowns last}
    //
    // The free degrees of freedom a surface dof stands for: itself if it is
    // free, its masters if it is constrained (a support or a Dirichlet
    // condition without masters stands for none).
    void
    SparseCholesky::factorize_with_last(
      const dealii::SparseMatrix<double>      &K,
      const dealii::AffineConstraints<double> &constraints,
      const std::vector<unsigned int>         &last_dofs)
    {
      const CholmodMatrix     K_lower = reduce(K, constraints);
      const std::vector<bool> is_last =
        unknowns_of_dofs(last_dofs, constraints, reduced_index, free.size());
      last.clear();
      for (unsigned int k = 0; k < free.size(); ++k)
        if (is_last[k])
          last.push_back(k);
      factorize_lower(K_lower);
    }



    // The ordering of the chosen kind (last_block_ordering.h) is handed to
    // CHOLMOD as the given one. The automatic choice tests the minimum
    // degree ordering on the analysis CHOLMOD makes of it anyway, and orders
    // and analyses a second time only when the test fails (or when the
    // minimum degree factor is too large for CHOLMOD to analyse).
    void
    SparseCholesky::order_last(const CholmodMatrix &K_lower)
    {
      std::vector<bool> is_last(K_lower.rows(), false);
      for (const unsigned int k : last)
        is_last[k] = true;
      if (last_ordering == LastBlockOrdering::automatic)
        try
          {
            analyze_with(K_lower, is_last, LastBlockOrdering::constrained_amd);
            const Analysis a = impl->llt.analysis();
            if (minimum_degree_suffices(a.factor_flops,
                                        a.factor_nonzeros,
                                        K_lower.nonZeros()))
              {
                record_analysis(LastBlockOrdering::constrained_amd);
                return;
              }
          }
        catch (const std::length_error &)
          {
            // The nested dissection below has the smaller factor.
          }
      const LastBlockOrdering chosen =
        last_ordering == LastBlockOrdering::automatic ?
          LastBlockOrdering::interior_nested_dissection :
          last_ordering;
      analyze_with(K_lower, is_last, chosen);
      record_analysis(chosen);
    }



    void
    SparseCholesky::analyze_with(const CholmodMatrix     &K_lower,
                                 const std::vector<bool> &is_last,
                                 const LastBlockOrdering  ordering)
    {
      std::vector<CholmodIndex> given =
        order_last_block(K_lower, is_last, ordering, impl->llt.cholmod());
      impl->llt.analyze_given(K_lower, given);
      // A factor CHOLMOD cannot address or allocate is reported as
      // std::length_error, which the condensation turns into an input error
      // naming the sizes. (With the 64-bit indices the first is out of
      // reach of any mesh this code builds.)
      const int status = impl->llt.cholmod().status;
      if (impl->llt.info() != Eigen::Success)
        internal::throw_if_too_large(status, K_lower.rows());
      AssertThrow(impl->llt.info() == Eigen::Success,
                  dealii::ExcMessage(
                    "SparseCholesky: CHOLMOD's analysis with the given "
                    "ordering failed (CHOLMOD status " +
                    std::to_string(status) + ")"));
      AssertThrow(impl->llt.permutation() == given,
                  dealii::ExcMessage("SparseCholesky: CHOLMOD did not keep "
                                     "the given ordering."));
    }



    // The analysis of the ordering CHOLMOD was given last, and the unknowns
    // of the last block in the order of the factor's columns.
    void
    SparseCholesky::record_analysis(const LastBlockOrdering ordering)
    {
      impl->analysis          = impl->llt.analysis();
      impl->analysis.n_last   = last.size();
      impl->analysis.ordering = last_ordering == LastBlockOrdering::automatic ?
                                  "automatic: " + to_string(ordering) :
                                  to_string(ordering);
      const std::vector<CholmodIndex> given = impl->llt.permutation();
      schur.resize(last.size());
      for (unsigned int k = 0; k < last.size(); ++k)
        schur[k] = free[given[given.size() - last.size() + k]];
    }



    const cholmod_factor &
    SparseCholesky::factor() const
    {
      AssertThrow(impl->factorized && !last.empty(),
                  dealii::ExcMessage(
                    "SparseCholesky: factorize_with_last() first."));
      const cholmod_factor &L = impl->llt.factor();
      AssertThrow(L.is_ll && (L.is_super || (L.is_monotonic && L.p != nullptr)),
                  dealii::ExcInternalError());
      return L;
    }
  } // namespace linear_algebra
} // namespace dpana
