// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/gmsh_file.h>
#include <dpana/geometry/gmsh_sections.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_in.h>

#include <cmath>
#include <fstream>

namespace dpana
{
  namespace geometry
  {
    template <int dim>
    void
    GmshFile<dim>::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Mesh file",
        "",
        dealii::Patterns::Anything(),
        "Path of an ASCII .msh file (format 2.2 or 4.1) of triangles (2D) or "
        "tetrahedra (3D), relative to the working directory. Boundary ids "
        "are the physical tags of the boundary elements and boundary names "
        "their $PhysicalNames; lengths in the file are mm.");
    }



    template <int dim>
    void
    GmshFile<dim>::parse_parameters(dealii::ParameterHandler &prm,
                                    const std::string        &path)
    {
      mesh_file = prm.get("Mesh file");
      parameter = path + " / Mesh file";
      read_boundary_names();
    }



    // Checks the sections of the file and reads its boundary names.
    template <int dim>
    void
    GmshFile<dim>::read_boundary_names()
    {
      const std::string error = parameter + ": mesh file '" + mesh_file;
      std::ifstream     in(mesh_file);
      if (mesh_file.empty() || !in)
        throw InputError(error + "' not found");
      const GmshOutline outline = read_gmsh_sections(in, dim, error);
      names                     = outline.boundary_names;
      n_cells                   = outline.n_cells;
      if (names.empty())
        throw InputError(error +
                         "' names no boundary: give every boundary a "
                         "physical group with a name, of dimension " +
                         std::to_string(dim - 1));
    }



    template <int dim>
    std::map<std::string, dealii::types::boundary_id>
    GmshFile<dim>::boundary_names() const
    {
      return names;
    }



    template <int dim>
    std::pair<double, std::string>
    GmshFile<dim>::estimated_size(const unsigned int n_global_refinements) const
    {
      return {n_cells * std::pow(2., dim * n_global_refinements),
              "Geometry / Global refinements"};
    }



    template <int dim>
    std::string
    GmshFile<dim>::description() const
    {
      return "'" + mesh_file + "'";
    }



    template <int dim>
    void
    GmshFile<dim>::create_triangulation(
      dealii::Triangulation<dim> &tria,
      const unsigned int          n_global_refinements) const
    {
      const std::string error = parameter + ": mesh file '" + mesh_file;
      std::ifstream     in(mesh_file);
      if (!in)
        throw InputError(error + "' not found");
      dealii::GridIn<dim> grid_in;
      grid_in.attach_triangulation(tria);
      try
        {
          grid_in.read_msh(in);
        }
      catch (const std::exception &e)
        {
          throw InputError(
            error + "' could not be read: " + parameters::one_line_message(e));
        }
      if (tria.n_active_cells() == 0 || !tria.all_reference_cells_are_simplex())
        throw InputError(error + "' must contain " +
                         (dim == 2 ? "triangles" : "tetrahedra") + " only");
      check_physical_groups(tria);
      tria.refine_global(n_global_refinements);
    }



    // Boundary faces outside every physical group come with id 0.
    template <int dim>
    void
    GmshFile<dim>::check_physical_groups(
      const dealii::Triangulation<dim> &tria) const
    {
      const auto id = unnamed_boundary_id(tria, names);
      if (id)
        throw InputError(
          parameter + ": mesh file '" + mesh_file + "' has boundary faces " +
          (*id == 0 ? std::string("in no physical group") :
                      "in the unnamed physical group " + std::to_string(*id)));
    }



    template class GmshFile<2>;
    template class GmshFile<3>;
  } // namespace geometry
} // namespace dpana
