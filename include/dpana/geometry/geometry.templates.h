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
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <cmath>
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
          throw InputError("Geometry: type 'gmsh' is not available yet "
                           "(parameter Type)");
        }
      else
        {
          throw InputError("Geometry: type '" + type_name +
                           "' is not available yet (parameter Type)");
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
          default:
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
    // itself and every boundary face stays on its side. Near $c$ the cells
    // shrink by the factor $t^{p-1}$ of the derivative. The boundary ids are
    // then set from the face centres, after the global refinements.
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



    template <int dim>
    void
    Geometry<dim>::create_curved(dealii::Triangulation<dim> &) const
    {
      AssertThrow(false, dealii::ExcNotImplemented());
    }



    template <int dim>
    void
    Geometry<dim>::read_gmsh(dealii::Triangulation<dim> &) const
    {
      AssertThrow(false, dealii::ExcNotImplemented());
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
