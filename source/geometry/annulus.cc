// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/annulus.h>
#include <dpana/parameters/list_syntax.h>

#include <deal.II/base/patterns.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <cmath>

namespace dpana
{
  namespace geometry
  {
    namespace
    {
      // The polar grid of the class documentation. Angles run from -pi/2
      // (the lowest point) in the quarter, from -pi (the left end) to 0 (the
      // right end) in the half annulus.
      void
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
    } // namespace



    template <int dim>
    Annulus<dim>::Annulus(const bool quarter)
      : CurvedShape<dim>(quarter)
      , inner_radius(0.5)
      , outer_radius(1.)
    {
      Assert(dim == 2, dealii::ExcNotImplemented());
    }



    // @sect3{Parameters}
    template <int dim>
    void
    Annulus<dim>::declare_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Double;
      prm.declare_entry("Centre",
                        internal::repeat("0", dim),
                        dealii::Patterns::List(Double(), dim, dim),
                        "Centre x, y (mm) of the circles.");
      prm.declare_entry("Inner radius",
                        "0.5",
                        Double(0.),
                        "Inner radius Ri (mm).");
      prm.declare_entry("Outer radius",
                        "1",
                        Double(0.),
                        "Outer radius Ro (mm).");
      ContactRefinement::declare_parameters(
        prm, "the lowest point of the inner circle (Centre - Ri e_y)");
    }



    template <int dim>
    void
    Annulus<dim>::parse_parameters(dealii::ParameterHandler &prm,
                                   const std::string        &path)
    {
      this->centre =
        parameters::parse_point<dim>(prm.get("Centre"), path + " / Centre");
      inner_radius = prm.get_double("Inner radius");
      outer_radius = prm.get_double("Outer radius");
      if (!(inner_radius > 0 && outer_radius > inner_radius))
        throw InputError(path + ": need 0 < Inner radius < Outer radius");
      this->refinement.parse_parameters(prm, path);
    }



    template <int dim>
    std::map<std::string, dealii::types::boundary_id>
    Annulus<dim>::boundary_names() const
    {
      if (this->quarter)
        return {{"inner", 0}, {"outer", 1}, {"x_axis", 2}, {"y_axis", 3}};
      return {{"inner", 0}, {"outer", 1}, {"left", 2}, {"right", 3}};
    }



    template <int dim>
    std::string
    Annulus<dim>::description() const
    {
      using internal::format_number;
      return "Ri = " + format_number(inner_radius) +
             ", Ro = " + format_number(outer_radius) + ", centre (" +
             format_number(this->centre[0]) + ", " +
             format_number(this->centre[1]) + ")" +
             this->refinement.description();
    }



    // @sect3{Creating the mesh}
    template <int dim>
    void
    Annulus<dim>::make_quadrilaterals(dealii::Triangulation<2> &quads) const
    {
      make_half_annulus_quads(quads,
                              dealii::Point<2>(this->centre[0],
                                               this->centre[1]),
                              inner_radius,
                              outer_radius,
                              this->quarter);
    }



    template <int dim>
    dealii::Point<2>
    Annulus<dim>::contact_point() const
    {
      return dealii::Point<2>(this->centre[0], this->centre[1]) -
             dealii::Tensor<1, 2>({0., inner_radius});
    }



    // The straight edges by their coordinates, the arcs by the nearer
    // radius.
    template <int dim>
    std::string
    Annulus<dim>::boundary_name(const dealii::Point<dim> &x) const
    {
      const dealii::Point<dim> &c   = this->centre;
      const double              tol = 1e-8 * outer_radius;
      if (this->quarter && std::abs(x[1] - c[1]) < tol)
        return "x_axis";
      if (this->quarter && std::abs(x[0] - c[0]) < tol)
        return "y_axis";
      if (std::abs(x[1] - c[1]) < tol)
        return (x[0] < c[0] ? "left" : "right");
      const double rho = std::hypot(x[0] - c[0], x[1] - c[1]);
      return (std::abs(rho - inner_radius) < std::abs(rho - outer_radius) ?
                "inner" :
                "outer");
    }



    template class Annulus<2>;
    template class Annulus<3>;
  } // namespace geometry
} // namespace dpana
