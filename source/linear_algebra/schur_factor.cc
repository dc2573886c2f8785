// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The last diagonal block L_22 of a factorisation with unknowns ordered last
// (SparseCholesky::factorize_with_last()): the Cholesky factor of the Schur
// complement on them, read and applied on the supernodes of CHOLMOD's factor.
#include <dpana/linear_algebra/blas.h>
#include <dpana/linear_algebra/sparse_cholesky.h>

#include <algorithm>

namespace dpana
{
  namespace linear_algebra
  {
    // The columns n0 = n - n_last .. n - 1 of the supernodal factor: each
    // supernode s holds the columns super[s] .. super[s+1]-1 as a dense
    // column-major block of nsrow = pi[s+1] - pi[s] rows, whose row indices
    // are s[pi[s] ..] (the supernode's own columns first). Every row of a
    // column j >= n0 is >= j, hence in the last block.
    Eigen::MatrixXd
    SparseCholesky::schur_factor() const
    {
      const cholmod_factor &L     = factor();
      const CholmodIndex    n     = L.n;
      const CholmodIndex    n0    = n - last.size();
      const auto           *super = static_cast<const CholmodIndex *>(L.super);
      const auto           *pi    = static_cast<const CholmodIndex *>(L.pi);
      const auto           *px    = static_cast<const CholmodIndex *>(L.px);
      const auto           *rows  = static_cast<const CholmodIndex *>(L.s);
      const double         *x     = static_cast<const double *>(L.x);

      Eigen::MatrixXd L22 = Eigen::MatrixXd::Zero(last.size(), last.size());
      for (std::size_t s = 0; s < L.nsuper; ++s)
        {
          if (super[s + 1] <= n0)
            continue;
          const CholmodIndex nsrow = pi[s + 1] - pi[s];
          for (CholmodIndex j = std::max(super[s], n0); j < super[s + 1]; ++j)
            {
              const double *column = x + px[s] + (j - super[s]) * nsrow;
              for (CholmodIndex k = j - super[s]; k < nsrow; ++k)
                L22(rows[pi[s] + k] - n0, j - n0) = column[k];
            }
        }
      return L22;
    }



    // The forward substitution with L_22, supernode by supernode of the
    // last block and in place: the rows of W of the supernode's columns are
    // solved with its dense diagonal block (TRSM), then the product of its
    // block below the diagonal with them (GEMM) is subtracted from the rows
    // of W its row indices name. The columns of a supernode that straddles
    // the start n0 of the block and lie before it are skipped: W vanishes
    // on their rows. So are the columns of W that begin after the
    // supernode's last row. Both products are the system BLAS' (blas.h).
    void
    SparseCholesky::solve_schur_factor(Eigen::MatrixXd        &W,
                                       const std::vector<int> &first_rows) const
    {
      AssertDimension(W.rows(), last.size());
      AssertDimension(first_rows.size(), W.cols());
      Assert(std::is_sorted(first_rows.begin(), first_rows.end()),
             dealii::ExcMessage("first_rows must be increasing"));
      const cholmod_factor &L     = factor();
      const CholmodIndex    n0    = L.n - last.size();
      const auto           *super = static_cast<const CholmodIndex *>(L.super);
      const auto           *pi    = static_cast<const CholmodIndex *>(L.pi);
      const auto           *px    = static_cast<const CholmodIndex *>(L.px);
      const auto           *rows  = static_cast<const CholmodIndex *>(L.s);
      const double         *x     = static_cast<const double *>(L.x);
      const int             ldw   = W.rows();
      const double          one = 1.0, zero = 0.0;
      std::vector<double>   update;
      for (std::size_t s = 0; s < L.nsuper; ++s)
        {
          if (super[s + 1] <= n0)
            continue;
          // The sizes of one supernode fit the BLAS' int; its offset px[s]
          // in the factor may not.
          const int          nscol = super[s + 1] - super[s];
          const int          nsrow = pi[s + 1] - pi[s];
          const CholmodIndex first = std::max(super[s], n0);
          const int          k0    = first - super[s];
          const int          ncols = super[s + 1] - first;
          const int          nrhs  = std::upper_bound(first_rows.begin(),
                                            first_rows.end(),
                                            super[s + 1] - 1 - n0) -
                           first_rows.begin();
          if (nrhs == 0)
            continue;
          const double *S  = x + px[s];
          double       *Wd = W.data() + (first - n0);
          dtrsm_("L",
                 "L",
                 "N",
                 "N",
                 &ncols,
                 &nrhs,
                 &one,
                 S + k0 + std::size_t(k0) * nsrow,
                 &nsrow,
                 Wd,
                 &ldw);
          const int nbelow = nsrow - nscol;
          if (nbelow == 0)
            continue;
          update.resize(std::size_t(nbelow) * nrhs);
          dgemm_("N",
                 "N",
                 &nbelow,
                 &nrhs,
                 &ncols,
                 &one,
                 S + nscol + std::size_t(k0) * nsrow,
                 &nsrow,
                 Wd,
                 &ldw,
                 &zero,
                 update.data(),
                 &nbelow);
          const CholmodIndex *below = rows + pi[s] + nscol;
          for (int c = 0; c < nrhs; ++c)
            {
              double       *w = W.data() + std::size_t(c) * ldw - n0;
              const double *u = update.data() + std::size_t(c) * nbelow;
              for (int k = 0; k < nbelow; ++k)
                w[below[k]] -= u[k];
            }
        }
    }



    void
    SparseCholesky::solve_schur_factor(Eigen::MatrixXd &W) const
    {
      solve_schur_factor(W, std::vector<int>(W.cols(), 0));
    }



  } // namespace linear_algebra
} // namespace dpana
