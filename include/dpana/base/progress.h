// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_base_progress_h
#define dpana_base_progress_h

#include <deal.II/base/timer.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <string>

namespace dpana
{
  /**
   * One phase of a run, timed: prints "[dpana] assembling ..." when the
   * phase starts and the wall time (" 0.12 s") when it ends, and counts the
   * time in a TimerOutput section of the same name (for the summary table at
   * the end of the run).
   */
  class Phase
  {
  public:
    Phase(dealii::TimerOutput &timer,
          const std::string   &name,
          std::ostream        &out = std::cout)
      : scope(timer, name)
      , out(out)
      , start(std::chrono::steady_clock::now())
    {
      out << "[dpana] " << name << " ... " << std::flush;
    }

    ~Phase()
    {
      const std::chrono::duration<double> t =
        std::chrono::steady_clock::now() - start;
      out << std::fixed << std::setprecision(2) << t.count() << " s"
          << std::defaultfloat << std::setprecision(6) << std::endl;
    }

  private:
    dealii::TimerOutput::Scope            scope;
    std::ostream                         &out;
    std::chrono::steady_clock::time_point start;
  };
} // namespace dpana

#endif
