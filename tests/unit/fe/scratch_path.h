// A file or directory name for one test in the temporary directory, with the
// test process' id in it, and a file of such a name removed at its end: two
// test runs at the same time (a sanitizer build next to a Release one, two
// checkouts) never write, list or remove each other's scratch files.
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

    // A scratch file of that name, removed when the object ends.
    class ScratchFile
    {
    public:
      explicit ScratchFile(const std::string &name)
        : path(scratch_path(name).string())
      {
        std::filesystem::remove(path);
      }
      ~ScratchFile()
      {
        std::filesystem::remove(path);
      }
      ScratchFile(const ScratchFile &) = delete;
      ScratchFile &
      operator=(const ScratchFile &) = delete;

      const std::string path;
    };
  } // namespace test
} // namespace dpana

#endif
