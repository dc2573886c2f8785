// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The body: its parameters, the building of its mesh (the mesh itself and
// its partition over ranks are in body_mesh.cc), the set-up of its degrees of
// freedom (the kinematic conditions are in constraints.cc, the rigid motions in
// rigid_modes.cc), the solution, and the explicit instantiation of the
// class for dim = 2 and 3. The assembly and the postprocessing are in
// assembly.cc and postprocessing.cc.

#include <dpana/base/exceptions.h>
#include <dpana/body/body.h>
#include <dpana/body/vertex_sparsity.h>

#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_simplex_p.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>
#include <cmath>

namespace dpana
{
  namespace
  {
    // The sparsity pattern of K made by deal.II cell by cell, where the
    // couplings of the mesh vertices (vertex_sparsity.h) do not serve: a
    // constraint ties two vertices, or the body is partitioned. A
    // partitioned body keeps the couplings of its own cells only: the
    // pattern has a row for every dof (its start and its diagonal entry,
    // about 20 bytes a dof with the matrix) but the other entries of this
    // rank's share of K alone.
    template <int dim>
    void
    make_cell_sparsity_pattern(
      const dealii::DoFHandler<dim>           &dofs,
      const dealii::AffineConstraints<double> &constraints,
      const unsigned int                       n_parts,
      const unsigned int                       this_part,
      dealii::SparsityPattern                 &pattern)
    {
      dealii::DynamicSparsityPattern dsp(dofs.n_dofs());
      if (n_parts > 1)
        dealii::DoFTools::make_sparsity_pattern(
          dofs, dsp, constraints, false, this_part);
      else
        dealii::DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
      pattern.copy_from(dsp);
    }
  } // namespace



  // @sect3{Construction and parameters}

  template <int dim>
  Body<dim>::Body(const std::string &name)
    : name_(name)
    , fe_(dealii::FE_SimplexP<dim>(1), dim)
    , mapping_(dealii::FE_SimplexP<dim>(1))
    , applied_resultant()
  {
  }



