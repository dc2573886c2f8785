// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_body_loads_h
#define dpana_body_loads_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  /**
   * The loads of a body (subsection "Loads"):
   *
   * - Pressure (MPa) on named boundaries, positive = compressive, i.e. the
   *   traction is -p n with n the outward unit normal:
   *   `set Pressure = top: 50; right: 100`;
   * - Traction (MPa), a constant vector per named boundary:
   *   `set Traction = top: 0, -50`;
   * - Concentrated forces (N in 3D, N/mm of thickness in 2D) at the mesh
   *   vertex nearest to a given point: `set Concentrated forces = 0, 80: 0,
   *   -200000`;
   * - Body force (N/mm^3), constant: `set Body force = 0, -7.85e-5`.
   *
   * A program can also set a body force given by a Function.
   */
  template <int dim>
  struct Loads
  {
    struct Pressure
    {
      std::string boundary;
      double      pressure;
      std::string parameter;
    };

    struct Traction
    {
      std::string            boundary;
      dealii::Tensor<1, dim> traction;
      std::string            parameter;
    };

    struct ConcentratedForce
    {
      dealii::Point<dim>     point;
      dealii::Tensor<1, dim> force;
      std::string            parameter;
    };

    std::vector<Pressure>                        pressure;
    std::vector<Traction>                        traction;
    std::vector<ConcentratedForce>               concentrated_forces;
    std::shared_ptr<const dealii::Function<dim>> body_force;

    /**
     * Declares the entries Pressure, Traction, Concentrated forces and Body
     * force of the subsection "Loads" (the caller has entered it).
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Reads the subsection (the caller has entered it); @p path is the
     * subsection's path for error messages, e.g. "Body 1 / Loads". A zero
     * body force leaves body_force empty.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

    /**
     * The boundary names used by pressures and tractions, with the
     * parameter that used them.
     */
    std::vector<std::pair<std::string, std::string>>
    used_boundaries() const;
  };
} // namespace dpana

#endif
