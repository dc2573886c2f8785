// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_linear_algebra_schur_factorization_h
#define dpana_linear_algebra_schur_factorization_h

#include <dpana/linear_algebra/sparse_cholesky.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace dpana
{
  namespace linear_algebra
  {
    /**
     * What the condensation of a body needs of a factorisation of its
     * reduced stiffness matrix $K_r$ (see SparseCholesky for the reduction
     * by the constraints): the solves of the load and of the recovery, and
     * the Schur complement of $K_r$ on the unknowns $\Gamma$ of the contact
     * surface.
     *
     * With the unknowns split into the interior $I$ and $\Gamma$,
     * @f[
     *   K_r = \begin{pmatrix} K_{II} & K_{I\Gamma} \\
     *                         K_{\Gamma I} & K_{\Gamma\Gamma} \end{pmatrix},
     *   \qquad
     *   S = K_{\Gamma\Gamma} - K_{\Gamma I} K_{II}^{-1} K_{I\Gamma}
     *     = L_S L_S^T ,
     * @f]
     * and for a right-hand side $B$ that vanishes outside $\Gamma$,
     * $B^T K_r^{-1} B = B_\Gamma^T S^{-1} B_\Gamma = W^T W$ with
     * $W = L_S^{-1} B_\Gamma$. A back end provides $L_S$ only through the
     * triangular solve solve_schur_factor(), so that it may keep it where
     * it computed it: a sparse Cholesky factorisation with $\Gamma$ ordered
     * last holds $L_S$ as the last diagonal block of its factor
     * (CholmodSchurFactorization); a multifrontal solver with a Schur option
     * returns $S$ itself, whose dense Cholesky factor is $L_S$
     * (MumpsSchurFactorization). The two give the same $W^T W$ up to
     * round-off.
     */
    class SchurFactorization
    {
    public:
      virtual ~SchurFactorization() = default;

      /**
       * Factor the reduced matrix $K_r$ on the degrees of freedom that
       * @p constraints leaves free, with the Schur complement on the free
       * degrees of freedom that @p gamma_dofs stand for (the dofs
       * themselves, or the masters of the constrained ones). @p K must have
       * been assembled with these (closed) constraints. Throws
       * NotPositiveDefiniteError if $K_r$ is not positive definite.
       */
      virtual void
      factorize(const dealii::SparseMatrix<double>      &K,
                const dealii::AffineConstraints<double> &constraints,
                const std::vector<unsigned int>         &gamma_dofs) = 0;

      /**
       * The free degrees of freedom of $\Gamma$, in the order of the rows of
       * $S$ and $L_S$.
       */
      virtual const std::vector<unsigned int> &
      schur_dofs() const = 0;

      /**
       * $W \leftarrow L_S^{-1} W$ for @p W of schur_dofs().size() rows, in
       * place.
       */
      virtual void
      solve_schur_factor(Eigen::MatrixXd &W) const = 0;

      /**
       * solve_schur_factor() for a @p W whose column j vanishes in the rows
       * before first_rows[j], @p first_rows increasing. As $L_S$ is lower
       * triangular, W stays zero there; a back end may skip that work. The
       * default ignores @p first_rows.
       */
      virtual void
      solve_schur_factor(Eigen::MatrixXd        &W,
                         const std::vector<int> &first_rows) const
      {
        (void)first_rows;
        solve_schur_factor(W);
      }

      /**
       * $u = M K_r^{-1} M^T b$ for a full-length vector of nodal forces
       * $b$: the displacement that satisfies the homogeneous constraints.
       */
      virtual Eigen::VectorXd
      solve(const Eigen::VectorXd &b) const = 0;

      /**
       * The body's own solve: @p f_condensed holds $M^T(f - K\bar u)$ in its
       * free rows (assembled with the inhomogeneous constraints); on return
       * @p u holds $M K_r^{-1} f_r + \bar u$.
       */
      virtual void
      solve_condensed(const dealii::Vector<double> &f_condensed,
                      dealii::Vector<double>       &u) const = 0;

      /**
       * The name of the back end, for logs and tables.
       */
      virtual std::string
      name() const = 0;
    };



    /**
     * The degrees of freedom of 0..@p n_dofs-1 that @p constraints leaves
     * free, in increasing order (@p free), and for every degree of freedom
     * its index among them, or -1 if it is constrained (@p reduced_index):
     * the unknowns of the reduced matrix $K_r$.
     */
    void
    number_free_dofs(const dealii::AffineConstraints<double> &constraints,
                     const unsigned int                       n_dofs,
                     std::vector<unsigned int>               &free,
                     std::vector<int>                        &reduced_index);

    /**
     * The free unknowns that the degrees of freedom @p dofs stand for: for
     * each of the @p n_free degrees of freedom that @p constraints leaves
     * free (numbered by @p reduced_index: the index of a dof among the free
     * ones, -1 for a constrained one), whether one of @p dofs is that dof
     * or a constrained dof of which it is a master (a dof of a Dirichlet
     * condition without masters stands for none).
     */
    std::vector<bool>
    unknowns_of_dofs(const std::vector<unsigned int>         &dofs,
                     const dealii::AffineConstraints<double> &constraints,
                     const std::vector<int>                  &reduced_index,
                     const unsigned int                       n_free);



    /**
     * The SchurFactorization of CHOLMOD: a SparseCholesky factored with the
     * unknowns of $\Gamma$ ordered last (SparseCholesky::
     * factorize_with_last()), whose last diagonal block is $L_S$. An
     * adapter: it forwards every call to the SparseCholesky it is given,
     * which stays the caller's (and may be used directly, e.g. for blocked
     * solves). With no dofs of $\Gamma$, factorize() is the plain
     * SparseCholesky::factorize(K, constraints).
     */
    class CholmodSchurFactorization : public SchurFactorization
    {
    public:
      explicit CholmodSchurFactorization(SparseCholesky &cholesky);

      void
      factorize(const dealii::SparseMatrix<double>      &K,
                const dealii::AffineConstraints<double> &constraints,
                const std::vector<unsigned int>         &gamma_dofs) override;

      const std::vector<unsigned int> &
      schur_dofs() const override;

      void
      solve_schur_factor(Eigen::MatrixXd &W) const override;

      void
      solve_schur_factor(Eigen::MatrixXd        &W,
                         const std::vector<int> &first_rows) const override;

      Eigen::VectorXd
      solve(const Eigen::VectorXd &b) const override;

      void
      solve_condensed(const dealii::Vector<double> &f_condensed,
                      dealii::Vector<double>       &u) const override;

      std::string
      name() const override;

    private:
      SparseCholesky &cholesky;
    };
  } // namespace linear_algebra
} // namespace dpana

#endif
