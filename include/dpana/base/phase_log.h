// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_base_phase_log_h
#define dpana_base_phase_log_h

#include <deal.II/base/timer.h>

#include <chrono>
#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  /**
   * The record of the phases of one run: every phase (mesh, assembly,
   * contact surface, factorization, condensation, contact solve, recovery,
   * output)
   * is timed by one dealii::TimerOutput, and after it ends the peak resident
   * memory of the process so far (getrusage) is noted. Both go to the log
   * and to summary.json.
   *
   * A phase is opened with a Scope, which prints "[dpana] what ... " when it
   * starts and the wall time when it ends. Several scopes may add to the same
   * phase (e.g. the factorization of two bodies).
   */
  class PhaseLog
  {
  public:
    /**
     * @p out receives the progress lines; nullptr: a quiet run.
     */
    explicit PhaseLog(std::ostream *out);

    /**
     * Where the progress lines go; nullptr: nowhere.
     */
    void
    set_output(std::ostream *stream)
    {
      out = stream;
    }

    class Scope
    {
    public:
      Scope(PhaseLog &log, const std::string &phase, const std::string &what);
      ~Scope();

      Scope(const Scope &) = delete;
      Scope &
      operator=(const Scope &) = delete;

    private:
      PhaseLog                             &log;
      std::string                           phase;
      dealii::TimerOutput::Scope            timer_scope;
      std::chrono::steady_clock::time_point start;
    };

    /**
     * Opens @p phase; @p what is the progress text (default: the phase).
     */
    Scope
    phase(const std::string &phase, const std::string &what = "");

    /**
     * Counts @p seconds, measured before the phase was opened, in @p phase:
     * the reading of the mesh files while the parameters are read belongs
     * to the mesh phase, where the other meshes are built.
     */
    void
    add(const std::string &phase, const double seconds);

    /**
     * Wall time of every phase (s), with what add() counted in it.
     */
    std::map<std::string, double>
    timings() const;

    /**
     * Peak resident memory of the process at the end of every phase (MB).
     */
    const std::map<std::string, double> &
    peak_memory() const
    {
      return memory;
    }

    /**
     * One line "Timings (s): ...; peak memory (MB): ..." for the log.
     */
    void
    print(std::ostream &out) const;

  private:
    std::ostream                 *out;
    dealii::TimerOutput           timer;
    std::map<std::string, double> memory;
    std::map<std::string, double> added;
    std::vector<std::string>      order; // of the phases' first scopes
  };

  /**
   * Peak resident memory of this process so far, in MB (getrusage).
   */
  double
  peak_memory_mb();
} // namespace dpana

#endif
