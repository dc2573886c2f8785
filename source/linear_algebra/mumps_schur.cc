// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/base/exceptions.h>

#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <string>

#include "mumps_schur_impl.h"

namespace dpana
{
  namespace linear_algebra
  {
    using parallel::check;
    using parallel::QuietPetsc;



    namespace
    {
      // MUMPS gives a count of factor entries that does not fit in its
      // integers as minus the count in millions.
      long
      entries(const int infog_value)
      {
        return infog_value < 0 ? -1000000L * infog_value : infog_value;
      }
    } // namespace



    // The private state: mumps_schur_impl.h.



    // MUMPS' INFOG(i), RINFOG(i) and ICNTL(i), from the direct instance or
    // through PETSc.
    int
    MumpsSchurFactorization::Impl::infog(const int i) const
    {
      return direct ? direct->infog(i) : parallel::infog(F, i);
    }



    double
    MumpsSchurFactorization::Impl::rinfog(const int i) const
    {
      return direct ? direct->rinfog(i) : parallel::rinfog(F, i);
    }



    int
    MumpsSchurFactorization::Impl::icntl(const int i) const
    {
      if (direct)
        return direct->icntl(i);
      PetscInt value = 0;
      MatMumpsGetIcntl(F, i, &value);
      return value;
    }



    // What MUMPS reports of the factor, after its analysis or its
    // factorisation.
    MumpsSchurFactorization::Statistics
    MumpsSchurFactorization::Impl::statistics() const
    {
      Statistics s;
      s.out_of_core              = icntl(22) == 1;
      s.estimated_ooc_max_mb     = infog(26);
      s.estimated_ooc_total_mb   = infog(27);
      s.estimated_flops          = rinfog(1);
      s.flops                    = rinfog(3);
      s.estimated_max_mb         = infog(16);
      s.estimated_total_mb       = infog(17);
      s.estimated_factor_entries = entries(infog(20));
      s.used_max_mb              = infog(21);
      s.used_total_mb            = infog(22);
      s.factor_entries           = entries(infog(29));
      s.schur_size               = gamma.size();
      s.ordering                 = infog(7);
      return s;
    }



    // The constraints, and a copy without their inhomogeneities for the
    // homogeneous solves.
    void
    MumpsSchurFactorization::Impl::copy_constraints(
      const dealii::AffineConstraints<double> &c)
    {
      AssertThrow(c.is_closed(),
                  dealii::ExcMessage("MumpsSchurFactorization: the "
                                     "constraints must be closed."));
      constraints.copy_from(c);
      homogeneous.clear();
      for (const auto &line : c.get_lines())
        {
          homogeneous.add_line(line.index);
          homogeneous.add_entries(line.index, line.entries);
        }
      homogeneous.close();
    }



    // The free degrees of freedom, numbered consecutively, and the unknowns
    // of Gamma among them: a free dof of Gamma stands for itself, a
    // constrained one for its masters.
    void
    MumpsSchurFactorization::Impl::number_unknowns(
      const unsigned int               n_rows,
      const std::vector<unsigned int> &gamma_dofs)
    {
      number_free_dofs(constraints, n_rows, free, reduced_index);
      const std::vector<bool> in_gamma =
        unknowns_of_dofs(gamma_dofs, constraints, reduced_index, free.size());
      gamma.clear();
      schur.clear();
      for (unsigned int k = 0; k < free.size(); ++k)
        if (in_gamma[k])
          {
            gamma.push_back(k);
            schur.push_back(free[k]);
          }
    }



