// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_output_output_h
#define dpana_output_output_h

#include <dpana/body/body.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace dpana
{
  namespace output
  {
    /**
     * The "Output" subsection: where a run writes its files, and which.
     */
    struct Parameters
    {
      std::string directory = "output";
      bool        write_vtu = true;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * The file name stem of a body: "Body 1" -> "body-1".
     */
    std::string
    file_stem(const std::string &body_name);

    /**
     * Writes the VTU file @p filename of a solved body whose stresses have
     * been computed (Body::compute_stresses() or Body::postprocess()):
     * - point data "displacement" (mm), a vector (ParaView: Warp By Vector);
     * - cell data "stress_xx", "stress_yy", "stress_xy" (, "stress_zz",
     *   "stress_yz", "stress_xz") in MPa, constant in each P1 cell, with
     *   "stress_zz" the out-of-plane stress in 2D, and "von_mises" (MPa).
     * The elastic runs and the contact runs both write their bodies with it.
     */
    template <int dim>
    void
    write_vtu_file(const Body<dim> &body, const std::string &filename);

    /**
     * Writes DIRECTORY/STEM.vtu (by write_vtu_file()) and DIRECTORY/STEM.pvd
     * for a solved and postprocessed body. Returns the names of the files
     * written.
     */
    template <int dim>
    std::vector<std::string>
    write_vtu(const Body<dim> &body, const std::string &directory);

    /**
     * The JSON object of one body's results (no timings, so that it can be
     * compared between runs): sizes, material, largest displacement and
     * von Mises stress, load resultant, reactions, concentrated forces with
     * the vertex that carried them.
     */
    template <int dim>
    void
    write_body_summary(const Body<dim> &body, std::ostream &out);

    /**
     * Writes a {"section": seconds, ...} JSON object.
     */
    void
    write_timings(const std::map<std::string, double> &timings,
                  std::ostream                        &out);
  } // namespace output
} // namespace dpana

#endif
