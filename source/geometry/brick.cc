// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/brick.h>
#include <dpana/parameters/list_syntax.h>

#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <cmath>

namespace dpana
{
  namespace geometry
  {
    template <int dim>
    Brick<dim>::Brick()
      : subdivisions(dim, 1)
      , grading_exponents(dim, 1.)
    {
      for (unsigned int d = 0; d < dim; ++d)
        upper_corner[d] = 1.;
    }



    // @sect3{Parameters}
    //
    // Points are comma separated lists of dim coordinates.
    template <int dim>
    void
    Brick<dim>::declare_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Double;
      using dealii::Patterns::Integer;
      using dealii::Patterns::List;
      using internal::repeat;

      prm.declare_entry("Lower corner",
                        repeat("0", dim),
                        List(Double(), dim, dim),
                        "The corner with the smallest coordinates, x, y (, z) "
                        "in mm.");
      prm.declare_entry("Upper corner",
                        repeat("1", dim),
                        List(Double(), dim, dim),
                        "The corner with the largest coordinates, x, y (, z) "
                        "in mm.");
      prm.declare_entry("Subdivisions",
                        repeat("1", dim),
                        List(Integer(1), dim, dim),
                        "Number of cell layers in the x, y (, z) directions "
                        "before the global refinements. Each rectangle of "
                        "the grid is split into 2 triangles, each brick into "
                        "5 tetrahedra.");
      prm.declare_entry(
        "Grading centre",
        repeat("0", dim),
        List(Double(), dim, dim),
        "Coordinates c_d (mm) of the planes x_d = c_d towards which the "
        "vertices are clustered, one per direction; read only for the "
        "directions whose grading exponent differs from 1, and then it must "
        "lie between the corners. E.g. centre (0, 40) with exponents (2, 2) "
        "refines towards the point (0, 40); exponents (1, 2) refine towards "
        "the line y = 40.");
      prm.declare_entry(
        "Grading exponents",
        repeat("1", dim),
        List(Double(1., 10.), dim, dim),
        "Grading exponent p_d >= 1 per direction (dimensionless). A vertex at "
        "relative distance t in [0, 1] from the grading plane (t = 1 at the "
        "corner) is moved to relative distance t^p; p = 1 is a uniform grid, "
        "p > 1 makes the cells next to the plane smaller (the first of n "
        "layers by the factor n^(p-1)) and those far from it larger.");
      if (dim == 2)
        prm.declare_entry(
          "Diagonals",
          "one direction",
          dealii::Patterns::Selection("one direction|alternating"),
          "How each rectangle of the grid is split into 2 triangles. one "
          "direction: every diagonal runs the same way (deal.II's split). "
          "alternating: the direction alternates from rectangle to rectangle "
          "as on a checkerboard, so that the mesh is mirror-symmetric about "
          "every grid line. Choose it for a half model whose symmetry axis is "
          "a side: the half and its mirror image then form one checkerboard, "
          "whereas with one direction the diagonals of the whole change "
          "direction at the axis, and the tractions next to that seam carry "
          "an error of the first order in h (doc/geometry.md).");
      prm.declare_entry(
        "Load patch centre",
        repeat("0", dim),
        List(Double(), dim, dim),
        "Centre (mm) of the load patch on the top; its y coordinate is not "
        "read. E.g. the lower corner of a quarter model whose symmetry planes "
        "pass through it.");
      prm.declare_entry(
        "Load patch half width",
        "0",
        Double(0.),
        "Half width w (mm) of the boundary `load patch`: the faces of the top "
        "whose centres lie within w of the Load patch centre in x (and z). "
        "0: no load patch, the whole top is `top`.");
    }