    // MUMPS' LL^T with the Schur index set. A zero pivot is reported by
    // MUMPS as INFOG(1) < 0, which PETSc returns either as an error of the
    // numeric factorisation or as a factor error; a negative one is only
    // counted (INFOG(12)), the factorisation of a symmetric positive
    // definite matrix (MUMPS' SYM = 1) going on without pivoting. A
    // workspace that its analysis estimated too small (INFOG(1) = -8, -9,
    // -11, -12, -14, -15; it happens on several ranks) is enlarged: the
    // factorisation is made again with twice the relaxation ICNTL(14) of
    // the estimate, up to three times.
    void
    MumpsSchurFactorization::Impl::factor_interior()
    {
      PetscInt relaxation = 0;
      for (unsigned int attempt = 0;; ++attempt)
        {
          const PetscInt status    = try_factor(relaxation);
          const bool     workspace = status == -8 || status == -9 ||
                                 status == -11 || status == -12 ||
                                 status == -14 || status == -15;
          if (status == 0)
            break;
          // MUMPS' error of its out-of-core layer: a file it could not
          // write or read (a full disk, a directory removed meanwhile).
          if (status == -90)
            throw InputError(
              "MUMPS could not write or read its factor files in Contact / "
              "Out-of-core directory = '" +
              out_of_core_directory + "' (INFOG(1) = -90, a matrix of " +
              std::to_string(free.size()) + " unknowns); is the disk full?");
          if (!workspace || attempt == 3)
            throw NotPositiveDefiniteError(
              "MUMPS' Cholesky factorisation failed (INFOG(1) = " +
              std::to_string(status) + ") on a matrix of " +
              std::to_string(free.size()) +
              " unknowns: it is not positive definite; a stiffness matrix is "
              "singular when the body is not held against rigid motions");
          relaxation = 2 * std::max<PetscInt>(icntl(14), 20);
          destroy_factor();
        }
      // Later solves with F are solves with K_II only (the direct instance
      // sets this for each solve).
      if (!direct)
        check(MatMumpsSetIcntl(F, 26, 0), "MatMumpsSetIcntl(26)");
    }



    // One analysis and factorisation, with the memory relaxation
    // ICNTL(14) = @p relaxation if it is positive; MUMPS' INFOG(1), or -10
    // (MUMPS' code of a singular matrix) for a negative pivot.
    PetscInt
    MumpsSchurFactorization::Impl::try_factor(const PetscInt relaxation)
    {
      if (calls_mumps_directly())
        return try_factor_directly(relaxation);
      check(MatGetFactor(K, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &F),
            "MatGetFactor(MATSOLVERMUMPS)");
      if (F == nullptr)
        throw InputError("this PETSc has no MUMPS (MatGetFactor); "
                         "Contact / Factorisation back end = mumps and the "
                         "MPI route need a PETSc configured with MUMPS");
      if (relaxation > 0)
        check(MatMumpsSetIcntl(F, 14, relaxation), "MatMumpsSetIcntl(14)");
      const bool out_of_core = !out_of_core_directory.empty();
      if (out_of_core)
        check(MatMumpsSetIcntl(F, 22, 1), "MatMumpsSetIcntl(22)");
      // MUMPS computes a centralised Schur complement on rank 0: there the
      // index set lists all the unknowns of Gamma, on the other ranks none.
      if (!gamma.empty())
        {
          IS is;
          check(ISCreateGeneral(communicator,
                                rank == 0 ? gamma.size() : 0,
                                gamma.data(),
                                PETSC_COPY_VALUES,
                                &is),
                "ISCreateGeneral");
          check(MatFactorSetSchurIS(F, is), "MatFactorSetSchurIS");
          ISDestroy(&is);
        }
      MatFactorInfo info;
      check(MatFactorInfoInitialize(&info), "MatFactorInfoInitialize");
      // Out of core, ICNTL(22) = 1 is set on F above; the directory reaches
      // MUMPS only through PETSc's options database, which the analysis
      // reads (-mat_mumps_ooc_tmpdir), so it is put there for the analysis
      // alone.
      if (out_of_core)
        check(PetscOptionsSetValue(nullptr,
                                   "-mat_mumps_ooc_tmpdir",
                                   out_of_core_directory.c_str()),
              "PetscOptionsSetValue(-mat_mumps_ooc_tmpdir)");
      const PetscErrorCode symbolic =
        MatCholeskyFactorSymbolic(F, K, nullptr, &info);
      if (out_of_core)
        PetscOptionsClearValue(nullptr, "-mat_mumps_ooc_tmpdir");
      check(symbolic, "MatCholeskyFactorSymbolic");
      if (analysis_check)
        analysis_check(statistics());
      const PetscErrorCode code  = MatCholeskyFactorNumeric(F, K, &info);
      MatFactorError       error = MAT_FACTOR_NOERROR;
      MatFactorGetError(F, &error);
      PetscInt status = 0, negative = 0;
      MatMumpsGetInfog(F, 1, &status);
      MatMumpsGetInfog(F, 12, &negative);
      if (negative > 0)
        return -10;
      if (status == 0 && (code != 0 || error != MAT_FACTOR_NOERROR))
        return -1;
      return status;
    }



