// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_gmsh_file_h
#define dpana_geometry_gmsh_file_h

#include <dpana/geometry/gmsh_sections.h>
#include <dpana/geometry/shape.h>

namespace dpana
{
  namespace geometry
  {
    /**
     * A mesh read from an ASCII gmsh file (format 2.2 or 4.1) of triangles
     * (2D) or tetrahedra (3D): the type `gmsh`, `subsection Gmsh`, entry
     * Mesh file. Lengths in the file are mm.
     *
     * The file is read once, already in parse_parameters(), by
     * read_gmsh_mesh(), which checks what a reader of the format usually
     * takes for granted (a file of one version written in the layout of
     * another, a node tag given twice, a cell of zero measure), so that a
     * bad file, a missing file or an unnamed boundary is reported on one
     * line before any work is done. create_triangulation() builds the mesh
     * from what was read, as deal.II's GridIn::read_msh would: every
     * boundary face gets the physical tag of its boundary element as
     * boundary id, and id 0 if it belongs to no physical group. The
     * boundary names are the $PhysicalNames of the groups of dimension dim -
     * 1; a boundary face in no named group is an input error. The global
     * refinements act on the simplices read.
     */
    template <int dim>
    class GmshFile : public Shape<dim>
    {
    public:
      /**
       * Declares Mesh file.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path) override;

      void
      create_triangulation(
        dealii::Triangulation<dim> &tria,
        const unsigned int          n_global_refinements) const override;

      std::map<std::string, dealii::types::boundary_id>
      boundary_names() const override;

      /**
       * The cells of the file, 2^dim children per refinement.
       */
      std::pair<double, std::string>
      estimated_size(const unsigned int n_global_refinements) const override;

      /**
       * The file name in quotes and the time its reading took.
       */
      std::string
      description() const override;

      /**
       * The wall time of reading and checking the file in
       * parse_parameters() (s).
       */
      double
      reading_time() const override;

      /**
       * Frees the nodes and cells read (about 50 bytes per dof).
       */
      void
      release_mesh_data() override;

    private:
      std::string                                       mesh_file;
      std::string                                       parameter;
      std::map<std::string, dealii::types::boundary_id> names;
      unsigned long long                                n_cells = 0;
      GmshMesh                                          mesh;
      bool                                              released = false;
      double                                            seconds  = 0;

      void
      read_mesh();

      void
      check_physical_groups(const dealii::Triangulation<dim> &tria) const;
    };
  } // namespace geometry
} // namespace dpana

#endif