  // The body enters the subsection of each of its components, which
  // declares and reads its own entries. The messages of the geometry do not
  // know the name of the body; it is added to them here.
  template <int dim>
  void
  Body<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    geometry::Geometry<dim>::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Material");
    Material::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Boundary conditions");
    BoundaryConditions<dim>::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Loads");
    Loads<dim>::declare_parameters(prm);
    prm.leave_subsection();
  }



  template <int dim>
  void
  Body<dim>::parse_parameters(dealii::ParameterHandler &prm)
  {
    geometry = std::make_unique<geometry::Geometry<dim>>();
    prm.enter_subsection("Geometry");
    try
      {
        geometry->parse_parameters(prm);
      }
    catch (const InputError &e)
      {
        // Name the body in the message, as all other entries do.
        throw InputError(name_ + " / " + e.what());
      }
    prm.leave_subsection();
    prm.enter_subsection("Material");
    material_.parse_parameters(prm, name_ + " / Material");
    prm.leave_subsection();
    prm.enter_subsection("Boundary conditions");
    bcs.parse_parameters(prm, name_ + " / Boundary conditions");
    prm.leave_subsection();
    prm.enter_subsection("Loads");
    loads_.parse_parameters(prm, name_ + " / Loads");
    prm.leave_subsection();
  }



  template <int dim>
  void
  Body<dim>::create_mesh()
  {
    AssertThrow(geometry != nullptr,
                dealii::ExcMessage("Body::create_mesh() needs the "
                                   "parameters of a Geometry subsection."));
    tria.clear();
    names = geometry->boundary_names();
    // What the geometry read to build the mesh (a mesh file's nodes and
    // cells) is freed once the mesh is built: with a distributed mesh on
    // every rank, though only rank 0 builds it.
    if (mesh_is_distributed())
      {
        create_whole_mesh_on_root();
        geometry->release_mesh_data();
        return;
      }
    try
      {
        geometry->create_triangulation(tria);
      }
    catch (const InputError &e)
      {
        throw InputError(name_ + " / " + e.what());
      }
    geometry->release_mesh_data();
    n_whole_cells    = tria.n_active_cells();
    n_whole_vertices = tria.n_used_vertices();
  }



  // @sect3{Named boundaries}

  // Every boundary name the kinematic conditions and the loads use must be
  // one the mesh has and some face carries (BodyMesh::resolve()).
  template <int dim>
  void
  Body<dim>::check_boundary_names() const
  {
    for (const auto &[boundary, parameter] : bcs.used_boundaries())
      resolve(boundary, parameter);
    for (const auto &[boundary, parameter] : loads_.used_boundaries())
      resolve(boundary, parameter);
  }



  // @sect3{Set-up: degrees of freedom, constraints, rigid motions}

  template <int dim>
  void
  Body<dim>::setup()
  {
    local_mesh.reset();
    serial_index.clear();
    if (mesh_is_distributed())
      {
        set_up_distributed();
        material_.check(name_ + " / Material");
      }
    else
      {
        // Check every input before any work is done.
        check_boundary_names();
        material_.check(name_ + " / Material");
        n_whole_cells    = tria.n_active_cells();
        n_whole_vertices = tria.n_used_vertices();
        dof_handler_.reinit(tria);
        if (n_parts_ > 1)
          partition_cells();
        dof_handler_.distribute_dofs(fe_);
        if (n_parts_ > 1)
          number_dofs_by_subdomain();
        number_vertex_dofs();
        make_constraints();
        rigid_modes =
          RigidModes<dim>(tria, dofs_of_vertex, dof_handler_.n_dofs());
        free_modes = rigid_modes.free_modes(constraints_);
        locate_concentrated_forces();
      }

    if (n_parts_ > 1 || !make_vertex_sparsity_pattern<dim>(
                          tria, dofs_of_vertex, constraints_, sparsity_pattern))
      make_cell_sparsity_pattern(
        dof_handler_, constraints_, n_parts_, this_part_, sparsity_pattern);
    matrix.reinit(sparsity_pattern);
    rhs.reinit(dof_handler_.n_dofs());
    u.reinit(dof_handler_.n_dofs());
  }



  // The dofs of subdomain 0 first, then those of subdomain 1, ... (a dof
  // on the boundary between subdomains goes to one of them), keeping their
  // relative order; serial_index remembers the number each had before.
  template <int dim>
  void
  Body<dim>::number_dofs_by_subdomain()
  {
    std::vector<dealii::types::global_dof_index> new_index(
      dof_handler_.n_dofs());
    dealii::DoFRenumbering::compute_subdomain_wise(new_index, dof_handler_);
    serial_index.resize(new_index.size());
    for (dealii::types::global_dof_index i = 0; i < new_index.size(); ++i)
      serial_index[new_index[i]] = i;
    dof_handler_.renumber_dofs(new_index);
  }



  // The nodal degrees of freedom of each vertex. For the vector-valued P1
  // element the cell-local degrees of freedom are ordered vertex by vertex,
  // component by component within a vertex; this is checked once.
  template <int dim>
  void
  Body<dim>::number_vertex_dofs()
  {
    for (unsigned int i = 0; i < fe_.n_dofs_per_cell(); ++i)
      AssertThrow(fe_.system_to_component_index(i).first == i % dim,
                  dealii::ExcInternalError());
    dofs_of_vertex.assign(tria.n_vertices(), {});
    for (auto &d : dofs_of_vertex)
      d.fill(dealii::numbers::invalid_dof_index);
    std::vector<dealii::types::global_dof_index> local(fe_.n_dofs_per_cell());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c < dim; ++c)
            dofs_of_vertex[cell->vertex_index(v)][c] = local[v * dim + c];
      }
  }



  // A concentrated force acts at the used vertex nearest to the requested
  // point (the first of them if several are equally near). A point farther
  // from every vertex than the largest cell is wide lies outside the body:
  // an error. A point that is not a vertex is moved: a warning.
  template <int dim>
  void
  Body<dim>::locate_concentrated_forces()
  {
    concentrated.clear();
    concentrated_vertex.clear();
    warnings_.clear();
    const auto &vertices = tria.get_vertices();
    double      h        = 0;
    for (const auto &cell : tria.active_cell_iterators())
      h = std::max(h, cell->diameter());
    for (const auto &cf : loads_.concentrated_forces)
      {
        unsigned int best = dealii::numbers::invalid_unsigned_int;
        for (unsigned int v = 0; v < vertices.size(); ++v)
          if (tria.vertex_used(v) &&
              (best == dealii::numbers::invalid_unsigned_int ||
               vertices[v].distance(cf.point) <
                 vertices[best].distance(cf.point)))
            best = v;
        const double      distance = vertices[best].distance(cf.point);
        std::stringstream text;
        text << "the point (" << cf.point << ") lies " << distance
             << " mm from the nearest vertex (" << vertices[best] << ")";
        if (distance > h)
          {
            text << ", farther than the largest cell is wide (" << h
                 << " mm): it is outside the body";
            throw InputError(cf.parameter + ": " + text.str());
          }
        if (distance > 1e-6 * h)
          warnings_.push_back(cf.parameter + ": " + text.str() +
                              ", where the force is applied");
        concentrated.push_back({cf.point, vertices[best], cf.force});
        concentrated_vertex.push_back(best);
      }
  }



  template <int dim>
  void
  Body<dim>::check_held() const
  {
    if (free_modes.empty())
      return;
    std::string list;
    for (const auto &m : free_modes)
      list += (list.empty() ? "" : ", ") + m.description;
    throw InputError(name_ + ": not held: rigid motion" +
                     (free_modes.size() > 1 ? "s " : " ") + list +
                     (free_modes.size() > 1 ? " are" : " is") +
                     " free; add Dirichlet or symmetry conditions");
  }



  // @sect3{Solution}

  template <int dim>
  void
  Body<dim>::solve()
  {
    check_held();
    cholesky.factorize(matrix, constraints_);
    cholesky.solve_condensed(rhs, u);
  }



  template <int dim>
  void
  Body<dim>::set_solution(const dealii::Vector<double> &solution)
  {
    AssertThrow(solution.size() == dof_handler_.n_dofs(),
                dealii::ExcDimensionMismatch(solution.size(),
                                             dof_handler_.n_dofs()));
    u = solution;
  }



  template <int dim>
  double
  Body<dim>::max_displacement() const
  {
    double m = 0;
    for (const auto &d : dofs_of_vertex)
      if (d[0] != dealii::numbers::invalid_dof_index)
        {
          double s = 0;
          for (unsigned int c = 0; c < dim; ++c)
            s += u[d[c]] * u[d[c]];
          m = std::max(m, std::sqrt(s));
        }
    return m;
  }



  // The members defined in this file and the inline ones; those of
  // constraints.cc, assembly.cc and postprocessing.cc are instantiated
  // there.
  template class Body<2>;
  template class Body<3>;
} // namespace dpana
