// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_body_boundary_conditions_templates_h
#define dpana_body_boundary_conditions_templates_h

#include <dpana/base/exceptions.h>
#include <dpana/body/boundary_conditions.h>
#include <dpana/parameters/list_syntax.h>

#include <deal.II/base/function.h>

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



  template <int dim>
  void
  Loads<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    prm.declare_entry(
      "Pressure",
      "",
      Anything(),
      "Uniform pressure p (MPa) on named boundaries, positive when "
      "compressive: the traction is -p n, n the outward unit normal. A list "
      "of 'boundary: p' separated by semicolons; e.g. 'top: 50; right: "
      "100'. Empty: none.");
    prm.declare_entry(
      "Traction",
      "",
      Anything(),
      "Uniform traction vector (MPa) on named boundaries: a list of "
      "'boundary: tx, ty(, tz)' separated by semicolons; e.g. 'top: 0, "
      "-50'. Empty: none.");
    prm.declare_entry(
      "Concentrated forces",
      "",
      Anything(),
      "Forces applied at the mesh vertex nearest to a point (the vertex used "
      "is reported in the log): a list of 'x, y(, z): Fx, Fy(, Fz)' "
      "separated by semicolons, coordinates in mm, forces in N (3D) or N/mm "
      "of thickness (2D); e.g. '0, 80: 0, -200000'. Empty: none.");
    prm.declare_entry("Body force",
                      dim == 2 ? "0, 0" : "0, 0, 0",
                      Anything(),
                      "Constant body force per unit volume (N/mm^3), "
                      "components x, y(, z); e.g. gravity on steel is "
                      "'0, -7.7e-5'.");
  }



  template <int dim>
  void
  Loads<dim>::parse_parameters(dealii::ParameterHandler &prm,
                               const std::string        &path)
  {
    pressure.clear();
    traction.clear();
    concentrated_forces.clear();
    body_force.reset();

    const std::string p_pressure = path + " / Pressure";
    for (const auto &item :
         parameters::split_key_value_list(prm.get("Pressure"), p_pressure))
      pressure.push_back({item.key,
                          parameters::parse_double(item.value, p_pressure),
                          p_pressure});

    const std::string p_traction = path + " / Traction";
    for (const auto &item :
         parameters::split_key_value_list(prm.get("Traction"), p_traction))
      {
        const auto t = parameters::parse_doubles(item.value, dim, p_traction);
        dealii::Tensor<1, dim> tv;
        for (unsigned int d = 0; d < dim; ++d)
          tv[d] = t[d];
        traction.push_back({item.key, tv, p_traction});
      }

    const std::string p_forces = path + " / Concentrated forces";
    for (const auto &item :
         parameters::split_key_value_list(prm.get("Concentrated forces"),
                                          p_forces))
      {
        const auto x = parameters::parse_doubles(item.key, dim, p_forces);
        const auto F = parameters::parse_doubles(item.value, dim, p_forces);
        ConcentratedForce cf;
        for (unsigned int d = 0; d < dim; ++d)
          {
            cf.point[d] = x[d];
            cf.force[d] = F[d];
          }
        concentrated_forces.push_back(cf);
      }

    const std::string p_body = path + " / Body force";
    const auto        b =
      parameters::parse_doubles(prm.get("Body force"), dim, p_body);
    bool                   nonzero = false;
    dealii::Vector<double> bv(dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        bv[d] = b[d];
        nonzero |= (b[d] != 0.0);
      }
    if (nonzero)
      body_force =
        std::make_shared<dealii::Functions::ConstantFunction<dim>>(bv);
  }



  template <int dim>
  std::vector<std::pair<std::string, std::string>>
  Loads<dim>::used_boundaries() const
  {
    std::vector<std::pair<std::string, std::string>> used;
    for (const auto &p : pressure)
      used.emplace_back(p.boundary, p.parameter);
    for (const auto &t : traction)
      used.emplace_back(t.boundary, t.parameter);
    return used;
  }
} // namespace dpana

#endif
