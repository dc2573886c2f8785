// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/disc.h>
#include <dpana/parameters/list_syntax.h>

#include <deal.II/base/patterns.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <array>
#include <cmath>

namespace dpana
{
  namespace geometry
  {
    // The lower half (or the lower right quarter, x >= c_x) of the disc of
    // centre c and radius r as 6 (or 3) quadrilaterals (see the class
    // documentation of Disc), and with @p whole its mirror image above
    // y = c_y as well. Manifold 0 (polar) on the curved boundary, manifold 1
    // (transfinite interpolation) on the cells, flat straight boundaries.
    void
    make_disc_quadrilaterals(dealii::Triangulation<2> &quads,
                             const dealii::Point<2>    c,
                             const double              r,
                             const bool                quarter,
                             const bool                whole)
    {
      const double a = 0.5 * r, s = r / std::sqrt(2.);
      // Vertices relative to the centre: the lower half (0-10), then the
      // mirror images of the vertices 5-10 below y = 0 (11-16).
      std::vector<dealii::Point<2>> v = {{-r, 0},  // 0
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
      for (unsigned int i = 5; i <= 10; ++i)
        v.emplace_back(v[i][0], -v[i][1]);
      // Cells in deal.II's lexicographic vertex order (v0, v1, v2, v3 =
      // (0,0), (1,0), (0,1), (1,1) of the reference square).
      const std::vector<std::array<unsigned int, 4>> left  = {{{5, 6, 1, 2}},
                                                              {{8, 5, 0, 1}},
                                                              {{9, 6, 8, 5}}};
      const std::vector<std::array<unsigned int, 4>> right = {{{6, 7, 2, 3}},
                                                              {{7, 10, 3, 4}},
                                                              {{9, 10, 6, 7}}};

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
      // The mirror image of a cell: its vertices below y = 0 replaced by
      // their images, its rows swapped to keep the orientation.
      auto mirrored = [](const std::array<unsigned int, 4> &q) {
        const auto m = [](const unsigned int i) { return i < 5 ? i : i + 6; };
        return std::array<unsigned int, 4>{
          {m(q[2]), m(q[3]), m(q[0]), m(q[1])}};
      };
      for (const auto &q : right)
        {
          add(q);
          if (whole)
            add(mirrored(q));
        }
      if (!quarter)
        for (const auto &q : left)
          {
            add(q);
            if (whole)
              add(mirrored(q));
          }
      dealii::SubCellData subcell_data;
      dealii::GridTools::delete_unused_vertices(vertices, cells, subcell_data);
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
            // circle (no straight boundary face has both ends on it).
            const double r0 = (face->vertex(0) - c).norm();
            const double r1 = (face->vertex(1) - c).norm();
            const bool   on_circle =
              std::abs(r0 - r) < 1e-10 * r && std::abs(r1 - r) < 1e-10 * r;
            face->set_manifold_id(
              on_circle ? 0 : dealii::numbers::flat_manifold_id);
          }
      quads.set_manifold(0, dealii::PolarManifold<2>(c));
      dealii::TransfiniteInterpolationManifold<2> transfinite;
      transfinite.initialize(quads);
      quads.set_manifold(1, transfinite);
    }



    template <int dim>
    Disc<dim>::Disc(const bool quarter)
      : Disc(quarter, /*whole=*/false)
    {
    }



    template <int dim>
    Disc<dim>::Disc(const bool quarter, const bool whole)
      : CurvedShape<dim>(quarter)
      , whole(whole)
      , radius(1.)
      , length(1.)
      , n_axial_subdivisions(4)
    {
      Assert(!quarter || dim == 2, dealii::ExcNotImplemented());
      Assert(!whole || dim == 2, dealii::ExcNotImplemented());
    }



