// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_output_summary_h
#define dpana_output_summary_h

#include <dpana/base/machine.h>
#include <dpana/base/phase_log.h>
#include <dpana/body/body.h>
#include <dpana/scene/contact_summary.h>

#include <string>

#include <nlohmann/json.hpp>

namespace dpana
{
  namespace output
  {
    /**
     * The results of one body: sizes, material, largest displacement and
     * von Mises stress, load resultant, reactions (elastic runs),
     * concentrated forces with the vertex that carried them.
     */
    template <int dim>
    nlohmann::json
    to_json(const Body<dim> &body);

    /**
     * The answer of a contact run: solver result (converged, iterations,
     * residual and its parts, message), half width, pressure, zones, rigid
     * displacements of the floating bodies and the comparisons with the
     * references.
     */
    nlohmann::json
    to_json(const scene::ContactSummary &summary, const unsigned int dim);

    /**
     * "timings" (s) and "peak_memory_mb" of every phase.
     */
    nlohmann::json
    to_json(const PhaseLog &phases);

    /**
     * The machine of the run (base/machine.h) and its number of MPI
     * processes: `processor` (null where not known), `cores`,
     * `blas_kernels` and `blas_threads` (null with a BLAS other than
     * OpenBLAS), `mpi_processes`.
     */
    nlohmann::json
    to_json(const Machine &machine, const unsigned int mpi_processes);

    /**
     * Writes @p summary to @p filename, indented.
     */
    void
    write_json(const nlohmann::json &summary, const std::string &filename);
  } // namespace output
} // namespace dpana

#endif
