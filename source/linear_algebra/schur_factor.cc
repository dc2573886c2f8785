// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The last diagonal block L_22 of a factorisation with unknowns ordered last
// (SparseCholesky::factorize_with_last()): the Cholesky factor of the Schur
// complement on them, read and applied on CHOLMOD's factor itself, on its
// dense supernodes or, for a simplicial factor, column by column.
#include <dpana/linear_algebra/blas.h>
#include <dpana/linear_algebra/sparse_cholesky.h>

#include <algorithm>

namespace dpana
{
  namespace linear_algebra
  {
    namespace
    {
      // The arrays of a simplicial factor: column j holds nz[j] entries
      // from p[j] on, the diagonal first, then rows below it (CHOLMOD's
      // packed, monotonic form of the final L L^T).
      struct SimplicialArrays
      {
        explicit SimplicialArrays(const cholmod_factor &L)
          : p(static_cast<const CholmodIndex *>(L.p))
          , nz(static_cast<const CholmodIndex *>(L.nz))
          , rows(static_cast<const CholmodIndex *>(L.i))
          , x(static_cast<const double *>(L.x))
        {
        }
        const CholmodIndex *p, *nz, *rows;
        const double       *x;
      };



      // The arrays of a supernodal factor: each supernode s holds the
      // columns super[s] .. super[s+1]-1 as a dense column-major block of
      // nsrow = pi[s+1] - pi[s] rows, whose row indices are rows[pi[s] ..]
      // (the supernode's own columns first), from x[px[s]] on.
      struct SupernodalArrays
      {
        explicit SupernodalArrays(const cholmod_factor &L)
          : super(static_cast<const CholmodIndex *>(L.super))
          , pi(static_cast<const CholmodIndex *>(L.pi))
          , px(static_cast<const CholmodIndex *>(L.px))
          , rows(static_cast<const CholmodIndex *>(L.s))
          , x(static_cast<const double *>(L.x))
        {
        }
        const CholmodIndex *super, *pi, *px, *rows;
        const double       *x;
      };



      // The columns n0 .. n - 1 of a simplicial factor. Every row of a
      // column j >= n0 is >= j, hence in the last block (also on the
      // supernodes below).
      void
      read_simplicial(const cholmod_factor &L,
                      const CholmodIndex    n0,
                      Eigen::MatrixXd      &L22)
      {
        const SimplicialArrays F(L);
        for (CholmodIndex j = n0; j < CholmodIndex(L.n); ++j)
          for (CholmodIndex k = F.p[j]; k < F.p[j] + F.nz[j]; ++k)
            L22(F.rows[k] - n0, j - n0) = F.x[k];
      }



      // The columns n0 .. n - 1 of a supernodal factor.
      void
      read_supernodal(const cholmod_factor &L,
                      const CholmodIndex    n0,
                      Eigen::MatrixXd      &L22)
      {
        const SupernodalArrays F(L);
        for (std::size_t s = 0; s < L.nsuper; ++s)
          {
            if (F.super[s + 1] <= n0)
              continue;
            const CholmodIndex nsrow = F.pi[s + 1] - F.pi[s];
            for (CholmodIndex j = std::max(F.super[s], n0); j < F.super[s + 1];
                 ++j)
              {
                const double *column = F.x + F.px[s] + (j - F.super[s]) * nsrow;
                for (CholmodIndex k = j - F.super[s]; k < nsrow; ++k)
                  L22(F.rows[F.pi[s] + k] - n0, j - n0) = column[k];
              }
          }
      }



      // The forward substitution with the columns n0 .. n - 1 of a
      // simplicial factor, one column at a time: the row of W of column j
      // is divided by the diagonal, then its multiples are subtracted from
      // the rows below. A column of W whose first row lies below j is left
      // alone (it vanishes there).
      void
      solve_simplicial(const cholmod_factor   &L,
                       const CholmodIndex      n0,
                       Eigen::MatrixXd        &W,
                       const std::vector<int> &first_rows)
      {
        const SimplicialArrays F(L);
        for (CholmodIndex j = n0; j < CholmodIndex(L.n); ++j)
          {
            const int row = j - n0;
            const int nrhs =
              std::upper_bound(first_rows.begin(), first_rows.end(), row) -
              first_rows.begin();
            for (int c = 0; c < nrhs; ++c)
              {
                double &w = W(row, c);
                w /= F.x[F.p[j]];
                for (CholmodIndex k = F.p[j] + 1; k < F.p[j] + F.nz[j]; ++k)
                  W(F.rows[k] - n0, c) -= F.x[k] * w;
              }
          }
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
      solve_supernodal(const cholmod_factor   &L,
                       const CholmodIndex      n0,
                       Eigen::MatrixXd        &W,
                       const std::vector<int> &first_rows)
      {
        const SupernodalArrays F(L);
        const CholmodIndex    *super = F.super, *pi = F.pi, *px = F.px,
                           *rows = F.rows;
        const double       *x    = F.x;
        const int           ldw  = W.rows();
        const double        one = 1.0, zero = 0.0;
        std::vector<double> update;
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
    } // namespace



    Eigen::MatrixXd
    SparseCholesky::schur_factor() const
    {
      const cholmod_factor &L  = factor();
      const CholmodIndex    n0 = L.n - last.size();
      Eigen::MatrixXd L22 = Eigen::MatrixXd::Zero(last.size(), last.size());
      if (L.is_super)
        read_supernodal(L, n0, L22);
      else
        read_simplicial(L, n0, L22);
      return L22;
    }



    void
    SparseCholesky::solve_schur_factor(Eigen::MatrixXd        &W,
                                       const std::vector<int> &first_rows) const
    {
      AssertDimension(W.rows(), last.size());
      AssertDimension(first_rows.size(), W.cols());
      Assert(std::is_sorted(first_rows.begin(), first_rows.end()),
             dealii::ExcMessage("first_rows must be increasing"));
      const cholmod_factor &L  = factor();
      const CholmodIndex    n0 = L.n - last.size();
      if (L.is_super)
        solve_supernodal(L, n0, W, first_rows);
      else
        solve_simplicial(L, n0, W, first_rows);
    }



    void
    SparseCholesky::solve_schur_factor(Eigen::MatrixXd &W) const
    {
      solve_schur_factor(W, std::vector<int>(W.cols(), 0));
    }



  } // namespace linear_algebra
} // namespace dpana
