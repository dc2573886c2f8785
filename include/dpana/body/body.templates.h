// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_body_body_templates_h
#define dpana_body_body_templates_h

#include <dpana/base/exceptions.h>
#include <dpana/body/body.h>
#include <dpana/body/boundary_conditions.templates.h>

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace dpana
{
  // @sect3{Construction and parameters}

  template <int dim>
  Body<dim>::Body(const std::string &name)
    : name_(name)
    , fe_(dealii::FE_SimplexP<dim>(1), dim)
    , mapping_(dealii::FE_SimplexP<dim>(1))
    , applied_resultant()
  {
  }



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
    geometry->create_triangulation(tria);
    names = geometry->boundary_names();
  }



  template <int dim>
  dealii::Triangulation<dim> &
  Body<dim>::triangulation()
  {
    return tria;
  }



  template <int dim>
  const dealii::Triangulation<dim> &
  Body<dim>::triangulation() const
  {
    return tria;
  }



  template <int dim>
  void
  Body<dim>::set_boundary_names(
    const std::map<std::string, dealii::types::boundary_id> &n)
  {
    names = n;
  }



  template <int dim>
  const std::map<std::string, dealii::types::boundary_id> &
  Body<dim>::boundary_names() const
  {
    return names;
  }



  template <int dim>
  std::string
  Body<dim>::geometry_description() const
  {
    std::ostringstream s;
    if (geometry)
      s << geometry->description() << ", ";
    s << tria.n_active_cells() << (dim == 2 ? " triangles" : " tetrahedra")
      << ", " << tria.n_used_vertices() << " vertices";
    return s.str();
  }



  template <int dim>
  Material &
  Body<dim>::material()
  {
    return material_;
  }



  template <int dim>
  const Material &
  Body<dim>::material() const
  {
    return material_;
  }



  template <int dim>
  BoundaryConditions<dim> &
  Body<dim>::boundary_conditions()
  {
    return bcs;
  }



  template <int dim>
  Loads<dim> &
  Body<dim>::loads()
  {
    return loads_;
  }



  template <int dim>
  const std::string &
  Body<dim>::name() const
  {
    return name_;
  }



  // @sect3{Set-up: degrees of freedom, constraints, rigid motions}

  // A boundary name used by a parameter must be one of the names of the
  // mesh, and some boundary face must carry it: a condition on an empty set
  // of faces would silently do nothing.
  template <int dim>
  dealii::types::boundary_id
  Body<dim>::resolve(const std::string &boundary,
                     const std::string &parameter) const
  {
    const auto it = names.find(boundary);
    if (it == names.end())
      {
        std::string list;
        for (const auto &[n, id] : names)
          list += (list.empty() ? "" : ", ") + n;
        throw InputError(parameter + ": no boundary named '" + boundary +
                         "' (this body has: " + list + ")");
      }
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary() && face->boundary_id() == it->second)
        return it->second;
    throw InputError(parameter + ": no face of the mesh carries boundary '" +
                     boundary + "' (id " + std::to_string(it->second) + ")");
  }



  template <int dim>
  std::vector<unsigned int>
  Body<dim>::boundary_vertices(const dealii::types::boundary_id id) const
  {
    std::set<unsigned int> vertices;
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary() && face->boundary_id() == id)
        for (const unsigned int v : face->vertex_indices())
          vertices.insert(face->vertex_index(v));
    return {vertices.begin(), vertices.end()};
  }



  template <int dim>
  void
  Body<dim>::setup()
  {
    // Check every boundary name before any work is done.
    for (const auto &[boundary, parameter] : bcs.used_boundaries())
      resolve(boundary, parameter);
    for (const auto &[boundary, parameter] : loads_.used_boundaries())
      resolve(boundary, parameter);
    material_.check(name_ + " / Material");

    dof_handler_.reinit(tria);
    dof_handler_.distribute_dofs(fe_);

    // The nodal degrees of freedom of each vertex. For the vector-valued P1
    // element the cell-local degrees of freedom are ordered vertex by
    // vertex, component by component within a vertex; check this once.
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
    component_of_dof.assign(dof_handler_.n_dofs(), 0);
    for (const auto &d : dofs_of_vertex)
      for (unsigned int c = 0; c < dim; ++c)
        if (d[c] != dealii::numbers::invalid_dof_index)
          component_of_dof[d[c]] = c;

    make_constraints();

    dealii::DynamicSparsityPattern dsp(dof_handler_.n_dofs());
    dealii::DoFTools::make_sparsity_pattern(dof_handler_,
                                            dsp,
                                            constraints_,
                                            false);
    sparsity_pattern.copy_from(dsp);
    matrix.reinit(sparsity_pattern);
    rhs.reinit(dof_handler_.n_dofs());
    u.reinit(dof_handler_.n_dofs());

    find_free_rigid_modes();
    locate_concentrated_forces();
  }



  // The kinematic conditions as constraints on vertex values. Prescribed
  // displacements come first, then fixed components, then symmetry
  // conditions: a vertex value constrained by an earlier condition is not
  // constrained again (so at a corner between a loaded and a fixed boundary
  // the prescribed value wins).
  template <int dim>
  void
  Body<dim>::make_constraints()
  {
    constraints_.clear();
    support_directions.clear();

    for (const auto &p : bcs.prescribed)
      {
        const auto id = resolve(p.boundary, p.parameter);
        AssertThrow(p.displacement && p.displacement->n_components == dim,
                    dealii::ExcMessage(
                      "A prescribed displacement needs a Function with dim "
                      "components."));
        for (const unsigned int v : boundary_vertices(id))
          for (unsigned int c = 0; c < dim; ++c)
            if (p.components[c] &&
                !constraints_.is_constrained(dofs_of_vertex[v][c]))
              {
                constraints_.add_line(dofs_of_vertex[v][c]);
                dealii::Tensor<1, dim> e;
                e[c] = 1.0;
                support_directions[v].emplace_back(p.boundary, e);
                constraints_.set_inhomogeneity(
                  dofs_of_vertex[v][c],
                  p.displacement->value(tria.get_vertices()[v], c));
              }
      }

    for (const auto &f : bcs.fixed)
      {
        const auto id = resolve(f.boundary, f.parameter);
        for (const unsigned int v : boundary_vertices(id))
          for (unsigned int c = 0; c < dim; ++c)
            if (f.components[c] &&
                !constraints_.is_constrained(dofs_of_vertex[v][c]))
              {
                constraints_.add_line(dofs_of_vertex[v][c]);
                dealii::Tensor<1, dim> e;
                e[c] = 1.0;
                support_directions[v].emplace_back(f.boundary, e);
              }
      }

    // Symmetry: the normal n of a flat boundary is computed from its faces
    // and checked to be the same on all of them (up to sign). Then u . n = 0
    // is imposed at every vertex of the boundary. A vertex may lie on
    // several symmetry planes (a corner), so the conditions are collected
    // per vertex first and solved there by Gauss-Jordan elimination: each
    // independent condition eliminates one component p that no other
    // condition has constrained (the one of largest coefficient),
    //   u_p = -sum_{j not eliminated} r_j u_j,
    // which for a plane normal to an axis is simply u_p = 0, and never ties
    // two components to each other in a cycle.
    std::map<unsigned int,
             std::vector<std::pair<std::string, dealii::Tensor<1, dim>>>>
      planes_at_vertex;
    for (const auto &s : bcs.symmetry)
      {
        const auto             id = resolve(s.boundary, s.parameter);
        dealii::Tensor<1, dim> normal;
        for (const auto &face : tria.active_face_iterators())
          if (face->at_boundary() && face->boundary_id() == id)
            {
              dealii::Tensor<1, dim> n;
              if constexpr (dim == 2)
                {
                  const auto t = face->vertex(1) - face->vertex(0);
                  n[0]         = t[1];
                  n[1]         = -t[0];
                }
              else
                n = dealii::cross_product_3d(face->vertex(1) - face->vertex(0),
                                             face->vertex(2) - face->vertex(0));
              n /= n.norm();
              if (normal.norm() == 0.0)
                normal = n;
              else if (std::abs(n * normal) < 1.0 - 1e-8)
                throw InputError(s.parameter + ": boundary '" + s.boundary +
                                 "' is not flat (a symmetry condition "
                                 "needs a plane)");
            }
        for (unsigned int d = 0; d < dim; ++d)
          if (std::abs(normal[d]) > 1.0 - 1e-12)
            {
              normal    = dealii::Tensor<1, dim>();
              normal[d] = 1.0;
            }
        for (const unsigned int v : boundary_vertices(id))
          planes_at_vertex[v].emplace_back(s.boundary, normal);
      }

    for (const auto &[v, planes] : planes_at_vertex)
      {
        const auto &dofs = dofs_of_vertex[v];
        std::vector<std::pair<std::string, dealii::Tensor<1, dim>>> rows;
        std::vector<unsigned int>                                   pivots;
        std::array<bool, dim> eliminated{};
        for (const auto &[boundary, n] : planes)
          {
            dealii::Tensor<1, dim> r = n;
            for (unsigned int i = 0; i < rows.size(); ++i)
              r -= r[pivots[i]] * rows[i].second;
            unsigned int p    = dealii::numbers::invalid_unsigned_int;
            double       best = 1e-8;
            for (unsigned int c = 0; c < dim; ++c)
              if (!eliminated[c] && !constraints_.is_constrained(dofs[c]) &&
                  std::abs(r[c]) > best)
                {
                  best = std::abs(r[c]);
                  p    = c;
                }
            // Nothing left to eliminate: the condition is implied by those
            // already imposed at this vertex.
            if (p == dealii::numbers::invalid_unsigned_int)
              continue;
            r /= r[p];
            for (auto &row : rows)
              row.second -= row.second[p] * r;
            rows.emplace_back(boundary, r);
            support_directions[v].emplace_back(boundary, n);
            pivots.push_back(p);
            eliminated[p] = true;
          }
        for (unsigned int i = 0; i < rows.size(); ++i)
          {
            const unsigned int p        = pivots[i];
            const auto        &boundary = rows[i].first;
            const auto        &r        = rows[i].second;
            constraints_.add_line(dofs[p]);
            for (unsigned int c = 0; c < dim; ++c)
              if (!eliminated[c] && std::abs(r[c]) > 1e-14)
                {
                  constraints_.add_entry(dofs[p], dofs[c], -r[c]);
                }
          }
      }

    constraints_.close();
  }



  // The rigid motions: translations e_d, and infinitesimal rotations
  // omega x (x - c) about the centroid c of the vertices, divided by the
  // largest distance L of a vertex from c so that all columns have entries
  // of order one. A combination R a of them satisfies the homogeneous
  // constraints (u_i = sum_j a_ij u_j) iff C R a = 0, where row i of C R is
  // (R_i - sum_j a_ij R_j). The free rigid motions are the kernel of the
  // small matrix C R (dim(dim+1)/2 columns), found with an SVD.
  template <int dim>
  void
  Body<dim>::find_free_rigid_modes()
  {
    const unsigned int n_modes  = dim == 2 ? 3 : 6;
    const auto        &vertices = tria.get_vertices();

    dealii::Point<dim> centre;
    unsigned int       n_used = 0;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (tria.vertex_used(v))
        {
          centre += vertices[v];
          ++n_used;
        }
    centre /= n_used;
    double L = 0;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (tria.vertex_used(v))
        L = std::max(L, vertices[v].distance(centre));

    rigid_modes = Eigen::MatrixXd::Zero(dof_handler_.n_dofs(), n_modes);
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (tria.vertex_used(v) &&
          dofs_of_vertex[v][0] != dealii::numbers::invalid_dof_index)
        {
          const auto  x = (vertices[v] - centre) / L;
          const auto &d = dofs_of_vertex[v];
          for (unsigned int c = 0; c < dim; ++c)
            rigid_modes(d[c], c) = 1.0;
          if constexpr (dim == 2)
            {
              rigid_modes(d[0], 2) = -x[1];
              rigid_modes(d[1], 2) = x[0];
            }
          else
            {
              // Rotations about the x, y and z axes: e_k x (x - c).
              rigid_modes(d[1], 3) = -x[2];
              rigid_modes(d[2], 3) = x[1];
              rigid_modes(d[0], 4) = x[2];
              rigid_modes(d[2], 4) = -x[0];
              rigid_modes(d[0], 5) = -x[1];
              rigid_modes(d[1], 5) = x[0];
            }
        }
    if (dim == 2)
      rigid_names = {"x", "y", "rotation"};
    else
      rigid_names = {"x",
                     "y",
                     "z",
                     "rotation about x",
                     "rotation about y",
                     "rotation about z"};

    const auto      lines = constraints_.get_lines();
    Eigen::MatrixXd CR(std::max<std::size_t>(lines.size(), 1), n_modes);
    CR.setZero();
    unsigned int row = 0;
    for (const auto &line : lines)
      {
        CR.row(row) = rigid_modes.row(line.index);
        for (const auto &[j, a] : line.entries)
          CR.row(row) -= a * rigid_modes.row(j);
        ++row;
      }

    const double tolerance = 1e-8;
    free_modes.clear();

    // First the single named motions that are free...
    std::vector<unsigned int> named;
    for (unsigned int k = 0; k < n_modes; ++k)
      if (CR.col(k).norm() < tolerance)
        named.push_back(k);

    // ... then the kernel of C R: its dimension is the number of free
    // motions; those not among the named ones are combinations.
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(CR, Eigen::ComputeFullV);
    const auto                       &sigma = svd.singularValues();
    unsigned int                      rank  = 0;
    for (int i = 0; i < sigma.size(); ++i)
      if (sigma(i) > tolerance)
        ++rank;
    const unsigned int n_free = n_modes - rank;
    Eigen::MatrixXd    kernel = svd.matrixV().rightCols(n_free);

    for (const unsigned int k : named)
      {
        RigidMode mode;
        mode.description  = rigid_names[k];
        mode.coefficients = Eigen::VectorXd::Unit(n_modes, k);
        free_modes.push_back(mode);
      }
    // Remove the named directions from the kernel basis and describe what
    // remains.
    if (n_free > named.size())
      {
        Eigen::MatrixXd rest = kernel;
        for (const unsigned int k : named)
          rest.row(k).setZero();
        Eigen::JacobiSVD<Eigen::MatrixXd> svd_rest(rest, Eigen::ComputeThinU);
        for (unsigned int i = 0; i < n_free - named.size(); ++i)
          {
            RigidMode mode;
            mode.coefficients    = svd_rest.matrixU().col(i);
            const auto        &a = mode.coefficients;
            std::ostringstream s;
            s.precision(4);
            if (dim == 2 && std::abs(a(2)) > tolerance)
              {
                // a_x e_x + a_y e_y + theta (x - c)^perp / L is a rotation
                // about q = c + L (-a_y, a_x) / theta.
                dealii::Point<2> q(centre[0] - L * a(1) / a(2),
                                   centre[1] + L * a(0) / a(2));
                for (unsigned int d = 0; d < 2; ++d)
                  if (std::abs(q[d]) < 1e-10 * L)
                    q[d] = 0.0;
                s << "rotation about (" << q[0] << ", " << q[1] << ")";
              }
            else
              {
                s << "combination";
                for (unsigned int k = 0; k < n_modes; ++k)
                  if (std::abs(a(k)) > 1e-6)
                    s << " " << a(k) << " (" << rigid_names[k] << ")";
              }
            mode.description = s.str();
            free_modes.push_back(mode);
          }
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



  // A concentrated force acts at the used vertex nearest to the requested
  // point.
  template <int dim>
  void
  Body<dim>::locate_concentrated_forces()
  {
    concentrated.clear();
    const auto &vertices = tria.get_vertices();
    for (const auto &cf : loads_.concentrated_forces)
      {
        unsigned int best = dealii::numbers::invalid_unsigned_int;
        for (unsigned int v = 0; v < vertices.size(); ++v)
          if (tria.vertex_used(v) &&
              (best == dealii::numbers::invalid_unsigned_int ||
               vertices[v].distance(cf.point) <
                 vertices[best].distance(cf.point)))
            best = v;
        concentrated.push_back({cf.point, vertices[best], cf.force});
      }
  }



  // @sect3{Assembly}

  // The local stiffness matrix and load vector of one cell, without
  // constraints:
  //   K_ij = \int lambda div(phi_i) div(phi_j) + 2 mu eps(phi_i):eps(phi_j),
  //   f_i  = \int phi_i . b + \int_{faces with loads} phi_i . t,
  // with t = -p n on a pressure boundary.
  template <int dim>
  Body<dim>::CellValues::CellValues(const dealii::Mapping<dim>       &mapping,
                                    const dealii::FiniteElement<dim> &fe)
    : quadrature(2)
    , face_quadrature(2)
    , fe_values(mapping,
                fe,
                quadrature,
                dealii::update_values | dealii::update_gradients |
                  dealii::update_quadrature_points | dealii::update_JxW_values)
    , fe_face_values(mapping,
                     fe,
                     face_quadrature,
                     dealii::update_values | dealii::update_normal_vectors |
                       dealii::update_JxW_values)
  {
  }



  template <int dim>
  void
  Body<dim>::assemble_cell(
    const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
    CellValues                                                   &values,
    dealii::FullMatrix<double>                                   &cell_matrix,
    dealii::Vector<double> &cell_rhs) const
  {
    auto &fe_values      = values.fe_values;
    auto &fe_face_values = values.fe_face_values;
    const dealii::FEValuesExtractors::Vector displacement(0);
    const unsigned int                       n      = fe_.n_dofs_per_cell();
    const double                             lambda = material_.lambda(dim);
    const double                             mu     = material_.mu();

    cell_matrix = 0;
    cell_rhs    = 0;
    fe_values.reinit(cell);

    std::vector<dealii::SymmetricTensor<2, dim>> eps(n);
    std::vector<double>                          div(n);
    dealii::Vector<double>                       b(dim);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            eps[i] = fe_values[displacement].symmetric_gradient(i, q);
            div[i] = dealii::trace(eps[i]);
          }
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            cell_matrix(i, j) +=
              (lambda * div[i] * div[j] + 2.0 * mu * (eps[i] * eps[j])) * JxW;
        if (loads_.body_force)
          {
            loads_.body_force->vector_value(fe_values.quadrature_point(q), b);
            for (unsigned int i = 0; i < n; ++i)
              {
                const unsigned int c = fe_.system_to_component_index(i).first;
                cell_rhs(i) += fe_values.shape_value(i, q) * b[c] * JxW;
              }
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        cell_matrix(i, j) = cell_matrix(j, i);

    if (loads_.pressure.empty() && loads_.traction.empty())
      return;
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
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int c = fe_.system_to_component_index(i).first;
                  cell_rhs(i) += fe_face_values.shape_value(i, q) *
                                 traction[c] * fe_face_values.JxW(q);
                }
            }
        }
  }



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
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        assemble_cell(cell, values, cell_matrix, cell_rhs);
        cell->get_dof_indices(local);
        constraints_.distribute_local_to_global(
          cell_matrix, cell_rhs, local, matrix, rhs);
      }

    // Concentrated forces at vertices; a force on a constrained value is
    // taken by the support (or passed on to the values it depends on).
    const auto &vertices = tria.get_vertices();
    for (const auto &cf : concentrated)
      {
        unsigned int v = 0;
        while (!(tria.vertex_used(v) && vertices[v] == cf.vertex))
          ++v;
        dealii::Vector<double>                       force(dim);
        std::vector<dealii::types::global_dof_index> dofs(dim);
        for (unsigned int c = 0; c < dim; ++c)
          {
            force[c] = cf.force[c];
            dofs[c]  = dofs_of_vertex[v][c];
          }
        constraints_.distribute_local_to_global(force, dofs, rhs);
      }
  }



  // @sect3{Solution and postprocessing}

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



  // Stresses: the strain of a P1 field is constant in a cell, so one
  // evaluation at the centroid gives it. The von Mises stress is that of the
  // full 3D stress tensor, with sigma_zz the out-of-plane stress in 2D:
  //   sigma_vM = sqrt( 1/2 [ (sxx - syy)^2 + (syy - szz)^2 + (szz - sxx)^2 ]
  //                    + 3 (sxy^2 + syz^2 + sxz^2) ) = sqrt(3 J2).
  template <int dim>
  void
  Body<dim>::compute_stresses()
  {
    const dealii::QGaussSimplex<dim>         centroid(1);
    dealii::FEValues<dim>                    fe_centroid(mapping_,
                                      fe_,
                                      centroid,
                                      dealii::update_gradients);
    const dealii::FEValuesExtractors::Vector displacement(0);
    stress.assign(tria.n_active_cells(), {});
    stress_zz.assign(dim == 2 ? tria.n_active_cells() : 0, 0.0);
    von_mises.assign(tria.n_active_cells(), 0.0);

    std::vector<dealii::SymmetricTensor<2, dim>> strain(1);
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        fe_centroid.reinit(cell);
        fe_centroid[displacement].get_function_symmetric_gradients(u, strain);
        const auto s   = material_.stress(strain[0]);
        const auto ci  = cell->active_cell_index();
        double     szz = 0;
        stress[ci]     = s;
        if constexpr (dim == 2)
          {
            szz           = material_.out_of_plane_stress(s);
            stress_zz[ci] = szz;
          }
        double sxx = s[0][0], syy = s[1][1];
        double szz3   = dim == 3 ? s[dim - 1][dim - 1] : szz;
        double shear2 = s[0][1] * s[0][1];
        if constexpr (dim == 3)
          shear2 += s[1][2] * s[1][2] + s[0][2] * s[0][2];
        von_mises[ci] = std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) +
                                         (syy - szz3) * (syy - szz3) +
                                         (szz3 - sxx) * (szz3 - sxx)) +
                                  3.0 * shear2);
      }
  }



  // Reactions: r = K u - f with the UNCONSTRAINED K and f, assembled cell by
  // cell; r vanishes (to round-off) at free values and is the support force
  // at constrained ones.
  template <int dim>
  void
  Body<dim>::postprocess()
  {
    compute_stresses();

    CellValues values(mapping_, fe_);

    const unsigned int         n = fe_.n_dofs_per_cell();
    dealii::Vector<double>     residual(u.size());
    dealii::FullMatrix<double> cell_matrix(n, n);
    dealii::Vector<double>     cell_rhs(n), u_local(n), Ku_local(n);
    std::vector<dealii::types::global_dof_index> local(n);
    applied_resultant = 0;

    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
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
    const auto &vertices = tria.get_vertices();
    for (const auto &cf : concentrated)
      for (unsigned int v = 0; v < vertices.size(); ++v)
        if (tria.vertex_used(v) && vertices[v] == cf.vertex)
          {
            for (unsigned int c = 0; c < dim; ++c)
              residual[dofs_of_vertex[v][c]] -= cf.force[c];
            applied_resultant += cf.force;
            break;
          }

    // The reactions: at a supported vertex the nodal residual r_v is the
    // sum of the support forces of the conditions acting there, each along
    // its own direction d_i (e_c for a fixed or prescribed component, the
    // normal for a symmetry plane): r_v = sum_i lambda_i d_i. Solving this
    // small system per vertex splits corner forces correctly between the
    // boundaries, and the reactions add up to minus the load resultant.
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



  // @sect3{Access}

  template <int dim>
  const dealii::DoFHandler<dim> &
  Body<dim>::dof_handler() const
  {
    return dof_handler_;
  }

  template <int dim>
  const dealii::Mapping<dim> &
  Body<dim>::mapping() const
  {
    return mapping_;
  }

  template <int dim>
  const dealii::FiniteElement<dim> &
  Body<dim>::fe() const
  {
    return fe_;
  }

  template <int dim>
  const dealii::AffineConstraints<double> &
  Body<dim>::constraints() const
  {
    return constraints_;
  }

  template <int dim>
  const dealii::SparseMatrix<double> &
  Body<dim>::system_matrix() const
  {
    return matrix;
  }

  template <int dim>
  const dealii::Vector<double> &
  Body<dim>::system_rhs() const
  {
    return rhs;
  }

  template <int dim>
  const dealii::Vector<double> &
  Body<dim>::solution() const
  {
    return u;
  }

  template <int dim>
  const linear_algebra::SparseCholesky &
  Body<dim>::factorization() const
  {
    return cholesky;
  }

  template <int dim>
  void
  Body<dim>::set_solver_block_size(const unsigned int block_size)
  {
    cholesky.set_block_size(block_size);
  }

  template <int dim>
  const std::vector<std::array<dealii::types::global_dof_index, dim>> &
  Body<dim>::vertex_dofs() const
  {
    return dofs_of_vertex;
  }

  template <int dim>
  const Eigen::MatrixXd &
  Body<dim>::rigid_mode_vectors() const
  {
    return rigid_modes;
  }

  template <int dim>
  const std::vector<std::string> &
  Body<dim>::rigid_mode_names() const
  {
    return rigid_names;
  }

  template <int dim>
  const std::vector<typename Body<dim>::RigidMode> &
  Body<dim>::free_rigid_modes() const
  {
    return free_modes;
  }

  template <int dim>
  const std::vector<typename Body<dim>::AppliedConcentratedForce> &
  Body<dim>::applied_concentrated_forces() const
  {
    return concentrated;
  }

  template <int dim>
  const std::vector<dealii::SymmetricTensor<2, dim>> &
  Body<dim>::cell_stress() const
  {
    return stress;
  }

  template <int dim>
  const std::vector<double> &
  Body<dim>::cell_out_of_plane_stress() const
  {
    return stress_zz;
  }

  template <int dim>
  const std::vector<double> &
  Body<dim>::cell_von_mises() const
  {
    return von_mises;
  }

  template <int dim>
  const std::map<std::string, dealii::Tensor<1, dim>> &
  Body<dim>::reactions() const
  {
    return reaction;
  }

  template <int dim>
  dealii::Tensor<1, dim>
  Body<dim>::applied_load_resultant() const
  {
    return applied_resultant;
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
} // namespace dpana

#endif
