// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_body_body_mesh_h
#define dpana_body_body_mesh_h

#include <dpana/geometry/geometry.h>

#include <deal.II/base/mpi.h>

#include <deal.II/grid/tria.h>

#include <deal.II/distributed/fully_distributed_tria.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  /**
   * The mesh of a body and its partition over MPI ranks: the part of a Body
   * that knows cells, vertices and named boundaries but no degrees of
   * freedom. Body derives from it; the set-up that needs both (the
   * distributed mesh, the numbering of the dofs by subdomain) is Body's.
   *
   * <h3>Whole and distributed meshes</h3>
   *
   * On one process, and on several ranks with the replicated or the
   * distributed assembly on the whole mesh, every rank holds the whole mesh
   * (tria). With a distributed mesh (partition(communicator, true)) rank 0
   * builds the whole mesh alone, and Body::setup() replaces it on every rank
   * by a parallel::fullydistributed::Triangulation of that rank's cells and
   * a layer of ghost cells (local_mesh); n_cells() and n_vertices() still
   * count the whole mesh.
   */
  template <int dim>
  class BodyMesh
  {
  public:
    /**
     * The mesh, for programs that build it themselves; they must then call
     * set_boundary_names(). After Body::setup() of a body whose mesh is
     * distributed, the cells of this rank and a layer of ghost cells.
     */
    dealii::Triangulation<dim> &
    triangulation()
    {
      return local_mesh ? *local_mesh : tria;
    }
    const dealii::Triangulation<dim> &
    triangulation() const
    {
      return local_mesh ? *local_mesh : tria;
    }

    /**
     * The number of cells and of vertices of the whole mesh, also when it
     * is distributed (known after Body::setup()).
     */
    unsigned int
    n_cells() const
    {
      return n_whole_cells;
    }
    unsigned int
    n_vertices() const
    {
      return n_whole_vertices;
    }

    /**
     * The boundary names of the mesh and their boundary ids.
     */
    void
    set_boundary_names(
      const std::map<std::string, dealii::types::boundary_id> &new_names)
    {
      names = new_names;
    }
    const std::map<std::string, dealii::types::boundary_id> &
    boundary_names() const
    {
      return names;
    }

    /**
     * A one-line description of the geometry (for the log).
     */
    std::string
    geometry_description() const;

    /**
     * The wall time of reading the body's mesh file while the parameters
     * were read (s; 0 for a generated mesh), which the scene counts in the
     * mesh phase.
     */
    double
    mesh_reading_time() const
    {
      return geometry ? geometry->reading_time() : 0.;
    }

    /**
     * Splits the body over the ranks of @p communicator for a distributed
     * assembly (doc/parallel.md), before Body::setup(), which partitions
     * the cells (METIS on rank 0, the subdomain of each cell sent to the
     * others), numbers the dofs of each rank contiguously and assembles
     * each rank's cells only. The mesh stays whole on every rank, unless
     * @p distribute_mesh (call partition() before Body::create_mesh()
     * then): rank 0 alone builds the whole mesh, computes what needs it
     * (the checks of the boundary names, the constraints, the supports, the
     * vertices of the concentrated forces) in the numbering of one process
     * and sends every rank the description of its cells
     * (distributed_mesh.cc). With one rank nothing changes.
     */
    void
    partition(const MPI_Comm communicator, const bool distribute_mesh = false);

    /**
     * The number of parts of partition() (1 if it was not called) and the
     * part of this rank, which is the subdomain id of its cells.
     */
    unsigned int
    n_parts() const
    {
      return n_parts_;
    }
    unsigned int
    this_part() const
    {
      return this_part_;
    }

    /**
     * The ranks of partition() (MPI_COMM_SELF if it was not called).
     */
    MPI_Comm
    communicator() const
    {
      return communicator_;
    }

    /**
     * The vertices of the faces of a boundary id, while the whole mesh
     * exists (on a distributed body only during the set-up).
     */
    std::vector<unsigned int>
    boundary_vertices(const dealii::types::boundary_id id) const;

  protected:
    /**
     * The boundary id of a boundary name used by @p parameter. Throws
     * dpana::InputError if the mesh has no such name or no face carries it.
     */
    dealii::types::boundary_id
    resolve(const std::string &boundary, const std::string &parameter) const;

    /**
     * Partitions the cells of the whole mesh into n_parts_ subdomains (rank
     * 0 partitions, every rank receives the subdomain of every cell).
     */
    void
    partition_cells();

    bool
    mesh_is_distributed() const
    {
      return n_parts_ > 1 && distribute_mesh_;
    }

    std::unique_ptr<geometry::Geometry<dim>> geometry;
    // The whole mesh; with a distributed mesh, released by Body::setup()
    // once the distributed one (local_mesh) is made.
    dealii::Triangulation<dim> tria;
    std::unique_ptr<dealii::parallel::fullydistributed::Triangulation<dim>>
                                                      local_mesh;
    unsigned int                                      n_whole_cells    = 0;
    unsigned int                                      n_whole_vertices = 0;
    std::map<std::string, dealii::types::boundary_id> names;

    // The partition of partition(): the ranks, whether the mesh is
    // distributed, the number of parts and this rank's part.
    MPI_Comm     communicator_    = MPI_COMM_SELF;
    bool         distribute_mesh_ = false;
    unsigned int n_parts_         = 1;
    unsigned int this_part_       = 0;
  };
} // namespace dpana

#endif
