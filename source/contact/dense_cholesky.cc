#include <dpana/contact/dense_cholesky.h>
#include <dpana/linear_algebra/blas.h>

#include <climits>
#include <stdexcept>
#include <type_traits>

// OpenBLAS' thread count; weak, so that another system BLAS without them
// links as well (the calls are then skipped).
extern "C"
{
  void
  openblas_set_num_threads(int) __attribute__((weak));
  int
  openblas_get_num_threads() __attribute__((weak));

  // LAPACK: the inverse of a symmetric positive definite matrix from the
  // factor of dpotrf_ (only the triangle uplo of the result is written).
  void
  dpotri_(const char *uplo, const int *n, double *a, const int *lda, int *info);
}

namespace dpana
{
  namespace contact
  {
    namespace
    {
      int
      as_int(const Eigen::Index n)
      {
        return static_cast<int>(std::min<Eigen::Index>(n, INT_MAX));
      }



      // BLAS' triangular solve in the precision of Scalar.
      template <typename Scalar>
      constexpr auto
      trsm()
      {
        if constexpr (std::is_same_v<Scalar, float>)
          return &strsm_;
        else
          return &dtrsm_;
      }



      // R <- L^{-1} R or L^{-T} R (BLAS trsm) with the lower triangle L of
      // @p factor, in the precision of its scalars.
      template <typename Scalar>
      void
      lower_triangular_solve(
        const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> &factor,
        const bool                                                   transpose,
        Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>       &R)
      {
        const int    n = as_int(factor.rows()), k = as_int(R.cols());
        const Scalar one   = 1;
        const char  *trans = transpose ? "T" : "N";
        trsm<Scalar>()(
          "L", "L", trans, "N", &n, &k, &one, factor.data(), &n, R.data(), &n);
      }



      // OpenBLAS on one thread for the blocks below 1024 rows (restored at
      // the end of the scope): there the threads' start and synchronisation
      // cost more than they save, and on a machine with more runnable jobs
      // than cores a factorisation of a few hundred rows took up to ten
      // times longer on two threads than on one.
      class ThreadsForSize
      {
      public:
        explicit ThreadsForSize(const Eigen::Index rows)
        {
          if (rows < 1024 && openblas_set_num_threads &&
              openblas_get_num_threads)
            {
              saved = openblas_get_num_threads();
              if (saved > 1)
                openblas_set_num_threads(1);
            }
        }

        ~ThreadsForSize()
        {
          if (saved > 1)
            openblas_set_num_threads(saved);
        }

      private:
        int saved = 0;
      };
    } // namespace



    bool
    DenseCholesky::compute(const Eigen::MatrixXd &H)
    {
      if (H.rows() < small)
        {
          single = false;
          factor.resize(0, 0);
          llt.compute(H);
          ok = (llt.info() == Eigen::Success);
          return ok;
        }
      factor = H;
      return factor_in_place();
    }



    bool
    DenseCholesky::compute(Eigen::MatrixXd &&H)
    {
      if (H.rows() < small)
        return compute(static_cast<const Eigen::MatrixXd &>(H));
      factor = std::move(H);
      return factor_in_place();
    }



    bool
    DenseCholesky::factor_in_place()
    {
      const ThreadsForSize threads(factor.rows());
      const int            n    = as_int(factor.rows());
      int                  info = 0;
      single                    = factor.rows() >= single_precision_size;
      if (single)
        {
          factor_single = factor.cast<float>();
          spotrf_("L", &n, factor_single.data(), &n, &info);
          if (info == 0)
            {
              factor.resize(0, 0);
              ok = true;
              return ok;
            }
          single = false;
          factor_single.resize(0, 0);
        }
      dpotrf_("L", &n, factor.data(), &n, &info);
      ok = (info == 0);
      return ok;
    }



    void
    DenseCholesky::solve_in_place(Eigen::MatrixXd &R) const
    {
      if (R.size() == 0)
        return;
      if (uses_eigen())
        {
          for (Eigen::Index j = 0; j < R.cols(); ++j)
            llt.solveInPlace(R.col(j));
          return;
        }
      const ThreadsForSize threads(rows());
      const int            n = as_int(rows()), k = as_int(R.cols());
      int                  info = 0;
      if (single)
        {
          Eigen::MatrixXf Rs = R.cast<float>();
          spotrs_("L", &n, &k, factor_single.data(), &n, Rs.data(), &n, &info);
          R = Rs.cast<double>();
        }
      else
        dpotrs_("L", &n, &k, factor.data(), &n, R.data(), &n, &info);
    }



    Eigen::MatrixXd
    DenseCholesky::solve(const Eigen::MatrixXd &R) const
    {
      Eigen::MatrixXd X = R;
      solve_in_place(X);
      return X;
    }



    Eigen::VectorXd
    DenseCholesky::solve(const Eigen::VectorXd &r) const
    {
      Eigen::MatrixXd X = r;
      solve_in_place(X);
      return X.col(0);
    }



    Eigen::MatrixXd
    DenseCholesky::inverse() const
    {
      if (single)
        throw std::logic_error(
          "DenseCholesky::inverse() needs a factor in double precision");
      if (factor.size() == 0)
        {
          const Eigen::Index n = llt.matrixLLT().rows();
          Eigen::MatrixXd    X = Eigen::MatrixXd::Identity(n, n);
          solve_in_place(X);
          return 0.5 * (X + X.transpose()); // symmetric in full
        }
      Eigen::MatrixXd      X = factor;
      const ThreadsForSize threads(X.rows());
      const int            n    = as_int(X.rows());
      int                  info = 0;
      dpotri_("L", &n, X.data(), &n, &info);
      // dpotri writes the lower triangle; mirror it.
      for (Eigen::Index c = 1; c < X.cols(); ++c)
        for (Eigen::Index a = 0; a < c; ++a)
          X(a, c) = X(c, a);
      return X;
    }



    void
    DenseCholesky::solve_lower_in_place(Eigen::MatrixXd &R) const
    {
      triangular_solve(R, false);
    }



    void
    DenseCholesky::solve_upper_in_place(Eigen::MatrixXd &R) const
    {
      triangular_solve(R, true);
    }



    void
    DenseCholesky::triangular_solve(Eigen::MatrixXd &R,
                                    const bool       transpose) const
    {
      if (R.size() == 0)
        return;
      if (uses_eigen())
        {
          for (Eigen::Index j = 0; j < R.cols(); ++j)
            if (transpose)
              llt.matrixU().solveInPlace(R.col(j));
            else
              llt.matrixL().solveInPlace(R.col(j));
          return;
        }
      const ThreadsForSize threads(rows());
      if (single)
        {
          Eigen::MatrixXf Rs = R.cast<float>();
          lower_triangular_solve(factor_single, transpose, Rs);
          R = Rs.cast<double>();
        }
      else
        lower_triangular_solve(factor, transpose, R);
    }
  } // namespace contact
} // namespace dpana
