// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The `dpana` command: it starts the program dpana-solver, which lies next
// to it, with the same arguments, after asking the C library's allocator
// for transparent huge pages (the GLIBC_TUNABLES entry glibc.malloc.hugetlb=1:
// malloc marks the memory it maps with madvise(MADV_HUGEPAGE)).
//
// Why: a contact run touches its matrices, factor and dense blocks once,
// soon after allocating them, and every first touch of a 4 KiB page costs a
// page fault. On virtual machines a fault costs up to 12.5 us (measured on
// the machine of benchmarks/convergence: first writes of 4 to 64 MB at
// 12.4 to 12.8 us per page), which made half the solve time of a 2D run of
// 19 350 dofs; with 2 MiB pages it takes 1/512 of the faults. The tunable is
// read by the dynamic loader when a program starts, so it cannot be set from
// inside dpana-solver: hence this small program, which links no library but
// the C one (it loads OpenBLAS only to ask which kernels it chose, below) and
// replaces itself by dpana-solver (execv: same process, same MPI environment
// under mpirun).
//
// A GLIBC_TUNABLES that names glibc.malloc.hugetlb already is left as it is
// (glibc.malloc.hugetlb=0 turns the huge pages off); other tunables in it
// are kept.
//
// It also makes sure that OpenBLAS, the BLAS of CHOLMOD's supernodal factor
// and of the dense blocks of the condensation, computes with the vector
// instructions of the processor. OpenBLAS chooses its kernels by the
// processor's model when it is loaded; a model it does not know gets its
// generic SSE3 kernels ("Prescott"). OpenBLAS 0.3.21 of Debian 12 does not
// know the Xeons of family 6, model 207 (those of the machine of
// benchmarks/convergence): there the quarter sphere at 36 891 dofs took
// 7.6-9.5 s to solve with "Prescott" and 2.8-2.9 s with the AVX2 kernels
// ("Haswell"), to the same answers. So when OpenBLAS reports its generic
// kernels on a processor with AVX2 and FMA, OPENBLAS_CORETYPE, which
// OpenBLAS reads when it is loaded, names the AVX2 kernels. Not the AVX-512
// ones, though that processor has AVX-512 and they were faster still (2.0-2.6
// s): with them GetFEM's Newton iteration broke down on one scene of the
// convergence benchmark where it converges with both others, and OpenBLAS'
// issue tracker reports wrong results of its AVX-512 kernels in builds for
// several processors, as Debian's is. A given OPENBLAS_CORETYPE is left as
// it is; a processor whose model OpenBLAS knows keeps OpenBLAS' own choice.

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <dlfcn.h>
#include <limits.h>
#include <strings.h>
#include <unistd.h>

namespace
{
  // The directory of this executable.
  std::string
  own_directory()
  {
    char      path[PATH_MAX];
    const int n = readlink("/proc/self/exe", path, sizeof(path) - 1);
    if (n <= 0)
      return ".";
    path[n]                = '\0';
    const std::string full = path;
    const std::size_t cut  = full.rfind('/');
    return cut == std::string::npos ? "." : full.substr(0, cut);
  }



  // GLIBC_TUNABLES with the huge pages of malloc asked for, unless it names
  // them already.
  std::string
  tunables()
  {
    const char       *given = std::getenv("GLIBC_TUNABLES");
    const std::string entry = "glibc.malloc.hugetlb=1";
    if (given == nullptr || given[0] == '\0')
      return entry;
    const std::string t = given;
    if (t.find("glibc.malloc.hugetlb") != std::string::npos)
      return t;
    return t + ":" + entry;
  }



  // Whether the OpenBLAS of this system runs its generic kernels here (false
  // without OpenBLAS). Loading it runs its choice of kernels, as in
  // dpana-solver; this process is replaced by dpana-solver right after.
  bool
  openblas_is_generic()
  {
    void *blas = dlopen("libopenblas.so.0", RTLD_NOW | RTLD_LOCAL);
    if (blas == nullptr)
      return false;
    using CoreName = char *(*)();
    const auto name =
      reinterpret_cast<CoreName>(dlsym(blas, "openblas_get_corename"));
    const char *core   = name == nullptr ? nullptr : name();
    const bool  result = core != nullptr && strcasecmp(core, "Prescott") == 0;
    dlclose(blas);
    return result;
  }



  // The OpenBLAS kernels of AVX2 when OpenBLAS would run its generic ones on
  // a processor with AVX2 and FMA; null to leave its choice (libgcc's tests
  // include the operating system's support of the registers).
  const char *
  blas_kernels()
  {
    if (std::getenv("OPENBLAS_CORETYPE") != nullptr || !openblas_is_generic())
      return nullptr;
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
      return "Haswell";
    return nullptr;
  }
} // namespace



int
main(int, char **argv)
{
  const std::string solver = own_directory() + "/dpana-solver";
  setenv("GLIBC_TUNABLES", tunables().c_str(), 1);
  if (const char *kernels = blas_kernels())
    setenv("OPENBLAS_CORETYPE", kernels, 1);
  argv[0] = const_cast<char *>(solver.c_str());
  execv(solver.c_str(), argv);
  std::fprintf(stderr,
               "dpana: error: cannot run %s: %s\n",
               solver.c_str(),
               std::strerror(errno));
  return 1;
}
