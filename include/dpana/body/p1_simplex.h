// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The geometry of a P1 simplex: a triangle or a tetrahedron with the affine
// mapping of its vertices. Its P1 shape functions are its barycentric
// coordinates lambda_0 ... lambda_dim, whose gradients are constant on the
// cell. With the edge vectors of vertex 0 as the columns of
//   J = [x_1 - x_0, ..., x_dim - x_0],
// the mapping is x = x_0 + J xi, the reference coordinates are xi_k =
// lambda_k (k >= 1), so
//   grad lambda_k = row k-1 of J^{-1}   (k = 1 ... dim),
//   grad lambda_0 = -(grad lambda_1 + ... + grad lambda_dim),
// and the measure of the cell is |det J| / dim!.
//
// The assembly and the stresses of a body use this instead of an FEValues
// object: for P1 elements it gives the same gradients and measure with a
// few hundred operations per cell instead of the general mapping's work at
// every quadrature point (tests/unit/fe/p1_simplex_test.cc compares the
// two).
#ifndef dpana_body_p1_simplex_h
#define dpana_body_p1_simplex_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>

namespace dpana
{
  template <int dim>
  struct P1Simplex
  {
    // |det J| / dim!: the area of a triangle, the volume of a tetrahedron.
    double measure;
    // The gradients of the barycentric coordinates, one per vertex in the
    // cell's vertex order.
    std::array<dealii::Tensor<1, dim>, dim + 1> gradients;
  };



  template <int dim>
  P1Simplex<dim>
  p1_simplex(const std::array<dealii::Point<dim>, dim + 1> &vertices)
  {
    static_assert(dim == 2 || dim == 3, "triangles and tetrahedra only");
    dealii::Tensor<2, dim> J;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int i = 0; i < dim; ++i)
        J[i][k] = vertices[k + 1][i] - vertices[0][i];
    const double det = dealii::determinant(J);
    Assert(det != 0.0,
           dealii::ExcMessage("a simplex cell of zero measure: its vertices "
                              "are collinear (2D) or coplanar (3D)"));

    P1Simplex<dim> simplex;
    simplex.measure = std::abs(det) / (dim == 2 ? 2.0 : 6.0);
    const dealii::Tensor<2, dim> J_inverse = dealii::invert(J);
    simplex.gradients[0]                   = dealii::Tensor<1, dim>();
    for (unsigned int k = 1; k <= dim; ++k)
      {
        simplex.gradients[k] = J_inverse[k - 1];
        simplex.gradients[0] -= simplex.gradients[k];
      }
    return simplex;
  }



  // The same for a cell of a triangulation (its vertices in its own order,
  // which is the order of the vertex dofs of FE_SimplexP(1)).
  template <int dim, typename CellIterator>
  P1Simplex<dim>
  p1_simplex(const CellIterator &cell)
  {
    Assert(cell->n_vertices() == dim + 1,
           dealii::ExcMessage("P1 simplex geometry of a cell that is not a "
                              "simplex"));
    std::array<dealii::Point<dim>, dim + 1> vertices;
    for (unsigned int v = 0; v <= dim; ++v)
      vertices[v] = cell->vertex(v);
    return p1_simplex<dim>(vertices);
  }
} // namespace dpana

#endif
