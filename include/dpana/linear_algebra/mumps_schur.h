// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_linear_algebra_mumps_schur_h
#define dpana_linear_algebra_mumps_schur_h

#include <dpana/linear_algebra/last_block_ordering.h>
#include <dpana/linear_algebra/schur_factorization.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <mpi.h>

namespace dpana
{
  namespace linear_algebra
  {
    /**
     * The SchurFactorization of MUMPS (the multifrontal solver of Amestoy,
     * Duff, L'Excellent and Koster, SIAM J. Matrix Anal. Appl. 23, 2001),
     * reached through PETSc.
     *
     * <h3>Factorisation</h3>
     *
     * The upper triangle of the reduced matrix $K_r$ (see SparseCholesky for
     * the reduction by the constraints) is handed to PETSc as a sequential
     * symmetric matrix (MATSEQSBAIJ, marked positive definite) and factored
     * by MUMPS' $LL^T$ (MatGetFactor with MATSOLVERMUMPS,
     * MAT_FACTOR_CHOLESKY) with the unknowns of $\Gamma$ as the Schur
     * index set (MatFactorSetSchurIS, MUMPS' ICNTL(19)): MUMPS eliminates
     * the interior unknowns $I$ with a fill-reducing ordering (below) and
     * returns the dense Schur complement
     * $S = K_{\Gamma\Gamma} - K_{\Gamma I} K_{II}^{-1} K_{I\Gamma}$.
     * Its dense Cholesky factor $S = L_S L_S^T$ (LAPACK potrf) then serves
     * solve_schur_factor() (LAPACK trtrs).
     *
     * <h3>Ordering</h3>
     *
     * Asked for a Schur complement, the MUMPS of Debian 12 (5.5, built
     * without METIS and SCOTCH) orders the interior by approximate minimum
     * degree, whose fronts and flops grow much faster than those of a
     * nested dissection on 3D meshes (doc/parallel.md). PETSc cannot hand
     * MUMPS an ordering for a Cholesky factorisation. After set_ordering()
     * with an ordering, a factorisation therefore calls MUMPS through its
     * own C interface (dmumps_c, on the same communicator) with the
     * ordering of SparseCholesky (order_last_block(), $\Gamma$ last) as
     * its user ordering (ICNTL(7) = 1, which MUMPS keeps with a Schur
     * complement): the same Schur complement, interior solves and out-of-
     * core factor. The matrix is still assembled in PETSc, which serves
     * the products with it; each rank hands MUMPS the rows of it that it
     * owns (MUMPS' distributed input, ICNTL(18) = 3), and rank 0 computes
     * the ordering on the pattern of the whole matrix, gathered there.
     * MUMPS' analysis is sequential on rank 0 in either case.
     *
     * <h3>Solves</h3>
     *
     * The factor of MUMPS covers $K_{II}$ only: a solve with it (MatSolve,
     * MUMPS' ICNTL(26) = 0) returns $K_{II}^{-1} b_I$ and zero on $\Gamma$.
     * A solve with $K_r$ is composed of two of them and one with $S$:
     * @f[
     *   x_\Gamma = S^{-1}\left(b_\Gamma - K_{\Gamma I} K_{II}^{-1} b_I\right),
     *   \qquad
     *   x_I = K_{II}^{-1}\left(b_I - K_{I\Gamma} x_\Gamma\right),
     * @f]
     * the products with the off-diagonal blocks taken as products with
     * $K_r$ of vectors that vanish on $\Gamma$ or on $I$. solve() and
     * solve_condensed() fold and extend by the constraints as the
     * corresponding functions of SparseCholesky do, through the
     * AffineConstraints themselves (condense() and distribute()).
     *
     * <h3>PETSc</h3>
     *
     * PETSc must be initialised before the first factorize(): deal.II's
     * Utilities::MPI::MPI_InitFinalize does so, and where no one has,
     * factorize() initialises it itself (PetscInitializeNoArguments) and
     * finalises it at exit. Errors of
     * PETSc are returned, not printed, and thrown as exceptions; a pivot
     * of MUMPS that is not positive, or a Schur complement that is not, is
     * a NotPositiveDefiniteError as for SparseCholesky.
     *
     * <h3>Over MPI</h3>
     *
     * The factorisation lives on the communicator given to the constructor.
     * On one rank (MPI_COMM_SELF, the serial route) the matrix is
     * sequential. On several (the MPI route, doc/parallel.md) every rank
     * calls every function with the same arguments (the body and its
     * reduced matrix are known on every rank) and inserts only the rows of
     * $K_r$ it owns, a contiguous block as PETSc splits them, into a
     * distributed matrix (MATMPISBAIJ); MUMPS analyses, factors and solves
     * over all ranks. Its Schur complement is centralised: $S$ is returned
     * on rank 0 only (the index set of $\Gamma$ is empty on the other
     * ranks) and factored there; $L_S$ stays on rank 0, so that
     * solve_schur_factor() (the condensation, which forms $A$ on rank 0
     * only) is for rank 0 alone, and the solves compute the Schur unknowns
     * on rank 0 and broadcast them ($n_\Gamma$ numbers instead of the
     * $n_\Gamma^2$ of $L_S$).
     * The interior solves are distributed (MatSolve on distributed vectors,
     * ICNTL(26) = 0); their results are gathered on every rank, so solve()
     * and solve_condensed() return the full vector everywhere.
     *
     * <h3>Out of core</h3>
     *
     * After set_out_of_core_directory(), MUMPS writes the factor of
     * $K_{II}$ to files in that directory as it computes it (its
     * ICNTL(22) = 1; the directory is handed to PETSc as the option
     * -mat_mumps_ooc_tmpdir for the analysis only) and reads it back for
     * every solve; only the active frontal matrices, $S$ and $L_S$ stay in
     * memory. The files are MUMPS' own, named with its prefix; MUMPS
     * removes them when the factorisation is destroyed (its JOB = -2),
     * which the destructor does also when an exception unwinds the run.
     *
     * <h3>A matrix assembled in shares</h3>
     *
     * After set_matrix_in_shares(true), the matrix each rank gives
     * factorize() is its share of $K$ (the cells it assembled, see
     * Body::partition()); $K$ is their sum. Every rank then adds all the
     * entries of its share to the distributed matrix (ADD_VALUES; PETSc
     * sends the rows another rank owns to it), so that no rank needs the
     * whole $K$. The constraints and the dofs of $\Gamma$ are still the
     * same on every rank.
     */
    class MumpsSchurFactorization : public SchurFactorization
    {
    public:
      /**
       * A factorisation over the ranks of @p communicator (MPI_COMM_SELF:
       * one process; MPI_COMM_WORLD: the MPI route). Every function is then
       * collective on it.
       */
      explicit MumpsSchurFactorization(
        const MPI_Comm communicator = MPI_COMM_SELF);
      ~MumpsSchurFactorization() override;
      MumpsSchurFactorization(const MumpsSchurFactorization &) = delete;
      MumpsSchurFactorization &
      operator=(const MumpsSchurFactorization &) = delete;

