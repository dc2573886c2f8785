// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
// MumpsSchurFactorization with a given ordering: the unknowns of K_r ordered
// as SparseCholesky orders them (last_block_ordering.h, the unknowns of
// Gamma last) and handed to MUMPS through its own interface (mumps_direct.h).

#include <type_traits>

#include "mumps_schur_impl.h"

namespace dpana
{
  namespace linear_algebra
  {
    // The ordering is computed on the pattern of K_r: its upper triangle by
    // rows is its lower triangle by columns, the layout CHOLMOD takes.
    std::vector<long>
    MumpsSchurFactorization::Impl::elimination_order() const
    {
      const CholmodIndex        n = free.size();
      std::vector<CholmodIndex> outer(csr_start.begin(), csr_start.end()),
        inner(csr_columns.begin(), csr_columns.end());
      const Eigen::Map<const CholmodMatrix> K_lower(
        n, n, inner.size(), outer.data(), inner.data(), csr_values.data());
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
      direct             = std::make_unique<DirectMumps>();
      const int analysis = direct->analyse(csr_start,
                                           csr_columns,
                                           csr_values,
                                           elimination_order(),
                                           gamma,
                                           out_of_core_directory,
                                           relaxation);
      if (analysis < 0)
        return analysis;
      if (analysis_check)
        analysis_check(statistics());
      const int status = direct->factorize();
      if (direct->infog(12) > 0)
        return -10;
      return status;
    }
  } // namespace linear_algebra
} // namespace dpana
