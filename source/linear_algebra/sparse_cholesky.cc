// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/linear_algebra/blas_threads.h>
#include <dpana/linear_algebra/schur_factorization.h>
#include <dpana/linear_algebra/sparse_cholesky.h>

#include <algorithm>
#include <sstream>

#include "sparse_cholesky_impl.h"

namespace dpana
{
  namespace linear_algebra
  {
    namespace
    {
      // The lower triangle of the rows and columns i of K with index[i] >= 0,
      // renumbered to index[i] (increasing with i), in compressed columns,
      // without explicit zeros. Column c of the lower triangle holds the
      // entries (r, c), r >= c, of the rows r: the rows are visited in
      // increasing order, so each column receives its row indices sorted,
      // and the matrix is built in two passes without a sort.
      CholmodMatrix
      lower_triangle(const dealii::SparseMatrix<double> &K,
                     const std::vector<int>             &index,
                     const std::size_t                   n)
      {
        const auto for_each_entry = [&](const auto &visit) {
          for (unsigned int row = 0; row < K.m(); ++row)
            if (index[row] >= 0)
              for (auto it = K.begin(row); it != K.end(row); ++it)
                {
                  const int c = index[it->column()];
                  if (c >= 0 && c <= index[row] && it->value() != 0.0)
                    visit(index[row], c, it->value());
                }
        };
        CholmodMatrix             K_lower(n, n);
        std::vector<CholmodIndex> next(n + 1, 0);
        for_each_entry([&](int, const int c, double) { ++next[c + 1]; });
        for (std::size_t c = 0; c < n; ++c)
          next[c + 1] += next[c];
        K_lower.resizeNonZeros(next[n]);
        std::copy(next.begin(), next.end(), K_lower.outerIndexPtr());
        for_each_entry([&](const int r, const int c, const double value) {
          K_lower.innerIndexPtr()[next[c]] = r;
          K_lower.valuePtr()[next[c]++]    = value;
        });
        return K_lower;
      }
    } // namespace


    SparseCholesky::SparseCholesky()
      : impl(std::make_unique<Impl>())
      , n_rows(0)
      , n_block(64)
      , last_ordering(LastBlockOrdering::automatic)
    {
      // CHOLMOD prints its warnings (e.g. "not positive definite") itself
      // unless told not to; dpana reports them through exceptions instead.
      impl->llt.cholmod().print = 0;
      // The supernodal or the simplicial method by CHOLMOD's own rule
      // (set_factor_kind()). Both end as L L^T: the simplicial factor is
      // converted to it, packed and with its columns in order (final_asis
      // off; a supernodal factor is L L^T already).
      set_factor_kind(FactorKind::automatic);
      cholmod_common &c = impl->llt.cholmod();
      c.final_asis      = 0;
      c.final_ll        = 1;
      c.final_pack      = 1;
      c.final_monotonic = 1;
    }



    SparseCholesky::~SparseCholesky() = default;



    void
    SparseCholesky::factorize(const dealii::SparseMatrix<double> &K)
    {
      AssertThrow(K.m() == K.n(), dealii::ExcNotQuadratic());
      n_rows = K.m();
      free.resize(n_rows);
      for (unsigned int i = 0; i < n_rows; ++i)
        free[i] = i;
      reduced_index.assign(n_rows, 0);
      for (unsigned int i = 0; i < n_rows; ++i)
        reduced_index[i] = i;
      lines.clear();
      last.clear();

      factorize_lower(lower_triangle(K, reduced_index, n_rows));
    }



    void
    SparseCholesky::factorize(const Eigen::SparseMatrix<double> &K)
    {
      AssertThrow(K.rows() == K.cols(), dealii::ExcNotQuadratic());
      n_rows = K.rows();
      free.resize(n_rows);
      reduced_index.resize(n_rows);
      for (unsigned int i = 0; i < n_rows; ++i)
        free[i] = reduced_index[i] = i;
      lines.clear();
      last.clear();
      const CholmodMatrix K_lower = K.triangularView<Eigen::Lower>();
      factorize_lower(K_lower);
    }



