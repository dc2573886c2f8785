// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_base_machine_h
#define dpana_base_machine_h

#include <string>

namespace dpana
{
  /**
   * What a run's times depend on besides the scene: the processor, its
   * cores, and the BLAS kernels the factorisations and the dense products
   * ran on. summary.json records it (`machine`), so that two runs of one
   * scene on different days, perhaps on different machines, say whether
   * their times can be compared.
   *
   * OpenBLAS chooses its kernels by the processor's model, and the `dpana`
   * command names the AVX2 ones where OpenBLAS would run its generic ones
   * on a processor that has AVX2 (OPENBLAS_CORETYPE): the same executable
   * factorises 1.4-1.6 times faster or slower by this choice alone.
   */
  struct Machine
  {
    /// The processor's model name, on x86 with its family and model numbers
    /// (/proc/cpuinfo); empty where not known.
    std::string processor;
    /// The logical cores the process may run on.
    unsigned int cores = 0;
    /// OpenBLAS' kernels in this process (openblas_get_corename()); empty
    /// with a BLAS other than OpenBLAS.
    std::string blas_kernels;
    /// OpenBLAS' threads; 0 with a BLAS other than OpenBLAS.
    int blas_threads = 0;
  };

  /// The machine this process runs on.
  Machine
  this_machine();

  /// One line for the log: "Machine: <processor>, <n> cores; OpenBLAS
  /// <kernels> kernels on <t> threads".
  std::string
  describe(const Machine &machine);
} // namespace dpana

#endif
