// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The sparsity pattern of a P1 vector field built from the mesh vertices
// (make_vertex_sparsity_pattern) against deal.II's own, made cell by cell
// with the constraints eliminated (DoFTools::make_sparsity_pattern, the
// independent reference): every entry of deal.II's pattern must be in it,
// and it holds nothing but the dim x dim blocks of vertices that share a
// cell. Constraints within a vertex (a dof fixed, a dof tied to another
// component of its vertex, as an inclined symmetry plane does) are
// accepted; a constraint between two vertices makes it decline.

#include <dpana/body/vertex_sparsity.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <set>

#include <gtest/gtest.h>

namespace
{
  using namespace dealii;

  template <int dim>
  struct P1Field
  {
    Triangulation<dim> tria;
    FESystem<dim>      fe{FE_SimplexP<dim>(1), dim};
    DoFHandler<dim>    dofs;
    std::vector<std::array<types::global_dof_index, dim>> of_vertex;

    P1Field()
    {
      GridGenerator::subdivided_hyper_cube_with_simplices(tria, 3);
      dofs.reinit(tria);
      dofs.distribute_dofs(fe);
      of_vertex.resize(tria.n_vertices());
      std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        {
          cell->get_dof_indices(local);
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int c = 0; c < dim; ++c)
              of_vertex[cell->vertex_index(v)][c] =
                local[fe.component_to_system_index(c, v)];
        }
    }

    // The pairs of vertices that share a cell.
    std::set<std::pair<unsigned int, unsigned int>>
    vertex_pairs() const
    {
      std::set<std::pair<unsigned int, unsigned int>> pairs;
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          for (const unsigned int w : cell->vertex_indices())
            pairs.emplace(cell->vertex_index(v), cell->vertex_index(w));
      return pairs;
    }
  };

  template <int dim>
  void
  expect_superset_of_deal_ii(const P1Field<dim>              &field,
                             const AffineConstraints<double> &constraints)
  {
    SparsityPattern ours;
    ASSERT_TRUE(dpana::make_vertex_sparsity_pattern<dim>(
      field.tria, field.of_vertex, constraints, ours));
    DynamicSparsityPattern reference(field.dofs.n_dofs());
    DoFTools::make_sparsity_pattern(field.dofs, reference, constraints, false);
    ASSERT_EQ(ours.n_rows(), reference.n_rows());
    for (unsigned int i = 0; i < reference.n_rows(); ++i)
      for (auto e = reference.begin(i); e != reference.end(i); ++e)
        EXPECT_TRUE(ours.exists(i, e->column())) << i << " " << e->column();

    // Nothing but the blocks of vertices that share a cell: their number
    // of entries, dim^2 per (ordered) pair.
    EXPECT_EQ(ours.n_nonzero_elements(),
              dim * dim * field.vertex_pairs().size());
  }

  template <int dim>
  void
  check_vertex_pattern()
  {
    const P1Field<dim>        field;
    AffineConstraints<double> none;
    none.close();
    expect_superset_of_deal_ii(field, none);

    // Vertex 0 fixed in x, vertex 1's y tied to its x.
    AffineConstraints<double> within;
    within.add_line(field.of_vertex[0][0]);
    within.add_line(field.of_vertex[1][1]);
    within.add_entry(field.of_vertex[1][1], field.of_vertex[1][0], 0.5);
    within.close();
    expect_superset_of_deal_ii(field, within);

    // A dof of vertex 1 tied to a dof of vertex 2: declined.
    AffineConstraints<double> across;
    across.add_line(field.of_vertex[1][0]);
    across.add_entry(field.of_vertex[1][0], field.of_vertex[2][0], 1.0);
    across.close();
    SparsityPattern untouched;
    EXPECT_FALSE(dpana::make_vertex_sparsity_pattern<dim>(
      field.tria, field.of_vertex, across, untouched));
    EXPECT_EQ(untouched.n_rows(), 0u);
  }
} // namespace

TEST(VertexSparsity, HoldsDealIIsPattern2D)
{
  check_vertex_pattern<2>();
}

TEST(VertexSparsity, HoldsDealIIsPattern3D)
{
  check_vertex_pattern<3>();
}
