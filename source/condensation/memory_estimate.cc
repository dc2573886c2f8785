// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/condensation/memory_estimate.h>

#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include <unistd.h>

namespace dpana
{
  namespace condensation
  {
    std::string
    MemoryEstimate::describe() const
    {
      if (!made)
        return "not made (the factorisation back end has no symbolic "
               "analysis to estimate from)";
      const double       GB = 1e9;
      std::ostringstream s;
      s << n_dofs << " dofs, n_Gamma = " << n_gamma << ", n_c = " << n_c
        << ": about " << std::setprecision(3) << total() / GB << " GB (factor "
        << factor / GB << " GB, dense blocks W and A " << dense / GB
        << " GB, in use before " << current / GB << " GB)";
      if (!ordering.empty())
        s << ", ordering " << ordering;
      if (!method.empty())
        s << ", " << method << " factor";
      return s.str();
    }



    MemoryEstimate
    estimate_memory(const linear_algebra::SparseCholesky::Analysis &analysis,
                    const unsigned int                              n_dofs,
                    const unsigned int                              n_c)
    {
      MemoryEstimate m;
      m.made          = true;
      m.n_dofs        = n_dofs;
      m.n_gamma       = analysis.n_last;
      m.ordering      = analysis.ordering;
      m.method        = analysis.supernodal ? "supernodal" : "simplicial";
      m.n_c           = n_c;
      m.current       = resident_memory();
      const double ng = analysis.n_last;
      const double nc = n_c;
      // CHOLMOD's 64-bit interface: 8 bytes per number and per index.
      m.factor = 8.0 * (analysis.factor_entries + analysis.factor_indices +
                        analysis.largest_update) +
                 16.0 * analysis.matrix_entries +
                 8.0 * 8.0 * analysis.n_unknowns;
      m.dense = 8.0 * (ng * nc + 5.0 * nc * nc);
      return m;
    }



    double
    resident_memory()
    {
      std::ifstream statm("/proc/self/statm");
      double        size = 0, resident = 0;
      statm >> size >> resident;
      return resident * sysconf(_SC_PAGESIZE);
    }



    double
    memory_limit(const double limit_gb)
    {
      if (limit_gb > 0)
        return limit_gb * 1e9;
      std::ifstream meminfo("/proc/meminfo");
      std::string   key;
      double        value = 0;
      std::string   unit;
      while (meminfo >> key >> value >> unit)
        if (key == "MemAvailable:")
          return resident_memory() + value * 1024.0;
      return std::numeric_limits<double>::infinity();
    }



    MemoryReservations::Decision
    MemoryReservations::request(const MemoryEstimate &estimate,
                                const double          limit)
    {
      const std::lock_guard<std::mutex> lock(mutex);
      if (estimate.total() + granted <= limit)
        {
          granted += estimate.factor + estimate.dense;
          return Decision::granted;
        }
      return granted > 0 ? Decision::deferred : Decision::refused;
    }
  } // namespace condensation
} // namespace dpana