    template <int dim>
    void
    Brick<dim>::parse_parameters(dealii::ParameterHandler &prm,
                                 const std::string        &path)
    {
      using parameters::parse_point;
      parameter = path;
      lower_corner =
        parse_point<dim>(prm.get("Lower corner"), path + " / Lower corner");
      upper_corner =
        parse_point<dim>(prm.get("Upper corner"), path + " / Upper corner");
      const auto n = dealii::Utilities::string_to_int(
        dealii::Utilities::split_string_list(prm.get("Subdivisions")));
      subdivisions.assign(n.begin(), n.end());
      grading_centre =
        parse_point<dim>(prm.get("Grading centre"), path + " / Grading centre");
      grading_exponents =
        parameters::parse_doubles(prm.get("Grading exponents"),
                                  dim,
                                  path + " / Grading exponents");
      patch_centre     = parse_point<dim>(prm.get("Load patch centre"),
                                      path + " / Load patch centre");
      patch_half_width = prm.get_double("Load patch half width");
      alternating      = dim == 2 && prm.get("Diagonals") == "alternating";
      for (unsigned int d = 0; d < dim; ++d)
        {
          if (!(upper_corner[d] > lower_corner[d]))
            throw InputError(path +
                             " / Upper corner: must exceed Lower corner in "
                             "every coordinate");
          if (grading_exponents[d] != 1. &&
              (grading_centre[d] < lower_corner[d] ||
               grading_centre[d] > upper_corner[d]))
            throw InputError(path + " / Grading centre: must lie between Lower "
                                    "corner and Upper corner in every graded "
                                    "direction");
        }
      if (patch_half_width > 0.)
        for (unsigned int d = 0; d < dim; ++d)
          if (d != 1 &&
              (patch_centre[d] + patch_half_width <= lower_corner[d] ||
               patch_centre[d] - patch_half_width >= upper_corner[d]))
            throw InputError(path + " / Load patch centre: the patch misses "
                                    "the top face");
    }



    template <int dim>
    std::map<std::string, dealii::types::boundary_id>
    Brick<dim>::boundary_names() const
    {
      std::map<std::string, dealii::types::boundary_id> names = {{"left", 0},
                                                                 {"right", 1},
                                                                 {"bottom", 2},
                                                                 {"top", 3}};
      if (dim == 3)
        {
          names["front"] = 4;
          names["back"]  = 5;
        }
      if (patch_half_width > 0.)
        names["load patch"] = 6;
      return names;
    }



    template <int dim>
    std::string
    Brick<dim>::description() const
    {
      std::string sizes, cells;
      for (unsigned int d = 0; d < dim; ++d)
        {
          sizes += (d == 0 ? "" : " x ") +
                   internal::format_number(upper_corner[d] - lower_corner[d]);
          cells += (d == 0 ? "" : " x ") + std::to_string(subdivisions[d]);
        }
      return sizes + ", " + cells + " subdivisions" +
             (alternating ? ", alternating diagonals" : "") +
             (graded() ? ", graded" : "") +
             (patch_half_width > 0. ?
                ", load patch half width " +
                  internal::format_number(patch_half_width) :
                "");
    }



    template <int dim>
    bool
    Brick<dim>::graded() const
    {
      return std::any_of(grading_exponents.begin(),
                         grading_exponents.end(),
                         [](const double p) { return p != 1.; });
    }



    template <int dim>
    std::pair<double, std::string>
    Brick<dim>::estimated_size(const unsigned int n_global_refinements) const
    {
      double n_coarse = dim == 2 ? 2 : 5;
      for (const unsigned int n : subdivisions)
        n_coarse *= n;
      // The entry to blame: the Subdivisions if they alone are too many.
      return {n_coarse * std::pow(2., dim * n_global_refinements),
              n_coarse > max_cells ? parameter + " / Subdivisions" :
                                     "Geometry / Global refinements"};
    }



    // @sect3{Creating the mesh}
    template <int dim>
    void
    Brick<dim>::create_triangulation(
      dealii::Triangulation<dim> &tria,
      const unsigned int          n_global_refinements) const
    {
      if (alternating)
        create_alternating_triangles(tria);
      else
        dealii::GridGenerator::subdivided_hyper_rectangle_with_simplices(
          tria, subdivisions, lower_corner, upper_corner, false);
      if (graded())
        apply_grading(tria);
      tria.refine_global(n_global_refinements);
      set_boundary_ids(tria);
    }



