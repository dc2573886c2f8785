// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/gmsh_file.h>
#include <dpana/geometry/gmsh_sections.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

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
      read_mesh();
    }



    // Reads and checks the whole file, once, before any work is done; the
    // time it takes is counted in the assembly phase (reading_time()).
    template <int dim>
    void
    GmshFile<dim>::read_mesh()
    {
      const auto        start = std::chrono::steady_clock::now();
      const std::string error = parameter + ": mesh file '" + mesh_file;
      std::ifstream     in(mesh_file);
      if (mesh_file.empty() || !in)
        throw InputError(error + "' not found");
      mesh = read_gmsh_mesh(in, dim, error);
      if (mesh.n_cells() == 0)
        throw InputError(error + "' must contain " +
                         (dim == 2 ? "triangles" : "tetrahedra") + " only");
      names   = mesh.boundary_names;
      n_cells = mesh.n_cells();
      seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
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
      std::ostringstream s;
      s << "'" << mesh_file << "' (read in " << std::fixed
        << std::setprecision(2) << seconds << " s)";
      return s.str();
    }



    namespace
    {
      template <int dim>
      std::vector<dealii::Point<dim>>
      vertices_of(const GmshMesh &mesh)
      {
        std::vector<dealii::Point<dim>> vertices(mesh.nodes.size());
        for (std::size_t i = 0; i < vertices.size(); ++i)
          for (unsigned int d = 0; d < dim; ++d)
            vertices[i][d] = mesh.nodes[i][d];
        return vertices;
      }



      // The cells, their material ids the physical tags.
      template <int dim>
      std::vector<dealii::CellData<dim>>
      cells_of(const GmshMesh &mesh)
      {
        std::vector<dealii::CellData<dim>> cells(mesh.n_cells());
        for (std::size_t c = 0; c < cells.size(); ++c)
          {
            const auto first = mesh.cell_nodes.begin() + (dim + 1) * c;
            cells[c].vertices.assign(first, first + dim + 1);
            cells[c].material_id = mesh.cell_tags[c];
          }
        return cells;
      }



      // The boundary elements, their boundary ids the physical tags: lines
      // in 2D, triangles in 3D.
      template <int dim>
      dealii::SubCellData
      boundary_of(const GmshMesh &mesh)
      {
        dealii::SubCellData boundary;
        for (std::size_t f = 0; f < mesh.face_tags.size(); ++f)
          {
            const auto first = mesh.face_nodes.begin() + dim * f;
            if constexpr (dim == 2)
              {
                auto &line = boundary.boundary_lines.emplace_back();
                std::copy(first, first + 2, line.vertices.begin());
                line.boundary_id = mesh.face_tags[f];
              }
            else
              {
                auto &triangle = boundary.boundary_quads.emplace_back();
                triangle.vertices.assign(first, first + 3);
                triangle.boundary_id = mesh.face_tags[f];
              }
          }
        return boundary;
      }
    } // namespace



    template <int dim>
    void
    GmshFile<dim>::release_mesh_data()
    {
      mesh     = GmshMesh();
      released = true;
    }



    // The mesh read: the same cells, material ids and boundary ids as
    // GridIn::read_msh gives, cells of negative measure turned as it does;
    // nodes that no cell uses (GridIn keeps them, unused) are dropped.
    template <int dim>
    void
    GmshFile<dim>::create_triangulation(
      dealii::Triangulation<dim> &tria,
      const unsigned int          n_global_refinements) const
    {
      AssertThrow(!released,
                  dealii::ExcMessage("GmshFile::create_triangulation() after "
                                     "release_mesh_data()"));
      auto                vertices = vertices_of<dim>(mesh);
      auto                cells    = cells_of<dim>(mesh);
      dealii::SubCellData boundary = boundary_of<dim>(mesh);
      try
        {
          dealii::GridTools::delete_unused_vertices(vertices, cells, boundary);
          dealii::GridTools::invert_cells_with_negative_measure(vertices,
                                                                cells);
          tria.create_triangulation(vertices, cells, boundary);
        }
      catch (const std::exception &e)
        {
          throw InputError(
            parameter + ": mesh file '" + mesh_file +
            "' could not be read: " + parameters::one_line_message(e));
        }
      check_physical_groups(tria);
      tria.refine_global(n_global_refinements);
    }



    template <int dim>
    double
    GmshFile<dim>::reading_time() const
    {
      return seconds;
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
