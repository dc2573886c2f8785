// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_linear_algebra_blas_h
#define dpana_linear_algebra_blas_h

// The dense level-3 BLAS kernels of the condensation through the Schur
// complement and the LAPACK Cholesky routines of the contact solvers
// (contact::DenseCholesky), declared with the Fortran calling convention of the
// reference BLAS (every argument by address, column-major storage). They are
// called directly rather than through Eigen's own products: Eigen's kernels run
// on one core with the instruction set the library was compiled for (SSE2 for
// a distribution build), while the system BLAS (OpenBLAS on Debian, the
// same library CHOLMOD's supernodal factorisation uses) picks the kernels of
// the processor it runs on and uses every core. On the dense blocks of a 3D
// contact surface (10^4 rows and columns) this is the difference between a
// few and a few tens of GFlop/s.
extern "C"
{
  /// B <- alpha op(A)^-1 B (side L) for triangular A.
  void
  dtrsm_(const char   *side,
         const char   *uplo,
         const char   *transa,
         const char   *diag,
         const int    *m,
         const int    *n,
         const double *alpha,
         const double *a,
         const int    *lda,
         double       *b,
         const int    *ldb);

  /// C <- alpha op(A) op(B) + beta C.
  void
  dgemm_(const char   *transa,
         const char   *transb,
         const int    *m,
         const int    *n,
         const int    *k,
         const double *alpha,
         const double *a,
         const int    *lda,
         const double *b,
         const int    *ldb,
         const double *beta,
         double       *c,
         const int    *ldc);

  /// C <- alpha op(A) op(A)^T + beta C, one triangle of C.
  void
  dsyrk_(const char   *uplo,
         const char   *trans,
         const int    *n,
         const int    *k,
         const double *alpha,
         const double *a,
         const int    *lda,
         const double *beta,
         double       *c,
         const int    *ldc);

  /// LAPACK: the Cholesky factor of a symmetric positive definite A, in
  /// place (one triangle); info > 0 if A is not positive definite.
  void
  dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info);

  /// Single precision: spotrf_, spotrs_ and strsm_ as their d versions.
  void
  spotrf_(const char *uplo, const int *n, float *a, const int *lda, int *info);

  void
  spotrs_(const char  *uplo,
          const int   *n,
          const int   *nrhs,
          const float *a,
          const int   *lda,
          float       *b,
          const int   *ldb,
          int         *info);

  void
  strsm_(const char  *side,
         const char  *uplo,
         const char  *transa,
         const char  *diag,
         const int   *m,
         const int   *n,
         const float *alpha,
         const float *a,
         const int   *lda,
         float       *b,
         const int   *ldb);

  /// LAPACK: B <- A^-1 B with the factor of dpotrf_.
  void
  dpotrs_(const char   *uplo,
          const int    *n,
          const int    *nrhs,
          const double *a,
          const int    *lda,
          double       *b,
          const int    *ldb,
          int          *info);
}

#endif
