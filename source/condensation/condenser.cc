// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/condensation/condenser.h>
#include <dpana/linear_algebra/blas.h>
#include <dpana/linear_algebra/mumps_schur.h>

#include <Eigen/QR>

#include <algorithm>
#include <iomanip>
#include <numeric>
#include <sstream>

#include <sys/statvfs.h>

namespace dpana
{
  namespace condensation
  {
    namespace
    {
      // The memory estimate of a factorisation by MUMPS, made from its
      // analysis: the largest workspace of one rank that MUMPS estimated
      // (INFOG(16), the factor and its frontal matrices), the dense blocks
      // of the Schur route (the Schur complement and its Cholesky factor,
      // n_Gamma^2 each, W, n_Gamma x n_c, and A, n_c^2) and the resident
      // memory before the factorisation. On more than one rank the largest
      // resident memory of the ranks is taken, so that all ranks decide
      // alike. Out of core the factor is on disk: the workspace is MUMPS'
      // estimate for an out-of-core factorisation (INFOG(26), the active
      // frontal matrices and the buffers of its input and output).
      MemoryEstimate
      mumps_estimate(
        const linear_algebra::MumpsSchurFactorization::Statistics &statistics,
        const unsigned int                                         n_dofs,
        const unsigned int                                         n_c,
        const MPI_Comm                                             communicator)
      {
        MemoryEstimate m;
        m.made          = true;
        m.n_dofs        = n_dofs;
        m.n_gamma       = statistics.schur_size;
        m.n_c           = n_c;
        const double ng = m.n_gamma, nc = n_c;
        m.factor =
          1e6 * (statistics.out_of_core ? statistics.estimated_ooc_max_mb :
                                          statistics.estimated_max_mb);
        m.dense        = 8.0 * (2.0 * ng * ng + ng * nc + nc * nc);
        double current = resident_memory();
        MPI_Allreduce(
          &current, &m.current, 1, MPI_DOUBLE, MPI_MAX, communicator);
        return m;
      }



      // Out of core, the factor goes to disk: its entries, 8 bytes each
      // (MUMPS' estimate after the analysis, INFOG(20), summed over the
      // ranks), must fit in the space free in the directory. An
      // InputError naming the directory otherwise, on every rank alike.
      void
      check_disk_space(
        const linear_algebra::MumpsSchurFactorization::Statistics &statistics,
        const std::string                                         &directory,
        const std::string                                         &body)
      {
        struct statvfs disk;
        if (statvfs(directory.c_str(), &disk) != 0)
          return;
        const double available =
          static_cast<double>(disk.f_bavail) * disk.f_frsize;
        const double needed = 8.0 * statistics.estimated_factor_entries;
        if (needed <= available)
          return;
        std::ostringstream message;
        message << body << ": the factor written out of core would need about "
                << std::setprecision(3) << needed / 1e9
                << " GB of disk, more than the " << available / 1e9
                << " GB free in Contact / Out-of-core directory = '"
                << directory << "'";
        throw InputError(message.str());
      }
    } // namespace



    template <int dim>
    Condenser<dim>::Condenser(
      const Body<dim>                            &body,
      const contact_surface::ContactSurface<dim> &surface,
      const Parameters                           &parameters)
      : body(body)
      , surface(surface)
      , parameters(parameters)
    {
    }



