// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_body_rigid_modes_h
#define dpana_body_rigid_modes_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>

#include <Eigen/Dense>

#include <array>
#include <string>
#include <vector>

namespace dpana
{
  /**
   * A rigid motion left free by the constraints of a body: a combination,
   * with the given coefficients, of the columns of RigidModes::vectors(),
   * and a description for the log and the error messages ("x",
   * "rotation", "rotation about (1, 2)", "combination ...").
   */
  struct RigidMode
  {
    std::string     description;
    Eigen::VectorXd coefficients;
  };



  /**
   * The rigid motions of a body discretised by a nodal (P1) displacement
   * field, and those of them that its kinematic constraints leave free.
   *
   * <h3>Nodal vectors</h3>
   *
   * The infinitesimal rigid motions are spanned by the dim translations e_d
   * and the dim(dim-1)/2 rotations omega x (x - c) about the centroid c of
   * the used vertices (in 2D the single rotation (-(y - c_y), x - c_x); in
   * 3D the rotations about the x, y and z axes). The rotations are divided
   * by the largest distance L of a vertex from c, so that every column of
   * the matrix R of nodal values has entries of order one and the largest
   * nodal displacement of a rotation is 1. The columns are named "x", "y"
   * (, "z"), then "rotation" in 2D or "rotation about x", "rotation about
   * y", "rotation about z" in 3D.
   *
   * <h3>Free motions</h3>
   *
   * The constraints of the body are lines u_i = sum_j a_ij u_j + b_i. A
   * rigid motion R a satisfies their homogeneous part if and only if C R
   * a = 0, where row i of the small matrix C R (one column per rigid motion)
   * is R_i - sum_j a_ij R_j. The free rigid motions are thus the kernel of
   * C R, found from its singular value decomposition: its dimension is the
   * number of singular values below a tolerance 1e-8. The motions of
   * single columns that are free (a column of C R that vanishes) are
   * reported by their names; the part of the kernel orthogonal to them is
   * spanned by the leading left singular vectors of the kernel basis with
   * the named directions removed. In 2D such a motion with a rotation part
   * theta, a_x e_x + a_y e_y + theta (x - c)^perp / L, is a rotation about
   * the point q = c + L (-a_y, a_x) / theta and described as such; other
   * combinations list their coefficients.
   */
  template <int dim>
  class RigidModes
  {
  public:
    /**
     * The number of rigid motions: 3 in 2D, 6 in 3D.
     */
    static constexpr unsigned int n_modes = dim * (dim + 1) / 2;

    /**
     * No motions (an empty matrix of nodal vectors).
     */
    RigidModes() = default;

    /**
     * The nodal vectors of the rigid motions of the mesh @p tria, whose
     * vertex v carries the degrees of freedom @p vertex_dofs[v] (invalid
     * for unused vertices) among @p n_dofs.
     */
    RigidModes(
      const dealii::Triangulation<dim> &tria,
      const std::vector<std::array<dealii::types::global_dof_index, dim>>
                                           &vertex_dofs,
      const dealii::types::global_dof_index n_dofs);

    /**
     * The same for vertices given by their @p points, vertex v carrying the
     * degrees of freedom @p vertex_dofs[v] (a distributed mesh, whose
     * vertices every rank knows this way).
     */
    RigidModes(
      const std::vector<dealii::Point<dim>> &points,
      const std::vector<std::array<dealii::types::global_dof_index, dim>>
                                           &vertex_dofs,
      const dealii::types::global_dof_index n_dofs);

    /**
     * The matrix R of nodal vectors, one column per rigid motion.
     */
    const Eigen::MatrixXd &
    vectors() const
    {
      return nodal_vectors;
    }

    /**
     * The names of the columns of vectors().
     */
    const std::vector<std::string> &
    names() const
    {
      return mode_names;
    }

    /**
     * An orthonormal basis, in the coefficients of the columns of
     * vectors(), of the rigid motions that satisfy the homogeneous part of
     * @p constraints: first the free single columns, then the rest of the
     * kernel of C R.
     */
    std::vector<RigidMode>
    free_modes(const dealii::AffineConstraints<double> &constraints) const;

  private:
    dealii::Point<dim>       centre;
    double                   length = 1.0;
    Eigen::MatrixXd          nodal_vectors;
    std::vector<std::string> mode_names;

    /**
     * The centroid c of the used vertices and their largest distance L
     * from it.
     */
    void
    find_centre_and_length(const std::vector<dealii::Point<dim>> &points);

    /**
     * The small matrix C R of the homogeneous constraints applied to the
     * rigid motions (one row per constrained value, at least one row).
     */
    Eigen::MatrixXd
    constrained_motions(
      const dealii::AffineConstraints<double> &constraints) const;

    /**
     * The free rigid motions of the kernel basis @p kernel of C R that are
     * orthogonal to the free single columns @p named.
     */
    std::vector<RigidMode>
    combined_modes(const Eigen::MatrixXd           &kernel,
                   const std::vector<unsigned int> &named) const;

    /**
     * The description of the combination @p a of the columns.
     */
    std::string
    describe(const Eigen::VectorXd &a) const;
  };
} // namespace dpana

#endif
