// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_base_simulation_h
#define dpana_base_simulation_h

#include <dpana/body/body.h>
#include <dpana/output/output.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  /**
   * One run of dpana on a parameter file:
   *
   *     set Dimension = 2
   *     subsection Body 1       (Geometry, Material, Boundary conditions,
   *                              Loads)
   *     subsection Output
   *     subsection Linear solver
   *
   * The phases: build the meshes and constraints and check everything
   * that can be wrong with the input (a body that is not held included),
   * THEN create the output directory and write the parameters used into it,
   * assemble, factor and solve, postprocess, write the results. If a phase
   * after the creation of the output directory fails, the directory is
   * removed again (if this run created it), so that a failed run leaves no
   * output behind.
   */
  template <int dim>
  class Simulation
  {
  public:
    Simulation();

    /**
     * Declares every entry except "Dimension" (see
     * parameters::declare_dimension()).
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Runs all phases; @p prm is the handler the parameters were read with,
     * written as parameters.prm/.json into the output directory.
     */
    void
    run(const dealii::ParameterHandler &prm);

    /**
     * The bodies (after run(), solved).
     */
    const std::vector<std::unique_ptr<Body<dim>>> &
    bodies() const;

  private:
    std::vector<std::unique_ptr<Body<dim>>> bodies_;
    output::Parameters                      output_parameters;
    unsigned int                            block_size;
  };
} // namespace dpana

#endif
