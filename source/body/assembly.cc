// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The assembly of the stiffness matrix and the load vector of a body.

#include <dpana/base/exceptions.h>
#include <dpana/base/warnings.h>
#include <dpana/body/body.h>
#include <dpana/body/p1_simplex.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>

namespace dpana
{
  // @sect3{The cell terms}

  // The local stiffness matrix and load vector of one cell, without
  // constraints:
  //   K_ij = \int lambda div(phi_i) div(phi_j) + 2 mu eps(phi_i):eps(phi_j),
  //   f_i  = \int phi_i . b + \int_{faces with loads} phi_i . t,
  // with t = -p n on a pressure boundary.
  template <int dim>
  Body<dim>::CellValues::CellValues(const dealii::Mapping<dim>       &mapping,
                                    const dealii::FiniteElement<dim> &fe)
    : eps(fe.n_dofs_per_cell())
    , div(fe.n_dofs_per_cell())
    , mapping(mapping)
    , fe(fe)
  {
  }



  template <int dim>
  dealii::FEValues<dim> &
  Body<dim>::CellValues::fe_values()
  {
    if (!cell)
      cell.emplace(mapping,
                   fe,
                   dealii::QGaussSimplex<dim>(2),
                   dealii::update_values | dealii::update_quadrature_points |
                     dealii::update_JxW_values);
    return *cell;
  }



  template <int dim>
  dealii::FEFaceValues<dim> &
  Body<dim>::CellValues::fe_face_values()
  {
    if (!face)
      face.emplace(mapping,
                   fe,
                   dealii::QGaussSimplex<dim - 1>(2),
                   dealii::update_values | dealii::update_normal_vectors |
                     dealii::update_JxW_values);
    return *face;
  }



  template <int dim>
  void
  Body<dim>::assemble_cell(
    const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
    CellValues                                                   &values,
    dealii::FullMatrix<double>                                   &cell_matrix,
    dealii::Vector<double> &cell_rhs) const
  {
    const unsigned int n      = fe_.n_dofs_per_cell();
    const double       lambda = material_.lambda(dim);
    const double       mu     = material_.mu();

    cell_matrix = 0;
    cell_rhs    = 0;

    // P1 on a simplex with its affine mapping: the shape function of dof i
    // is e_c lambda_v, the unit vector of its component c times the
    // barycentric coordinate of its vertex v, so its strain
    // sym(e_c (x) grad lambda_v) and its divergence d lambda_v / d x_c are
    // constant on the cell, and the stiffness integral is the integrand
    // times the measure of the cell (p1_simplex.h).
    Assert(fe_.degree == 1 && n == dim * (dim + 1),
           dealii::ExcNotImplemented());
    const auto simplex = p1_simplex<dim>(cell);
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto [c, v] = fe_.system_to_component_index(i);
        dealii::Tensor<2, dim> gradient;
        gradient[c]   = simplex.gradients[v];
        values.eps[i] = dealii::symmetrize(gradient);
        values.div[i] = simplex.gradients[v][c];
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j <= i; ++j)
        cell_matrix(i, j) = (lambda * values.div[i] * values.div[j] +
                             2.0 * mu * (values.eps[i] * values.eps[j])) *
                            simplex.measure;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        cell_matrix(i, j) = cell_matrix(j, i);