    void
    SparseCholesky::factorize(
      const dealii::SparseMatrix<double>      &K,
      const dealii::AffineConstraints<double> &constraints)
    {
      last.clear();
      factorize_lower(reduce(K, constraints));
    }



    CholmodMatrix
    SparseCholesky::reduce(const dealii::SparseMatrix<double>      &K,
                           const dealii::AffineConstraints<double> &constraints)
    {
      AssertThrow(K.m() == K.n(), dealii::ExcNotQuadratic());
      AssertThrow(constraints.is_closed(),
                  dealii::ExcMessage(
                    "SparseCholesky: the constraints must be closed."));
      n_rows = K.m();

      // Number the free degrees of freedom consecutively and copy the
      // constraint lines.
      number_free_dofs(constraints, n_rows, free, reduced_index);
      lines.clear();
      for (const auto &line : constraints.get_lines())
        {
          AssertThrow(line.index < n_rows, dealii::ExcInternalError());
          Line l;
          l.index         = line.index;
          l.inhomogeneity = line.inhomogeneity;
          for (const auto &entry : line.entries)
            {
              // Closed constraints refer to free degrees of freedom only.
              Assert(reduced_index[entry.first] >= 0,
                     dealii::ExcInternalError());
              l.entries.emplace_back(entry.first, entry.second);
            }
          lines.push_back(std::move(l));
        }

      // The reduced matrix: the free rows and columns of the condensed
      // matrix, lower triangle.
      return lower_triangle(K, reduced_index, free.size());
    }



    void
    SparseCholesky::factorize_lower(const CholmodMatrix &K_lower)
    {
      impl->factorized = false;
      AssertThrow(K_lower.rows() > 0,
                  dealii::ExcMessage(
                    "SparseCholesky: there is nothing to factor (no free "
                    "degrees of freedom)."));
      schur.clear();
      if (last.empty())
        {
          impl->llt.analyzePattern(K_lower);
          AssertThrow(impl->llt.info() == Eigen::Success,
                      dealii::ExcMessage(
                        "SparseCholesky: CHOLMOD's symbolic analysis failed."));
          impl->analysis          = impl->llt.analysis();
          impl->analysis.ordering = "CHOLMOD";
        }
      else
        order_last(K_lower);
      impl->analysis.matrix_entries = K_lower.nonZeros();
      if (impl->check)
        impl->check(impl->analysis);
      // CHOLMOD's OpenMP loops on this thread (blas_threads.h).
      serial_openmp_regions();
      impl->llt.factorize(K_lower);
      if (impl->llt.info() != Eigen::Success)
        internal::throw_if_too_large(impl->llt.cholmod().status,
                                     K_lower.rows());
      if (impl->llt.info() != Eigen::Success)
        {
          std::ostringstream message;
          message << "sparse Cholesky factorisation failed: the matrix ("
                  << K_lower.rows()
                  << " unknowns) is not positive definite (breakdown at "
                     "pivot "
                  << impl->llt.failed_column()
                  << "); a stiffness matrix is singular when the body is "
                     "not held against rigid motions";
          throw NotPositiveDefiniteError(message.str());
        }
      impl->factorized = true;
    }



    void
    SparseCholesky::set_factor_kind(const FactorKind kind)
    {
      impl->llt.cholmod().supernodal =
        kind == FactorKind::automatic  ? CHOLMOD_AUTO :
        kind == FactorKind::supernodal ? CHOLMOD_SUPERNODAL :
                                         CHOLMOD_SIMPLICIAL;
    }



    void
    SparseCholesky::set_last_block_ordering(const LastBlockOrdering ordering)
    {
      last_ordering = ordering;
    }



    void
    SparseCholesky::set_analysis_check(
      std::function<void(const Analysis &)> check)
    {
      impl->check = std::move(check);
    }



    const SparseCholesky::Analysis &
    SparseCholesky::analysis() const
    {
      return impl->analysis;
    }



    const std::vector<unsigned int> &
    SparseCholesky::schur_dofs() const
    {
      return schur;
    }



