// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/body/boundary_conditions.h>
#include <dpana/parameters/list_syntax.h>

#include <deal.II/base/function.h>

#include <deal.II/lac/vector.h>

namespace dpana
{
  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    prm.declare_entry(
      "Fixed",
      "",
      Anything(),
      "Displacement components held at zero on named boundaries: a list of "
      "'boundary: components' separated by semicolons, the components being "
      "x, y, z or all; e.g. 'bottom: x, y; left: x'. Empty: none.");
    prm.declare_entry(
      "Symmetry",
      "",
      Anything(),
      "Flat named boundaries on which the normal displacement is zero and "
      "the tangential displacement free (a plane of symmetry, or a "
      "frictionless flat support), separated by commas or semicolons; e.g. "
      "'left, front'. Empty: none.");
    prm.declare_entry(
      "Prescribed displacement",
      "",
      Anything(),
      "Given displacement components (mm) on named boundaries: a list of "
      "'boundary: component = value, ...' separated by semicolons; e.g. "
      "'top: y = -0.01; right: x = 0.02, y = 0'. Unlisted components stay "
      "free. Takes precedence over Fixed and Symmetry at shared vertices. "
      "Empty: none.");
  }



  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(dealii::ParameterHandler &prm,
                                            const std::string        &path)
  {
    fixed.clear();
    symmetry.clear();
    prescribed.clear();

    const std::string p_fixed = path + " / Fixed";
    for (const auto &item :
         parameters::split_key_value_list(prm.get("Fixed"), p_fixed))
      fixed.push_back({item.key,
                       parameters::parse_components(item.value, dim, p_fixed),
                       p_fixed});

    const std::string p_symmetry = path + " / Symmetry";
    for (const auto &name :
         parameters::split_names(prm.get("Symmetry"), p_symmetry))
      symmetry.push_back({name, p_symmetry});

    const std::string p_prescribed = path + " / Prescribed displacement";
    for (const auto &item :
         parameters::split_key_value_list(prm.get("Prescribed displacement"),
                                          p_prescribed))
      {
        const auto [mask, values] =
          parameters::parse_component_values(item.value, dim, p_prescribed);
        dealii::Vector<double> v(dim);
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = values[d];
        prescribed.push_back(
          {item.key,
           mask,
           std::make_shared<dealii::Functions::ConstantFunction<dim>>(v),
           p_prescribed});
      }
  }



  template <int dim>
  std::vector<std::pair<std::string, std::string>>
  BoundaryConditions<dim>::used_boundaries() const
  {
    std::vector<std::pair<std::string, std::string>> used;
    for (const auto &f : fixed)
      used.emplace_back(f.boundary, f.parameter);
    for (const auto &s : symmetry)
      used.emplace_back(s.boundary, s.parameter);
    for (const auto &p : prescribed)
      used.emplace_back(p.boundary, p.parameter);
    return used;
  }



  template struct BoundaryConditions<2>;
  template struct BoundaryConditions<3>;
} // namespace dpana