    // @sect3{The coupling operator V}
    //
    // Column dim j + k of V holds the nodal forces of a unit traction along
    // direction k of contact element j (n, then tau): V_ik = int phi_i e_k
    // over the element's projection. On a face, the P1 shape function of
    // one of the face's vertices is the barycentric coordinate of that
    // vertex (the others vanish), so each quadrature point of the element
    // (ContactElement::points, exact for this linear integrand) adds
    // weight * lambda_v * e_k to the rows of vertex v, whose degrees of
    // freedom the face holds (Face::dofs).
    template <int dim>
    void
    Condenser<dim>::assemble_coupling()
    {
      std::vector<Eigen::Triplet<double>> triplets;
      const auto                         &faces = surface.get_faces();
      for (unsigned int j = 0; j < surface.n_elements(); ++j)
        {
          const auto                             &element = surface.element(j);
          std::array<dealii::Tensor<1, dim>, dim> directions;
          directions[0] = element.normal;
          for (unsigned int k = 1; k < dim; ++k)
            directions[k] = element.tangents[k - 1];
          for (const auto &p : element.points)
            {
              const auto &F = faces[p.face];
              for (unsigned int v = 0; v < F.points.size(); ++v)
                if (p.barycentric[v] != 0.0)
                  for (unsigned int c = 0; c < dim; ++c)
                    for (unsigned int k = 0; k < dim; ++k)
                      if (directions[k][c] != 0.0)
                        triplets.emplace_back(F.dofs[dim * v + c],
                                              dim * j + k,
                                              p.weight * p.barycentric[v] *
                                                directions[k][c]);
            }
        }
      V.resize(body.dof_handler().n_dofs(), dim * surface.n_elements());
      V.setFromTriplets(triplets.begin(), triplets.end());
    }



    // @sect3{Factorisation}
    //
    // The fictitious supports are chosen in fictitious_supports.cc.
    template <int dim>
    void
    Condenser<dim>::factorize()
    {
      const auto &modes = body.free_rigid_modes();
      const auto &Rall  = body.rigid_mode_vectors();
      R.resize(Rall.rows(), modes.size());
      for (unsigned int k = 0; k < modes.size(); ++k)
        R.col(k) = Rall * modes[k].coefficients;

      const auto &body_constraints = body.constraints();
      const auto  n_dofs           = body.dof_handler().n_dofs();

      std::vector<unsigned int> free;
      for (unsigned int i = 0; i < n_dofs; ++i)
        if (!body_constraints.is_constrained(i))
          free.push_back(i);
      supports = choose_supports(free);

      // The body's constraints plus u_s = 0 at the supports.
      constraints.clear();
      for (const auto &line : body_constraints.get_lines())
        {
          constraints.add_line(line.index);
          constraints.add_entries(line.index, line.entries);
          constraints.set_inhomogeneity(line.index, line.inhomogeneity);
        }
      for (const unsigned int s : supports)
        constraints.add_line(s);
      constraints.close();

      // The back end of the Schur route; the blocked solves factor with
      // CHOLMOD alone (no dofs ordered last). CHOLMOD's analysis is followed
      // by the memory estimate, before the numerical factorisation.
      std::vector<unsigned int> gamma;
      if (parameters.method == Method::schur)
        {
          if (V.rows() == 0)
            assemble_coupling();
          gamma = surface_dofs();
        }
      cholesky.set_analysis_check(
        [this](const linear_algebra::SparseCholesky::Analysis &analysis) {
          check_memory(analysis);
        });
      cholesky.set_last_block_ordering(parameters.ordering);
      if (parameters.backend == Backend::mumps)
        back_end = make_mumps_back_end();
      else
        back_end =
          std::make_unique<linear_algebra::CholmodSchurFactorization>(cholesky);
      try
        {
          back_end->factorize(body.system_matrix(), constraints, gamma);
        }
      catch (const std::length_error &error)
        {
          throw InputError(
            body.name() + ": " + error.what() + " (" +
            std::to_string(body.dof_handler().n_dofs()) +
            " dofs, n_c = " + std::to_string(dim * surface.n_elements()) +
            "); use a coarser mesh or larger contact "
            "elements");
        }
      catch (const linear_algebra::NotPositiveDefiniteError &)
        {
          throw InputError(body.name() +
                           ": the stiffness matrix is not positive definite "
                           "even with fictitious supports of the free rigid "
                           "motions; check the boundary conditions");
        }

      // u_o: the rows of the body's right-hand side at the (remaining) free
      // degrees of freedom already hold M^T (f - K u_bar).
      const auto            &rhs = body.system_rhs();
      dealii::Vector<double> u;
      back_end->solve_condensed(rhs, u);
      u_o = Eigen::Map<const Eigen::VectorXd>(u.begin(), u.size());

      // e = -R^T f_r over the free degrees of freedom of the body's own
      // constraints (the rows of R there are the reduced rigid motions).
      e = Eigen::VectorXd::Zero(R.cols());
      for (const unsigned int i : free)
        e -= rhs[i] * R.row(i).transpose();
    }



