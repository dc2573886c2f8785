// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/circle.h>
#include <dpana/parameters/list_syntax.h>

#include <deal.II/base/patterns.h>

#include <cmath>

namespace dpana
{
  namespace geometry
  {
    template <int dim>
    Circle<dim>::Circle(const bool half)
      : Disc<dim>(half, /*whole=*/true)
      , patch_half_width(0.)
    {
    }



    // @sect3{Parameters}
    template <int dim>
    void
    Circle<dim>::declare_parameters(dealii::ParameterHandler &prm)
    {
      Disc<dim>::declare_parameters(prm);
      prm.declare_entry("Load patch half width",
                        "0",
                        dealii::Patterns::Double(0.),
                        "Half width w (mm) of the boundary `load patch`: the "
                        "faces of the upper arc whose centres lie within w "
                        "of the vertical axis x = Centre_x (whole faces, so "
                        "its width is w rounded to the faces). 0: no patch.");
      prm.declare_entry("Load patch refinements",
                        "0",
                        dealii::Patterns::Integer(0, 10),
                        "Extra refinements of the cells within the Load "
                        "patch half width of the highest point of the "
                        "circle (Centre + R e_y).");
    }



    template <int dim>
    void
    Circle<dim>::parse_parameters(dealii::ParameterHandler &prm,
                                  const std::string        &path)
    {
      Disc<dim>::parse_parameters(prm, path);
      patch_half_width = prm.get_double("Load patch half width");
      if (!(patch_half_width < this->radius))
        throw InputError(path +
                         " / Load patch half width: must be less than the "
                         "Radius");
      patch_refinement.n_refinements =
        prm.get_integer("Load patch refinements");
      patch_refinement.radius = patch_half_width;
      if (patch_refinement.n_refinements > 0 && !(patch_half_width > 0))
        throw InputError(path +
                         " / Load patch refinements: need a positive Load "
                         "patch half width");
    }



    template <int dim>
    std::map<std::string, dealii::types::boundary_id>
    Circle<dim>::boundary_names() const
    {
      std::map<std::string, dealii::types::boundary_id> names = {{"curved", 1}};
      if (this->quarter)
        names["axis"] = 2;
      if (patch_half_width > 0)
        names["load patch"] = 3;
      return names;
    }



    template <int dim>
    std::string
    Circle<dim>::description() const
    {
      std::string s = Disc<dim>::description();
      if (patch_half_width > 0)
        s += ", load patch half width " +
             internal::format_number(patch_half_width) + " (" +
             std::to_string(patch_refinement.n_refinements) + " refinements)";
      return s;
    }



    // @sect3{Creating the mesh}
    template <int dim>
    std::vector<std::pair<dealii::Point<2>, ContactRefinement>>
    Circle<dim>::further_refinements() const
    {
      if (patch_refinement.n_refinements == 0)
        return {};
      return {
        {dealii::Point<2>(this->centre[0], this->centre[1] + this->radius),
         patch_refinement}};
    }



    // The faces on the axis (half model), the load patch on the upper arc,
    // and all others on the arc.
    template <int dim>
    std::string
    Circle<dim>::boundary_name(const dealii::Point<dim> &x) const
    {
      const dealii::Point<dim> &c   = this->centre;
      const double              tol = 1e-8 * this->radius;
      if (this->quarter && std::abs(x[0] - c[0]) < tol)
        return "axis";
      if (x[1] > c[1] && std::abs(x[0] - c[0]) < patch_half_width)
        return "load patch";
      return "curved";
    }



    template class Circle<2>;
    template class Circle<3>;
  } // namespace geometry
} // namespace dpana
