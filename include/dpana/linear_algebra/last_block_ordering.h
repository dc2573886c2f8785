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
      interior_nested_dissection,
      /**
       * CHOLMOD's own default strategy (nmethods = 0, cholmod_core.h) with
       * $\Gamma$ last: constrained_amd first, kept when
       * minimum_degree_suffices() says its factor is good; otherwise
       * interior_nested_dissection. In 2D, and in 3D bodies of a few
       * thousand unknowns, the minimum degree ordering takes less time than
       * METIS (0.2 to 0.3 s for 10^5 unknowns in 2D) and its factor is at
       * most a third larger; in larger 3D bodies the nested dissection's
       * factor is smaller by a factor of 1.4 to 2.3
       * (benchmarks/condensation).
       */
      automatic
    };

    /**
     * The name of @p ordering as the parameter files and the logs spell it:
     * "moved last", "constrained AMD", "interior nested dissection",
     * "automatic".
     */
    std::string
    to_string(const LastBlockOrdering ordering);

    /**
     * CHOLMOD's test of a minimum degree ordering (cholmod_core.h, the
     * documentation of Common->nmethods): the ordering is good, and no
     * nested dissection is tried, when the factorisation costs fewer than
     * 500 flops per entry of the factor or the factor has fewer than 5
     * times the entries of the lower triangle of the matrix.
     */
    bool
    minimum_degree_suffices(const double flops,
                            const double factor_nonzeros,
                            const double matrix_entries);

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