    // @sect3{Memory estimate}
    //
    // After the symbolic analysis, before the numerical factorisation: the
    // estimate of memory_estimate.h, for the blocked solves with their
    // dense blocks of n_dofs x columns (right-hand sides, solutions, the
    // extended copy) instead of W.
    template <int dim>
    void
    Condenser<dim>::check_memory(
      const linear_algebra::SparseCholesky::Analysis &analysis)
    {
      const unsigned int n_dofs = body.dof_handler().n_dofs();
      const unsigned int n_c    = dim * surface.n_elements();
      estimate                  = estimate_memory(analysis, n_dofs, n_c);
      if (parameters.method == Method::blocked_solves)
        estimate.dense +=
          8.0 * 3.0 * n_dofs * std::min(parameters.columns_per_solve, n_c);
      check_memory_limit();
    }



    // The back end MUMPS (on every rank of MPI_COMM_WORLD on the MPI route,
    // on this process alone otherwise), with the memory estimate made from
    // its analysis before its numerical factorisation.
    template <int dim>
    std::unique_ptr<linear_algebra::SchurFactorization>
    Condenser<dim>::make_mumps_back_end()
    {
      const bool     mpi          = parameters.route == parallel::Route::mpi;
      const MPI_Comm communicator = mpi ? MPI_COMM_WORLD : MPI_COMM_SELF;
      if (mpi)
        parallel::check_ranks(body.name(),
                              body.n_cells(),
                              parallel::n_world_ranks());
      auto mumps =
        std::make_unique<linear_algebra::MumpsSchurFactorization>(communicator);
      // A body partitioned over the ranks holds its share of K on each.
      mumps->set_matrix_in_shares(mpi && body.n_parts() > 1);
      mumps->set_out_of_core_directory(parameters.out_of_core_directory);
      if (!parameters.mumps_orders_itself)
        mumps->set_ordering(parameters.ordering);
      mumps->set_analysis_check(
        [this, communicator](
          const linear_algebra::MumpsSchurFactorization::Statistics &s) {
          if (s.out_of_core)
            check_disk_space(s, parameters.out_of_core_directory, body.name());
          estimate = mumps_estimate(s,
                                    body.dof_handler().n_dofs(),
                                    dim * surface.n_elements(),
                                    communicator);
          check_memory_limit();
        });
      return mumps;
    }



    // An InputError if #estimate exceeds Contact / Memory limit (GB) or,
    // without one, the memory this machine has available.
    template <int dim>
    void
    Condenser<dim>::check_memory_limit() const
    {
      const double limit = memory_limit(parameters.memory_limit_gb);
      if (reservations != nullptr)
        switch (reservations->request(estimate, limit))
          {
            case MemoryReservations::Decision::granted:
              return;
            case MemoryReservations::Decision::deferred:
              throw Deferred();
            case MemoryReservations::Decision::refused:
              break;
          }
      else if (estimate.total() <= limit)
        return;
      std::ostringstream message;
      message << body.name() << ": the condensation would need "
              << estimate.describe() << ", more than ";
      if (parameters.memory_limit_gb > 0)
        message << "Contact / Memory limit (GB) = "
                << parameters.memory_limit_gb;
      else
        message << "the " << limit / 1e9
                << " GB this machine has available (Contact / Memory limit "
                   "(GB))";
      message << "; use a coarser mesh or larger contact elements";
      // The Schur route holds dense blocks of the n_Gamma surface unknowns
      // (the last supernode of the factor, W); the blocked solves hold none
      // (a factor with CHOLMOD's own ordering, n_c solves), which for a
      // large n_Gamma is far less memory (the quarter sphere of 479 958
      // dofs, n_Gamma = 40 144: 44.9 GB estimated on the Schur route, 14.1
      // GB estimated and 11.2 GB used with the blocked solves).
      const double gamma_blocks = 8.0 * estimate.n_gamma * estimate.n_gamma;
      if (parameters.method == Method::schur &&
          parameters.backend == Backend::cholmod &&
          parameters.route != parallel::Route::mpi &&
          gamma_blocks > 0.1 * estimate.total())
        message << ", or Contact / Condensation method = blocked solves: "
                   "it keeps no dense block of the n_Gamma = "
                << estimate.n_gamma << " surface unknowns (n_Gamma^2 numbers, "
                << std::setprecision(3) << gamma_blocks / 1e9
                << " GB here), at the cost of " << estimate.n_c << " solves";
      throw InputError(message.str());
    }



