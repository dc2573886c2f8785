// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/output/output_directory.h>

#include <regex>

#include <unistd.h>

namespace dpana
{
  namespace output
  {
    namespace fs = std::filesystem;

    bool
    is_output_file(const std::string &name)
    {
      static const std::regex files(
        "parameters\\.(prm|json)|summary\\.json|bodies\\.pvd|body_[0-9]+\\.(vtu|msh)|"
        "contact_surface\\.vtu|contact\\.(csv|png)|problem\\.hdf5");
      return std::regex_match(name, files);
    }



    namespace
    {
      // The path @p directory names, normalised, without a trailing
      // separator ("results/" is the directory "results").
      fs::path
      directory_path(const std::string &directory)
      {
        fs::path p = fs::path(directory).lexically_normal();
        if (p.filename().empty() && p.has_relative_path())
          p = p.parent_path();
        return p;
      }



      // The outermost missing ancestor of @p p (empty if its parent exists).
      fs::path
      first_missing_parent(const fs::path &p)
      {
        fs::path missing;
        for (fs::path q = p.parent_path(); !q.empty() && !fs::exists(q);
             q          = q.parent_path())
          missing = q;
        return missing;
      }



      void
      check_replaceable(const fs::path &directory)
      {
        const std::string what =
          "Output / Directory: '" + directory.string() + "' ";
        if (!fs::exists(directory))
          return;
        if (!fs::is_directory(directory))
          throw InputError(what + "is a file, not a directory");
        for (const auto &entry : fs::directory_iterator(directory))
          if (!is_output_file(entry.path().filename().string()))
            throw InputError(what + "holds '" +
                             entry.path().filename().string() +
                             "', which dpana did not write; name a new or "
                             "empty directory");
      }
    } // namespace



    OutputDirectory::OutputDirectory(const std::string &directory)
      : final_path(directory_path(directory))
    {
      if (final_path.filename().empty() || final_path.filename() == "." ||
          final_path.filename() == "..")
        throw InputError("Output / Directory: '" + directory +
                         "' must name a directory of its own");
      check_replaceable(final_path);
      created_parent = first_missing_parent(final_path);
      staging_path =
        final_path.parent_path() / ("." + final_path.filename().string() +
                                    ".partial-" + std::to_string(getpid()));
      std::error_code ec;
      fs::create_directories(staging_path, ec);
      if (ec)
        {
          if (!created_parent.empty())
            fs::remove_all(created_parent, ec);
          throw InputError("Output / Directory: cannot create '" + directory +
                           "': " + ec.message());
        }
    }



    OutputDirectory::~OutputDirectory()
    {
      if (committed)
        return;
      std::error_code ec;
      fs::remove_all(staging_path, ec);
      if (!created_parent.empty())
        fs::remove_all(created_parent, ec);
    }



    // The previous directory is moved aside, the staged one put in its
    // place, and only then the previous one removed: at no moment is there
    // a half-written directory under the final name.
    void
    OutputDirectory::commit()
    {
      const fs::path old =
        final_path.parent_path() / ("." + final_path.filename().string() +
                                    ".old-" + std::to_string(getpid()));
      std::error_code ec;
      const bool      existed = fs::exists(final_path);
      if (existed)
        fs::rename(final_path, old);
      fs::rename(staging_path, final_path, ec);
      if (ec)
        {
          if (existed)
            fs::rename(old, final_path);
          throw InputError("Output / Directory: cannot write '" +
                           final_path.string() + "': " + ec.message());
        }
      committed = true;
      if (existed)
        fs::remove_all(old);
    }
  } // namespace output
} // namespace dpana
