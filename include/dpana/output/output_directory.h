// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_output_output_directory_h
#define dpana_output_output_directory_h

#include <filesystem>
#include <string>

namespace dpana
{
  namespace output
  {
    /**
     * The output directory of a run, written all at once.
     *
     * The constructor checks, before any expensive work, that the directory
     * can be written: it creates a staging directory next to it (a hidden
     * sibling `.NAME.partial-PID`) and the parents that are missing. The run
     * writes its files into staging(); commit() then replaces the directory
     * by the staging directory, so that afterwards it holds exactly this
     * run's files (no stale body_2.vtu or contact.png of an earlier run). A
     * run that fails before commit() leaves nothing behind: the destructor
     * removes the staging directory and the parents it created, and the
     * results of the previous run stay intact.
     *
     * A directory is replaced only if it holds nothing but files dpana
     * writes; otherwise (e.g. `Output / Directory = .`) the constructor
     * throws dpana::InputError naming the entry.
     */
    class OutputDirectory
    {
    public:
      explicit OutputDirectory(const std::string &directory);
      ~OutputDirectory();

      OutputDirectory(const OutputDirectory &) = delete;
      OutputDirectory &
      operator=(const OutputDirectory &) = delete;

      /**
       * Where the run writes its files until commit().
       */
      std::string
      staging() const
      {
        return staging_path.string();
      }

      /**
       * Makes the staged files the output directory.
       */
      void
      commit();

    private:
      std::filesystem::path final_path;
      std::filesystem::path staging_path;
      // The outermost parent this object created, removed on failure.
      std::filesystem::path created_parent;
      bool                  committed = false;
    };

    /**
     * Whether @p name is a file dpana writes into an output directory.
     */
    bool
    is_output_file(const std::string &name);
  } // namespace output
} // namespace dpana

#endif
