// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_geometry_h
#define dpana_geometry_geometry_h

#include <dpana/geometry/shape.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <deal.II/grid/tria.h>

#include <map>
#include <memory>
#include <string>

namespace dpana
{
  namespace geometry
  {
    /**
     * The geometry of one body: the parameters of the "Geometry" subsection
     * and the simplex mesh (triangles in 2D, tetrahedra in 3D) built from
     * them.
     *
     * The subsection holds the entries every shape shares, `Type` and
     * `Global refinements`, and one subsection per shape, named after its
     * type, with the entries of that shape only:
     *
     *     subsection Geometry
     *       set Type               = quarter disc
     *       set Global refinements = 2
     *       subsection Quarter disc
     *         set Radius = 40
     *         set Centre = 0, 40
     *       end
     *     end
     *
     * The types and the classes that make them are
     * - `rectangle` (2D) and `box` (3D): an axis-parallel brick with optional
     *   tensor-product grading towards a plane, an edge or a point (Brick);
     * - `half disc` and `quarter disc` (2D), `half cylinder` (3D): the lower
     *   half of a disc (the cylinder of the Hertz scenes, touching the ground
     *   at its lowest point), with optional local refinement around that
     *   point (Disc);
     * - `half annulus` and `quarter annulus` (2D): the lower half (or the
     *   lower right quarter) of an annulus, with optional local refinement
     *   around the lowest point of the inner circle (Annulus);
     * - `gmsh`: an ASCII gmsh file (format 2.2 or 4.1) with named physical
     *   groups (GmshFile).
     *
     * This class reads the shared entries, declares the subsection of every
     * shape of the dimension and lets the chosen shape read its own and
     * build the mesh.
     *
     * Every boundary face of a created mesh carries one of the ids listed by
     * boundary_names(). All manifold ids of the created mesh are flat: the
     * curved boundaries are polygons whose vertices lie exactly on the
     * circles (see doc/geometry.md), which is what a MappingFE of degree one
     * sees anyway.
     *
     * All lengths are in mm.
     */
    template <int dim>
    class Geometry
    {
    public:
      Geometry();

      /**
       * Declares the entries of the "Geometry" subsection and the
       * subsections of the shapes of this dimension. The caller has already
       * entered that subsection.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * Reads the entries of the subsection and of the subsection of the
       * chosen shape (the caller has entered the "Geometry" subsection).
       * Throws dpana::InputError with a one-line message naming the
       * parameter by its path ("Geometry / Half disc / Radius: ...") or the
       * file on bad values, e.g. a missing mesh file.
       */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /**
       * Builds the simplex mesh, refined as asked, with boundary ids set and
       * all manifold ids flat. The triangulation must be empty.
       */
      void
      create_triangulation(dealii::Triangulation<dim> &tria) const;

      /**
       * Name -> boundary id of every named boundary of the mesh this object
       * creates.
       */
      const std::map<std::string, dealii::types::boundary_id> &
      boundary_names() const
      {
        return names;
      }

      /**
       * The boundary id of a named boundary. Throws dpana::InputError
       * "no boundary named 'x' (this geometry has: a, b, c)".
       */
      dealii::types::boundary_id
      boundary_id(const std::string &name) const;

      /**
       * A one-line description for the log, e.g. "rectangle 40 x 40, 16 x 16
       * subdivisions".
       */
      std::string
      description() const;

      /**
       * The wall time of reading the mesh file while the parameters were
       * read (s; 0 for a generated mesh).
       */
      double
      reading_time() const
      {
        return shape->reading_time();
      }

      /**
       * Frees what the shape keeps only to build its mesh (Shape::
       * release_mesh_data()), once the mesh is built.
       */
      void
      release_mesh_data()
      {
        shape->release_mesh_data();
      }

    private:
      std::string                 type_name;
      unsigned int                n_global_refinements;
      std::unique_ptr<Shape<dim>> shape;

      std::map<std::string, dealii::types::boundary_id> names;

      void
      check_boundary_ids(const dealii::Triangulation<dim> &tria) const;
    };
  } // namespace geometry
} // namespace dpana

#endif
