// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The mesh of a body: its description for the log, its named boundaries,
// and the partition of its cells over MPI ranks.

#include <dpana/base/exceptions.h>
#include <dpana/body/body_mesh.h>

#include <deal.II/grid/grid_tools.h>

#include <set>
#include <sstream>

namespace dpana
{
  template <int dim>
  std::string
  BodyMesh<dim>::geometry_description() const
  {
    std::ostringstream s;
    if (geometry)
      s << geometry->description() << ", ";
    const bool whole = !local_mesh;
    s << (whole ? tria.n_active_cells() : n_whole_cells)
      << (dim == 2 ? " triangles" : " tetrahedra") << ", "
      << (whole ? tria.n_used_vertices() : n_whole_vertices) << " vertices";
    return s.str();
  }



  // A boundary name used by a parameter must be one of the names of the
  // mesh, and some boundary face must carry it: a condition on an empty set
  // of faces would silently do nothing.
  template <int dim>
  dealii::types::boundary_id
  BodyMesh<dim>::resolve(const std::string &boundary,
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
  BodyMesh<dim>::boundary_vertices(const dealii::types::boundary_id id) const
  {
    std::set<unsigned int> vertices;
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary() && face->boundary_id() == id)
        for (const unsigned int v : face->vertex_indices())
          vertices.insert(face->vertex_index(v));
    return {vertices.begin(), vertices.end()};
  }



  // @sect3{Partition over MPI ranks}
  //
  // partition() only records the ranks; setup() partitions, when the mesh
  // is complete.
  template <int dim>
  void
  BodyMesh<dim>::partition(const MPI_Comm communicator,
                           const bool     distribute_mesh)
  {
    communicator_    = communicator;
    distribute_mesh_ = distribute_mesh;
    n_parts_         = dealii::Utilities::MPI::n_mpi_processes(communicator);
    this_part_       = dealii::Utilities::MPI::this_mpi_process(communicator);
  }



  // The cells split into n_parts_ subdomains of about equal size with few
  // faces between them (METIS on the graph of cells that share a face).
  // Rank 0 partitions and sends the subdomain of every active cell to the
  // others, so that all ranks hold the same partition whatever the
  // partitioner does with its ties.
  template <int dim>
  void
  BodyMesh<dim>::partition_cells()
  {
    std::vector<unsigned int> subdomain(tria.n_active_cells());
    if (this_part_ == 0)
      {
        dealii::GridTools::partition_triangulation(n_parts_, tria);
        for (const auto &cell : tria.active_cell_iterators())
          subdomain[cell->active_cell_index()] = cell->subdomain_id();
      }
    MPI_Bcast(
      subdomain.data(), subdomain.size(), MPI_UNSIGNED, 0, communicator_);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_subdomain_id(subdomain[cell->active_cell_index()]);
  }



  template class BodyMesh<2>;
  template class BodyMesh<3>;
} // namespace dpana