    template <int dim>
    std::vector<unsigned int>
    Condenser<dim>::surface_dofs() const
    {
      std::vector<bool> on_surface(V.rows(), false);
      for (Eigen::Index c = 0; c < V.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(V, c); it; ++it)
          on_surface[it.row()] = true;
      std::vector<unsigned int> dofs;
      for (unsigned int i = 0; i < on_surface.size(); ++i)
        if (on_surface[i])
          dofs.push_back(i);
      return dofs;
    }



    template <int dim>
    void
    Condenser<dim>::condense(const unsigned int columns_per_pass)
    {
      Assert(back_end != nullptr, dealii::ExcInternalError());
      if (V.rows() == 0)
        assemble_coupling();
      if (parameters.method == Method::schur)
        condense_through_schur_complement();
      else
        condense_by_blocked_solves(columns_per_pass);
      s_o = V.transpose() * u_o;
      G   = R.transpose() * V;
    }



    // @sect3{Condensation through the Schur complement}
    //
    // V_Gamma = M^T V on the unknowns of the last block, in the order of the
    // factor: a row of a constrained dof is folded into its masters (none
    // for a support). Its columns are taken in the order of their first
    // nonzero row, so that W_Gamma = L_22^{-1} V_Gamma, computed in place,
    // keeps the zeros above it (lower triangular L_22): the triangular solve
    // and the product A = W^T W skip them.
    template <int dim>
    void
    Condenser<dim>::condense_through_schur_complement()
    {
      // On the MPI route A is formed on rank 0 alone, which solves the
      // contact problem; the other ranks keep it empty.
      const auto &dofs   = back_end->schur_dofs();
      relative_asymmetry = 0.0;
      if (parameters.route == parallel::Route::mpi && !parallel::is_root())
        {
          A.resize(0, 0);
          return;
        }
      A.setZero(V.cols(), V.cols());
      if (dofs.empty())
        return;
      std::vector<int> position(V.rows(), -1);
      for (unsigned int k = 0; k < dofs.size(); ++k)
        position[dofs[k]] = k;
      Eigen::SparseMatrix<double> V_Gamma(dofs.size(), V.cols());
      {
        std::vector<Eigen::Triplet<double>> entries;
        for (Eigen::Index c = 0; c < V.outerSize(); ++c)
          for (Eigen::SparseMatrix<double>::InnerIterator it(V, c); it; ++it)
            if (!constraints.is_constrained(it.row()))
              entries.emplace_back(position[it.row()], c, it.value());
            else
              for (const auto &[j, a] :
                   *constraints.get_constraint_entries(it.row()))
                entries.emplace_back(position[j], c, a * it.value());
        V_Gamma.setFromTriplets(entries.begin(), entries.end());
      }

      // The columns by first row (a column of V_Gamma without entries, if
      // any, last), then W in that order.
      std::vector<int> first(V.cols(), dofs.size());
      for (Eigen::Index c = 0; c < V_Gamma.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(V_Gamma, c); it;
             ++it)
          first[c] = std::min<int>(first[c], it.row());
      Eigen::PermutationMatrix<Eigen::Dynamic> order(V.cols());
      std::iota(order.indices().begin(), order.indices().end(), 0);
      std::stable_sort(order.indices().begin(),
                       order.indices().end(),
                       [&](const int i, const int j) {
                         return first[i] < first[j];
                       });
      std::vector<int> first_rows(V.cols());
      Eigen::MatrixXd  W = Eigen::MatrixXd::Zero(dofs.size(), V.cols());
      for (Eigen::Index k = 0; k < W.cols(); ++k)
        {
          const int c   = order.indices()(k);
          first_rows[k] = first[c];
          for (Eigen::SparseMatrix<double>::InnerIterator it(V_Gamma, c); it;
               ++it)
            W(it.row(), k) = it.value();
        }
      V_Gamma.resize(0, 0);

      back_end->solve_schur_factor(W, first_rows);
      trapezoidal_gram(W, first_rows, A);
      W.resize(0, 0);
      // Back to the order of the contact unknowns: A = P A_sorted P^T, in
      // place (Eigen follows the cycles of the permutation).
      A = A.selfadjointView<Eigen::Lower>();
      A = order * A;
      A = A * order.transpose();
    }



