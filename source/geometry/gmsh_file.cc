// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/gmsh_file.h>

#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_in.h>

#include <fstream>
#include <sstream>

namespace dpana
{
  namespace geometry
  {
    namespace
    {
      // Reads the $PhysicalNames section whose header line @p in has just
      // passed: name -> tag of the groups of dimension dim - 1.
      void
      read_physical_names(
        std::istream                                      &in,
        const int                                          dim,
        const std::string                                 &error,
        std::map<std::string, dealii::types::boundary_id> &names)
      {
        unsigned int n = 0;
        std::string  line;
        in >> n;
        std::getline(in, line);
        for (unsigned int i = 0; i < n; ++i)
          {
            int          group_dim = -1;
            unsigned int tag       = 0;
            in >> group_dim >> tag;
            std::getline(in, line);
            if (!in)
              throw InputError(error + "': malformed $PhysicalNames section");
            // The name is the text between the double quotes.
            const auto        first = line.find('"');
            const auto        last  = line.rfind('"');
            const std::string name =
              (first != std::string::npos && last > first) ?
                line.substr(first + 1, last - first - 1) :
                dealii::Utilities::trim(line);
            if (group_dim != dim - 1)
              continue;
            if (names.count(name) != 0)
              throw InputError(error + "' names two boundaries '" + name + "'");
            names[name] = tag;
          }
      }



      // The first line of a deal.II exception text that says what went
      // wrong (its messages span several lines).
      std::string
      reason_of(const std::exception &e)
      {
        std::istringstream what(e.what());
        std::string        line, reason = "read error";
        while (std::getline(what, line))
          {
            line = dealii::Utilities::trim(line);
            if (!line.empty() && line.find("-----") == std::string::npos &&
                line.rfind("An error occurred", 0) != 0 &&
                line.rfind("Additional information", 0) != 0)
              reason = line;
          }
        return reason;
      }
    } // namespace



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



    // Checks the $MeshFormat of the file and reads its boundary names.
    template <int dim>
    void
    GmshFile<dim>::read_boundary_names()
    {
      const std::string error = parameter + ": mesh file '" + mesh_file;
      std::ifstream     in(mesh_file);
      if (mesh_file.empty() || !in)
        throw InputError(error + "' not found");

      names.clear();
      std::string line;
      bool        format_seen = false, names_seen = false;
      while (std::getline(in, line))
        if (line.rfind("$MeshFormat", 0) == 0)
          {
            double version   = 0;
            int    file_type = -1;
            in >> version >> file_type;
            if (!in || file_type != 0 || version < 2. || version >= 5.)
              throw InputError(error + "' is not an ASCII gmsh file of "
                                       "format 2.2 or 4.1");
            format_seen = true;
          }
        else if (line.rfind("$PhysicalNames", 0) == 0)
          {
            read_physical_names(in, dim, error, names);
            names_seen = true;
          }
      if (!format_seen)
        throw InputError(error + "' has no $MeshFormat section, it is not a "
                                 "gmsh file");
      if (!names_seen || names.empty())
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
          throw InputError(error + "' could not be read: " + reason_of(e));
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
