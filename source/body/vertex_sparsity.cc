// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/body/vertex_sparsity.h>

#include <algorithm>

namespace dpana
{
  namespace
  {
    // The vertex of every dof; false if a constraint ties a dof to a dof
    // of another vertex.
    template <int dim>
    bool
    constraints_within_vertices(
      const std::vector<std::array<dealii::types::global_dof_index, dim>>
                                              &dofs_of_vertex,
      const dealii::AffineConstraints<double> &constraints,
      std::vector<unsigned int>               &vertex_of_dof)
    {
      for (unsigned int v = 0; v < dofs_of_vertex.size(); ++v)
        for (const auto dof : dofs_of_vertex[v])
          if (dof != dealii::numbers::invalid_dof_index)
            vertex_of_dof[dof] = v;
      for (const auto &line : constraints.get_lines())
        for (const auto &[master, weight] : line.entries)
          if (vertex_of_dof[master] != vertex_of_dof[line.index])
            return false;
      return true;
    }



    // The vertices that share a cell with each vertex (itself included),
    // sorted, in compressed rows.
    template <int dim>
    void
    vertex_neighbours(const dealii::Triangulation<dim> &tria,
                      std::vector<unsigned int>        &start,
                      std::vector<unsigned int>        &neighbours)
    {
      const unsigned int n = tria.n_vertices();
      start.assign(n + 1, 0);
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          start[cell->vertex_index(v) + 1] += cell->n_vertices();
      for (unsigned int v = 0; v < n; ++v)
        start[v + 1] += start[v];
      neighbours.resize(start[n]);
      std::vector<unsigned int> next(start.begin(), start.end() - 1);
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          for (const unsigned int w : cell->vertex_indices())
            neighbours[next[cell->vertex_index(v)]++] = cell->vertex_index(w);
      // Sort and drop repeated vertices, row by row, in place.
      unsigned int end = 0;
      for (unsigned int v = 0; v < n; ++v)
        {
          const auto first = neighbours.begin() + start[v];
          const auto last  = neighbours.begin() + start[v + 1];
          std::sort(first, last);
          const auto unique_end = std::unique(first, last);
          start[v]              = end;
          for (auto w = first; w != unique_end; ++w)
            neighbours[end++] = *w; // end <= w: the rows only move forward
        }
      start[n] = end;
      neighbours.resize(end);
    }
  } // namespace



  template <int dim>
  bool
  make_vertex_sparsity_pattern(
    const dealii::Triangulation<dim> &tria,
    const std::vector<std::array<dealii::types::global_dof_index, dim>>
                                            &dofs_of_vertex,
    const dealii::AffineConstraints<double> &constraints,
    dealii::SparsityPattern                 &pattern)
  {
    std::size_t n_dofs = 0;
    for (const auto &dofs : dofs_of_vertex)
      for (const auto dof : dofs)
        if (dof != dealii::numbers::invalid_dof_index)
          n_dofs = std::max<std::size_t>(n_dofs, dof + 1);
    std::vector<unsigned int> vertex_of_dof(n_dofs);
    if (!constraints_within_vertices<dim>(dofs_of_vertex,
                                          constraints,
                                          vertex_of_dof))
      return false;

    std::vector<unsigned int> start, neighbours;
    vertex_neighbours(tria, start, neighbours);
    std::vector<unsigned int> row_length(n_dofs);
    for (std::size_t i = 0; i < n_dofs; ++i)
      {
        const unsigned int v = vertex_of_dof[i];
        row_length[i]        = dim * (start[v + 1] - start[v]);
      }
    pattern.reinit(n_dofs, n_dofs, row_length);
    std::vector<dealii::types::global_dof_index> columns;
    for (std::size_t i = 0; i < n_dofs; ++i)
      {
        const unsigned int v = vertex_of_dof[i];
        columns.clear();
        for (unsigned int k = start[v]; k < start[v + 1]; ++k)
          for (const auto dof : dofs_of_vertex[neighbours[k]])
            columns.push_back(dof);
        std::sort(columns.begin(), columns.end());
        pattern.add_entries(i, columns.begin(), columns.end(), true);
      }
    pattern.compress();
    return true;
  }



  template bool
  make_vertex_sparsity_pattern<2>(
    const dealii::Triangulation<2> &,
    const std::vector<std::array<dealii::types::global_dof_index, 2>> &,
    const dealii::AffineConstraints<double> &,
    dealii::SparsityPattern &);
  template bool
  make_vertex_sparsity_pattern<3>(
    const dealii::Triangulation<3> &,
    const std::vector<std::array<dealii::types::global_dof_index, 3>> &,
    const dealii::AffineConstraints<double> &,
    dealii::SparsityPattern &);
} // namespace dpana
