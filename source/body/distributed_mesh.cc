// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The set-up of a body whose mesh is distributed over the MPI ranks
// (Body::partition() with distribute_mesh, doc/parallel.md): rank 0 alone
// builds the whole mesh, partitions it, computes there what needs the
// whole mesh and sends every rank the description of its cells; each rank
// then holds a parallel::fullydistributed::Triangulation of its cells and a
// layer of ghosts.

#include <dpana/base/exceptions.h>
#include <dpana/body/body.h>

#include <deal.II/base/mpi.templates.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <numeric>
#include <sstream>

#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <malloc.h>

namespace dpana
{
  namespace internal
  {
    // What rank 0 computes on the whole mesh for all ranks, in the
    // numbering of one process: the degrees of freedom of the serial
    // numbering (that of DoFHandler::distribute_dofs() on the whole mesh,
    // which keeps the components of a vertex consecutive) and the vertices
    // numbered by it (serial vertex = serial dof of its first component /
    // dim).
    template <int dim>
    struct WholeMeshData
    {
      // An error found on the whole mesh (an InputError's message), or
      // empty.
      std::string  error;
      unsigned int n_cells    = 0;
      unsigned int n_vertices = 0;
      // The point of every serial vertex.
      std::vector<dealii::Point<dim>> points;
      // The constraints, in serial dofs.
      std::vector<dealii::AffineConstraints<double>::ConstraintLine>
        constraint_lines;
      // The conditions at every supported serial vertex.
      std::map<unsigned int,
               std::vector<std::pair<std::string, dealii::Tensor<1, dim>>>>
        support_directions;
      // The concentrated forces, and the serial vertex of each.
      std::vector<typename Body<dim>::AppliedConcentratedForce> concentrated;
      std::vector<unsigned int> force_serial_vertices;
      std::vector<std::string>  warnings;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &error &n_cells &n_vertices &points &constraint_lines
          &support_directions &concentrated &force_serial_vertices &warnings;
      }
    };
  } // namespace internal



  namespace
  {
    // Sends @p description from rank 0 to rank @p rank, packed, in pieces
    // of at most 2^30 bytes (an MPI count is an int).
    constexpr unsigned long long piece = 1ULL << 30;

    template <int dim>
    void
    send_description(
      const dealii::TriangulationDescription::Description<dim, dim>
                        &description,
      const unsigned int rank,
      const MPI_Comm     communicator)
    {
      const std::vector<char> buffer =
        dealii::Utilities::pack(description, false);
      const unsigned long long size = buffer.size();
      MPI_Send(&size, 1, MPI_UNSIGNED_LONG_LONG, rank, 0, communicator);
      for (unsigned long long k = 0; k < size; k += piece)
        MPI_Send(buffer.data() + k,
                 static_cast<int>(std::min(piece, size - k)),
                 MPI_CHAR,
                 rank,
                 1,
                 communicator);
    }



    template <int dim>
    dealii::TriangulationDescription::Description<dim, dim>
    receive_description(const MPI_Comm communicator)
    {
      unsigned long long size = 0;
      MPI_Recv(&size,
               1,
               MPI_UNSIGNED_LONG_LONG,
               0,
               0,
               communicator,
               MPI_STATUS_IGNORE);
      std::vector<char> buffer(size);
      for (unsigned long long k = 0; k < size; k += piece)
        MPI_Recv(buffer.data() + k,
                 static_cast<int>(std::min(piece, size - k)),
                 MPI_CHAR,
                 0,
                 1,
                 communicator,
                 MPI_STATUS_IGNORE);
      return dealii::Utilities::unpack<
        dealii::TriangulationDescription::Description<dim, dim>>(buffer, false);
    }



    // Points ordered lexicographically.
    template <int dim>
    bool
    less(const dealii::Point<dim> &a, const dealii::Point<dim> &b)
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (a[d] != b[d])
          return a[d] < b[d];
      return false;
    }



    // The serial vertices sorted by their points.
    template <int dim>
    std::vector<unsigned int>
    sorted_by_point(const std::vector<dealii::Point<dim>> &points)
    {
      std::vector<unsigned int> sorted(points.size());
      std::iota(sorted.begin(), sorted.end(), 0);
      std::sort(sorted.begin(),
                sorted.end(),
                [&](const unsigned int a, const unsigned int b) {
                  return less(points[a], points[b]);
                });
      return sorted;
    }



    // The serial vertex at the point @p x, which must be among the
    // @p sorted points (sorted_by_point()): the distributed mesh copies the
    // points of the whole mesh, whose vertices lie at distinct points
    // (checked by rank 0).
    template <int dim>
    unsigned int
    find_vertex(const std::vector<dealii::Point<dim>> &points,
                const std::vector<unsigned int>       &sorted,
                const dealii::Point<dim>              &x)
    {
      const auto it =
        std::lower_bound(sorted.begin(),
                         sorted.end(),
                         x,
                         [&](const unsigned int v, const auto &p) {
                           return less(points[v], p);
                         });
      AssertThrow(it != sorted.end() && !less(x, points[*it]),
                  dealii::ExcInternalError());
      return *it;
    }
  } // namespace



  // @sect3{The whole mesh on rank 0}
  //
  // Rank 0 builds the whole mesh; the others only learn its size. An error
  // of the geometry reaches every rank, so that all stop alike.
  template <int dim>
  void
  Body<dim>::create_whole_mesh_on_root()
  {
    std::string error;
    if (this_part_ == 0)
      try
        {
          geometry->create_triangulation(tria);
          n_whole_cells    = tria.n_active_cells();
          n_whole_vertices = tria.n_used_vertices();
        }
      catch (const InputError &e)
        {
          error = name_ + " / " + e.what();
        }
    error = dealii::Utilities::MPI::broadcast(communicator_, error, 0);
    if (!error.empty())
      throw InputError(error);
    n_whole_cells =
      dealii::Utilities::MPI::broadcast(communicator_, n_whole_cells, 0);
    n_whole_vertices =
      dealii::Utilities::MPI::broadcast(communicator_, n_whole_vertices, 0);
  }



  // @sect3{The set-up of a distributed mesh}
  //
  // Rank 0, on the whole mesh (flattened: its active cells become coarse
  // cells, in their order, so that the ids of the cells give the order of
  // one process): the boundary checks, the serial numbering of the dofs,
  // the constraints, the vertices of the concentrated forces, the
  // partition by METIS and the description of every rank's cells, which
  // it sends. Every rank then builds its distributed mesh, numbers its
  // dofs (deal.II's numbering, contiguous on each rank), finds the serial
  // vertex of each vertex of its own cells by its point, and the pairs
  // (serial dof, dof) of all ranks are gathered: every rank knows the
  // serial number of every dof, the dofs of every serial vertex, and so
  // the constraints, supports and forces in its numbering.
  template <int dim>
  void
  Body<dim>::set_up_distributed()
  {
    internal::WholeMeshData<dim> data;
    if (this_part_ == 0)
      {
        try
          {
            check_boundary_names();
          }
        catch (const InputError &e)
          {
            data.error = e.what();
          }
        if (data.error.empty())
          {
            if (tria.n_levels() > 1)
              {
                dealii::Triangulation<dim> flat;
                dealii::GridGenerator::flatten_triangulation(tria, flat);
                tria.clear();
                tria.copy_triangulation(flat);
              }
            whole_mesh_data(data);
          }
      }
    data = dealii::Utilities::MPI::broadcast(communicator_, data, 0);
    if (!data.error.empty())
      throw InputError(data.error);

    dealii::TriangulationDescription::Description<dim, dim> description;
    if (this_part_ == 0)
      {
        dealii::GridTools::partition_triangulation(n_parts_, tria);
        namespace TD = dealii::TriangulationDescription;
        for (unsigned int r = 1; r < n_parts_; ++r)
          send_description(TD::Utilities::create_description_from_triangulation(
                             tria, communicator_, TD::default_setting, r),
                           r,
                           communicator_);
        description = TD::Utilities::create_description_from_triangulation(
          tria, communicator_, TD::default_setting, 0);
        tria.clear();
        malloc_trim(0);
      }
    else
      description = receive_description<dim>(communicator_);
    // The communicator is not part of the packed description.
    description.comm = communicator_;

    local_mesh =
      std::make_unique<dealii::parallel::fullydistributed::Triangulation<dim>>(
        communicator_);
    local_mesh->create_triangulation(description);
    description = {};
    dof_handler_.reinit(*local_mesh);
    dof_handler_.distribute_dofs(fe_);
    number_serial_vertices(data.points);
    apply_whole_mesh_data(data);
  }



  // Rank 0: the serial numbering of the dofs on the whole mesh, and what
  // the constraints, the supports and the concentrated forces are in it;
  // an InputError of these is kept in data.error.
  template <int dim>
  void
  Body<dim>::whole_mesh_data(internal::WholeMeshData<dim> &data)
  {
    dof_handler_.reinit(tria);
    dof_handler_.distribute_dofs(fe_);
    number_vertex_dofs();
    try
      {
        make_constraints();
        locate_concentrated_forces();
      }
    catch (const InputError &e)
      {
        data.error = e.what();
      }
    std::vector<unsigned int> serial_vertex(tria.n_vertices(), 0);
    data.points.resize(dof_handler_.n_dofs() / dim);
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      if (dofs_of_vertex[v][0] != dealii::numbers::invalid_dof_index)
        {
          serial_vertex[v] = dofs_of_vertex[v][0] / dim;
          for (unsigned int c = 0; c < dim; ++c)
            AssertThrow(dofs_of_vertex[v][c] == dim * serial_vertex[v] + c,
                        dealii::ExcInternalError());
          data.points[serial_vertex[v]] = tria.get_vertices()[v];
        }
    // Every rank finds its vertices by their points: two vertices at one
    // point (a mesh with coincident nodes) would be confused.
    const std::vector<unsigned int> sorted = sorted_by_point(data.points);
    for (unsigned int k = 1; k < sorted.size() && data.error.empty(); ++k)
      if (!less(data.points[sorted[k - 1]], data.points[sorted[k]]))
        {
          std::ostringstream point;
          point << data.points[sorted[k]];
          data.error = name_ + ": two vertices of the mesh lie at the point (" +
                       point.str() +
                       "); a distributed mesh finds its vertices by their "
                       "points (use Contact / Parallel mesh = whole)";
        }
    const auto &lines = constraints_.get_lines();
    data.constraint_lines.assign(lines.begin(), lines.end());
    for (const auto &[v, directions] : support_directions)
      data.support_directions[serial_vertex[v]] = directions;
    data.concentrated = concentrated;
    for (const unsigned int v : concentrated_vertex)
      data.force_serial_vertices.push_back(serial_vertex[v]);
    data.warnings   = warnings_;
    data.n_cells    = tria.n_active_cells();
    data.n_vertices = tria.n_used_vertices();
    dof_handler_.clear();
  }



  // Every rank: the serial vertex of each vertex of its own cells, found by
  // its point, and the pairs (serial vertex, its dofs here) of all ranks
  // gathered: dofs_of_vertex (by serial vertex) and serial_index.
  template <int dim>
  void
  Body<dim>::number_serial_vertices(
    const std::vector<dealii::Point<dim>> &points)
  {
    const std::vector<unsigned int> sorted = sorted_by_point(points);
    std::vector<dealii::types::global_dof_index> own;
    std::vector<dealii::types::global_dof_index> local(fe_.n_dofs_per_cell());
    std::vector<bool> seen(local_mesh->n_vertices(), false);
    for (const auto &cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(local);
          for (const unsigned int v : cell->vertex_indices())
            if (!seen[cell->vertex_index(v)])
              {
                seen[cell->vertex_index(v)] = true;
                own.push_back(find_vertex(points, sorted, cell->vertex(v)));
                for (unsigned int c = 0; c < dim; ++c)
                  own.push_back(local[v * dim + c]);
              }
        }
    dofs_of_vertex.assign(points.size(), {});
    serial_index.assign(dof_handler_.n_dofs(),
                        dealii::numbers::invalid_dof_index);
    for (const auto &part :
         dealii::Utilities::MPI::all_gather(communicator_, own))
      for (std::size_t k = 0; k < part.size(); k += dim + 1)
        for (unsigned int c = 0; c < dim; ++c)
          {
            dofs_of_vertex[part[k]][c]    = part[k + 1 + c];
            serial_index[part[k + 1 + c]] = dim * part[k] + c;
          }
    AssertThrow(std::none_of(serial_index.begin(),
                             serial_index.end(),
                             [](const auto i) {
                               return i == dealii::numbers::invalid_dof_index;
                             }),
                dealii::ExcInternalError());
  }



  // Every rank: the constraints, supports and forces of rank 0 in this
  // numbering, and the rigid motions from the points of the vertices.
  template <int dim>
  void
  Body<dim>::apply_whole_mesh_data(const internal::WholeMeshData<dim> &data)
  {
    n_whole_cells    = data.n_cells;
    n_whole_vertices = data.n_vertices;
    std::vector<dealii::types::global_dof_index> dof_of_serial(
      serial_index.size());
    for (dealii::types::global_dof_index i = 0; i < serial_index.size(); ++i)
      dof_of_serial[serial_index[i]] = i;

    constraints_.clear();
    for (const auto &line : data.constraint_lines)
      {
        const auto i = dof_of_serial[line.index];
        constraints_.add_line(i);
        for (const auto &[j, a] : line.entries)
          constraints_.add_entry(i, dof_of_serial[j], a);
        constraints_.set_inhomogeneity(i, line.inhomogeneity);
      }
    constraints_.close();
    support_directions  = data.support_directions;
    concentrated        = data.concentrated;
    concentrated_vertex = data.force_serial_vertices;
    warnings_           = data.warnings;

    rigid_modes =
      RigidModes<dim>(data.points, dofs_of_vertex, dof_handler_.n_dofs());
    free_modes = rigid_modes.free_modes(constraints_);
  }



  template void
  Body<2>::create_whole_mesh_on_root();
  template void
  Body<3>::create_whole_mesh_on_root();
  template void
  Body<2>::set_up_distributed();
  template void
  Body<3>::set_up_distributed();
} // namespace dpana
