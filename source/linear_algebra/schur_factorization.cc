// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/linear_algebra/schur_factorization.h>

namespace dpana
{
  namespace linear_algebra
  {
    CholmodSchurFactorization::CholmodSchurFactorization(
      SparseCholesky &cholesky)
      : cholesky(cholesky)
    {
    }



    void
    CholmodSchurFactorization::factorize(
      const dealii::SparseMatrix<double>      &K,
      const dealii::AffineConstraints<double> &constraints,
      const std::vector<unsigned int>         &gamma_dofs)
    {
      if (gamma_dofs.empty())
        cholesky.factorize(K, constraints);
      else
        cholesky.factorize_with_last(K, constraints, gamma_dofs);
    }



    const std::vector<unsigned int> &
    CholmodSchurFactorization::schur_dofs() const
    {
      return cholesky.schur_dofs();
    }



    void
    CholmodSchurFactorization::solve_schur_factor(Eigen::MatrixXd &W) const
    {
      cholesky.solve_schur_factor(W);
    }



    Eigen::VectorXd
    CholmodSchurFactorization::solve(const Eigen::VectorXd &b) const
    {
      return cholesky.solve(b);
    }



    void
    CholmodSchurFactorization::solve_condensed(
      const dealii::Vector<double> &f_condensed,
      dealii::Vector<double>       &u) const
    {
      cholesky.solve_condensed(f_condensed, u);
    }



    std::string
    CholmodSchurFactorization::name() const
    {
      return "cholmod";
    }
  } // namespace linear_algebra
} // namespace dpana
