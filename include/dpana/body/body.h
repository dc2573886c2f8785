// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_body_body_h
#define dpana_body_body_h

#include <dpana/body/boundary_conditions.h>
#include <dpana/body/loads.h>
#include <dpana/body/material.h>
#include <dpana/body/rigid_modes.h>
#include <dpana/geometry/geometry.h>
#include <dpana/linear_algebra/sparse_cholesky.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <deal.II/distributed/fully_distributed_tria.h>

#include <Eigen/Dense>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  namespace internal
  {
    template <int dim>
    struct WholeMeshData;
  }

  /**
   * One linear elastic body: its simplex mesh, the P1 displacement space,
   * the stiffness matrix K and load vector f with the kinematic conditions
   * eliminated, the rigid motions those conditions leave free, and, once
   * solved, the displacement and the stresses.
   *
   * <h3>Discretisation</h3>
   *
   * The displacement u is continuous and linear on every triangle or
   * tetrahedron: FESystem(FE_SimplexP(1), dim), with the MappingFE of the
   * same degree (the mapping every simplex computation must be given; the
   * default MappingQ1 of deal.II is for quadrilaterals and hexahedra). The
   * weak form of equilibrium, find u with the kinematic conditions such that
   * for all admissible v
   *
   *   \int_Omega eps(v) : C : eps(u) dx
   *     = \int_Omega v . b dx + \int_{Gamma_N} v . t ds + sum_k v(x_k) . F_k,
   *
   * gives K u = f. The strain of a P1 field is constant in each cell, so the
   * stiffness needs a single quadrature point; the loads use QGaussSimplex
   * rules that integrate quadratic integrands exactly.
   *
   * <h3>Kinematic conditions</h3>
   *
   * Every condition is a constraint on the nodal values at the vertices of
   * the faces of a named boundary, collected in one AffineConstraints
   * object: fixed components and prescribed displacements set a nodal value,
   * a symmetry condition sets the normal component u . n = 0 (for a boundary
   * normal to a coordinate axis simply that component, otherwise one
   * component as a combination of the others). K and f are assembled with
   * these constraints eliminated (u = M v + u_bar) and the SparseCholesky
   * factors the reduced matrix of the free unknowns v.
   *
   * <h3>Rigid motions</h3>
   *
   * A body is held if the only rigid motion (the 3 in 2D, 6 in 3D
   * infinitesimal translations and rotations) that satisfies the homogeneous
   * constraints is zero. setup() computes which ones are left free (see
   * RigidModes and free_rigid_modes()); K_r is singular exactly when there
   * are any.
   */
  template <int dim>
  class Body
  {
  public:
    /**
     * A rigid motion left free by the constraints: a combination, with the
     * given coefficients, of the columns of rigid_mode_vectors(), and its
     * description.
     */
    using RigidMode = dpana::RigidMode;

    /**
     * A concentrated force as applied: the requested point, the mesh vertex
     * nearest to it that carries the force, and the force.
     */
    struct AppliedConcentratedForce
    {
      dealii::Point<dim>     requested_point;
      dealii::Point<dim>     vertex;
      dealii::Tensor<1, dim> force;
    };

    /**
     * @p name is used in the log and in error messages, e.g. "Body 1".
     */
    explicit Body(const std::string &name = "Body 1");

    /**
     * Declares the subsections Geometry, Material, Boundary conditions and
     * Loads, each by its own component (geometry::Geometry, Material,
     * BoundaryConditions, Loads). The caller has entered the body's
     * subsection ("Body 1").
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Reads them (the caller has entered the body's subsection). Throws
     * dpana::InputError on bad values.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Builds the mesh described by the Geometry subsection.
     */
    void
    create_mesh();

    /**
     * The mesh, for programs that build it themselves; they must then call
     * set_boundary_names(). After setup() of a body whose mesh is
     * distributed (partition()), the cells of this rank and a layer of
     * ghost cells around them (a parallel::fullydistributed::Triangulation).
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
     * is distributed (known after setup()).
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
     * assembly phase.
     */
    double
    mesh_reading_time() const
    {
      return geometry->reading_time();
    }

    /**
     * The components of the body (its material, kinematic conditions and
     * loads), for programs that set them up themselves, and its name.
     */
    Material &
    material()
    {
      return material_;
    }
    const Material &
    material() const
    {
      return material_;
    }
    BoundaryConditions<dim> &
    boundary_conditions()
    {
      return bcs;
    }
    Loads<dim> &
    loads()
    {
      return loads_;
    }
    const std::string &
    name() const
    {
      return name_;
    }

    /**
     * Splits the body over the ranks of @p communicator for a distributed
     * assembly (doc/parallel.md), before setup(). setup() then partitions
     * the cells (METIS, through GridTools::partition_triangulation, on rank
     * 0, the subdomain of each cell sent to the others) and numbers the
     * degrees of freedom subdomain by subdomain, so that the dofs of each
     * rank are contiguous; assemble() assembles the cells of this rank
     * only. system_matrix() is then this rank's share of K (the sum of the
     * shares over the ranks is K), system_rhs() the whole f (summed over
     * the ranks). The mesh itself stays whole on every rank, unless
     * @p distribute_mesh (call partition() before create_mesh() then):
     * create_mesh() builds the whole mesh on rank 0 alone, and setup()
     * sends every rank the description of its cells, of which it builds a
     * parallel::fullydistributed::Triangulation with a layer of ghosts, on
     * which the degrees of freedom are numbered (deal.II's numbering,
     * contiguous on each rank) and the cells assembled, output and
     * collected into contact surfaces. What needs the whole mesh rank 0
     * computes before it releases it, in the numbering of one process: the
     * checks of the boundary names, the constraints, the supports and the
     * vertices of the concentrated forces (distributed_mesh.cc); every rank
     * translates them into its numbering. The vectors of all degrees of
     * freedom (f, u, the rigid motions), the points and dofs of every
     * vertex and the constraints stay whole on every rank. With one rank
     * nothing changes.
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
     * The number degree of freedom @p i has in the numbering of
     * DoFHandler::distribute_dofs() (that of one process), which the
     * numbering by subdomains of a partitioned body changes: results and
     * choices that depend on the order of the dofs are made in this order,
     * so that they do not depend on the number of ranks.
     */
    dealii::types::global_dof_index
    serial_dof_index(const dealii::types::global_dof_index i) const
    {
      return serial_index.empty() ? i : serial_index[i];
    }

    /**
     * Distributes the degrees of freedom, builds the constraints of the
     * boundary conditions and the sparsity pattern, and finds the free rigid
     * motions. Throws dpana::InputError for a boundary name that the mesh
     * does not have or no face carries, or a symmetry boundary that is not
     * flat.
     */
    void
    setup();

    /**
     * Throws dpana::InputError "Body 1: not held: rigid motions x, y are
     * free; ..." if free_rigid_modes() is not empty.
     */
    void
    check_held() const;

    /**
     * Assembles K and f with the constraints eliminated.
     */
    void
    assemble();

    /**
     * Factors K_r (sparse Cholesky) and solves for the displacement.
     */
    void
    solve();

    /**
     * Replaces the displacement by @p solution, a vector of the body's
     * degrees of freedom computed elsewhere (a contact run recovers it from
     * the contact tractions, u = K^{-1} (f + V r)). Call compute_stresses()
     * or postprocess() afterwards.
     */
    void
    set_solution(const dealii::Vector<double> &solution);

    /**
     * The stress in each cell (constant for P1), its out-of-plane component
     * in 2D and the von Mises stress, from the current displacement.
     */
    void
    compute_stresses();

    /**
     * compute_stresses(), and the reaction forces of the supported
     * boundaries.
     */
    void
    postprocess();

    // --- Results and internal objects -------------------------------------

    const dealii::DoFHandler<dim> &
    dof_handler() const
    {
      return dof_handler_;
    }
    const dealii::Mapping<dim> &
    mapping() const
    {
      return mapping_;
    }
    const dealii::FiniteElement<dim> &
    fe() const
    {
      return fe_;
    }
    const dealii::AffineConstraints<double> &
    constraints() const
    {
      return constraints_;
    }
    const dealii::SparseMatrix<double> &
    system_matrix() const
    {
      return matrix;
    }
    const dealii::Vector<double> &
    system_rhs() const
    {
      return rhs;
    }
    const dealii::Vector<double> &
    solution() const
    {
      return u;
    }
    const linear_algebra::SparseCholesky &
    factorization() const
    {
      return cholesky;
    }

    /**
     * Number of right-hand sides per CHOLMOD call in blocked solves with
     * the factorisation (parameter "Linear solver / Block size").
     */
    void
    set_solver_block_size(const unsigned int block_size)
    {
      cholesky.set_block_size(block_size);
    }

    /**
     * The degrees of freedom of every vertex of the mesh: dofs[v][c] is the
     * c-th displacement component at vertex v (invalid for unused vertices).
     * A distributed mesh: v is the vertex of the whole mesh.
     */
    const std::vector<std::array<dealii::types::global_dof_index, dim>> &
    vertex_dofs() const
    {
      return dofs_of_vertex;
    }

    /**
     * The vertices of the faces of a boundary id.
     */
    std::vector<unsigned int>
    boundary_vertices(const dealii::types::boundary_id id) const;

    /**
     * The nodal vectors of the rigid motions, one per column: translations
     * x, y (, z), then the rotation(s) about the centroid of the vertices,
     * scaled so that the largest nodal displacement of a rotation is 1.
     */
    const Eigen::MatrixXd &
    rigid_mode_vectors() const
    {
      return rigid_modes.vectors();
    }
    const std::vector<std::string> &
    rigid_mode_names() const
    {
      return rigid_modes.names();
    }

    /**
     * An orthonormal basis (in the coefficients of rigid_mode_vectors()) of
     * the rigid motions that satisfy the homogeneous constraints, each with
     * a description ("x", "rotation", "rotation about (1, 2)"...).
     */
    const std::vector<RigidMode> &
    free_rigid_modes() const
    {
      return free_modes;
    }

    const std::vector<AppliedConcentratedForce> &
    applied_concentrated_forces() const
    {
      return concentrated;
    }

    /**
     * Stress tensor of each active cell (index = active cell index).
     */
    const std::vector<dealii::SymmetricTensor<2, dim>> &
    cell_stress() const
    {
      return stress;
    }

    /**
     * sigma_zz of each cell in 2D (zero in plane stress), empty in 3D.
     */
    const std::vector<double> &
    cell_out_of_plane_stress() const
    {
      return stress_zz;
    }

    /**
     * Von Mises stress of each cell, sqrt(3 J2) of the full 3D stress.
     */
    const std::vector<double> &
    cell_von_mises() const
    {
      return von_mises;
    }

    /**
     * The largest von Mises stress of all cells (of all ranks, if the mesh
     * is distributed), from compute_stresses(); 0 before.
     */
    double
    max_von_mises() const
    {
      return max_von_mises_;
    }

    /**
     * For every named boundary that carries a kinematic condition, the
     * resultant of its support forces (N, or N/mm in 2D), from the nodal
     * residual r = K u - f of the supported vertices, split at a vertex
     * with several conditions along their directions (see postprocess()).
     * The reactions of all boundaries add up to minus
     * applied_load_resultant().
     */
    const std::map<std::string, dealii::Tensor<1, dim>> &
    reactions() const
    {
      return reaction;
    }

    /**
     * The resultant of all applied loads (body force, tractions, pressures,
     * concentrated forces).
     */
    dealii::Tensor<1, dim>
    applied_load_resultant() const
    {
      return applied_resultant;
    }

    /**
     * The warnings of the setup, one line each (e.g. a concentrated force
     * moved to a vertex far from its point); the log prints them and
     * summary.json lists them.
     */
    const std::vector<std::string> &
    warnings() const
    {
      return warnings_;
    }

    /**
     * Largest nodal displacement magnitude (mm).
     */
    double
    max_displacement() const;

  private:
    // The conditions acting at one supported vertex: (boundary, direction
    // of the support force).
    using SupportDirections =
      std::vector<std::pair<std::string, dealii::Tensor<1, dim>>>;

    std::string name_;

    std::unique_ptr<geometry::Geometry<dim>> geometry;
    // The whole mesh; with a distributed mesh, released by setup() once the
    // distributed one (local_mesh) is made.
    dealii::Triangulation<dim> tria;
    std::unique_ptr<dealii::parallel::fullydistributed::Triangulation<dim>>
                                                      local_mesh;
    bool                                              distribute_mesh_ = false;
    unsigned int                                      n_whole_cells    = 0;
    unsigned int                                      n_whole_vertices = 0;
    std::map<std::string, dealii::types::boundary_id> names;

    Material                material_;
    BoundaryConditions<dim> bcs;
    Loads<dim>              loads_;

    dealii::FESystem<dim>   fe_;
    dealii::MappingFE<dim>  mapping_;
    dealii::DoFHandler<dim> dof_handler_;
    std::vector<std::array<dealii::types::global_dof_index, dim>>
                                      dofs_of_vertex;
    dealii::AffineConstraints<double> constraints_;
    dealii::SparsityPattern           sparsity_pattern;
    dealii::SparseMatrix<double>      matrix;
    dealii::Vector<double>            rhs;
    dealii::Vector<double>            u;
    linear_algebra::SparseCholesky    cholesky;

    RigidModes<dim>                       rigid_modes;
    std::vector<RigidMode>                free_modes;
    std::vector<AppliedConcentratedForce> concentrated;
    // The mesh vertex of each of the concentrated forces.
    std::vector<unsigned int> concentrated_vertex;
    std::vector<std::string>  warnings_;

    std::vector<dealii::SymmetricTensor<2, dim>>  stress;
    std::vector<double>                           stress_zz;
    std::vector<double>                           von_mises;
    double                                        max_von_mises_ = 0;
    std::map<std::string, dealii::Tensor<1, dim>> reaction;
    // For every supported vertex, the conditions acting there.
    std::map<unsigned int, SupportDirections> support_directions;
    dealii::Tensor<1, dim>                    applied_resultant;

    // --- Set-up (body.cc) ---------------------------------------------------

    // The partition of partition(): the ranks, the number of parts and this
    // rank's part; for a partitioned body, the serial number of each dof.
    MPI_Comm                                     communicator_ = MPI_COMM_SELF;
    unsigned int                                 n_parts_      = 1;
    unsigned int                                 this_part_    = 0;
    std::vector<dealii::types::global_dof_index> serial_index;

    void
    partition_cells();
    void
    number_dofs_by_subdomain();
    // --- The distributed mesh (distributed_mesh.cc) ------------------------

    void
    create_whole_mesh_on_root();
    void
    set_up_distributed();
    void
    whole_mesh_data(internal::WholeMeshData<dim> &data);
    void
    number_serial_vertices(const std::vector<dealii::Point<dim>> &points);
    void
    apply_whole_mesh_data(const internal::WholeMeshData<dim> &data);

    dealii::types::boundary_id
    resolve(const std::string &boundary, const std::string &parameter) const;
    void
    check_boundary_names() const;
    void
    number_vertex_dofs();
    void
    locate_concentrated_forces();

    // --- Kinematic conditions (constraints.cc) ------------------------------

    void
    make_constraints();
    void
    constrain_components(const dealii::types::boundary_id id,
                         const std::string               &boundary,
                         const std::vector<bool>         &components,
                         const dealii::Function<dim>     *displacement);
    std::map<unsigned int, SupportDirections>
    symmetry_planes_at_vertices() const;
    void
    constrain_symmetry_at_vertex(const unsigned int       v,
                                 const SupportDirections &planes);

    // --- Assembly (assembly.cc) ---------------------------------------------

    // The quadrature rules and the FEValues objects of the assembly of
    // one cell (shared by assemble() and the reactions of postprocess()).
    struct CellValues
    {
      CellValues(const dealii::Mapping<dim>       &mapping,
                 const dealii::FiniteElement<dim> &fe);
      const dealii::QGaussSimplex<dim>     quadrature;
      const dealii::QGaussSimplex<dim - 1> face_quadrature;
      dealii::FEValues<dim>                fe_values;
      dealii::FEFaceValues<dim>            fe_face_values;
      // The strains and divergences of the shape functions on the cell
      // (constant for P1), kept from cell to cell.
      std::vector<dealii::SymmetricTensor<2, dim>> eps;
      std::vector<double>                          div;
    };
    void
    assemble_cell(
      const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
      CellValues                                                   &values,
      dealii::FullMatrix<double>                                   &cell_matrix,
      dealii::Vector<double> &cell_rhs) const;
    void
    assemble_boundary_loads(
      const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
      dealii::FEFaceValues<dim> &fe_face_values,
      dealii::Vector<double>    &cell_rhs) const;
    void
    add_concentrated_forces();

    // --- Postprocessing (postprocessing.cc) ---------------------------------

    dealii::Vector<double>
    nodal_residual();
    void
    split_reactions(const dealii::Vector<double> &residual);
  };
} // namespace dpana

#endif
