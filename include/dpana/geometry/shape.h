// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_shape_h
#define dpana_geometry_shape_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <deal.II/grid/tria.h>

#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

namespace dpana
{
  namespace geometry
  {
    /**
     * One shape a body can take: the interface every shape of the
     * "Geometry" subsection implements (the brick, the discs and the half
     * cylinder, the annuli, the gmsh file). A shape owns its own
     * subsection, `subsection Rectangle`, `subsection Half disc`, ..., named
     * after its `Type`; Geometry<dim> declares these subsections, enters the
     * one of the chosen type and hands it to parse_parameters().
     *
     * Each shape also provides a static
     * `declare_parameters(dealii::ParameterHandler &)` that declares its
     * entries in its subsection (the caller has entered it).
     */
    template <int dim>
    class Shape
    {
    public:
      virtual ~Shape() = default;

      /**
       * Reads the entries of the shape's subsection, which the caller has
       * entered. @p path is the path of that subsection (e.g. "Geometry /
       * Half disc"): every dpana::InputError thrown starts with it.
       */
      virtual void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path) = 0;

      /**
       * Builds the simplex mesh with @p n_global_refinements uniform
       * refinements into the empty @p tria and sets the boundary ids of
       * boundary_names() on every boundary face.
       */
      virtual void
      create_triangulation(dealii::Triangulation<dim> &tria,
                           const unsigned int n_global_refinements) const = 0;

      /**
       * The number of cells of the mesh with @p n_global_refinements,
       * estimated before it is built, and the entry that makes it that
       * large (e.g. "Geometry / Rectangle / Subdivisions"). Geometry<dim>
       * hands both to check_mesh_size() as soon as the entries are read,
       * so that a mesh this machine cannot hold is refused before any work.
       */
      virtual std::pair<double, std::string>
      estimated_size(const unsigned int n_global_refinements) const = 0;

      /**
       * Name -> boundary id of every named boundary of the mesh.
       */
      virtual std::map<std::string, dealii::types::boundary_id>
      boundary_names() const = 0;

      /**
       * The sizes of the shape for the one-line description of the log,
       * e.g. "40 x 40, 16 x 16 subdivisions".
       */
      virtual std::string
      description() const = 0;

      /**
       * The wall time spent in parse_parameters() reading input files of
       * the mesh (s), which the scene counts in the mesh phase with the
       * building of the mesh; 0 for the shapes generated in
       * create_triangulation().
       */
      virtual double
      reading_time() const
      {
        return 0.0;
      }

      /**
       * Frees what the shape keeps only to build its mesh (the nodes and
       * cells read from a mesh file), once the mesh is built; nothing for
       * the generated shapes. create_triangulation() may not be called
       * afterwards.
       */
      virtual void
      release_mesh_data()
      {
      }
    };



    /**
     * The id of a boundary face of @p tria that carries none of the ids of
     * @p names, if there is one: such a face would silently escape every
     * boundary condition.
     */
    template <int dim>
    std::optional<dealii::types::boundary_id>
    unnamed_boundary_id(
      const dealii::Triangulation<dim>                        &tria,
      const std::map<std::string, dealii::types::boundary_id> &names);



    /**
     * The largest mesh a run accepts: 5e7 cells. A linear simplex mesh needs
     * about 1 kB per cell for the triangulation, the degrees of freedom and
     * the stiffness matrix, so that 5e7 cells already ask for some 50 GB.
     */
    constexpr double max_cells = 5e7;

    /**
     * Refuses, before anything is built, a mesh whose estimated number of
     * cells @p n_cells (Shape::estimated_size()) exceeds max_cells: a one-line dpana::InputError that
     * names @p parameter (the entry that makes the mesh that large) and the
     * estimate, instead of a std::bad_alloc after minutes of work.
     */
    void
    check_mesh_size(const double n_cells, const std::string &parameter);



    namespace internal
    {
      /**
       * The default value of a point-valued entry: @p n copies of @p value
       * separated by commas.
       */
      inline std::string
      repeat(const std::string &value, const unsigned int n)
      {
        std::string s = value;
        for (unsigned int i = 1; i < n; ++i)
          s += ", " + value;
        return s;
      }

      /**
       * A length as the descriptions print it (shortest form, e.g. "40").
       */
      inline std::string
      format_number(const double x)
      {
        std::ostringstream s;
        s << x;
        return s.str();
      }
    } // namespace internal
  }   // namespace geometry
} // namespace dpana

#endif
