// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_geometry_templates_h
#define dpana_geometry_geometry_templates_h

#include <dpana/base/exceptions.h>
#include <dpana/geometry/geometry.h>

#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace dpana
{
  namespace geometry
  {
    namespace internal
    {
      // A point given as a comma separated list of dim numbers.
      template <int dim>
      dealii::Point<dim>
      parse_point(const std::string &text)
      {
        const std::vector<double> x = dealii::Utilities::string_to_double(
          dealii::Utilities::split_string_list(text));
        AssertThrow(x.size() == dim, dealii::ExcInternalError());
        dealii::Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = x[d];
        return p;
      }

      // The default value of a point-valued parameter: dim copies of a
      // number.
      inline std::string
      repeat(const std::string &value, const unsigned int n)
      {
        std::string s = value;
        for (unsigned int i = 1; i < n; ++i)
          s += ", " + value;
        return s;
      }

      inline std::string
      format_number(const double x)
      {
        std::ostringstream s;
        s << x;
        return s.str();
      }
    } // namespace internal



    // @sect3{Boundary names of gmsh files}
    //
    // deal.II's GridIn::read_msh (stream overload, the built-in ASCII
    // reader of the formats 2.2 and 4.1) gives every boundary face the
    // physical tag of its boundary element as boundary id, and id 0 to the
    // boundary faces that belong to no physical group. The names of the
    // tags come from the $PhysicalNames section, which GridIn skips; it is
    // parsed here, already in parse_parameters(), so that a missing file or
    // an unnamed boundary is reported before any work is done.
    namespace internal
    {
      inline std::map<std::string, dealii::types::boundary_id>
      read_gmsh_boundary_names(const std::string &file, const int dim)
      {
        std::ifstream in(file);
        if (file.empty() || !in)
          throw InputError("Geometry: mesh file '" + file +
                           "' not found (parameter Mesh file)");

        std::map<std::string, dealii::types::boundary_id> names;
        std::string                                       line;
        bool format_seen = false, names_seen = false;
        while (std::getline(in, line))
          {
            if (line.rfind("$MeshFormat", 0) == 0)
              {
                double version   = 0;
                int    file_type = -1;
                in >> version >> file_type;
                if (!in || file_type != 0 || version < 2. || version >= 5.)
                  throw InputError("Geometry: mesh file '" + file +
                                   "' is not an ASCII gmsh file of format "
                                   "2.2 or 4.1 (parameter Mesh file)");
                format_seen = true;
              }
            else if (line.rfind("$PhysicalNames", 0) == 0)
              {
                unsigned int n = 0;
                in >> n;
                std::getline(in, line);
                for (unsigned int i = 0; i < n; ++i)
                  {
                    int          group_dim = -1;
                    unsigned int tag       = 0;
                    in >> group_dim >> tag;
                    std::getline(in, line);
                    if (!in)
                      throw InputError("Geometry: mesh file '" + file +
                                       "': malformed $PhysicalNames section "
                                       "(parameter Mesh file)");
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
                      throw InputError("Geometry: mesh file '" + file +
                                       "' names two boundaries '" + name +
                                       "' (parameter Mesh file)");
                    names[name] = tag;
                  }
                names_seen = true;
              }
          }
        if (!format_seen)
          throw InputError("Geometry: mesh file '" + file +
                           "' has no $MeshFormat section, it is not a gmsh "
                           "file (parameter Mesh file)");
        if (!names_seen || names.empty())
          throw InputError("Geometry: mesh file '" + file +
                           "' names no boundary: give every boundary a "
                           "physical group with a name, of dimension " +
                           std::to_string(dim - 1) + " (parameter Mesh file)");
        return names;
      }
    } // namespace internal



    template <int dim>
    Geometry<dim>::Geometry()
      : type(dim == 2 ? Type::rectangle : Type::box)
      , type_name(dim == 2 ? "rectangle" : "box")
      , n_global_refinements(0)
      , subdivisions(dim, 1)
      , grading_exponents(dim, 1.)
      , radius(1.)
      , inner_radius(0.5)
      , outer_radius(1.)
      , length(1.)
      , n_axial_subdivisions(4)
      , n_contact_refinements(0)
      , contact_refinement_radius(0.25)
    {
      for (unsigned int d = 0; d < dim; ++d)
        upper_corner[d] = 1.;
    }



    // @sect3{Parameters}
    //
    // All types share one flat list of entries; each help string says which
    // types read it. Points are comma separated lists of dim coordinates.
    template <int dim>
    void
    Geometry<dim>::declare_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Anything;
      using dealii::Patterns::Double;
      using dealii::Patterns::Integer;
      using dealii::Patterns::List;
      using dealii::Patterns::Selection;
      using internal::repeat;

      prm.declare_entry(
        "Type",
        dim == 2 ? "rectangle" : "box",
        Selection(
          "rectangle|box|half disc|quarter disc|half cylinder|half annulus|"
          "quarter annulus|gmsh"),
        "The shape of the body. 2D: rectangle, half disc, quarter disc, "
        "half annulus, quarter annulus, gmsh. 3D: box, half cylinder, gmsh. "
        "See doc/geometry.md for the boundary names of each type.");
      prm.declare_entry(
        "Global refinements",
        "0",
        Integer(0, 10),
        "Number of uniform refinements; each one halves every edge. The "
        "curved types refine their quadrilateral mesh before it is split "
        "into simplices, so that new boundary vertices lie on the circles; "
        "rectangle, box and gmsh refine the simplex mesh.");

      prm.declare_entry("Lower corner",
                        repeat("0", dim),
                        List(Double(), dim, dim),
                        "rectangle/box: the corner with the smallest "
                        "coordinates, x, y (, z) in mm.");
      prm.declare_entry("Upper corner",
                        repeat("1", dim),
                        List(Double(), dim, dim),
                        "rectangle/box: the corner with the largest "
                        "coordinates, x, y (, z) in mm.");
      prm.declare_entry("Subdivisions",
                        repeat("1", dim),
                        List(Integer(1), dim, dim),
                        "rectangle/box: number of cell layers in the x, y "
                        "(, z) directions before the global refinements. "
                        "Each rectangle of the grid is split into 2 "
                        "triangles, each brick into 5 tetrahedra.");
      prm.declare_entry(
        "Grading centre",
        repeat("0", dim),
        List(Double(), dim, dim),
        "rectangle/box: coordinates c_d (mm) of the planes x_d = c_d towards "
        "which the vertices are clustered, one per direction; read only for "
        "the directions whose grading exponent differs from 1, and then it "
        "must lie between the corners. E.g. centre (0, 40) with exponents "
        "(2, 2) refines towards the point (0, 40); exponents (1, 2) refine "
        "towards the line y = 40.");
      prm.declare_entry(
        "Grading exponents",
        repeat("1", dim),
        List(Double(1., 10.), dim, dim),
        "rectangle/box: grading exponent p_d >= 1 per direction "
        "(dimensionless). A vertex at relative distance t in [0, 1] from the "
        "grading plane (t = 1 at the corner) is moved to relative distance "
        "t^p; p = 1 is a uniform grid, p > 1 makes the cells next to the "
        "plane smaller (the first of n layers by the factor n^(p-1)) and "
        "those far from it larger.");

      prm.declare_entry(
        "Centre",
        repeat("0", dim),
        List(Double(), dim, dim),
        "half disc, quarter disc, half annulus, quarter annulus: centre "
        "x, y (mm) of the circles. half cylinder: x, y of the axis and the "
        "z coordinate (mm) of its front end.");
      prm.declare_entry("Radius",
                        "1",
                        Double(0.),
                        "half disc, quarter disc, half cylinder: radius R "
                        "(mm).");
      prm.declare_entry("Inner radius",
                        "0.5",
                        Double(0.),
                        "half annulus, quarter annulus: inner radius (mm).");
      prm.declare_entry("Outer radius",
                        "1",
                        Double(0.),
                        "half annulus, quarter annulus: outer radius (mm).");
      prm.declare_entry("Length",
                        "1",
                        Double(0.),
                        "half cylinder: length L (mm) along z; the body "
                        "spans z from the third coordinate of Centre to "
                        "that plus L.");
      prm.declare_entry("Axial subdivisions",
                        "4",
                        Integer(1),
                        "half cylinder: number of cell layers along z before "
                        "the global refinements.");
      prm.declare_entry(
        "Contact refinements",
        "0",
        Integer(0, 10),
        "half disc, quarter disc, half cylinder: extra refinements of the "
        "cells near the lowest point of the circle (centre - R e_y); half "
        "annulus, quarter annulus: near the lowest point of the inner "
        "circle. The cells within the Contact refinement radius of that "
        "point end up 2^(this number) times smaller than the others.");
      prm.declare_entry("Contact refinement radius",
                        "0.25",
                        Double(0.),
                        "Radius (mm) of the zone around the contact point "
                        "refined by the Contact refinements.");

      prm.declare_entry(
        "Mesh file",
        "",
        Anything(),
        "gmsh: path of an ASCII .msh file (format 2.2 or 4.1) of triangles "
        "(2D) or tetrahedra (3D), relative to the working directory. "
        "Boundary ids are the physical tags of the boundary elements and "
        "boundary names their $PhysicalNames; lengths in the file are mm.");
    }



    template <int dim>
    void
    Geometry<dim>::parse_parameters(dealii::ParameterHandler &prm)
    {
      type_name                               = prm.get("Type");
      const std::map<std::string, Type> types = {
        {"rectangle", Type::rectangle},
        {"box", Type::box},
        {"half disc", Type::half_disc},
        {"quarter disc", Type::quarter_disc},
        {"half cylinder", Type::half_cylinder},
        {"half annulus", Type::half_annulus},
        {"quarter annulus", Type::quarter_annulus},
        {"gmsh", Type::gmsh}};
      Assert(types.count(type_name) == 1, dealii::ExcInternalError());
      type = types.at(type_name);

      // Each generated type exists in one dimension only.
      const bool only_2d =
        (type == Type::rectangle || type == Type::half_disc ||
         type == Type::quarter_disc || type == Type::half_annulus ||
         type == Type::quarter_annulus);
      const bool only_3d = (type == Type::box || type == Type::half_cylinder);
      if ((only_2d && dim != 2) || (only_3d && dim != 3))
        throw InputError("Geometry: type '" + type_name + "' needs " +
                         (only_2d ? "Dimension = 2" : "Dimension = 3") +
                         " (parameter Type)");

      n_global_refinements = prm.get_integer("Global refinements");

      names.clear();
      if (type == Type::rectangle || type == Type::box)
        {
          lower_corner = internal::parse_point<dim>(prm.get("Lower corner"));
          upper_corner = internal::parse_point<dim>(prm.get("Upper corner"));
          const auto n = dealii::Utilities::string_to_int(
            dealii::Utilities::split_string_list(prm.get("Subdivisions")));
          subdivisions.assign(n.begin(), n.end());
          grading_centre =
            internal::parse_point<dim>(prm.get("Grading centre"));
          grading_exponents = dealii::Utilities::string_to_double(
            dealii::Utilities::split_string_list(prm.get("Grading exponents")));
          for (unsigned int d = 0; d < dim; ++d)
            {
              if (!(upper_corner[d] > lower_corner[d]))
                throw InputError(
                  "Geometry: Upper corner must exceed Lower corner in every "
                  "coordinate (parameters Lower corner, Upper corner)");
              if (grading_exponents[d] != 1. &&
                  (grading_centre[d] < lower_corner[d] ||
                   grading_centre[d] > upper_corner[d]))
                throw InputError(
                  "Geometry: Grading centre must lie between Lower corner "
                  "and Upper corner in every graded direction (parameter "
                  "Grading centre)");
            }
          names = {{"left", 0}, {"right", 1}, {"bottom", 2}, {"top", 3}};
          if (dim == 3)
            {
              names["front"] = 4;
              names["back"]  = 5;
            }
        }
      else if (type == Type::gmsh)
        {
          mesh_file = prm.get("Mesh file");
          names     = internal::read_gmsh_boundary_names(mesh_file, dim);
        }
      else
        {
          // The curved types.
          centre                = internal::parse_point<dim>(prm.get("Centre"));
          radius                = prm.get_double("Radius");
          inner_radius          = prm.get_double("Inner radius");
          outer_radius          = prm.get_double("Outer radius");
          length                = prm.get_double("Length");
          n_axial_subdivisions  = prm.get_integer("Axial subdivisions");
          n_contact_refinements = prm.get_integer("Contact refinements");
          contact_refinement_radius =
            prm.get_double("Contact refinement radius");
          const bool disc =
            (type == Type::half_disc || type == Type::quarter_disc ||
             type == Type::half_cylinder);
          if (disc && !(radius > 0))
            throw InputError(
              "Geometry: Radius must be positive (parameter Radius)");
          if (!disc && !(inner_radius > 0 && outer_radius > inner_radius))
            throw InputError("Geometry: need 0 < Inner radius < Outer radius "
                             "(parameters Inner radius, Outer radius)");
          if (type == Type::half_cylinder && !(length > 0))
            throw InputError(
              "Geometry: Length must be positive (parameter Length)");
          if (n_contact_refinements > 0 && !(contact_refinement_radius > 0))
            throw InputError("Geometry: Contact refinement radius must be "
                             "positive when Contact refinements > 0 "
                             "(parameter Contact refinement radius)");

          switch (type)
            {
              case Type::half_disc:
                names = {{"top", 0}, {"curved", 1}};
                break;
              case Type::quarter_disc:
                names = {{"top", 0}, {"curved", 1}, {"axis", 2}};
                break;
              case Type::half_cylinder:
                names = {{"top", 0}, {"curved", 1}, {"front", 2}, {"back", 3}};
                break;
              case Type::half_annulus:
                names = {{"inner", 0}, {"outer", 1}, {"left", 2}, {"right", 3}};
                break;
              case Type::quarter_annulus:
                names = {{"inner", 0},
                         {"outer", 1},
                         {"x_axis", 2},
                         {"y_axis", 3}};
                break;
              default:
                Assert(false, dealii::ExcInternalError());
            }
        }
    }



    template <int dim>
    const std::map<std::string, dealii::types::boundary_id> &
    Geometry<dim>::boundary_names() const
    {
      return names;
    }



    template <int dim>
    dealii::types::boundary_id
    Geometry<dim>::boundary_id(const std::string &name) const
    {
      const auto p = names.find(name);
      if (p == names.end())
        {
          std::string list;
          for (const auto &n : names)
            list += (list.empty() ? "" : ", ") + n.first;
          throw InputError("no boundary named '" + name +
                           "' (this geometry has: " + list + ")");
        }
      return p->second;
    }



    template <int dim>
    std::string
    Geometry<dim>::description() const
    {
      using internal::format_number;
      std::string s = type_name;
      switch (type)
        {
          case Type::rectangle:
          case Type::box:
            {
              std::string sizes, cells;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  sizes += (d == 0 ? "" : " x ") +
                           format_number(upper_corner[d] - lower_corner[d]);
                  cells +=
                    (d == 0 ? "" : " x ") + std::to_string(subdivisions[d]);
                }
              s += " " + sizes + ", " + cells + " subdivisions";
              bool graded = false;
              for (unsigned int d = 0; d < dim; ++d)
                graded = graded || (grading_exponents[d] != 1.);
              if (graded)
                s += ", graded";
              break;
            }
          case Type::half_disc:
          case Type::quarter_disc:
          case Type::half_cylinder:
          case Type::half_annulus:
          case Type::quarter_annulus:
            {
              const bool disc =
                (type == Type::half_disc || type == Type::quarter_disc ||
                 type == Type::half_cylinder);
              if (disc)
                s += " R = " + format_number(radius);
              else
                s += " Ri = " + format_number(inner_radius) +
                     ", Ro = " + format_number(outer_radius);
              s += ", centre (" + format_number(centre[0]) + ", " +
                   format_number(centre[1]) + ")";
              if (type == Type::half_cylinder)
                s += ", L = " + format_number(length) + " (" +
                     std::to_string(n_axial_subdivisions) + " layers)";
              if (n_contact_refinements > 0)
                s += ", " + std::to_string(n_contact_refinements) +
                     " contact refinements within " +
                     format_number(contact_refinement_radius);
              break;
            }
          case Type::gmsh:
            s += " '" + mesh_file + "'";
            break;
        }
      s += ", " + std::to_string(n_global_refinements) + " global refinements";
      return s;
    }



    // @sect3{Creating the mesh}
    template <int dim>
    void
    Geometry<dim>::create_triangulation(dealii::Triangulation<dim> &tria) const
    {
      AssertThrow(tria.n_cells() == 0,
                  dealii::ExcMessage("The triangulation must be empty."));
      switch (type)
        {
          case Type::rectangle:
          case Type::box:
            create_brick(tria);
            break;
          case Type::gmsh:
            read_gmsh(tria);
            break;
          default:
            create_curved(tria);
            break;
        }
      tria.set_all_manifold_ids(dealii::numbers::flat_manifold_id);
      check_boundary_ids(tria);
    }



    // @sect4{Rectangle and box}
    //
    // The brick is built directly from simplices by
    // GridGenerator::subdivided_hyper_rectangle_with_simplices (without
    // colorize, which throws for simplices in deal.II 9.4). The optional
    // grading is a vertex transformation acting on each coordinate
    // separately: with the grading centre $c$, the corners $l < u$ and the
    // exponent $p$,
    // @f[
    //   x \mapsto c + (u - c)\left(\frac{x - c}{u - c}\right)^p \quad (x > c),
    //   \qquad
    //   x \mapsto c - (c - l)\left(\frac{c - x}{c - l}\right)^p \quad (x < c).
    // @f]
    // It is monotone and fixes $l$, $c$ and $u$, so it maps the brick onto
    // itself and every boundary face stays on its side. The local cell size
    // is multiplied by the derivative $p\,t^{p-1}$, $t$ the relative distance
    // from $c$, which is small near $c$. The boundary ids are then set from
    // the face centres, after the global refinements.
    template <int dim>
    void
    Geometry<dim>::create_brick(dealii::Triangulation<dim> &tria) const
    {
      dealii::GridGenerator::subdivided_hyper_rectangle_with_simplices(
        tria, subdivisions, lower_corner, upper_corner, false);

      bool graded = false;
      for (unsigned int d = 0; d < dim; ++d)
        graded = graded || (grading_exponents[d] != 1.);
      if (graded)
        {
          const dealii::Point<dim> l = lower_corner, u = upper_corner,
                                   c  = grading_centre;
          const std::vector<double> p = grading_exponents;
          dealii::GridTools::transform(
            [l, u, c, p](const dealii::Point<dim> &x) {
              dealii::Point<dim> y = x;
              for (unsigned int d = 0; d < dim; ++d)
                if (p[d] != 1.)
                  {
                    if (x[d] > c[d])
                      y[d] =
                        c[d] + (u[d] - c[d]) *
                                 std::pow((x[d] - c[d]) / (u[d] - c[d]), p[d]);
                    else if (x[d] < c[d])
                      y[d] =
                        c[d] - (c[d] - l[d]) *
                                 std::pow((c[d] - x[d]) / (c[d] - l[d]), p[d]);
                  }
              return y;
            },
            tria);
        }

      tria.refine_global(n_global_refinements);

      // Boundary ids from the face centres: 2d for the face at the lower
      // corner in direction d, 2d+1 for the one at the upper corner.
      double size = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        size = std::max(size, upper_corner[d] - lower_corner[d]);
      const double tolerance = 1e-10 * size;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const dealii::Point<dim> x     = face->center();
              bool                     found = false;
              for (unsigned int d = 0; d < dim && !found; ++d)
                if (std::abs(x[d] - lower_corner[d]) < tolerance)
                  {
                    face->set_boundary_id(2 * d);
                    found = true;
                  }
                else if (std::abs(x[d] - upper_corner[d]) < tolerance)
                  {
                    face->set_boundary_id(2 * d + 1);
                    found = true;
                  }
              Assert(found, dealii::ExcInternalError());
            }
    }



    // @sect4{Half disc, quarter disc, half cylinder and annuli}
    //
    // The curved shapes are first meshed with quadrilaterals, because deal.II
    // refines quadrilaterals along their manifolds: every vertex created on
    // the curved boundary lies exactly on the circle, and the interior
    // vertices follow a transfinite interpolation of the boundary, which
    // keeps the cells well shaped. The global refinements and the local
    // contact refinements are therefore applied to the quadrilateral mesh.
    //
    // The local refinements leave hanging nodes, which
    // GridGenerator::convert_hypercube_to_simplex_mesh does not accept
    // (deal.II 9.4 throws ExcNotImplemented for a mesh with hanging nodes;
    // splitting each cell on its own could not give a conforming mesh
    // anyway). The quadrilaterals are therefore split
    // into triangles here: each active quadrilateral becomes a fan of
    // triangles around its centre, one triangle per edge of its boundary
    // polygon, where the boundary polygon of a cell includes the midpoint
    // of every edge whose neighbour is refined. Both sides of such an edge
    // then use the midpoint as a vertex and the triangle mesh is
    // conforming: a quadrilateral gives 4 triangles plus one per hanging
    // node.
    //
    // In 3D (half cylinder) the triangles are extruded into prisms along z,
    // and each prism is split into three tetrahedra. Splitting every
    // quadrilateral side of a prism along the diagonal that joins the lower
    // vertex of smaller index to the upper vertex of larger index is a rule
    // both prisms sharing that side apply identically, so the tetrahedral
    // mesh is conforming as well.
    namespace internal
    {
      // The lower half (or the lower right quarter, x >= c_x) of the disc of
      // centre c and radius r, as 6 (or 3) quadrilaterals: two squares of
      // side a = r/2 around the centre of the flat side and four cells
      // between them and the circle, so that the lowest point of the circle
      // is a vertex. Manifold 0 (polar) on the curved boundary, manifold 1
      // (transfinite interpolation) on the cells, flat straight boundaries.
      inline void
      make_half_disc_quads(dealii::Triangulation<2> &quads,
                           const dealii::Point<2>    c,
                           const double              r,
                           const bool                quarter)
      {
        const double a = 0.5 * r, s = r / std::sqrt(2.);
        // Vertices relative to the centre.
        const std::vector<dealii::Point<2>> v = {{-r, 0},  // 0
                                                 {-a, 0},  // 1
                                                 {0, 0},   // 2
                                                 {a, 0},   // 3
                                                 {r, 0},   // 4
                                                 {-a, -a}, // 5
                                                 {0, -a},  // 6
                                                 {a, -a},  // 7
                                                 {-s, -s}, // 8
                                                 {0, -r},  // 9
                                                 {s, -s}}; // 10
        // Cells in deal.II's lexicographic vertex order (v0, v1, v2, v3 =
        // (0,0), (1,0), (0,1), (1,1) of the reference square).
        const std::vector<std::array<unsigned int, 4>> left  = {{{5, 6, 1, 2}},
                                                                {{8, 5, 0, 1}},
                                                                {{9, 6, 8, 5}}};
        const std::vector<std::array<unsigned int, 4>> right = {
          {{6, 7, 2, 3}}, {{7, 10, 3, 4}}, {{9, 10, 6, 7}}};

        std::vector<dealii::Point<2>> vertices;
        for (const auto &x : v)
          vertices.push_back(c + x);
        std::vector<dealii::CellData<2>> cells;
        auto add = [&cells](const std::array<unsigned int, 4> &q) {
          dealii::CellData<2> cell(4);
          for (unsigned int i = 0; i < 4; ++i)
            cell.vertices[i] = q[i];
          cells.push_back(cell);
        };
        for (const auto &q : right)
          add(q);
        if (!quarter)
          for (const auto &q : left)
            add(q);
        dealii::SubCellData subcell_data;
        dealii::GridTools::delete_unused_vertices(vertices,
                                                  cells,
                                                  subcell_data);
        // deal.II requires the lines shared by two quadrilaterals to have
        // the same direction seen from both; without this reordering the
        // refinement of the coarse cells is garbled (silently, in Release).
        dealii::GridTools::consistently_order_cells(cells);
        quads.create_triangulation(vertices, cells, subcell_data);

        quads.set_all_manifold_ids(1);
        for (const auto &face : quads.active_face_iterators())
          if (face->at_boundary())
            {
              // The curved faces are those whose vertices both lie on the
              // circle and not on the flat side.
              const double r0        = (face->vertex(0) - c).norm();
              const double r1        = (face->vertex(1) - c).norm();
              const bool   on_circle = std::abs(r0 - r) < 1e-10 * r &&
                                     std::abs(r1 - r) < 1e-10 * r &&
                                     face->center()[1] < c[1] - 1e-10 * r;
              face->set_manifold_id(
                on_circle ? 0 : dealii::numbers::flat_manifold_id);
            }
        quads.set_manifold(0, dealii::PolarManifold<2>(c));
        dealii::TransfiniteInterpolationManifold<2> transfinite;
        transfinite.initialize(quads);
        quads.set_manifold(1, transfinite);
      }



      // The lower half (or the lower right quarter) of the annulus of centre
      // c and radii ri < ro, as a polar grid: n_theta cells along the angle
      // and n_r layers with radii growing geometrically, so that all cells
      // are similar with an aspect ratio close to one. Polar manifold
      // everywhere.
      inline void
      make_half_annulus_quads(dealii::Triangulation<2> &quads,
                              const dealii::Point<2>    c,
                              const double              ri,
                              const double              ro,
                              const bool                quarter)
      {
        const double       pi      = dealii::numbers::PI;
        const double       angle   = quarter ? pi / 2 : pi;
        const double       log_q   = std::log(ro / ri);
        const unsigned int n_theta = std::max<unsigned int>(
          quarter ? 2 : 4, static_cast<unsigned int>(std::ceil(angle / log_q)));
        const double       d_theta = angle / n_theta;
        const unsigned int n_r     = std::max<unsigned int>(
          1, static_cast<unsigned int>(std::round(log_q / d_theta)));

        // Angles run from -pi/2 (the lowest point) in the quarter, from -pi
        // (the left end) to 0 (the right end) in the half annulus.
        const double                  theta_0 = quarter ? -pi / 2 : -pi;
        std::vector<dealii::Point<2>> vertices;
        for (unsigned int j = 0; j <= n_r; ++j)
          {
            const double rho = ri * std::pow(ro / ri, double(j) / n_r);
            for (unsigned int i = 0; i <= n_theta; ++i)
              {
                const double theta = theta_0 + i * d_theta;
                vertices.push_back(c + dealii::Point<2>(rho * std::cos(theta),
                                                        rho * std::sin(theta)));
              }
          }
        std::vector<dealii::CellData<2>> cells;
        for (unsigned int j = 0; j < n_r; ++j)
          for (unsigned int i = 0; i < n_theta; ++i)
            {
              dealii::CellData<2> cell(4);
              // The first reference direction is radial, the second one
              // counterclockwise, which gives a positive Jacobian.
              cell.vertices[0] = j * (n_theta + 1) + i;
              cell.vertices[1] = (j + 1) * (n_theta + 1) + i;
              cell.vertices[2] = j * (n_theta + 1) + i + 1;
              cell.vertices[3] = (j + 1) * (n_theta + 1) + i + 1;
              cells.push_back(cell);
            }
        dealii::GridTools::consistently_order_cells(cells);
        quads.create_triangulation(vertices, cells, dealii::SubCellData());
        quads.set_all_manifold_ids(0);
        quads.set_manifold(0, dealii::PolarManifold<2>(c));
      }



      // Refines, n times, the cells that intersect the disc of radius rho
      // around the point p. deal.II keeps at most one hanging node per face.
      inline void
      refine_near(dealii::Triangulation<2> &quads,
                  const dealii::Point<2>    p,
                  const double              rho,
                  const unsigned int        n)
      {
        for (unsigned int cycle = 0; cycle < n; ++cycle)
          {
            for (const auto &cell : quads.active_cell_iterators())
              if (cell->center().distance(p) < rho + 0.5 * cell->diameter())
                cell->set_refine_flag();
            quads.execute_coarsening_and_refinement();
          }
      }



      // Splits the active quadrilaterals into triangles as described above.
      // The vertices of the quadrilateral mesh keep their indices (unused
      // ones are removed later); the cell centres are appended.
      inline void
      quads_to_triangles(const dealii::Triangulation<2>   &quads,
                         std::vector<dealii::Point<2>>    &vertices,
                         std::vector<dealii::CellData<2>> &triangles)
      {
        vertices = quads.get_vertices();
        triangles.clear();
        // The boundary of the reference square, counterclockwise: each entry
        // is (face, first vertex, second vertex).
        const unsigned int loop[4][3] = {{2, 0, 1},
                                         {1, 1, 3},
                                         {3, 3, 2},
                                         {0, 2, 0}};
        for (const auto &cell : quads.active_cell_iterators())
          {
            std::vector<unsigned int> polygon;
            for (const auto &side : loop)
              {
                polygon.push_back(cell->vertex_index(side[1]));
                const auto face = cell->face(side[0]);
                if (face->has_children())
                  {
                    // The midpoint is the vertex the two halves share,
                    // whatever the orientation of the face.
                    Assert(face->n_children() == 2, dealii::ExcInternalError());
                    Assert(!face->child(0)->has_children(),
                           dealii::ExcInternalError());
                    polygon.push_back(face->child(0)->vertex_index(1));
                  }
              }
            const unsigned int centre = vertices.size();
            vertices.push_back(cell->center(/*respect_manifold=*/true));
            for (unsigned int i = 0; i < polygon.size(); ++i)
              {
                dealii::CellData<2> t(3);
                t.vertices = {centre,
                              polygon[i],
                              polygon[(i + 1) % polygon.size()]};
                // Counterclockwise orientation (positive Jacobian).
                const dealii::Tensor<1, 2> e1 =
                  vertices[t.vertices[1]] - vertices[t.vertices[0]];
                const dealii::Tensor<1, 2> e2 =
                  vertices[t.vertices[2]] - vertices[t.vertices[0]];
                if (e1[0] * e2[1] - e1[1] * e2[0] < 0)
                  std::swap(t.vertices[1], t.vertices[2]);
                triangles.push_back(t);
              }
          }
      }



      // Extrudes triangles along z through the planes z_0 < ... < z_n into
      // prisms, three tetrahedra each, positively oriented.
      inline void
      extrude_triangles(const std::vector<dealii::Point<2>>    &vertices_2d,
                        const std::vector<dealii::CellData<2>> &triangles,
                        const std::vector<double>              &z,
                        std::vector<dealii::Point<3>>          &vertices,
                        std::vector<dealii::CellData<3>>       &tets)
      {
        const unsigned int n2 = vertices_2d.size();
        vertices.clear();
        tets.clear();
        for (const double zk : z)
          for (const auto &x : vertices_2d)
            vertices.emplace_back(x[0], x[1], zk);
        for (unsigned int k = 0; k + 1 < z.size(); ++k)
          for (const auto &t : triangles)
            {
              std::array<unsigned int, 3> v = {
                {t.vertices[0], t.vertices[1], t.vertices[2]}};
              std::sort(v.begin(), v.end());
              const unsigned int a = k * n2 + v[0], b = k * n2 + v[1],
                                 c  = k * n2 + v[2];
              const unsigned int a1 = a + n2, b1 = b + n2, c1 = c + n2;
              for (const auto &q :
                   {std::array<unsigned int, 4>{{a, b, c, c1}},
                    std::array<unsigned int, 4>{{a, b, b1, c1}},
                    std::array<unsigned int, 4>{{a, a1, b1, c1}}})
                {
                  dealii::CellData<3> tet(4);
                  tet.vertices = {q[0], q[1], q[2], q[3]};
                  const dealii::Tensor<1, 3> e1 =
                    vertices[q[1]] - vertices[q[0]];
                  const dealii::Tensor<1, 3> e2 =
                    vertices[q[2]] - vertices[q[0]];
                  const dealii::Tensor<1, 3> e3 =
                    vertices[q[3]] - vertices[q[0]];
                  if (dealii::cross_product_3d(e1, e2) * e3 < 0)
                    std::swap(tet.vertices[2], tet.vertices[3]);
                  tets.push_back(tet);
                }
            }
      }
    } // namespace internal



    template <int dim>
    void
    Geometry<dim>::create_curved(dealii::Triangulation<dim> &tria) const
    {
      const dealii::Point<2> c(centre[0], centre[1]);
      const bool             disc =
        (type == Type::half_disc || type == Type::quarter_disc ||
         type == Type::half_cylinder);
      const bool quarter =
        (type == Type::quarter_disc || type == Type::quarter_annulus);

      // The cross-section, refined with quadrilaterals.
      dealii::Triangulation<2> quads(
        dealii::Triangulation<2>::limit_level_difference_at_vertices);
      if (disc)
        internal::make_half_disc_quads(quads, c, radius, quarter);
      else
        internal::make_half_annulus_quads(
          quads, c, inner_radius, outer_radius, quarter);
      quads.refine_global(n_global_refinements);
      const dealii::Point<2> contact_point =
        c - dealii::Tensor<1, 2>({0., disc ? radius : inner_radius});
      internal::refine_near(quads,
                            contact_point,
                            contact_refinement_radius,
                            n_contact_refinements);

      std::vector<dealii::Point<2>>    vertices_2d;
      std::vector<dealii::CellData<2>> triangles;
      internal::quads_to_triangles(quads, vertices_2d, triangles);

      // A characteristic length for the geometric tolerances.
      const double r_scale = disc ? radius : outer_radius;
      const double tol     = 1e-8 * r_scale;

      if constexpr (dim == 2)
        {
          dealii::SubCellData subcell_data;
          dealii::GridTools::delete_unused_vertices(vertices_2d,
                                                    triangles,
                                                    subcell_data);
          tria.create_triangulation(vertices_2d, triangles, subcell_data);
        }
      else
        {
          dealii::SubCellData subcell_data;
          dealii::GridTools::delete_unused_vertices(vertices_2d,
                                                    triangles,
                                                    subcell_data);
          const unsigned int n_z =
            n_axial_subdivisions * (1U << n_global_refinements);
          std::vector<double> z(n_z + 1);
          for (unsigned int k = 0; k <= n_z; ++k)
            z[k] = centre[dim - 1] + length * k / n_z;
          std::vector<dealii::Point<3>>    vertices;
          std::vector<dealii::CellData<3>> tets;
          internal::extrude_triangles(
            vertices_2d, triangles, z, vertices, tets);
          tria.create_triangulation(vertices, tets, dealii::SubCellData());
        }

      // Boundary ids from the face centres; the ids are those of the names
      // set in parse_parameters().
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
          {
            const dealii::Point<dim> x = face->center();
            std::string              name;
            if (dim == 3 && std::abs(x[dim - 1] - centre[dim - 1]) < tol)
              name = "front";
            else if (dim == 3 &&
                     std::abs(x[dim - 1] - centre[dim - 1] - length) < tol)
              name = "back";
            else if (disc)
              {
                if (std::abs(x[1] - c[1]) < tol)
                  name = "top";
                else if (quarter && std::abs(x[0] - c[0]) < tol)
                  name = "axis";
                else
                  name = "curved";
              }
            else
              {
                const double rho = std::hypot(x[0] - c[0], x[1] - c[1]);
                if (quarter && std::abs(x[1] - c[1]) < tol)
                  name = "x_axis";
                else if (quarter && std::abs(x[0] - c[0]) < tol)
                  name = "y_axis";
                else if (std::abs(x[1] - c[1]) < tol)
                  name = (x[0] < c[0] ? "left" : "right");
                else
                  name = (std::abs(rho - inner_radius) <
                              std::abs(rho - outer_radius) ?
                            "inner" :
                            "outer");
              }
            face->set_boundary_id(names.at(name));
          }
    }



    template <int dim>
    void
    Geometry<dim>::read_gmsh(dealii::Triangulation<dim> &tria) const
    {
      std::ifstream in(mesh_file);
      if (!in)
        throw InputError("Geometry: mesh file '" + mesh_file +
                         "' not found (parameter Mesh file)");
      dealii::GridIn<dim> grid_in;
      grid_in.attach_triangulation(tria);
      try
        {
          grid_in.read_msh(in);
        }
      catch (const std::exception &e)
        {
          // deal.II's messages span several lines; keep the first
          // non-empty line that is not a separator.
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
          throw InputError("Geometry: mesh file '" + mesh_file +
                           "' could not be read: " + reason +
                           " (parameter Mesh file)");
        }
      if (tria.n_active_cells() == 0 || !tria.all_reference_cells_are_simplex())
        throw InputError("Geometry: mesh file '" + mesh_file +
                         "' must contain " +
                         (dim == 2 ? "triangles" : "tetrahedra") +
                         " only (parameter Mesh file)");

      // Boundary faces outside every physical group come with id 0.
      std::set<dealii::types::boundary_id> named;
      for (const auto &n : names)
        named.insert(n.second);
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary() && named.count(face->boundary_id()) == 0)
          throw InputError(
            "Geometry: mesh file '" + mesh_file + "' has boundary faces " +
            (face->boundary_id() == 0 ? std::string("in no physical group") :
                                        "in the unnamed physical group " +
                                          std::to_string(face->boundary_id())) +
            " (parameter Mesh file)");

      tria.refine_global(n_global_refinements);
    }



    // Every boundary face must carry one of the named ids: a face with an
    // unnamed id would silently escape every boundary condition.
    template <int dim>
    void
    Geometry<dim>::check_boundary_ids(
      const dealii::Triangulation<dim> &tria) const
    {
      std::set<dealii::types::boundary_id> named;
      for (const auto &n : names)
        named.insert(n.second);
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary() && named.count(face->boundary_id()) == 0)
          throw InputError("Geometry: boundary faces with id " +
                           std::to_string(face->boundary_id()) +
                           " carry no boundary name (" + description() + ")");
    }
  } // namespace geometry
} // namespace dpana

#endif