    // @sect3{Condensation by blocked solves}
    template <int dim>
    void
    Condenser<dim>::condense_by_blocked_solves(
      const unsigned int columns_per_pass)
    {
      const unsigned int nc = V.cols();
      A.setZero(nc, nc);
      for (unsigned int c0 = 0; c0 < nc; c0 += columns_per_pass)
        {
          const unsigned int    nb = std::min(columns_per_pass, nc - c0);
          const Eigen::MatrixXd Vb = Eigen::MatrixXd(V.middleCols(c0, nb));
          const Eigen::MatrixXd Zb = cholesky.solve(Vb);
          A.middleCols(c0, nb)     = V.transpose() * Zb;
        }
      const double norm  = A.norm();
      relative_asymmetry = norm > 0 ? (A - A.transpose()).norm() / norm : 0.0;
      A                  = 0.5 * (A + A.transpose()).eval();
    }



    template <int dim>
    dealii::Vector<double>
    Condenser<dim>::recover(const Eigen::VectorXd &r,
                            const Eigen::VectorXd &alpha) const
    {
      Eigen::VectorXd u = u_o + back_end->solve(Eigen::VectorXd(V * r));
      if (R.cols() > 0)
        u += R * alpha;
      dealii::Vector<double> result(u.size());
      for (unsigned int i = 0; i < u.size(); ++i)
        result[i] = u(i);
      return result;
    }



    template <int dim>
    Eigen::VectorXd
    Condenser<dim>::surface_response(const dealii::Vector<double> &u) const
    {
      Eigen::VectorXd x(u.size());
      for (unsigned int i = 0; i < u.size(); ++i)
        x(i) = u[i];
      return V.transpose() * x;
    }



    // The lower triangle of A = W^T W for W whose column k vanishes above
    // row first_rows[k] (increasing): in panels of columns, each panel's
    // diagonal block by SYRK and the block below it by GEMM, over the rows
    // from the panel's first row on only (the later columns vanish above
    // it too).
    template <int dim>
    void
    Condenser<dim>::trapezoidal_gram(const Eigen::MatrixXd  &W,
                                     const std::vector<int> &first_rows,
                                     Eigen::MatrixXd        &A)
    {
      const int    n = W.cols(), m = W.rows(), panel = 256;
      const double one = 1.0, zero = 0.0;
      for (int k0 = 0; k0 < n; k0 += panel)
        {
          const int     width = std::min(panel, n - k0);
          const int     r0    = std::min(first_rows[k0], m);
          const int     rows  = m - r0;
          const int     below = n - k0 - width;
          const double *Wk    = W.data() + std::size_t(k0) * m + r0;
          double       *Ak    = A.data() + std::size_t(k0) * n + k0;
          const int     ld    = A.rows();
          if (rows == 0)
            continue;
          dsyrk_("L", "T", &width, &rows, &one, Wk, &m, &zero, Ak, &ld);
          if (below > 0)
            dgemm_("T",
                   "N",
                   &below,
                   &width,
                   &rows,
                   &one,
                   Wk + std::size_t(width) * m,
                   &m,
                   Wk,
                   &m,
                   &zero,
                   Ak + width,
                   &ld);
        }
    }



    template class Condenser<2>;
    template class Condenser<3>;
  } // namespace condensation
} // namespace dpana
