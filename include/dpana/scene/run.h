// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_scene_run_h
#define dpana_scene_run_h

#include <dpana/parameters/parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <iosfwd>
#include <string>

namespace dpana
{
  namespace scene
  {
    /**
     * Exit status of a run whose contact solver did not converge (and
     * `Contact / Allow non-converged` is false).
     */
    constexpr int exit_not_converged = 2;

    /**
     * Declares every entry of a parameter file whose outline (dimension,
     * number of bodies, contact or not) the pre-scan
     * parameters::scan_file() has read: the top-level entries `Dimension`
     * and `Number of bodies`, then Scene<dim>::declare_parameters().
     */
    void
    declare_parameters(dealii::ParameterHandler      &prm,
                       const parameters::FileOutline &outline);

    /**
     * Prints the documented parameter set of the run of @p prm_file (or of
     * an elastic 2D run of one body if @p prm_file is empty), its values
     * completed with the defaults.
     */
    void
    print_parameters(const std::string &prm_file, std::ostream &out);

    /**
     * Runs the scene of @p prm_file. Returns the exit status: 0 on success,
     * exit_not_converged if the contact solver did not converge (the output
     * is written and marked as such) and `Contact / Allow non-converged` is
     * false. Input errors are thrown as dpana::InputError.
     */
    int
    run(const std::string &prm_file);
  } // namespace scene
} // namespace dpana

#endif