    if (loads_.body_force)
      {
        auto &fe_values = values.fe_values();
        fe_values.reinit(cell);
        dealii::Vector<double> b(dim);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            loads_.body_force->vector_value(fe_values.quadrature_point(q), b);
            for (unsigned int i = 0; i < n; ++i)
              {
                const unsigned int c = fe_.system_to_component_index(i).first;
                cell_rhs(i) +=
                  fe_values.shape_value(i, q) * b[c] * fe_values.JxW(q);
              }
          }
      }

    if (!loads_.pressure.empty() || !loads_.traction.empty())
      assemble_boundary_loads(cell, values.fe_face_values(), cell_rhs);
  }



  // The pressures and tractions of all load entries on the boundary of a
  // face add up to one traction t - p n.
  template <int dim>
  void
  Body<dim>::assemble_boundary_loads(
    const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
    dealii::FEFaceValues<dim> &fe_face_values,
    dealii::Vector<double>    &cell_rhs) const
  {
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        {
          const auto             id     = cell->face(f)->boundary_id();
          double                 p      = 0;
          bool                   loaded = false;
          dealii::Tensor<1, dim> t;
          for (const auto &pl : loads_.pressure)
            if (names.at(pl.boundary) == id)
              {
                p += pl.pressure;
                loaded = true;
              }
          for (const auto &tl : loads_.traction)
            if (names.at(tl.boundary) == id)
              {
                t += tl.traction;
                loaded = true;
              }
          if (!loaded)
            continue;
          fe_face_values.reinit(cell, f);
          for (const unsigned int q : fe_face_values.quadrature_point_indices())
            {
              const auto traction = t - p * fe_face_values.normal_vector(q);
              for (unsigned int i = 0; i < fe_.n_dofs_per_cell(); ++i)
                {
                  const unsigned int c = fe_.system_to_component_index(i).first;
                  cell_rhs(i) += fe_face_values.shape_value(i, q) *
                                 traction[c] * fe_face_values.JxW(q);
                }
            }
        }
  }



  // @sect3{The global system}

  template <int dim>
  void
  Body<dim>::assemble()
  {
    matrix = 0;
    rhs    = 0;
    CellValues values(mapping_, fe_);

    const unsigned int                           n = fe_.n_dofs_per_cell();
    dealii::FullMatrix<double>                   cell_matrix(n, n);
    dealii::Vector<double>                       cell_rhs(n);
    std::vector<dealii::types::global_dof_index> local(n);
    // The resultant of the loads is summed on the way, before the
    // constraints move any of them onto supports: it is what the user
    // applied, in every run (the reactions of an elastic run, the contact
    // tractions of a contact run balance it).
    applied_resultant = 0;
    // The nodal loads as applied, before the constraints move them, for
    // the check of the loads on symmetry planes (summed over the parts of
    // a partitioned body, as f).
    dealii::Vector<double> applied(bcs.symmetry.empty() ? 0 : rhs.size());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        if (n_parts_ > 1 && cell->subdomain_id() != this_part_)
          continue;
        assemble_cell(cell, values, cell_matrix, cell_rhs);
        cell->get_dof_indices(local);
        // Most cells have no constrained dof: their entries go straight in
        // (the constraints' general path sorts and resolves every row).
        if (std::none_of(local.begin(), local.end(), [this](const auto i) {
              return constraints_.is_constrained(i);
            }))
          {
            matrix.add(local, cell_matrix);
            rhs.add(local, cell_rhs);
          }
        else
          constraints_.distribute_local_to_global(
            cell_matrix, cell_rhs, local, matrix, rhs);
        for (unsigned int i = 0; i < n; ++i)
          applied_resultant[fe_.system_to_component_index(i).first] +=
            cell_rhs[i];
        if (applied.size() > 0)
          applied.add(local, cell_rhs);
      }
    // A partitioned body: each rank has assembled its own cells; the
    // concentrated forces are added once (by rank 0), and the shares of f
    // and of the load resultant summed, so that every rank holds the whole
    // f. K stays in shares.
    if (n_parts_ == 1 || this_part_ == 0)
      {
        add_concentrated_forces(applied.size() > 0 ? &applied : nullptr);
        for (const auto &force : concentrated)
          applied_resultant += force.force;
      }
    if (n_parts_ > 1)
      {
        MPI_Allreduce(MPI_IN_PLACE,
                      rhs.begin(),
                      rhs.size(),
                      MPI_DOUBLE,
                      MPI_SUM,
                      communicator_);
        if (applied.size() > 0)
          MPI_Allreduce(MPI_IN_PLACE,
                        applied.begin(),
                        applied.size(),
                        MPI_DOUBLE,
                        MPI_SUM,
                        communicator_);
        double resultant[dim];
        for (unsigned int c = 0; c < dim; ++c)
          resultant[c] = applied_resultant[c];
        MPI_Allreduce(
          MPI_IN_PLACE, resultant, dim, MPI_DOUBLE, MPI_SUM, communicator_);
        for (unsigned int c = 0; c < dim; ++c)
          applied_resultant[c] = resultant[c];
      }
    // Loads beyond about 1e150 overflow in the squares of the solvers'
    // norms, near the largest double (1e307) already in the assembly's sums:
    // no answer could be trusted.
    const double sum = rhs.l1_norm();
    if (!std::isfinite(sum * sum))
      throw InputError(name_ +
                       " / Loads: the nodal forces are out of the range of "
                       "double precision (the square of their sum "
                       "overflows); the magnitudes of Pressure, Traction or "
                       "Concentrated forces are out of range");
    if (applied.size() > 0)
      warn_of_loads_across_symmetry(applied);
  }



  // A load normal to a plane of symmetry, at its vertices, has no mirror
  // image that would balance it in the whole body (its mirror image is its
  // negative): the symmetry condition takes it as a support would, and the
  // body never feels it. A tangential force at the axis of a half model,
  // or a pressure on the symmetry line, is such a load: the run would
  // answer the problem without it. Loads of faces that meet the plane at
  // an angle leave a small share there (the mirror face balances it), far
  // below the bound of 1e-3 of the loads' sum. Every rank of a partitioned
  // body holds the whole of @p applied and finds the same planes: on the
  // whole mesh, or with a distributed one, which holds only the ranks' own
  // cells, among the supports that rank 0 found on the whole mesh (a plane
  // is there at every vertex where it constrains a component).
  template <int dim>
  void
  Body<dim>::warn_of_loads_across_symmetry(
    const dealii::Vector<double> &applied)
  {
    std::map<unsigned int, SupportDirections> planes_at_vertices;
    if (mesh_is_distributed())
      {
        for (const auto &[v, supports] : support_directions)
          for (const auto &support : supports)
            if (std::any_of(bcs.symmetry.begin(),
                            bcs.symmetry.end(),
                            [&](const auto &s) {
                              return s.boundary == support.first;
                            }))
              planes_at_vertices[v].push_back(support);
      }
    else
      planes_at_vertices = symmetry_planes_at_vertices();
    std::map<std::string, double> across;
    for (const auto &[v, planes] : planes_at_vertices)
      for (const auto &[boundary, normal] : planes)
        {
          double f_n = 0;
          for (unsigned int c = 0; c < dim; ++c)
            f_n += applied[dofs_of_vertex[v][c]] * normal[c];
          across[boundary] += std::abs(f_n);
        }
    const double sum = applied.l1_norm();
    for (const auto &[boundary, f] : across)
      if (f > 1e-3 * sum)
        {
          std::ostringstream text;
          text << std::setprecision(6) << name_ << " / Loads: loads of " << f
               << " in all act across the symmetry boundary '" << boundary
               << "' (normal to it, at its vertices), of a sum of " << sum
               << " of all the loads; its symmetry condition takes them as "
                  "a support would, and the body does not feel them (a load "
                  "across a plane of symmetry has no mirror image: the "
                  "model is not symmetric)";
          add_warning(warnings_, text.str());
        }
  }



  // Concentrated forces at vertices; a force on a constrained value is
  // taken by the support (or passed on to the values it depends on).
  template <int dim>
  void
  Body<dim>::add_concentrated_forces(dealii::Vector<double> *applied)
  {
    for (unsigned int k = 0; k < concentrated.size(); ++k)
      {
        dealii::Vector<double>                       force(dim);
        std::vector<dealii::types::global_dof_index> dofs(dim);
        for (unsigned int c = 0; c < dim; ++c)
          {
            force[c] = concentrated[k].force[c];
            dofs[c]  = dofs_of_vertex[concentrated_vertex[k]][c];
          }
        constraints_.distribute_local_to_global(force, dofs, rhs);
        if (applied != nullptr)
          applied->add(dofs, force);
      }
  }



  // The functions called from the other files of the class.
  template Body<2>::CellValues::CellValues(const dealii::Mapping<2> &,
                                           const dealii::FiniteElement<2> &);
  template Body<3>::CellValues::CellValues(const dealii::Mapping<3> &,
                                           const dealii::FiniteElement<3> &);
  template void
  Body<2>::assemble_cell(const dealii::DoFHandler<2>::active_cell_iterator &,
                         CellValues &,
                         dealii::FullMatrix<double> &,
                         dealii::Vector<double> &) const;
  template void
  Body<3>::assemble_cell(const dealii::DoFHandler<3>::active_cell_iterator &,
                         CellValues &,
                         dealii::FullMatrix<double> &,
                         dealii::Vector<double> &) const;
  template void
  Body<2>::assemble();
  template void
  Body<3>::assemble();
} // namespace dpana