      void
      factorize(const dealii::SparseMatrix<double>      &K,
                const dealii::AffineConstraints<double> &constraints,
                const std::vector<unsigned int>         &gamma_dofs) override;

      const std::vector<unsigned int> &
      schur_dofs() const override;

      using SchurFactorization::solve_schur_factor;

      void
      solve_schur_factor(Eigen::MatrixXd &W) const override;

      Eigen::VectorXd
      solve(const Eigen::VectorXd &b) const override;

      void
      solve_condensed(const dealii::Vector<double> &f_condensed,
                      dealii::Vector<double>       &u) const override;

      std::string
      name() const override;

      /**
       * The dense lower triangular $L_S$ (row and column k belong to the
       * degree of freedom schur_dofs()[k]), for checks; empty on the
       * ranks other than 0 of a parallel factorisation.
       */
      const Eigen::MatrixXd &
      schur_factor() const;

      /**
       * The ordering of the interior unknowns MUMPS used (its INFOG(7):
       * 0 AMD, 1 given, 2 AMF, 3 SCOTCH, 4 PORD, 5 METIS, 6 QAMD), and the
       * memory its factorisation used, in MB (INFOG(22)).
       */
      int
      ordering() const;
      int
      factor_memory_mb() const;

      /**
       * The number of ranks of the factorisation.
       */
      unsigned int
      n_ranks() const;

      /**
       * What MUMPS reports of its factorisation (the same on every rank):
       * the flops of the elimination its analysis estimated (RINFOG(1))
       * and that it made (RINFOG(3)), the memory its analysis
       * estimated (INFOG(16): the largest of one rank, INFOG(17): the sum
       * over the ranks, in MB) and that the factorisation used (INFOG(21),
       * INFOG(22)), the entries of the factors its analysis estimated
       * (INFOG(20)) and that it made (INFOG(29)), the order of the
       * Schur complement, and the ordering MUMPS used (INFOG(7), as
       * ordering() returns it). The inputs of the cost model of
       * benchmarks/parallel. After the analysis only the estimates and
       * the order are set (the others are 0 or -1). Out of core, the
       * memory the analysis estimated for an out-of-core factorisation
       * (INFOG(26), INFOG(27)) is the one that counts.
       */
      struct Statistics
      {
        bool         out_of_core              = false;
        long         estimated_ooc_max_mb     = 0;
        long         estimated_ooc_total_mb   = 0;
        double       estimated_flops          = 0;
        double       flops                    = 0;
        long         estimated_max_mb         = 0;
        long         estimated_total_mb       = 0;
        long         used_max_mb              = 0;
        long         used_total_mb            = 0;
        long         estimated_factor_entries = 0;
        long         factor_entries           = 0;
        unsigned int schur_size               = 0;
        int          ordering                 = -1;

        /**
         * One line for the log.
         */
        std::string
        describe() const;
      };

      Statistics
      statistics() const;

      /**
       * A function that factorize() calls between MUMPS' analysis and its
       * numerical factorisation with the Statistics of the analysis (its
       * estimates of the flops and of the memory, the same on every rank),
       * e.g. to refuse a factorisation that would not fit by throwing
       * (on every rank alike). None by default.
       */
      void
      set_analysis_check(const std::function<void(const Statistics &)> &check);

      /**
       * Whether the matrices given to factorize() are shares of $K$ over
       * the ranks (see the class documentation); false by default. On one
       * rank a share is the whole matrix.
       */
      void
      set_matrix_in_shares(const bool in_shares);

      /**
       * Factor out of core, the factor's files in @p directory (see the
       * class documentation), from the next factorize() on; empty: in
       * memory, the default. The directory must exist and be writable.
       */
      void
      set_out_of_core_directory(const std::string &directory);

      /**
       * The ordering of the unknowns handed to MUMPS (see
       * the class documentation), from the next factorize() on; none (the
       * default): MUMPS' own.
       */
      void
      set_ordering(const std::optional<LastBlockOrdering> &ordering);

    private:
      /**
       * $x = K_r^{-1} b$ on the free degrees of freedom, composed as the
       * class documentation says.
       */
      Eigen::VectorXd
      solve_reduced(const Eigen::VectorXd &b) const;

      struct Impl;
      std::unique_ptr<Impl> impl;
    };
  } // namespace linear_algebra
} // namespace dpana

#endif
