// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#ifndef dpana_body_vertex_sparsity_h
#define dpana_body_vertex_sparsity_h

#include <deal.II/base/types.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <array>
#include <vector>

namespace dpana
{
  /**
   * The sparsity pattern of the stiffness matrix of a P1 vector field,
   * built from the mesh vertices: the dof of component a at vertex v
   * couples with every component of every vertex that shares a cell with
   * v (v included), in dim x dim blocks.
   *
   * deal.II's DoFTools::make_sparsity_pattern() finds the same couplings
   * cell by cell, in a dynamic pattern, and removes those of the
   * constrained dofs. The pattern here keeps them: it holds every entry of
   * that pattern as long as every constraint ties a dof to dofs of its own
   * vertex only (the symmetry planes, the supports and the Dirichlet
   * conditions of a body), which is checked; the entries it has in excess
   * stay zero in the assembled matrix. Returns false, and leaves
   * @p pattern as it was, when a constraint ties dofs of two vertices.
   *
   * @p dofs_of_vertex[v] holds the dofs of vertex v (the whole mesh, one
   * process).
   */
  template <int dim>
  bool
  make_vertex_sparsity_pattern(
    const dealii::Triangulation<dim> &tria,
    const std::vector<std::array<dealii::types::global_dof_index, dim>>
                                            &dofs_of_vertex,
    const dealii::AffineConstraints<double> &constraints,
    dealii::SparsityPattern                 &pattern);
} // namespace dpana

#endif
