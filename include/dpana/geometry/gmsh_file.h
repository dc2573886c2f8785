// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_gmsh_file_h
#define dpana_geometry_gmsh_file_h

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
     * deal.II's GridIn::read_msh (stream overload, the built-in ASCII reader
     * of the formats 2.2 and 4.1) gives every boundary face the physical tag
     * of its boundary element as boundary id, and id 0 to the boundary faces
     * that belong to no physical group. The names of the tags come from the
     * $PhysicalNames section, which GridIn skips; it is read here, already
     * in parse_parameters(), by read_gmsh_sections(), which also checks the
     * sections GridIn reads without checking them (a file GridIn would
     * misread, a node tag given twice, a cell of zero measure), so that a
     * bad file, a missing file or an unnamed boundary is reported on one
     * line before any work is done. An error GridIn reports itself (e.g. an
     * element type it does not know) is given with GridIn's reason. The
     * boundary names are these physical names (of the groups of dimension dim -
     * 1); a boundary face in no named group is an input error. The global
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
       * The file name in quotes.
       */
      std::string
      description() const override;

    private:
      std::string                                       mesh_file;
      std::string                                       parameter;
      std::map<std::string, dealii::types::boundary_id> names;
      unsigned long long                                n_cells = 0;

      void
      read_boundary_names();

      void
      check_physical_groups(const dealii::Triangulation<dim> &tria) const;
    };
  } // namespace geometry
} // namespace dpana

#endif
