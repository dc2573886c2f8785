// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_condensation_condenser_templates_h
#define dpana_condensation_condenser_templates_h

#include <dpana/base/exceptions.h>
#include <dpana/condensation/condenser.h>

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <Eigen/QR>

#include <algorithm>

namespace dpana
{
  namespace condensation
  {
    template <int dim>
    Condenser<dim>::Condenser(
      const Body<dim>                            &body,
      const contact_surface::ContactSurface<dim> &surface)
      : body(body)
      , surface(surface)
    {
    }



    // @sect3{The coupling operator V}
    //
    // For each face of each contact element, the face values of the P1
    // shape functions at the points of a QGaussSimplex rule (exact for the
    // linear integrand phi_i . e_k on a flat face) through the MappingFE of
    // the body.
    template <int dim>
    void
    Condenser<dim>::assemble_coupling()
    {
      const auto                          &fe = body.fe();
      const dealii::QGaussSimplex<dim - 1> quadrature(2);
      dealii::FEFaceValues<dim>            fe_face_values(body.mapping(),
                                               fe,
                                               quadrature,
                                               dealii::update_values |
                                                 dealii::update_JxW_values);
      const unsigned int                   n = fe.n_dofs_per_cell();
      std::vector<dealii::types::global_dof_index> local(n);
      std::vector<Eigen::Triplet<double>>          triplets;

      const auto &faces = surface.get_faces();
      for (unsigned int j = 0; j < surface.n_elements(); ++j)
        {
          const auto                             &element = surface.element(j);
          std::array<dealii::Tensor<1, dim>, dim> directions;
          directions[0] = element.normal;
          for (unsigned int k = 1; k < dim; ++k)
            directions[k] = element.tangents[k - 1];
          for (const unsigned int f : element.faces)
            {
              const auto &F = faces[f];
              const typename dealii::DoFHandler<dim>::active_cell_iterator cell(
                &body.triangulation(),
                F.cell->level(),
                F.cell->index(),
                &body.dof_handler());
              fe_face_values.reinit(cell, F.face_no);
              cell->get_dof_indices(local);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  double             phi_JxW = 0;
                  for (const unsigned int q :
                       fe_face_values.quadrature_point_indices())
                    phi_JxW +=
                      fe_face_values.shape_value(i, q) * fe_face_values.JxW(q);
                  if (phi_JxW == 0.0)
                    continue;
                  for (unsigned int k = 0; k < dim; ++k)
                    if (directions[k][c] != 0.0)
                      triplets.emplace_back(local[i],
                                            dim * j + k,
                                            phi_JxW * directions[k][c]);
                }
            }
        }
      V.resize(body.dof_handler().n_dofs(), dim * surface.n_elements());
      V.setFromTriplets(triplets.begin(), triplets.end());
    }



    // @sect3{Fictitious supports and factorisation}
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

      // The supports: among the free degrees of freedom, the m rows of R
      // picked by the column pivoting of a QR factorisation of R_F^T, so that
      // R restricted to them is as well conditioned as possible.
      supports.clear();
      std::vector<unsigned int> free;
      for (unsigned int i = 0; i < n_dofs; ++i)
        if (!body_constraints.is_constrained(i))
          free.push_back(i);
      if (R.cols() > 0)
        {
          Eigen::MatrixXd RFt(R.cols(), free.size());
          for (unsigned int k = 0; k < free.size(); ++k)
            RFt.col(k) = R.row(free[k]).transpose();
          Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(RFt);
          AssertThrow(qr.rank() == R.cols(), dealii::ExcInternalError());
          for (unsigned int k = 0; k < R.cols(); ++k)
            supports.push_back(free[qr.colsPermutation().indices()(k)]);
        }

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

      try
        {
          cholesky.factorize(body.system_matrix(), constraints);
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
      const auto     &rhs = body.system_rhs();
      const auto     &fr  = cholesky.free_dofs();
      Eigen::MatrixXd b_r(fr.size(), 1);
      for (unsigned int k = 0; k < fr.size(); ++k)
        b_r(k, 0) = rhs[fr[k]];
      u_o = cholesky.extend(cholesky.solve_reduced(b_r), false).col(0);

      // e = -R^T f_r over the free degrees of freedom of the body's own
      // constraints (the rows of R there are the reduced rigid motions).
      e = Eigen::VectorXd::Zero(R.cols());
      for (const unsigned int i : free)
        e -= rhs[i] * R.row(i).transpose();
    }



    // @sect3{Condensation by blocked solves}
    template <int dim>
    void
    Condenser<dim>::condense(const unsigned int columns_per_pass)
    {
      Assert(cholesky.is_factorized(), dealii::ExcInternalError());
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
      s_o                = V.transpose() * u_o;
      G                  = R.transpose() * V;
    }



    template <int dim>
    dealii::Vector<double>
    Condenser<dim>::recover(const Eigen::VectorXd &r,
                            const Eigen::VectorXd &alpha) const
    {
      Eigen::VectorXd u = u_o + cholesky.solve(Eigen::VectorXd(V * r));
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
  } // namespace condensation
} // namespace dpana

#endif