    // S as MUMPS returns it on rank 0 (dense, column-major, one triangle),
    // copied and factored there: its lower triangle becomes L_S,
    // which stays on rank 0 alone (the other ranks receive the Schur
    // unknowns of each solve from it).
    void
    MumpsSchurFactorization::Impl::factor_schur_complement()
    {
      const dealii::types::blas_int n = gamma.size();
      L.resize(rank == 0 ? n : 0, rank == 0 ? n : 0);
      if (n == 0)
        return;
      if (direct)
        L = direct->take_schur_complement();
      else
        copy_schur_complement();
      dealii::types::blas_int info = 0;
      if (rank == 0)
        {
          L.triangularView<Eigen::StrictlyUpper>().setZero();
          dealii::potrf("L", &n, L.data(), &n, &info);
        }
      MPI_Bcast(&info, 1, MPI_INT, 0, communicator);
      if (info != 0)
        throw NotPositiveDefiniteError(
          "the Schur complement on the contact surface (" + std::to_string(n) +
          " unknowns) is not positive definite "
          "(LAPACK potrf: " +
          std::to_string(info) + ")");
    }



    // S from PETSc into L, its lower triangle: on one process MUMPS returns
    // the lower one; on several the lower triangle by rows, which the
    // column-major array holds as its upper one (the rest of the array is
    // not set).
    void
    MumpsSchurFactorization::Impl::copy_schur_complement()
    {
      const dealii::types::blas_int n = gamma.size();
      Mat                           S;
      MatFactorSchurStatus          status;
      check(MatFactorGetSchurComplement(F, &S, &status),
            "MatFactorGetSchurComplement");
      if (rank == 0)
        {
          const PetscScalar *values;
          PetscInt           lda = 0;
          check(MatDenseGetLDA(S, &lda), "MatDenseGetLDA");
          check(MatDenseGetArrayRead(S, &values), "MatDenseGetArrayRead");
          for (dealii::types::blas_int j = 0; j < n; ++j)
            for (dealii::types::blas_int i = 0; i < n; ++i)
              L(i, j) = values[i + j * lda];
          MatDenseRestoreArrayRead(S, &values);
          if (rows.counts.size() > 1)
            L = L.transpose().eval();
        }
      MatFactorRestoreSchurComplement(F, &S, status);
    }



    Eigen::VectorXd
    MumpsSchurFactorization::Impl::solve_interior(
      const Eigen::VectorXd &b) const
    {
      if (direct)
        return direct->solve_interior(b);
      Eigen::VectorXd y = parallel::apply(MatSolve, F, rows, b, "MatSolve");
      for (const PetscInt k : gamma)
        y(k) = 0.0;
      return y;
    }



    Eigen::VectorXd
    MumpsSchurFactorization::Impl::multiply(const Eigen::VectorXd &x) const
    {
      return parallel::apply(MatMult, K, rows, x, "MatMult");
    }



