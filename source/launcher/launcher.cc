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
// inside dpana-solver: hence this small program, which loads no library but
// the C one and replaces itself by dpana-solver (execv: same process, same
// MPI environment under mpirun).
//
// A GLIBC_TUNABLES that names glibc.malloc.hugetlb already is left as it is
// (glibc.malloc.hugetlb=0 turns the huge pages off); other tunables in it
// are kept.

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <limits.h>
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
} // namespace



int
main(int, char **argv)
{
  const std::string solver = own_directory() + "/dpana-solver";
  setenv("GLIBC_TUNABLES", tunables().c_str(), 1);
  argv[0] = const_cast<char *>(solver.c_str());
  execv(solver.c_str(), argv);
  std::fprintf(stderr,
               "dpana: error: cannot run %s: %s\n",
               solver.c_str(),
               std::strerror(errno));
  return 1;
}
