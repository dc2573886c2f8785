// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_linear_algebra_sparse_cholesky_h
#define dpana_linear_algebra_sparse_cholesky_h

#include <dpana/linear_algebra/last_block_ordering.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace dpana
{
  namespace linear_algebra
  {
    /**
     * Thrown when the Cholesky factorisation breaks down because the matrix
     * is not symmetric positive definite. For a stiffness matrix this almost
     * always means that the body is not held: some rigid motion is left free
     * by the constraints.
     */
    class NotPositiveDefiniteError : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    /**
     * A sparse Cholesky factorisation $K = L L^T$ of a symmetric positive
     * definite matrix, computed once by CHOLMOD (SuiteSparse), by its
     * supernodal method or, for a sparse enough factor, its simplicial one
     * (set_factor_kind()), and then used for as many right-hand sides as
     * needed.
     *
     * <h3>Two ways of handling constraints</h3>
     *
     * The stiffness matrix of a body is assembled by deal.II with
     * AffineConstraints::distribute_local_to_global(). Every constrained
     * degree of freedom $u_i = \sum_j a_{ij} u_j + g_i$ is thereby eliminated:
     * writing $u = M v + \bar u$, where $v$ are the unconstrained (free)
     * degrees of freedom, $M$ the matrix of the constraints and $\bar u$ the
     * inhomogeneities, the rows and columns of the free degrees of freedom
     * hold the reduced matrix $K_r = M^T K M$ and the right-hand side holds
     * $f_r = M^T (f - K \bar u)$, while the rows and columns of the
     * constrained degrees of freedom are empty except for a positive
     * diagonal entry.
     *
     * - factorize(K) factors the whole matrix, artificial diagonal entries
     *   included. solve() is then the plain $K^{-1} b$: the caller is
     *   responsible for condensing $b$ and distributing the result.
     *
     * - factorize(K, constraints) extracts the reduced matrix $K_r$ on the
     *   free degrees of freedom only (the constrained rows and columns are
     *   dropped) and factors it. This is the form of the formulation
     *   (@f$A = V_r^T K_r^{-1} V_r@f$): solve(b) then takes a full-length
     *   vector of nodal forces $b$ and returns the full-length displacement
     *   $u = M K_r^{-1} M^T b$ that satisfies the homogeneous constraints
     *   ($\bar u = 0$), which is what a unit contact traction produces.
     *   The reduced quantities themselves are available through restrict(),
     *   solve_reduced() and extend(). The body's own solve, with the
     *   inhomogeneous constraints, is solve_condensed().
     *
     * Dropping the constrained rows rather than keeping their artificial
     * diagonal entries leaves the factor with only physical unknowns, so a
     * breakdown of the factorisation is always a property of the body (a
     * free rigid motion), never of the scaling of the constraints.
     *
     * <h3>Many right-hand sides</h3>
     *
     * solve(const Eigen::MatrixXd &) hands the right-hand sides to CHOLMOD
     * in blocks of block_size() columns: each block is one forward and one
     * backward substitution sweep through the supernodal factor, which is
     * much faster than the same number of single-vector solves because it
     * works with dense matrix-matrix kernels (BLAS 3).
     *
     * <h3>Size</h3>
     *
     * Every call goes through CHOLMOD's 64-bit interface (cholmod_l_*,
     * CholmodIndex): the factor may hold more than $2^{31}$ numbers, as the
     * factor of a 3D body of $10^6$ degrees of freedom with $10^4$ surface
     * unknowns ordered last does. Its row indices take 8 bytes each.
     */
    class SparseCholesky
    {
    public:
      SparseCholesky();
      ~SparseCholesky();
      SparseCholesky(const SparseCholesky &) = delete;
      SparseCholesky &
      operator=(const SparseCholesky &) = delete;

      /**
       * What CHOLMOD's symbolic analysis tells of the factorisation before
       * it is computed.
       */
      struct Analysis
      {
        /// Unknowns factored.
        unsigned int n_unknowns = 0;
        /// Unknowns of the last block (0 without factorize_with_last()).
        unsigned int n_last = 0;
        /// Whether the factor is supernodal (else simplicial).
        bool supernodal = true;
        /// Numbers the factor stores (a supernodal one: its dense
        /// supernodes, zeros of the amalgamation included): 8 bytes each.
        double factor_entries = 0;
        /// Row indices the factor stores (a supernodal one: one per row of
        /// each supernode): 8 bytes each in CHOLMOD's 64-bit interface.
        double factor_indices = 0;
        /// Numbers of the largest dense update matrix of a supernode, the
        /// workspace the numerical factorisation allocates on top of the
        /// factor: 8 bytes each.
        double largest_update = 0;
        /// Entries of the lower triangle handed to CHOLMOD (the numerical
        /// factorisation makes a permuted copy of it: 16 bytes each).
        double matrix_entries = 0;
        /// Nonzeros of L proper (without the amalgamation's zeros).
        double factor_nonzeros = 0;
        /// Floating point operations of the factorisation.
        double factor_flops = 0;
        /// The ordering: "CHOLMOD", to_string(LastBlockOrdering), or
        /// "automatic: " followed by the one the automatic choice took.
        std::string ordering;
      };

      /**
       * Factor the whole matrix @p K. Only its lower triangle is read; the
       * matrix must be symmetric. Throws NotPositiveDefiniteError if it is
       * not positive definite.
       */
      void
      factorize(const dealii::SparseMatrix<double> &K);

      /**
       * Factor an Eigen sparse matrix (lower triangle read).
       */
      void
      factorize(const Eigen::SparseMatrix<double> &K);

      /**
       * Factor the reduced matrix $K_r$ on the degrees of freedom that
       * @p constraints leaves free. @p K must have been assembled with these
       * (closed) constraints. The constraints are copied.
       */
      void
      factorize(const dealii::SparseMatrix<double>      &K,
                const dealii::AffineConstraints<double> &constraints);

      /**
       * Factor $K_r$ as factorize(K, constraints) does, with the free
       * degrees of freedom that @p last_dofs stand for (the dofs themselves,
       * or the masters of the constrained ones) ordered last: the ordering
       * is $P = $ [CHOLMOD's fill-reducing ordering of the other unknowns,
       * then these]. With $K_r = P^T L L^T P$, the last diagonal block
       * $L_{22}$ of $L$ ($n_\Gamma \times n_\Gamma$) is then the Cholesky
       * factor of the Schur complement of $K_r$ on these unknowns, and for a
       * right-hand side $B$ that vanishes outside them,
       * $B^T K_r^{-1} B = W^T W$ with $W = L_{22}^{-1} B_\Gamma$.
       *
       * This, solve_schur_factor() and schur_dofs() are what the Schur route
       * of the condensation needs of a factorisation; another back end (a
       * multifrontal solver with a Schur option, which returns the Schur
       * complement itself: its dense Cholesky factor then plays the part of
       * $L_{22}$) provides the same three.
       */
      void
      factorize_with_last(const dealii::SparseMatrix<double>      &K,
                          const dealii::AffineConstraints<double> &constraints,
                          const std::vector<unsigned int>         &last_dofs);

      /**
       * The ordering factorize_with_last() uses (default: automatic, the
       * minimum degree ordering where CHOLMOD's test finds it good, the
       * nested dissection of the interior otherwise; LastBlockOrdering
       * documents the choices; benchmarks/condensation compares them).
       */
      void
      set_last_block_ordering(const LastBlockOrdering ordering);

      /**
       * How CHOLMOD computes the factor: automatic (default) is CHOLMOD's
       * own rule, simplicial where the analysis counts fewer than 40 flops
       * per nonzero of the factor (the small bodies), supernodal otherwise.
       * The other two force one method (for tests and measurements).
       */
      enum class FactorKind
      {
        automatic,
        supernodal,
        simplicial
      };

      void
      set_factor_kind(const FactorKind kind);

      /**
       * A function called after the symbolic analysis of every
       * factorisation and before the numerical one, with what the analysis
       * found. It may throw to stop before the expensive part (the memory
       * estimate of a contact run does).
       */
      void
      set_analysis_check(std::function<void(const Analysis &)> check);

      /**
       * The symbolic analysis of the last factorisation.
       */
      const Analysis &
      analysis() const;

      /**
       * The dense lower triangular $L_{22}$ of factorize_with_last(): row
       * and column k belong to the degree of freedom schur_dofs()[k]. A
       * copy of $n_\Gamma^2$ numbers, for checks; the condensation uses
       * solve_schur_factor().
       */
      Eigen::MatrixXd
      schur_factor() const;

      /**
       * $W \leftarrow L_{22}^{-1} W$ for @p W of n_Gamma rows (in the order
       * of schur_dofs()), in place, working on the factor itself (no copy
       * of $L_{22}$): on its supernodes, or column by column of a simplicial
       * factor.
       */
      void
      solve_schur_factor(Eigen::MatrixXd &W) const;

      /**
       * solve_schur_factor() for a @p W whose column j vanishes in the rows
       * before first_rows[j], @p first_rows increasing: a supernode of
       * $L_{22}$ then only works on the columns that have begun by its last
       * row (W stays zero above first_rows[j], as $L_{22}$ is lower
       * triangular). For columns spread evenly over the rows this does a
       * third of the work of the full solve.
       */
      void
      solve_schur_factor(Eigen::MatrixXd        &W,
                         const std::vector<int> &first_rows) const;

      /**
       * The free degrees of freedom of the last block, in the order of the
       * rows of schur_factor().
       */
      const std::vector<unsigned int> &
      schur_dofs() const;

      /**
       * True once a factorisation is available.
       */
      bool
      is_factorized() const;

      /**
       * True if the factorisation is of a reduced system.
       */
      bool
      is_reduced() const;

      /**
       * Length of the vectors taken and returned by solve(): the number of
       * rows of the matrix handed to factorize().
       */
      unsigned int
      size() const;

      /**
       * Number of unknowns actually factored: the free degrees of freedom of
       * a reduced system, otherwise size().
       */
      unsigned int
      n_unknowns() const;

      /**
       * The free degrees of freedom, in the order of the reduced unknowns
       * (all of 0..size()-1 when the system is not reduced).
       */
      const std::vector<unsigned int> &
      free_dofs() const;

      /**
       * Number of right-hand sides handed to CHOLMOD at once (default 64).
       */
      void
      set_block_size(const unsigned int block_size);
      unsigned int
      block_size() const;

      /**
       * Solve for one right-hand side of length size(). For a reduced
       * system, $b$ is a vector of nodal forces and the result satisfies the
       * homogeneous constraints (see the class documentation).
       */
      Eigen::VectorXd
      solve(const Eigen::VectorXd &b) const;

      /**
       * Solve for the columns of @p B (size() rows), in blocks of
       * block_size() columns.
       */
      Eigen::MatrixXd
      solve(const Eigen::MatrixXd &B) const;

      /**
       * $M^T B$: fold the rows of constrained degrees of freedom into their
       * masters and keep the free rows (n_unknowns() rows result).
       */
      Eigen::MatrixXd restrict(const Eigen::MatrixXd &B) const;

      /**
       * $K_r^{-1} B_r$ for reduced right-hand sides (n_unknowns() rows), in
       * blocks.
       */
      Eigen::MatrixXd
      solve_reduced(const Eigen::MatrixXd &B_r) const;

      /**
       * $M X_r$ (+ $\bar u$ in every column unless @p homogeneous): fill the
       * free rows from @p X_r and compute the constrained ones.
       */
      Eigen::MatrixXd
      extend(const Eigen::MatrixXd &X_r, const bool homogeneous = true) const;

      /**
       * The body's own solve of a reduced system: @p f_condensed is the
       * right-hand side assembled with the (inhomogeneous) constraints, so it
       * already holds $M^T(f - K\bar u)$ in its free rows. On return @p u
       * holds $M K_r^{-1} f_r + \bar u$.
       */
      void
      solve_condensed(const dealii::Vector<double> &f_condensed,
                      dealii::Vector<double>       &u) const;

    private:
      /**
       * Number the free degrees of freedom, copy the constraint lines and
       * return the lower triangle of $K_r$.
       */
      CholmodMatrix
      reduce(const dealii::SparseMatrix<double>      &K,
             const dealii::AffineConstraints<double> &constraints);

      void
      factorize_lower(const CholmodMatrix &K_lower);

      /**
       * CHOLMOD's supernodal factor of factorize_with_last().
       */
      const cholmod_factor &
      factor() const;

      /**
       * Analyse again with the unknowns of #last at the end.
       */
      void
      order_last(const CholmodMatrix &K_lower);

      /**
       * CHOLMOD's symbolic analysis with the ordering @p ordering (not
       * automatic) of the unknowns, those with @p is_last last.
       */
      void
      analyze_with(const CholmodMatrix     &K_lower,
                   const std::vector<bool> &is_last,
                   const LastBlockOrdering  ordering);

      /**
       * Keeps the analysis of the last analyze_with() (made with
       * @p ordering) and the order of the last block's unknowns in it.
       */
      void
      record_analysis(const LastBlockOrdering ordering);

      struct Impl;
      std::unique_ptr<Impl> impl;

      unsigned int              n_rows;
      unsigned int              n_block;
      std::vector<unsigned int> free;

      // For every degree of freedom, its index among the free ones, or -1
      // if it is constrained.
      std::vector<int> reduced_index;

      // The constraint lines, copied: u_i = sum_j a_ij u_j + g_i, with all j
      // free (the constraints are closed).
      struct Line
      {
        unsigned int                                 index;
        std::vector<std::pair<unsigned int, double>> entries;
        double                                       inhomogeneity;
      };
      std::vector<Line> lines;

      // The reduced unknowns to be ordered last (empty: CHOLMOD's ordering),
      // and their degrees of freedom in the order of the factor.
      std::vector<unsigned int> last;
      std::vector<unsigned int> schur;
      LastBlockOrdering         last_ordering;
    };
  } // namespace linear_algebra
} // namespace dpana

#endif
