// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/body/rigid_modes.h>

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace dpana
{
  namespace
  {
    // A singular value of C R, or the norm of one of its columns, below
    // this is zero: the rigid motion satisfies the constraints.
    constexpr double tolerance = 1e-8;



    // A basis of the kernel of the matrix @p CR: the right singular vectors
    // of its singular values that are zero.
    Eigen::MatrixXd
    kernel_basis(const Eigen::MatrixXd &CR)
    {
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(CR, Eigen::ComputeFullV);
      const auto                       &sigma = svd.singularValues();
      unsigned int                      rank  = 0;
      for (int i = 0; i < sigma.size(); ++i)
        if (sigma(i) > tolerance)
          ++rank;
      return svd.matrixV().rightCols(CR.cols() - rank);
    }
  } // namespace



  // @sect3{The nodal vectors of the rigid motions}

  namespace
  {
    // The used vertices of the mesh that carry dofs, in their order.
    template <int dim>
    std::vector<unsigned int>
    vertices_with_dofs(
      const dealii::Triangulation<dim> &tria,
      const std::vector<std::array<dealii::types::global_dof_index, dim>>
        &vertex_dofs)
    {
      std::vector<unsigned int> vertices;
      for (unsigned int v = 0; v < tria.n_vertices(); ++v)
        if (tria.vertex_used(v) &&
            vertex_dofs[v][0] != dealii::numbers::invalid_dof_index)
          vertices.push_back(v);
      return vertices;
    }

    // The entries of @p all at @p indices, in their order.
    template <typename T>
    std::vector<T>
    select(const std::vector<T> &all, const std::vector<unsigned int> &indices)
    {
      std::vector<T> selected;
      selected.reserve(indices.size());
      for (const unsigned int i : indices)
        selected.push_back(all[i]);
      return selected;
    }
  } // namespace



  // The mesh: the points and dofs of its used vertices that carry dofs
  // (found once, for both).
  template <int dim>
  RigidModes<dim>::RigidModes(
    const dealii::Triangulation<dim> &tria,
    const std::vector<std::array<dealii::types::global_dof_index, dim>>
                                         &vertex_dofs,
    const dealii::types::global_dof_index n_dofs)
  {
    const std::vector<unsigned int> vertices =
      vertices_with_dofs<dim>(tria, vertex_dofs);
    *this = RigidModes(select(tria.get_vertices(), vertices),
                       select(vertex_dofs, vertices),
                       n_dofs);
  }



  template <int dim>
  RigidModes<dim>::RigidModes(
    const std::vector<dealii::Point<dim>> &points,
    const std::vector<std::array<dealii::types::global_dof_index, dim>>
                                         &vertex_dofs,
    const dealii::types::global_dof_index n_dofs)
  {
    find_centre_and_length(points);
    nodal_vectors = Eigen::MatrixXd::Zero(n_dofs, n_modes);
    for (unsigned int v = 0; v < points.size(); ++v)
      {
        const auto  x = (points[v] - centre) / length;
        const auto &d = vertex_dofs[v];
        for (unsigned int c = 0; c < dim; ++c)
          nodal_vectors(d[c], c) = 1.0;
        if constexpr (dim == 2)
          {
            nodal_vectors(d[0], 2) = -x[1];
            nodal_vectors(d[1], 2) = x[0];
          }
        else
          {
            // Rotations about the x, y and z axes: e_k x (x - c).
            nodal_vectors(d[1], 3) = -x[2];
            nodal_vectors(d[2], 3) = x[1];
            nodal_vectors(d[0], 4) = x[2];
            nodal_vectors(d[2], 4) = -x[0];
            nodal_vectors(d[0], 5) = -x[1];
            nodal_vectors(d[1], 5) = x[0];
          }
      }
    if (dim == 2)
      mode_names = {"x", "y", "rotation"};
    else
      mode_names = {"x",
                    "y",
                    "z",
                    "rotation about x",
                    "rotation about y",
                    "rotation about z"};
  }



  template <int dim>
  void
  RigidModes<dim>::find_centre_and_length(
    const std::vector<dealii::Point<dim>> &points)
  {
    centre = dealii::Point<dim>();
    for (const auto &x : points)
      centre += x;
    centre /= points.size();
    length = 0;
    for (const auto &x : points)
      length = std::max(length, x.distance(centre));
  }



  // @sect3{The rigid motions the constraints leave free}

  template <int dim>
  Eigen::MatrixXd
  RigidModes<dim>::constrained_motions(
    const dealii::AffineConstraints<double> &constraints) const
  {
    const auto      lines = constraints.get_lines();
    Eigen::MatrixXd CR(std::max<std::size_t>(lines.size(), 1), n_modes);
    CR.setZero();
    unsigned int row = 0;
    for (const auto &line : lines)
      {
        CR.row(row) = nodal_vectors.row(line.index);
        for (const auto &[j, a] : line.entries)
          CR.row(row) -= a * nodal_vectors.row(j);
        ++row;
      }
    return CR;
  }



  template <int dim>
  std::vector<RigidMode>
  RigidModes<dim>::free_modes(
    const dealii::AffineConstraints<double> &constraints) const
  {
    const Eigen::MatrixXd CR = constrained_motions(constraints);

    // First the single named motions that are free...
    std::vector<unsigned int> named;
    for (unsigned int k = 0; k < n_modes; ++k)
      if (CR.col(k).norm() < tolerance)
        named.push_back(k);
    std::vector<RigidMode> modes;
    for (const unsigned int k : named)
      modes.push_back({mode_names[k], Eigen::VectorXd::Unit(n_modes, k)});

    // ... then the kernel of C R: its dimension is the number of free
    // motions; those not among the named ones are combinations.
    for (auto &mode : combined_modes(kernel_basis(CR), named))
      modes.push_back(std::move(mode));
    return modes;
  }



  // The named directions are removed from the kernel basis; the leading
  // left singular vectors of what remains span the other free motions.
  template <int dim>
  std::vector<RigidMode>
  RigidModes<dim>::combined_modes(const Eigen::MatrixXd           &kernel,
                                  const std::vector<unsigned int> &named) const
  {
    std::vector<RigidMode> modes;
    const std::size_t      n_free = kernel.cols();
    if (n_free <= named.size())
      return modes;
    Eigen::MatrixXd rest = kernel;
    for (const unsigned int k : named)
      rest.row(k).setZero();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd_rest(rest, Eigen::ComputeThinU);
    for (unsigned int i = 0; i < n_free - named.size(); ++i)
      {
        const Eigen::VectorXd a = svd_rest.matrixU().col(i);
        modes.push_back({describe(a), a});
      }
    return modes;
  }



  template <int dim>
  std::string
  RigidModes<dim>::describe(const Eigen::VectorXd &a) const
  {
    std::ostringstream s;
    s.precision(4);
    if (dim == 2 && std::abs(a(2)) > tolerance)
      {
        // a_x e_x + a_y e_y + theta (x - c)^perp / L is a rotation about
        // q = c + L (-a_y, a_x) / theta.
        dealii::Point<2> q(centre[0] - length * a(1) / a(2),
                           centre[1] + length * a(0) / a(2));
        for (unsigned int d = 0; d < 2; ++d)
          if (std::abs(q[d]) < 1e-10 * length)
            q[d] = 0.0;
        s << "rotation about (" << q[0] << ", " << q[1] << ")";
      }
    else
      {
        s << "combination";
        for (unsigned int k = 0; k < n_modes; ++k)
          if (std::abs(a(k)) > 1e-6)
            s << " " << a(k) << " (" << mode_names[k] << ")";
      }
    return s.str();
  }



  template class RigidModes<2>;
  template class RigidModes<3>;
} // namespace dpana
