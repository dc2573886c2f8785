// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The kinematic conditions of a body as constraints on its vertex values.

#include <dpana/base/exceptions.h>
#include <dpana/body/body.h>

#include <cmath>

namespace dpana
{
  namespace
  {
    // The unit normal of a boundary face: the rotated edge in 2D, the
    // cross product of two edges in 3D.
    template <typename FaceIterator>
    auto
    unit_face_normal(const FaceIterator &face)
    {
      constexpr int          dim = FaceIterator::AccessorType::space_dimension;
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
      return n;
    }



    // The normal of the flat boundary @p id of a symmetry condition @p s:
    // the normal of its faces, checked to be the same on all of them (up to
    // sign), and made exactly a coordinate axis when it is one to round-off.
    template <int dim>
    dealii::Tensor<1, dim>
    symmetry_plane_normal(const dealii::Triangulation<dim> &tria,
                          const dealii::types::boundary_id  id,
                          const typename BoundaryConditions<dim>::Symmetry &s)
    {
      dealii::Tensor<1, dim> normal;
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          {
            const dealii::Tensor<1, dim> n = unit_face_normal(face);
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
      return normal;
    }
  } // namespace



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
        AssertThrow(p.displacement && p.displacement->n_components == dim,
                    dealii::ExcMessage(
                      "A prescribed displacement needs a Function with dim "
                      "components."));
        constrain_components(resolve(p.boundary, p.parameter),
                             p.boundary,
                             p.components,
                             p.displacement.get());
      }
    for (const auto &f : bcs.fixed)
      constrain_components(resolve(f.boundary, f.parameter),
                           f.boundary,
                           f.components,
                           nullptr);
    for (const auto &[v, planes] : symmetry_planes_at_vertices())
      constrain_symmetry_at_vertex(v, planes);

    constraints_.close();
  }



  // The selected components of the vertex values of a boundary that no
  // earlier condition has constrained are set to the value of the
  // prescribed @p displacement there, or to zero without one. The support
  // force of each such value acts along the coordinate axis e_c.
  template <int dim>
  void
  Body<dim>::constrain_components(const dealii::types::boundary_id id,
                                  const std::string               &boundary,
                                  const std::vector<bool>         &components,
                                  const dealii::Function<dim>     *displacement)
  {
    for (const unsigned int v : boundary_vertices(id))
      for (unsigned int c = 0; c < dim; ++c)
        if (components[c] && !constraints_.is_constrained(dofs_of_vertex[v][c]))
          {
            constraints_.add_line(dofs_of_vertex[v][c]);
            dealii::Tensor<1, dim> e;
            e[c] = 1.0;
            support_directions[v].emplace_back(boundary, e);
            if (displacement != nullptr)
              constraints_.set_inhomogeneity(
                dofs_of_vertex[v][c],
                displacement->value(tria.get_vertices()[v], c));
          }
  }



  // Symmetry: u . n = 0 at every vertex of a flat boundary of normal n. A
  // vertex may lie on several symmetry planes (a corner), so the planes are
  // collected per vertex, in the order of the conditions.
  template <int dim>
  std::map<unsigned int, typename Body<dim>::SupportDirections>
  Body<dim>::symmetry_planes_at_vertices() const
  {
    std::map<unsigned int, SupportDirections> planes_at_vertex;
    for (const auto &s : bcs.symmetry)
      {
        const auto id     = resolve(s.boundary, s.parameter);
        const auto normal = symmetry_plane_normal(tria, id, s);
        for (const unsigned int v : boundary_vertices(id))
          planes_at_vertex[v].emplace_back(s.boundary, normal);
      }
    return planes_at_vertex;
  }



  // The symmetry conditions of one vertex, solved by Gauss-Jordan
  // elimination: each independent condition eliminates one component p that
  // no other condition has constrained (the one of largest coefficient),
  //   u_p = -sum_{j not eliminated} r_j u_j,
  // which for a plane normal to an axis is simply u_p = 0, and never ties
  // two components to each other in a cycle. A condition implied by those
  // already imposed at the vertex is dropped.
  template <int dim>
  void
  Body<dim>::constrain_symmetry_at_vertex(const unsigned int       v,
                                          const SupportDirections &planes)
  {
    const auto               &dofs = dofs_of_vertex[v];
    SupportDirections         rows;
    std::vector<unsigned int> pivots;
    std::array<bool, dim>     eliminated{};
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
        const unsigned int p = pivots[i];
        constraints_.add_line(dofs[p]);
        for (unsigned int c = 0; c < dim; ++c)
          if (!eliminated[c] && std::abs(rows[i].second[c]) > 1e-14)
            constraints_.add_entry(dofs[p], dofs[c], -rows[i].second[c]);
      }
  }



  template void
  Body<2>::make_constraints();
  template void
  Body<3>::make_constraints();
} // namespace dpana
