// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_source_linear_algebra_sparse_cholesky_impl_h
#define dpana_source_linear_algebra_sparse_cholesky_impl_h

// The private state of SparseCholesky, shared by its two source files:
// sparse_cholesky.cc (the factorisation and the solves) and
// sparse_cholesky_last_block.cc (the ordering with the surface unknowns
// last and the analysis it gives).

#include <dpana/linear_algebra/sparse_cholesky.h>

#include <Eigen/CholmodSupport>

#include <functional>
#include <stdexcept>
#include <string>

namespace dpana
{
  namespace linear_algebra
  {
    namespace internal
    {
      // CHOLMOD's LL^T through Eigen's wrapper of its supernodal method
      // (SparseCholesky's constructor lets CHOLMOD choose the simplicial
      // method for a sparse factor). The wrapper keeps the column at which a
      // failed factorisation broke down ("minor") to itself; this subclass
      // makes it visible for the error message.
      class CholmodLLT
        : public Eigen::CholmodSupernodalLLT<CholmodMatrix, Eigen::Lower>
      {
      public:
        long
        failed_column() const
        {
          return this->m_cholmodFactor ?
                   static_cast<long>(this->m_cholmodFactor->minor) :
                   -1;
        }

        // The symbolic analysis with the given fill-reducing permutation
        // (factor column k is unknown perm[k]) and without the postordering
        // of the elimination tree, which could move columns of the last
        // block forward.
        void
        analyze_given(const CholmodMatrix       &K_lower,
                      std::vector<CholmodIndex> &perm)
        {
          if (this->m_cholmodFactor)
            cholmod_l_free_factor(&this->m_cholmodFactor, &this->cholmod());
          cholmod_sparse A = Eigen::viewAsCholmod(
            K_lower.template selfadjointView<Eigen::Lower>());
          cholmod_common &c         = this->cholmod();
          const int       nmethods  = c.nmethods;
          const int       ordering  = c.method[0].ordering;
          const int       postorder = c.postorder;
          c.nmethods                = 1;
          c.method[0].ordering      = CHOLMOD_GIVEN;
          c.postorder               = 0;
          this->m_cholmodFactor =
            cholmod_l_analyze_p(&A, perm.data(), nullptr, 0, &c);
          c.nmethods            = nmethods;
          c.method[0].ordering  = ordering;
          c.postorder           = postorder;
          this->m_isInitialized = true;
          this->m_info =
            this->m_cholmodFactor ? Eigen::Success : Eigen::NumericalIssue;
          this->m_analysisIsOk      = this->m_cholmodFactor != nullptr;
          this->m_factorizationIsOk = false;
        }

        // The fill-reducing permutation chosen by the last analysis.
        std::vector<CholmodIndex>
        permutation() const
        {
          const auto *p =
            static_cast<const CholmodIndex *>(this->m_cholmodFactor->Perm);
          return std::vector<CholmodIndex>(p, p + this->m_cholmodFactor->n);
        }

        const cholmod_factor &
        factor() const
        {
          return *this->m_cholmodFactor;
        }

        // What the last analysis found (CHOLMOD keeps the counts of the
        // ordering it selected in its workspace).
        SparseCholesky::Analysis
        analysis()
        {
          SparseCholesky::Analysis a;
          const cholmod_factor    &L = *this->m_cholmodFactor;
          const cholmod_common    &c = this->cholmod();
          a.n_unknowns               = L.n;
          a.supernodal               = L.is_super;
          a.factor_entries           = L.is_super ? double(L.xsize) : c.lnz;
          a.factor_indices           = L.is_super ? double(L.ssize) : c.lnz;
          a.largest_update           = L.is_super ? double(L.maxcsize) : 0.0;
          a.factor_nonzeros          = c.lnz;
          a.factor_flops             = c.fl;
          return a;
        }
      };



      // CHOLMOD's status after a failed analysis or factorisation: a factor
      // too large to address or to allocate is std::length_error.
      inline void
      throw_if_too_large(const int status, const Eigen::Index n_unknowns)
      {
        if (status == CHOLMOD_TOO_LARGE || status == CHOLMOD_OUT_OF_MEMORY)
          throw std::length_error(
            "the factor of " + std::to_string(n_unknowns) + " unknowns is " +
            (status == CHOLMOD_TOO_LARGE ? "too large for CHOLMOD to address" :
                                           "more than the memory CHOLMOD "
                                           "could allocate"));
      }
    } // namespace internal



    struct SparseCholesky::Impl
    {
      internal::CholmodLLT                                  llt;
      bool                                                  factorized = false;
      Analysis                                              analysis;
      std::function<void(const SparseCholesky::Analysis &)> check;
    };
  } // namespace linear_algebra
} // namespace dpana

#endif
