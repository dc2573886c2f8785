// A file or directory name for one test in the temporary directory, with the
// test process' id in it: two test runs at the same time (a sanitizer build
// next to a Release one, two checkouts) never write, list or remove each
// other's scratch files.
#ifndef dpana_tests_scratch_path_h
#define dpana_tests_scratch_path_h

#include <filesystem>
#include <string>

#include <unistd.h>

namespace dpana
{
  namespace test
  {
    inline std::filesystem::path
    scratch_path(const std::string &name)
    {
      return std::filesystem::temp_directory_path() /
             ("dpana_" + std::to_string(::getpid()) + "_" + name);
    }
  } // namespace test
} // namespace dpana

#endif
