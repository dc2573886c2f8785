// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The stresses of a body and the reaction forces of its supports.

#include <dpana/body/body.h>
#include <dpana/body/p1_simplex.h>

#include <algorithm>
#include <cmath>

namespace dpana
{
  namespace
  {
    // The von Mises stress of the full 3D stress tensor, with @p szz the
    // out-of-plane stress of a 2D body:
    //   sigma_vM = sqrt( 1/2 [ (sxx - syy)^2 + (syy - szz)^2 + (szz - sxx)^2 ]
    //                    + 3 (sxy^2 + syz^2 + sxz^2) ) = sqrt(3 J2).
    template <int dim>
    double
    von_mises_stress(const dealii::SymmetricTensor<2, dim> &s, const double szz)
    {
      double sxx = s[0][0], syy = s[1][1];
      double szz3   = dim == 3 ? s[dim - 1][dim - 1] : szz;
      double shear2 = s[0][1] * s[0][1];
      if constexpr (dim == 3)
        shear2 += s[1][2] * s[1][2] + s[0][2] * s[0][2];
      return std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) +
                              (syy - szz3) * (syy - szz3) +
                              (szz3 - sxx) * (szz3 - sxx)) +
                       3.0 * shear2);
    }
  } // namespace



  // @sect3{Stresses}

  // The strain of a P1 field is constant in a cell: with the gradients of
  // the barycentric coordinates (p1_simplex.h), grad u = sum over the dofs
  // i = (component c, vertex v) of u_i e_c (x) grad lambda_v.
  template <int dim>
  void
  Body<dim>::compute_stresses()
  {
    const unsigned int n_cells = triangulation().n_active_cells();
    stress.assign(n_cells, {});
    stress_zz.assign(dim == 2 ? n_cells : 0, 0.0);
    von_mises.assign(n_cells, 0.0);

    // A distributed mesh: the cells of this rank (the others are left at
    // zero; the output writes only these).
    std::vector<dealii::types::global_dof_index> local(fe_.n_dofs_per_cell());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const auto simplex = p1_simplex<dim>(cell);
        cell->get_dof_indices(local);
        dealii::Tensor<2, dim> gradient;
        for (unsigned int i = 0; i < local.size(); ++i)
          {
            const auto [c, v] = fe_.system_to_component_index(i);
            gradient[c] += u[local[i]] * simplex.gradients[v];
          }
        const auto s   = material_.stress(dealii::symmetrize(gradient));
        const auto ci  = cell->active_cell_index();
        double     szz = 0;
        stress[ci]     = s;
        if constexpr (dim == 2)
          {
            szz           = material_.out_of_plane_stress(s);
            stress_zz[ci] = szz;
          }
        von_mises[ci] = von_mises_stress(s, szz);
      }
    max_von_mises_ = 0;
    for (const double s : von_mises)
      max_von_mises_ = std::max(max_von_mises_, s);
    if (local_mesh)
      max_von_mises_ =
        dealii::Utilities::MPI::max(max_von_mises_, communicator_);
  }



  // @sect3{Reactions}

  template <int dim>
  void
  Body<dim>::postprocess()
  {
    compute_stresses();
    split_reactions(nodal_residual());
  }



  // The nodal residual r = K u - f with the UNCONSTRAINED K and f,
  // assembled cell by cell; r vanishes (to round-off) at free values and is
  // the support force at constrained ones. The resultant of the loads is
  // summed on the way. A distributed mesh: each rank sums its own cells,
  // and the sums of the ranks are added up (the residual of every dof on
  // every rank).
  template <int dim>
  dealii::Vector<double>
  Body<dim>::nodal_residual()
  {
    CellValues values(mapping_, fe_);

    const unsigned int         n = fe_.n_dofs_per_cell();
    dealii::Vector<double>     residual(u.size());
    dealii::FullMatrix<double> cell_matrix(n, n);
    dealii::Vector<double>     cell_rhs(n), u_local(n), Ku_local(n);
    std::vector<dealii::types::global_dof_index> local(n);
    applied_resultant = 0;

    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        assemble_cell(cell, values, cell_matrix, cell_rhs);
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < n; ++i)
          u_local[i] = u[local[i]];
        cell_matrix.vmult(Ku_local, u_local);
        for (unsigned int i = 0; i < n; ++i)
          {
            residual[local[i]] += Ku_local[i] - cell_rhs[i];
            applied_resultant[fe_.system_to_component_index(i).first] +=
              cell_rhs[i];
          }
      }
    if (local_mesh)
      {
        MPI_Allreduce(MPI_IN_PLACE,
                      residual.begin(),
                      residual.size(),
                      MPI_DOUBLE,
                      MPI_SUM,
                      communicator_);
        MPI_Allreduce(MPI_IN_PLACE,
                      &applied_resultant[0],
                      dim,
                      MPI_DOUBLE,
                      MPI_SUM,
                      communicator_);
      }
    for (unsigned int k = 0; k < concentrated.size(); ++k)
      {
        for (unsigned int c = 0; c < dim; ++c)
          residual[dofs_of_vertex[concentrated_vertex[k]][c]] -=
            concentrated[k].force[c];
        applied_resultant += concentrated[k].force;
      }
    return residual;
  }



  // At a supported vertex the nodal residual r_v is the sum of the support
  // forces of the conditions acting there, each along its own direction d_i
  // (e_c for a fixed or prescribed component, the normal for a symmetry
  // plane): r_v = sum_i lambda_i d_i. Solving this small system per vertex
  // splits corner forces correctly between the boundaries, and the
  // reactions add up to minus the load resultant.
  template <int dim>
  void
  Body<dim>::split_reactions(const dealii::Vector<double> &residual)
  {
    reaction.clear();
    for (const auto &[boundary, parameter] : bcs.used_boundaries())
      reaction[boundary] = dealii::Tensor<1, dim>();
    for (const auto &[v, directions] : support_directions)
      {
        Eigen::MatrixXd D(dim, directions.size());
        Eigen::VectorXd r(dim);
        for (unsigned int c = 0; c < dim; ++c)
          {
            r(c) = residual[dofs_of_vertex[v][c]];
            for (unsigned int i = 0; i < directions.size(); ++i)
              D(c, i) = directions[i].second[c];
          }
        const Eigen::VectorXd lambda = D.colPivHouseholderQr().solve(r);
        for (unsigned int i = 0; i < directions.size(); ++i)
          reaction[directions[i].first] += lambda(i) * directions[i].second;
      }
  }



  template void
  Body<2>::compute_stresses();
  template void
  Body<3>::compute_stresses();
  template void
  Body<2>::postprocess();
  template void
  Body<3>::postprocess();
} // namespace dpana
