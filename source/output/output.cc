// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/base/exceptions.h>
#include <dpana/output/output.templates.h>

#include <cctype>
#include <iomanip>

namespace dpana
{
  namespace output
  {
    void
    Parameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Directory",
        "output",
        dealii::Patterns::Anything(),
        "Directory of the results, relative to the working directory. It is "
        "created after the input has been checked and the meshes built; "
        "files of an earlier run in it are overwritten. It receives the "
        "parameters used (parameters.prm, parameters.json), one VTU + PVD "
        "per body, summary.json (results) and timings.json.");
      prm.declare_entry("Write VTU",
                        "true",
                        dealii::Patterns::Bool(),
                        "Write the VTU/PVD files of the bodies (displacement "
                        "in mm, stresses in MPa).");
    }



    void
    Parameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      directory = prm.get("Directory");
      write_vtu = prm.get_bool("Write VTU");
      if (directory.empty())
        throw InputError("Output / Directory: must not be empty");
    }



    std::string
    file_stem(const std::string &body_name)
    {
      std::string stem;
      for (const char c : body_name)
        stem +=
          std::isalnum(static_cast<unsigned char>(c)) ?
            static_cast<char>(std::tolower(static_cast<unsigned char>(c))) :
            '-';
      return stem;
    }



    void
    write_timings(const std::map<std::string, double> &timings,
                  std::ostream                        &out)
    {
      out << "{";
      bool first = true;
      for (const auto &[name, seconds] : timings)
        {
          out << (first ? "\n" : ",\n") << "  \"" << internal::escape(name)
              << "\": " << std::setprecision(6) << seconds;
          first = false;
        }
      out << "\n}\n";
    }



    template void
    write_vtu_file(const Body<2> &, const std::string &);
    template void
    write_vtu_file(const Body<3> &, const std::string &);
    template std::vector<std::string>
    write_vtu(const Body<2> &, const std::string &);
    template std::vector<std::string>
    write_vtu(const Body<3> &, const std::string &);
    template void
    write_body_summary(const Body<2> &, std::ostream &);
    template void
    write_body_summary(const Body<3> &, std::ostream &);
  } // namespace output
} // namespace dpana
