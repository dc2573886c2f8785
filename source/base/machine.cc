// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/machine.h>

#include <fstream>
#include <map>
#include <thread>

#include <dlfcn.h>
#include <sched.h>

namespace dpana
{
  namespace
  {
    // The entries of /proc/cpuinfo, each with the value of its first line
    // (that of the first processor); empty where the file is not there.
    std::map<std::string, std::string>
    cpuinfo()
    {
      std::map<std::string, std::string> entries;
      std::ifstream                      in("/proc/cpuinfo");
      std::string                        line;
      while (std::getline(in, line))
        {
          const auto colon = line.find(':');
          if (colon == std::string::npos || colon == 0)
            continue;
          const auto key_end = line.find_last_not_of(" \t", colon - 1);
          const auto first   = line.find_first_not_of(" \t", colon + 1);
          if (key_end == std::string::npos)
            continue;
          entries.emplace(line.substr(0, key_end + 1),
                          first == std::string::npos ? "" : line.substr(first));
        }
      return entries;
    }



    // The processor's model name, with its family and model numbers where
    // /proc/cpuinfo gives them (x86): a cloud's generic name ("Intel Xeon
    // Processor") covers several models. Other processors name their
    // model otherwise and get an empty string. Read once per process.
    const std::string &
    processor_model()
    {
      static const std::string name = [] {
        auto        entries = cpuinfo();
        std::string model   = entries["model name"];
        if (!model.empty() && !entries["cpu family"].empty() &&
            !entries["model"].empty())
          model += " (family " + entries["cpu family"] + ", model " +
                   entries["model"] + ")";
        return model;
      }();
      return name;
    }



    // The cores the process may run on (its affinity mask), else those of
    // the machine.
    unsigned int
    usable_cores()
    {
      cpu_set_t set;
      if (sched_getaffinity(0, sizeof(set), &set) == 0)
        return CPU_COUNT(&set);
      return std::thread::hardware_concurrency();
    }
  } // namespace



  Machine
  this_machine()
  {
    Machine m;
    m.processor = processor_model();
    m.cores     = usable_cores();
    // OpenBLAS' calls in the BLAS this process has loaded, looked up at run
    // time as in linear_algebra/blas_threads.cc.
    using CoreName   = char *(*)();
    using GetThreads = int (*)();
    const auto corename =
      reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
    const auto threads = reinterpret_cast<GetThreads>(
      dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    if (const char *name = corename == nullptr ? nullptr : corename())
      m.blas_kernels = name;
    if (threads != nullptr)
      m.blas_threads = threads();
    return m;
  }



  std::string
  describe(const Machine &machine)
  {
    std::string line =
      "Machine: " +
      (machine.processor.empty() ? std::string("processor not known") :
                                   machine.processor) +
      ", " + std::to_string(machine.cores) +
      (machine.cores == 1 ? " core; " : " cores; ");
    if (machine.blas_kernels.empty())
      return line + "a BLAS other than OpenBLAS";
    return line + "OpenBLAS " + machine.blas_kernels + " kernels on " +
           std::to_string(machine.blas_threads) +
           (machine.blas_threads == 1 ? " thread" : " threads");
  }
} // namespace dpana