    MumpsSchurFactorization::MumpsSchurFactorization(
      const MPI_Comm communicator)
      : impl(std::make_unique<Impl>(communicator))
    {
    }



    MumpsSchurFactorization::~MumpsSchurFactorization()
    {
      impl->destroy();
    }



    void
    MumpsSchurFactorization::factorize(
      const dealii::SparseMatrix<double>      &K,
      const dealii::AffineConstraints<double> &constraints,
      const std::vector<unsigned int>         &gamma_dofs)
    {
      AssertThrow(K.m() == K.n(), dealii::ExcNotQuadratic());
      parallel::ensure_petsc();
      const QuietPetsc quiet;
      impl->destroy();
      impl->copy_constraints(constraints);
      impl->number_unknowns(K.m(), gamma_dofs);
      AssertThrow(!impl->free.empty(),
                  dealii::ExcMessage(
                    "MumpsSchurFactorization: there is nothing to factor (no "
                    "free degrees of freedom)."));
      if (impl->in_shares)
        impl->create_matrix_from_shares(K);
      else
        impl->create_matrix(K);
      impl->factor_interior();
      impl->factor_schur_complement();
    }



    const std::vector<unsigned int> &
    MumpsSchurFactorization::schur_dofs() const
    {
      return impl->schur;
    }



    const Eigen::MatrixXd &
    MumpsSchurFactorization::schur_factor() const
    {
      return impl->L;
    }



    void
    MumpsSchurFactorization::solve_schur_factor(Eigen::MatrixXd &W) const
    {
      AssertThrow(W.rows() == impl->L.rows(),
                  dealii::ExcMessage("MumpsSchurFactorization: the factor "
                                     "of the Schur complement is on rank 0 "
                                     "only"));
      const dealii::types::blas_int n = W.rows(), nrhs = W.cols();
      if (n == 0 || nrhs == 0)
        return;
      dealii::types::blas_int info = 0;
      dealii::trtrs(
        "L", "N", "N", &n, &nrhs, impl->L.data(), &n, W.data(), &n, &info);
      AssertThrow(info == 0, dealii::ExcInternalError());
    }



    // The two interior solves and the one with S = L_S L_S^T (LAPACK potrs)
    // of the class documentation.
    Eigen::VectorXd
    MumpsSchurFactorization::solve_reduced(const Eigen::VectorXd &b) const
    {
      AssertThrow(impl->F != nullptr || impl->direct != nullptr,
                  dealii::ExcMessage(
                    "MumpsSchurFactorization: factorize() first."));
      const QuietPetsc quiet;
      Eigen::VectorXd  x = impl->solve_interior(b);
      if (impl->gamma.empty())
        return x;
      const Eigen::VectorXd         Kx = impl->multiply(x);
      const dealii::types::blas_int n = impl->gamma.size(), one = 1;
      Eigen::VectorXd               x_gamma(n);
      for (dealii::types::blas_int k = 0; k < n; ++k)
        x_gamma(k) = b(impl->gamma[k]) - Kx(impl->gamma[k]);
      // The Schur unknowns on rank 0, which holds L_S, sent to the others.
      dealii::types::blas_int info = 0;
      if (impl->rank == 0)
        dealii::potrs(
          "L", &n, &one, impl->L.data(), &n, x_gamma.data(), &n, &info);
      AssertThrow(info == 0, dealii::ExcInternalError());
      MPI_Bcast(x_gamma.data(), n, MPI_DOUBLE, 0, impl->communicator);

      Eigen::VectorXd z = Eigen::VectorXd::Zero(b.size());
      for (dealii::types::blas_int k = 0; k < n; ++k)
        z(impl->gamma[k]) = x_gamma(k);
      x = impl->solve_interior(b - impl->multiply(z));
      for (dealii::types::blas_int k = 0; k < n; ++k)
        x(impl->gamma[k]) = x_gamma(k);
      return x;
    }



