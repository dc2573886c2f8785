// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_body_boundary_conditions_h
#define dpana_body_boundary_conditions_h

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
   * The kinematic conditions of a body, attached to named boundaries
   * (subsection "Boundary conditions"; syntax in doc/parameters.md):
   *
   * - Fixed: some displacement components are zero, e.g.
   *   `set Fixed = bottom: x, y; left: x`;
   * - Symmetry: the normal displacement is zero on a flat boundary, the
   *   tangential ones are free, e.g. `set Symmetry = left, front`;
   * - Prescribed displacement: given values of some components (mm), e.g.
   *   `set Prescribed displacement = top: y = -0.01`.
   *
   * A program can also prescribe displacements given by a Function (e.g.
   * an exact solution).
   */
  template <int dim>
  struct BoundaryConditions
  {
    struct Fixed
    {
      std::string       boundary;
      std::vector<bool> components;
      std::string       parameter;
    };

    struct Prescribed
    {
      std::string                                  boundary;
      std::vector<bool>                            components;
      std::shared_ptr<const dealii::Function<dim>> displacement;
      std::string                                  parameter;
    };

    struct Symmetry
    {
      std::string boundary;
      std::string parameter;
    };

    std::vector<Fixed>      fixed;
    std::vector<Symmetry>   symmetry;
    std::vector<Prescribed> prescribed;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Reads the subsection (the caller has entered it); @p path is the
     * subsection's path for error messages, e.g. "Body 1 / Boundary
     * conditions".
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

    /**
     * All boundary names used, with the parameter that used them.
     */
    std::vector<std::pair<std::string, std::string>>
    used_boundaries() const;
  };



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
    };

    std::vector<Pressure>                        pressure;
    std::vector<Traction>                        traction;
    std::vector<ConcentratedForce>               concentrated_forces;
    std::shared_ptr<const dealii::Function<dim>> body_force;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

    std::vector<std::pair<std::string, std::string>>
    used_boundaries() const;
  };
} // namespace dpana

#endif