    bool
    SparseCholesky::is_factorized() const
    {
      return impl->factorized;
    }



    bool
    SparseCholesky::is_reduced() const
    {
      return free.size() != n_rows || !lines.empty();
    }



    unsigned int
    SparseCholesky::size() const
    {
      return n_rows;
    }



    unsigned int
    SparseCholesky::n_unknowns() const
    {
      return free.size();
    }



    const std::vector<unsigned int> &
    SparseCholesky::free_dofs() const
    {
      return free;
    }



    void
    SparseCholesky::set_block_size(const unsigned int block_size)
    {
      AssertThrow(block_size > 0,
                  dealii::ExcMessage("The block size must be positive."));
      n_block = block_size;
    }



    unsigned int
    SparseCholesky::block_size() const
    {
      return n_block;
    }



    Eigen::MatrixXd SparseCholesky::restrict(const Eigen::MatrixXd &B) const
    {
      AssertDimension(B.rows(), n_rows);
      Eigen::MatrixXd B_r(free.size(), B.cols());
      for (unsigned int k = 0; k < free.size(); ++k)
        B_r.row(k) = B.row(free[k]);
      // (M^T b)_j = b_j + sum over constrained i with entry a_ij of a_ij b_i.
      for (const Line &line : lines)
        for (const auto &[j, a] : line.entries)
          B_r.row(reduced_index[j]) += a * B.row(line.index);
      return B_r;
    }



    Eigen::MatrixXd
    SparseCholesky::solve_reduced(const Eigen::MatrixXd &B_r) const
    {
      AssertThrow(impl->factorized,
                  dealii::ExcMessage("SparseCholesky: factorize() first."));
      AssertDimension(B_r.rows(), free.size());
      Eigen::MatrixXd X_r(B_r.rows(), B_r.cols());
      for (Eigen::Index j = 0; j < B_r.cols(); j += n_block)
        {
          const Eigen::Index width =
            std::min<Eigen::Index>(n_block, B_r.cols() - j);
          X_r.middleCols(j, width) = impl->llt.solve(B_r.middleCols(j, width));
        }
      return X_r;
    }



    Eigen::MatrixXd
    SparseCholesky::extend(const Eigen::MatrixXd &X_r,
                           const bool             homogeneous) const
    {
      AssertDimension(X_r.rows(), free.size());
      Eigen::MatrixXd X = Eigen::MatrixXd::Zero(n_rows, X_r.cols());
      for (unsigned int k = 0; k < free.size(); ++k)
        X.row(free[k]) = X_r.row(k);
      for (const Line &line : lines)
        {
          if (!homogeneous)
            X.row(line.index).setConstant(line.inhomogeneity);
          for (const auto &[j, a] : line.entries)
            X.row(line.index) += a * X.row(j);
        }
      return X;
    }



    Eigen::VectorXd
    SparseCholesky::solve(const Eigen::VectorXd &b) const
    {
      const Eigen::MatrixXd X = solve(Eigen::MatrixXd(b));
      return X.col(0);
    }



    Eigen::MatrixXd
    SparseCholesky::solve(const Eigen::MatrixXd &B) const
    {
      AssertDimension(B.rows(), n_rows);
      if (!is_reduced())
        return solve_reduced(B);
      return extend(solve_reduced(restrict(B)), true);
    }



    void
    SparseCholesky::solve_condensed(const dealii::Vector<double> &f_condensed,
                                    dealii::Vector<double>       &u) const
    {
      AssertDimension(f_condensed.size(), n_rows);
      // The condensed right-hand side already is M^T (f - K u_bar) in its
      // free rows: gather them, solve, and extend with the inhomogeneities.
      Eigen::MatrixXd f_r(free.size(), 1);
      for (unsigned int k = 0; k < free.size(); ++k)
        f_r(k, 0) = f_condensed[free[k]];
      const Eigen::MatrixXd x = extend(solve_reduced(f_r), false);
      u.reinit(n_rows);
      for (unsigned int i = 0; i < n_rows; ++i)
        u[i] = x(i, 0);
    }
  } // namespace linear_algebra
} // namespace dpana
