// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/linear_algebra/schur_factorization.h>

namespace dpana
{
  namespace linear_algebra
  {
    void
    number_free_dofs(const dealii::AffineConstraints<double> &constraints,
                     const unsigned int                       n_dofs,
                     std::vector<unsigned int>               &free,
                     std::vector<int>                        &reduced_index)
    {
      reduced_index.assign(n_dofs, -1);
      free.clear();
      for (unsigned int i = 0; i < n_dofs; ++i)
        if (!constraints.is_constrained(i))
          {
            reduced_index[i] = free.size();
            free.push_back(i);
          }
    }



    std::vector<bool>
    unknowns_of_dofs(const std::vector<unsigned int>         &dofs,
                     const dealii::AffineConstraints<double> &constraints,
                     const std::vector<int>                  &reduced_index,
                     const unsigned int                       n_free)
    {
      std::vector<bool> result(n_free, false);
      for (const unsigned int i : dofs)
        {
          AssertIndexRange(i, reduced_index.size());
          if (reduced_index[i] >= 0)
            result[reduced_index[i]] = true;
          else
            for (const auto &[j, a] : *constraints.get_constraint_entries(i))
              result[reduced_index[j]] = true;
        }
      return result;
    }



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



    void
    CholmodSchurFactorization::solve_schur_factor(
      Eigen::MatrixXd        &W,
      const std::vector<int> &first_rows) const
    {
      cholesky.solve_schur_factor(W, first_rows);
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
