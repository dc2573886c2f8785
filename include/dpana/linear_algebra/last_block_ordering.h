// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_linear_algebra_last_block_ordering_h
#define dpana_linear_algebra_last_block_ordering_h

#include <Eigen/Sparse>

#include <string>
#include <vector>

#include <cholmod.h>

namespace dpana
{
  namespace linear_algebra
  {
    /**
     * The index type of CHOLMOD's 64-bit interface (the cholmod_l_*
     * functions), which every CHOLMOD call of dpana uses: a factor may then
     * hold more than $2^{31}$ numbers (17 GB), which a 3D body of a million
     * degrees of freedom with $10^4$ surface unknowns ordered last needs.
     */
    using CholmodIndex = SuiteSparse_long;

    /**
     * A sparse matrix in the index type of CHOLMOD's 64-bit interface, as
     * Eigen's CHOLMOD wrappers take it.
     */
    using CholmodMatrix =
      Eigen::SparseMatrix<double, Eigen::ColMajor, CholmodIndex>;

    /**
     * How the unknowns of a symmetric positive definite matrix are ordered
     * for a Cholesky factorisation $K = P^T L L^T P$ in which a given set
     * $\Gamma$ of unknowns must come last, so that the last diagonal block
     * of $L$ is the Cholesky factor of the Schur complement of $K$ on
     * $\Gamma$ (SparseCholesky::factorize_with_last()).
     *
     * Any ordering with $\Gamma$ last is exact; they differ in the fill of
     * the first block and in the coupling of the first block with $\Gamma$,
     * that is in the number of entries of $L$ and in the work of the
     * factorisation. On a 3D mesh the fill-reducing orderings of choice are
     * nested dissections (George 1973): the unknowns are split by a small
     * separator into two halves that are ordered first, recursively, and the
     * separator last. Forcing $\Gamma$ to the end of such an ordering of the
     * whole matrix breaks the recursion wherever $\Gamma$ crosses it;
     * ordering the interior graph alone keeps it intact.
     */
    enum class LastBlockOrdering
    {
      /**
       * CHOLMOD's own ordering of the whole matrix (approximate minimum
       * degree, or METIS when that is much better), with the unknowns of
       * $\Gamma$ moved to the end in the order it gave them.
       */
      moved_last,
      /**
       * Constrained approximate minimum degree (CAMD, Davis 2006) on the
       * whole graph, with $\Gamma$ a second constraint set ordered after the
       * first.
       */
      constrained_amd,
      /**
       * METIS' nested dissection (Karypis and Kumar 1998) of the graph of
       * the interior unknowns alone, postordered, then $\Gamma$ in its given
       * order. METIS is given the graph of the mesh vertices: consecutive
       * unknowns with the same couplings (the displacement components of a
       * vertex) are one weighted vertex of its graph.
       */
      interior_nested_dissection
    };

    /**
     * The name of @p ordering as the parameter files and the logs spell it:
     * "moved last", "constrained AMD", "interior nested dissection".
     */
    std::string
    to_string(const LastBlockOrdering ordering);

    /**
     * A fill-reducing permutation of the unknowns of the symmetric matrix
     * whose lower triangle is @p K_lower, with the unknowns $i$ for which
     * @p is_last[i] holds at the end: entry k of the result is the unknown
     * that becomes column k of the factor. @p common is the CHOLMOD
     * workspace of the factorisation that will use it (started by
     * cholmod_l_start()).
     */
    std::vector<CholmodIndex>
    order_last_block(const CholmodMatrix     &K_lower,
                     const std::vector<bool> &is_last,
                     const LastBlockOrdering  ordering,
                     cholmod_common          &common);
  } // namespace linear_algebra
} // namespace dpana

#endif
