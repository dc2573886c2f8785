// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/phase_log.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <sys/resource.h>

namespace dpana
{
  double
  peak_memory_mb()
  {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    // Linux reports ru_maxrss in kilobytes.
    return usage.ru_maxrss / 1024.0;
  }



  namespace
  {
    // The TimerOutput only collects the times (it never prints): its
    // stream is a sink that nothing is written to.
    std::ostream &
    null_stream()
    {
      static std::ostringstream sink;
      return sink;
    }
  } // namespace



  PhaseLog::PhaseLog(std::ostream *out)
    : out(out)
    , timer(null_stream(),
            dealii::TimerOutput::never,
            dealii::TimerOutput::wall_times)
  {
  }



  PhaseLog::Scope::Scope(PhaseLog          &log,
                         const std::string &phase,
                         const std::string &what)
    : log(log)
    , phase(phase)
    , timer_scope(log.timer, phase)
    , start(std::chrono::steady_clock::now())
  {
    if (std::find(log.order.begin(), log.order.end(), phase) == log.order.end())
      log.order.push_back(phase);
    if (log.out)
      *log.out << "[dpana] " << (what.empty() ? phase : what) << " ... "
               << std::flush;
  }



  PhaseLog::Scope::~Scope()
  {
    const std::chrono::duration<double> t =
      std::chrono::steady_clock::now() - start;
    log.memory[phase] = peak_memory_mb();
    if (log.out)
      *log.out << std::fixed << std::setprecision(2) << t.count() << " s"
               << std::defaultfloat << std::setprecision(6) << std::endl;
  }



  PhaseLog::Scope
  PhaseLog::phase(const std::string &phase, const std::string &what)
  {
    return Scope(*this, phase, what);
  }



  void
  PhaseLog::add(const std::string &phase, const double seconds)
  {
    added[phase] += seconds;
  }



  std::map<std::string, double>
  PhaseLog::timings() const
  {
    std::map<std::string, double> t = added;
    for (const auto &[name, s] :
         timer.get_summary_data(dealii::TimerOutput::total_wall_time))
      t[name] += s;
    return t;
  }



  void
  PhaseLog::print(std::ostream &o) const
  {
    const auto t = timings();
    o << "Timings (s):";
    for (const auto &name : order)
      o << " " << name << " " << t.at(name) << ";";
    o << " peak memory (MB):";
    for (const auto &name : order)
      o << " " << name << " " << std::fixed << std::setprecision(0)
        << memory.at(name) << ";";
    o << std::defaultfloat << std::setprecision(6) << std::endl;
  }
} // namespace dpana