    Eigen::VectorXd
    MumpsSchurFactorization::solve(const Eigen::VectorXd &b) const
    {
      const auto            &free = impl->free;
      dealii::Vector<double> u(b.size());
      for (unsigned int i = 0; i < u.size(); ++i)
        u[i] = b(i);
      impl->homogeneous.condense(u);
      Eigen::VectorXd b_r(free.size());
      for (unsigned int k = 0; k < free.size(); ++k)
        b_r(k) = u[free[k]];
      const Eigen::VectorXd x_r = solve_reduced(b_r);
      u                         = 0.0;
      for (unsigned int k = 0; k < free.size(); ++k)
        u[free[k]] = x_r(k);
      impl->homogeneous.distribute(u);
      Eigen::VectorXd x(u.size());
      for (unsigned int i = 0; i < u.size(); ++i)
        x(i) = u[i];
      return x;
    }



    void
    MumpsSchurFactorization::solve_condensed(
      const dealii::Vector<double> &f_condensed,
      dealii::Vector<double>       &u) const
    {
      const auto     &free = impl->free;
      Eigen::VectorXd f_r(free.size());
      for (unsigned int k = 0; k < free.size(); ++k)
        f_r(k) = f_condensed[free[k]];
      const Eigen::VectorXd x_r = solve_reduced(f_r);
      u.reinit(f_condensed.size());
      for (unsigned int k = 0; k < free.size(); ++k)
        u[free[k]] = x_r(k);
      impl->constraints.distribute(u);
    }



    std::string
    MumpsSchurFactorization::name() const
    {
      return "mumps";
    }



    int
    MumpsSchurFactorization::ordering() const
    {
      return impl->infog(7);
    }



    int
    MumpsSchurFactorization::factor_memory_mb() const
    {
      return impl->infog(22);
    }



    unsigned int
    MumpsSchurFactorization::n_ranks() const
    {
      return impl->rows.counts.size();
    }



    void
    MumpsSchurFactorization::set_analysis_check(
      const std::function<void(const Statistics &)> &check)
    {
      impl->analysis_check = check;
    }



    void
    MumpsSchurFactorization::set_matrix_in_shares(const bool in_shares)
    {
      impl->in_shares = in_shares;
    }



    void
    MumpsSchurFactorization::set_out_of_core_directory(
      const std::string &directory)
    {
      impl->out_of_core_directory = directory;
    }



    MumpsSchurFactorization::Statistics
    MumpsSchurFactorization::statistics() const
    {
      return impl->statistics();
    }



    void
    MumpsSchurFactorization::set_ordering(
      const std::optional<LastBlockOrdering> &ordering)
    {
      impl->given_ordering = ordering;
    }



    std::string
    MumpsSchurFactorization::Statistics::describe() const
    {
      const char *const orderings[] = {
        "AMD", "given", "AMF", "SCOTCH", "PORD", "METIS", "QAMD"};
      const auto gflops = std::to_string(flops / 1e9);
      return gflops.substr(0, gflops.find('.') + 3) +
             " Gflop, memory estimated " + std::to_string(estimated_total_mb) +
             " MB (at most " + std::to_string(estimated_max_mb) +
             " MB on one rank), used " + std::to_string(used_total_mb) +
             " MB (at most " + std::to_string(used_max_mb) +
             " MB on one rank), " +
             (out_of_core ?
                "out of core (estimated " +
                  std::to_string(estimated_ooc_total_mb) + " MB, at most " +
                  std::to_string(estimated_ooc_max_mb) +
                  " MB on one rank, in memory; the factor on disk), " :
                std::string()) +
             std::to_string(factor_entries) +
             " factor entries, Schur complement of " +
             std::to_string(schur_size) + " unknowns, ordering " +
             (ordering >= 0 && ordering <= 6 ? orderings[ordering] : "?");
    }
  } // namespace linear_algebra
} // namespace dpana
