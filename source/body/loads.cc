// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/base/exceptions.h>
#include <dpana/body/loads.h>
#include <dpana/parameters/list_syntax.h>

#include <deal.II/base/function.h>

#include <deal.II/lac/vector.h>

#include <set>

namespace dpana
{
  namespace
  {
    // The items of a list of loads on boundaries, each boundary once: a
    // boundary named twice would get the sum of its items, silently.
    std::vector<parameters::KeyValue>
    boundary_items(const std::string &entry, const std::string &parameter)
    {
      const auto items = parameters::split_key_value_list(entry, parameter);
      std::set<std::string> seen;
      for (const auto &item : items)
        if (!seen.insert(item.key).second)
          throw InputError(parameter + ": boundary '" + item.key +
                           "' is named twice (its items would add up); give "
                           "one item per boundary");
      return items;
    }
  } // namespace



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
    for (const auto &item : boundary_items(prm.get("Pressure"), p_pressure))
      pressure.push_back({item.key,
                          parameters::parse_double(item.value, p_pressure),
                          p_pressure});

    const std::string p_traction = path + " / Traction";
    for (const auto &item : boundary_items(prm.get("Traction"), p_traction))
      traction.push_back({item.key,
                          parameters::parse_vector<dim>(item.value, p_traction),
                          p_traction});

    const std::string p_forces = path + " / Concentrated forces";
    for (const auto &item :
         parameters::split_key_value_list(prm.get("Concentrated forces"),
                                          p_forces))
      concentrated_forces.push_back(
        {parameters::parse_point<dim>(item.key, p_forces),
         parameters::parse_vector<dim>(item.value, p_forces),
         p_forces});

    // A zero body force is no body force: the assembly skips it.
    const auto b = parameters::parse_vector<dim>(prm.get("Body force"),
                                                 path + " / Body force");
    if (b != dealii::Tensor<1, dim>())
      {
        dealii::Vector<double> bv(dim);
        for (unsigned int d = 0; d < dim; ++d)
          bv[d] = b[d];
        body_force =
          std::make_shared<dealii::Functions::ConstantFunction<dim>>(bv);
      }
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



  template struct Loads<2>;
  template struct Loads<3>;
} // namespace dpana