    // @sect3{Parameters}
    template <int dim>
    void
    Disc<dim>::declare_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Double;
      using dealii::Patterns::Integer;
      prm.declare_entry("Centre",
                        internal::repeat("0", dim),
                        dealii::Patterns::List(Double(), dim, dim),
                        dim == 2 ?
                          "Centre x, y (mm) of the circle." :
                          "x, y (mm) of the axis and the z coordinate (mm) "
                          "of the front end.");
      prm.declare_entry("Radius", "1", Double(0.), "Radius R (mm).");
      if (dim == 3)
        {
          prm.declare_entry("Length",
                            "1",
                            Double(0.),
                            "Length L (mm) along z; the body spans z from "
                            "the third coordinate of Centre to that plus L.");
          prm.declare_entry("Axial subdivisions",
                            "4",
                            Integer(1),
                            "Number of cell layers along z before the global "
                            "refinements.");
        }
      ContactRefinement::declare_parameters(
        prm, "the lowest point of the circle (Centre - R e_y)");
    }



    template <int dim>
    void
    Disc<dim>::parse_parameters(dealii::ParameterHandler &prm,
                                const std::string        &path)
    {
      this->centre =
        parameters::parse_point<dim>(prm.get("Centre"), path + " / Centre");
      radius = prm.get_double("Radius");
      if (!(radius > 0))
        throw InputError(path + " / Radius: must be positive");
      if (dim == 3)
        {
          length               = prm.get_double("Length");
          n_axial_subdivisions = prm.get_integer("Axial subdivisions");
          // At least 2 triangles, 3 tetrahedra each, per layer.
          check_mesh_size(6. * n_axial_subdivisions,
                          path + " / Axial subdivisions");
          if (!(length > 0))
            throw InputError(path + " / Length: must be positive");
        }
      this->refinement.parse_parameters(prm, path);
    }



    template <int dim>
    std::map<std::string, dealii::types::boundary_id>
    Disc<dim>::boundary_names() const
    {
      if (dim == 3)
        return {{"top", 0}, {"curved", 1}, {"front", 2}, {"back", 3}};
      if (this->quarter)
        return {{"top", 0}, {"curved", 1}, {"axis", 2}};
      return {{"top", 0}, {"curved", 1}};
    }



    template <int dim>
    std::string
    Disc<dim>::description() const
    {
      using internal::format_number;
      std::string s = "R = " + format_number(radius) + ", centre (" +
                      format_number(this->centre[0]) + ", " +
                      format_number(this->centre[1]) + ")";
      if (dim == 3)
        s += ", L = " + format_number(length) + " (" +
             std::to_string(n_axial_subdivisions) + " layers)";
      return s + this->refinement.description();
    }



    // @sect3{Creating the mesh}
    template <int dim>
    void
    Disc<dim>::make_quadrilaterals(dealii::Triangulation<2> &quads) const
    {
      make_disc_quadrilaterals(quads,
                               dealii::Point<2>(this->centre[0],
                                                this->centre[1]),
                               radius,
                               this->quarter,
                               whole);
    }



    template <int dim>
    dealii::Point<2>
    Disc<dim>::contact_point() const
    {
      return dealii::Point<2>(this->centre[0], this->centre[1]) -
             dealii::Tensor<1, 2>({0., radius});
    }



    template <int dim>
    std::vector<double>
    Disc<dim>::z_planes(const unsigned int n_global_refinements) const
    {
      const unsigned int n_z =
        n_axial_subdivisions * (1U << n_global_refinements);
      std::vector<double> z(n_z + 1);
      for (unsigned int k = 0; k <= n_z; ++k)
        z[k] = this->centre[dim - 1] + length * k / n_z;
      return z;
    }



    // The faces on the end planes (3D), on the flat side, on the axis
    // (quarter disc), and all others on the arc.
    template <int dim>
    std::string
    Disc<dim>::boundary_name(const dealii::Point<dim> &x) const
    {
      const dealii::Point<dim> &c   = this->centre;
      const double              tol = 1e-8 * radius;
      if (dim == 3 && std::abs(x[dim - 1] - c[dim - 1]) < tol)
        return "front";
      if (dim == 3 && std::abs(x[dim - 1] - c[dim - 1] - length) < tol)
        return "back";
      if (std::abs(x[1] - c[1]) < tol)
        return "top";
      if (this->quarter && std::abs(x[0] - c[0]) < tol)
        return "axis";
      return "curved";
    }



    template class Disc<2>;
    template class Disc<3>;
  } // namespace geometry
} // namespace dpana