    // The grid of Subdivisions rectangles with the vertices a, b, c, d
    // (lower left, lower right, upper right, upper left, counterclockwise),
    // each split along the diagonal a-c where i + j is even and b-d where it
    // is odd. Reflecting the grid about the line x = x_i maps the rectangle
    // (i + k, j) onto (i - 1 - k, j), whose parity differs, and its diagonal
    // a-c onto a diagonal b-d: the split is mirror-symmetric about every
    // grid line, in x and in y.
    template <int dim>
    void
    Brick<dim>::create_alternating_triangles(
      dealii::Triangulation<dim> &tria) const
    {
      Assert(dim == 2, dealii::ExcNotImplemented());
      const unsigned int nx = subdivisions[0], ny = subdivisions[1];
      std::vector<dealii::Point<dim>> vertices;
      for (unsigned int j = 0; j <= ny; ++j)
        for (unsigned int i = 0; i <= nx; ++i)
          {
            dealii::Point<dim> x = lower_corner;
            x[0] += (upper_corner[0] - lower_corner[0]) * i / nx;
            x[1] += (upper_corner[1] - lower_corner[1]) * j / ny;
            vertices.push_back(x);
          }
      const auto vertex = [nx](const unsigned int i, const unsigned int j) {
        return j * (nx + 1) + i;
      };
      std::vector<dealii::CellData<dim>> cells;
      const auto add = [&cells](const std::vector<unsigned int> &v) {
        dealii::CellData<dim> cell(v.size());
        cell.vertices = v;
        cells.push_back(cell);
      };
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            const unsigned int a = vertex(i, j), b = vertex(i + 1, j),
                               c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
            if ((i + j) % 2 == 0)
              {
                add({a, b, c});
                add({a, c, d});
              }
            else
              {
                add({a, b, d});
                add({b, c, d});
              }
          }
      tria.create_triangulation(vertices, cells, dealii::SubCellData());
    }



    // The grading map of the class documentation, direction by direction.
    template <int dim>
    void
    Brick<dim>::apply_grading(dealii::Triangulation<dim> &tria) const
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
                  y[d] = c[d] + (u[d] - c[d]) *
                                  std::pow((x[d] - c[d]) / (u[d] - c[d]), p[d]);
                else if (x[d] < c[d])
                  y[d] = c[d] - (c[d] - l[d]) *
                                  std::pow((c[d] - x[d]) / (c[d] - l[d]), p[d]);
              }
          return y;
        },
        tria);
    }



    // Boundary ids from the face centres: 2d for the face at the lower
    // corner in direction d, 2d+1 for the one at the upper corner, 6 for the
    // faces of the top (2 * 1 + 1 = 3) in the load patch.
    template <int dim>
    void
    Brick<dim>::set_boundary_ids(dealii::Triangulation<dim> &tria) const
    {
      double size = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        size = std::max(size, upper_corner[d] - lower_corner[d]);
      const double tolerance     = 1e-10 * size;
      unsigned int n_patch_faces = 0;
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
                    const bool patch = d == 1 && in_load_patch(x);
                    face->set_boundary_id(patch ? 6 : 2 * d + 1);
                    n_patch_faces += patch;
                    found = true;
                  }
              Assert(found, dealii::ExcInternalError());
            }
      // A patch narrower than the cells can miss every face centre: its
      // pressure would then act nowhere.
      if (patch_half_width > 0. && n_patch_faces == 0)
        throw InputError(parameter +
                         " / Load patch half width: no face centre of the "
                         "top lies within it; widen it or refine the mesh");
    }



    template <int dim>
    bool
    Brick<dim>::in_load_patch(const dealii::Point<dim> &x) const
    {
      if (!(patch_half_width > 0.))
        return false;
      for (unsigned int d = 0; d < dim; ++d)
        if (d != 1 && std::abs(x[d] - patch_centre[d]) > patch_half_width)
          return false;
      return true;
    }



    template class Brick<2>;
    template class Brick<3>;
  } // namespace geometry
} // namespace dpana
