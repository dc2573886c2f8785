// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/linear_algebra/last_block_ordering.h>

#include <deal.II/base/exceptions.h>

#include <Eigen/CholmodSupport>

namespace dpana
{
  namespace linear_algebra
  {
    std::string
    to_string(const LastBlockOrdering ordering)
    {
      switch (ordering)
        {
          case LastBlockOrdering::moved_last:
            return "moved last";
          case LastBlockOrdering::constrained_amd:
            return "constrained AMD";
          case LastBlockOrdering::interior_nested_dissection:
            return "interior nested dissection";
        }
      return "";
    }



    namespace
    {
      // CHOLMOD's analysis of the whole matrix with its default strategy; its
      // permutation with the last unknowns moved to the end (a stable
      // partition).
      std::vector<CholmodIndex>
      moved_last(const CholmodMatrix     &K_lower,
                 const std::vector<bool> &is_last,
                 cholmod_common          &common)
      {
        cholmod_sparse A = Eigen::viewAsCholmod(
          K_lower.template selfadjointView<Eigen::Lower>());
        cholmod_factor *L = cholmod_l_analyze(&A, &common);
        AssertThrow(L != nullptr,
                    dealii::ExcMessage("CHOLMOD's symbolic analysis failed."));
        const auto *p = static_cast<const CholmodIndex *>(L->Perm);
        std::vector<CholmodIndex> given;
        given.reserve(L->n);
        for (std::size_t k = 0; k < L->n; ++k)
          if (!is_last[p[k]])
            given.push_back(p[k]);
        for (std::size_t k = 0; k < L->n; ++k)
          if (is_last[p[k]])
            given.push_back(p[k]);
        cholmod_l_free_factor(&L, &common);
        return given;
      }



      // CAMD with the constraint sets 0 (interior) and 1 (last).
      std::vector<CholmodIndex>
      constrained_amd(const CholmodMatrix     &K_lower,
                      const std::vector<bool> &is_last,
                      cholmod_common          &common)
      {
        cholmod_sparse A = Eigen::viewAsCholmod(
          K_lower.template selfadjointView<Eigen::Lower>());
        std::vector<CholmodIndex> member(is_last.begin(), is_last.end());
        std::vector<CholmodIndex> perm(is_last.size());
        AssertThrow(
          cholmod_l_camd(&A, nullptr, 0, member.data(), perm.data(), &common),
          dealii::ExcMessage("CHOLMOD's CAMD ordering failed."));
        return perm;
      }



      // METIS on the interior block K_II (the rows and columns of the
      // interior unknowns), then the last unknowns in increasing order.
      std::vector<CholmodIndex>
      interior_nested_dissection(const CholmodMatrix     &K_lower,
                                 const std::vector<bool> &is_last,
                                 cholmod_common          &common)
      {
        std::vector<CholmodIndex> interior, index(is_last.size(), -1);
        for (std::size_t i = 0; i < is_last.size(); ++i)
          if (!is_last[i])
            {
              index[i] = interior.size();
              interior.push_back(i);
            }
        std::vector<Eigen::Triplet<double, CholmodIndex>> triplets;
        for (Eigen::Index c = 0; c < K_lower.outerSize(); ++c)
          for (CholmodMatrix::InnerIterator it(K_lower, c); it; ++it)
            if (index[it.row()] >= 0 && index[it.col()] >= 0)
              triplets.emplace_back(index[it.row()], index[it.col()], 1.0);
        CholmodMatrix graph(interior.size(), interior.size());
        graph.setFromTriplets(triplets.begin(), triplets.end());
        const CholmodMatrix &K_II = graph;

        std::vector<CholmodIndex> given(interior.size());
        if (!interior.empty())
          {
            cholmod_sparse A = Eigen::viewAsCholmod(
              K_II.template selfadjointView<Eigen::Lower>());
            AssertThrow(
              cholmod_l_metis(&A, nullptr, 0, 1, given.data(), &common),
              dealii::ExcMessage("CHOLMOD's METIS ordering failed."));
            for (CholmodIndex &k : given)
              k = interior[k];
          }
        for (std::size_t i = 0; i < is_last.size(); ++i)
          if (is_last[i])
            given.push_back(i);
        return given;
      }
    } // namespace



    std::vector<CholmodIndex>
    order_last_block(const CholmodMatrix     &K_lower,
                     const std::vector<bool> &is_last,
                     const LastBlockOrdering  ordering,
                     cholmod_common          &common)
    {
      AssertDimension(is_last.size(), K_lower.rows());
      switch (ordering)
        {
          case LastBlockOrdering::moved_last:
            return moved_last(K_lower, is_last, common);
          case LastBlockOrdering::constrained_amd:
            return constrained_amd(K_lower, is_last, common);
          case LastBlockOrdering::interior_nested_dissection:
            return interior_nested_dissection(K_lower, is_last, common);
        }
      return {};
    }
  } // namespace linear_algebra
} // namespace dpana
