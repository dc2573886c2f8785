// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_body_body_h
#define dpana_body_body_h

#include <dpana/body/body_mesh.h>
#include <dpana/body/boundary_conditions.h>
#include <dpana/body/loads.h>
#include <dpana/body/material.h>
#include <dpana/body/rigid_modes.h>
#include <dpana/linear_algebra/sparse_cholesky.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <Eigen/Dense>

#include <array>
#include <map>
#include <memory>
#include <optional>
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
   * One linear elastic body: its simplex mesh (BodyMesh, with the
   * partition over MPI ranks), the P1 displacement space,
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
  class Body : public BodyMesh<dim>
  {
  public:
    /**
     * A rigid motion left free by the constraints: a combination, with the
     * given coefficients, of the columns of rigid_mode_vectors(), and its
     * description.
     */
    using RigidMode = dpana::RigidMode;

    // The mesh and its partition (BodyMesh), public as they are there.
    using BodyMesh<dim>::triangulation;
    using BodyMesh<dim>::boundary_vertices;

    /**
     * A concentrated force as applied: the requested point, the mesh vertex
     * nearest to it that carries the force, and the force.
     */
    struct AppliedConcentratedForce
    {
      dealii::Point<dim>     requested_point;
      dealii::Point<dim>     vertex;
      dealii::Tensor<1, dim> force;

      /// Sent from rank 0 to the other ranks with the whole mesh's data.
      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &requested_point &vertex &force;
      }
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
    // The mesh and its partition (BodyMesh), used by name in the set-up.
    using BodyMesh<dim>::geometry;
    using BodyMesh<dim>::tria;
    using BodyMesh<dim>::local_mesh;
    using BodyMesh<dim>::n_whole_cells;
    using BodyMesh<dim>::n_whole_vertices;
    using BodyMesh<dim>::names;
    using BodyMesh<dim>::communicator_;
    using BodyMesh<dim>::n_parts_;
    using BodyMesh<dim>::this_part_;
    using BodyMesh<dim>::resolve;
    using BodyMesh<dim>::partition_cells;
    using BodyMesh<dim>::mesh_is_distributed;

    // The conditions acting at one supported vertex: (boundary, direction
    // of the support force).
    using SupportDirections =
      std::vector<std::pair<std::string, dealii::Tensor<1, dim>>>;

    std::string name_;

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

    // For a partitioned body, the serial number of each dof.
    std::vector<dealii::types::global_dof_index> serial_index;

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

    // The FEValues objects of the assembly of one cell (shared by
    // assemble() and the reactions of postprocess()), made at their first
    // use: the stiffness needs none (p1_simplex.h), only a body force or a
    // boundary load does, and making them costs about 0.25 ms, a tenth of
    // the whole solve of a body of a few hundred cells.
    struct CellValues
    {
      CellValues(const dealii::Mapping<dim>       &mapping,
                 const dealii::FiniteElement<dim> &fe);
      dealii::FEValues<dim> &
      fe_values();
      dealii::FEFaceValues<dim> &
      fe_face_values();
      // The strains and divergences of the shape functions on the cell
      // (constant for P1), kept from cell to cell.
      std::vector<dealii::SymmetricTensor<2, dim>> eps;
      std::vector<double>                          div;

    private:
      const dealii::Mapping<dim>              &mapping;
      const dealii::FiniteElement<dim>        &fe;
      std::optional<dealii::FEValues<dim>>     cell;
      std::optional<dealii::FEFaceValues<dim>> face;
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
    add_concentrated_forces(dealii::Vector<double> *applied);
    void
    warn_of_loads_across_symmetry(const dealii::Vector<double> &applied);

    // --- Postprocessing (postprocessing.cc) ---------------------------------

    dealii::Vector<double>
    nodal_residual();
    void
    split_reactions(const dealii::Vector<double> &residual);
  };
} // namespace dpana

#endif
