// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_condensation_memory_estimate_h
#define dpana_condensation_memory_estimate_h

#include <dpana/linear_algebra/sparse_cholesky.h>

#include <mutex>
#include <string>

namespace dpana
{
  namespace condensation
  {
    /**
     * The memory a body's condensation and the contact solve will need,
     * estimated from CHOLMOD's symbolic analysis before the numerical
     * factorisation, the expensive part, begins.
     *
     * The factorisation of the Schur route holds the factor, in CHOLMOD's
     * 64-bit interface: its $n_L$ numbers (factor_entries) and its $n_s$
     * row indices (factor_indices) of 8 bytes each (a simplicial factor:
     * one of each per nonzero). While it
     * runs, CHOLMOD adds the largest dense update matrix of a supernode
     * ($n_C$ numbers, largest_update), a permuted copy of the lower triangle
     * of the matrix ($n_K$ entries of a number and an index) and about
     * eight integer arrays of the $n$ unknowns (the permutation, the column
     * counts, the supernodal maps and their workspaces). The condensation
     * adds the dense block W (n_Gamma x n_c) and A (n_c x n_c); the contact
     * problem holds A once more and its solver a dense Cholesky factor of
     * the same size and a few matrices of that size for its iterations
     * (Alart-Curnier: the Jacobian and its factor). Hence
     * @f[
     *   M \approx M_\text{now}
     *       + 8 \left(n_L + n_s + n_C\right) + 16\, n_K + 64\, n
     *       + 8\, n_\Gamma n_c + 8 \cdot 5\, n_c^2 ,
     * @f]
     * with M_now the resident memory of the process when the estimate is
     * made (mesh, stiffness matrix and the reduced copy handed to CHOLMOD).
     */
    struct MemoryEstimate
    {
      /// False until it is made: by estimate_memory() from CHOLMOD's
      /// analysis, or from MUMPS' analysis (condenser.cc, mumps_estimate:
      /// its workspace estimate, in core or out of core).
      bool         made    = false;
      unsigned int n_dofs  = 0;
      unsigned int n_gamma = 0;
      unsigned int n_c     = 0;
      /// Resident memory before the factorisation (bytes).
      double current = 0;
      /// The factor and the factorisation's workspace (bytes).
      double factor = 0;
      /// W and the copies of A (bytes).
      double dense = 0;
      /// CHOLMOD's ordering (SparseCholesky::Analysis::ordering); empty for
      /// MUMPS, whose statistics name its own.
      std::string ordering;
      /// CHOLMOD's method: "supernodal" or "simplicial" (its choice,
      /// SparseCholesky::FactorKind); empty for MUMPS.
      std::string method;

      /**
       * The estimated peak, bytes.
       */
      double
      total() const
      {
        return current + factor + dense;
      }

      /**
       * "1115508 dofs, n_Gamma = 933, n_c = 466: about 1.9 GB (factor
       * 1.2 GB, dense blocks 0.01 GB, now 0.7 GB), ordering automatic:
       * constrained AMD, supernodal factor".
       */
      std::string
      describe() const;
    };

    /**
     * The estimate for a body of @p n_dofs degrees of freedom and @p n_c
     * contact unknowns from the analysis of its factorisation.
     */
    MemoryEstimate
    estimate_memory(const linear_algebra::SparseCholesky::Analysis &analysis,
                    const unsigned int                              n_dofs,
                    const unsigned int                              n_c);

    /**
     * The resident memory of this process now, in bytes (/proc/self/statm).
     */
    double
    resident_memory();

    /**
     * The memory this process may use: @p limit_gb if it is positive,
     * otherwise its resident memory plus the MemAvailable of
     * /proc/meminfo (what the kernel can give without swapping), in bytes.
     */
    double
    memory_limit(const double limit_gb);

    /**
     * The memory granted to condensations that run at the same time (the
     * bodies of a scene factorised concurrently, scene::Scene::condense()).
     * One after the other, each body's check (Condenser::factorize()) would
     * find the factor and dense blocks of the bodies before it in use; at
     * the same time it finds them only in part, so each check adds what the
     * others have been granted (their factor and dense blocks in full: what
     * they have allocated already is counted twice, on the safe side).
     *
     * A check that fails only because of the others' grants is deferred:
     * the body is factorised after them, with the check of a run one body
     * after the other. One that fails with no grant outstanding is refused
     * as it would be then.
     */
    class MemoryReservations
    {
    public:
      enum class Decision
      {
        granted,
        deferred,
        refused
      };

      /**
       * Whether @p estimate, with the grants made so far, fits in
       * @p limit (bytes); if it does, its factor and dense blocks are
       * granted.
       */
      Decision
      request(const MemoryEstimate &estimate, const double limit);

    private:
      std::mutex mutex;
      double     granted = 0;
    };
  } // namespace condensation
} // namespace dpana

#endif
