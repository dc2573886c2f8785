// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_body_boundary_conditions_h
#define dpana_body_boundary_conditions_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

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

    /**
     * Declares the entries Fixed, Symmetry and Prescribed displacement of
     * the subsection "Boundary conditions" (the caller has entered it).
     */
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
} // namespace dpana

#endif
