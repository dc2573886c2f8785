// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/base/exceptions.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/exceptions.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace dpana
{
  namespace parameters
  {
    namespace
    {
      std::string
      collapse_whitespace(const std::string &text)
      {
        std::string out;
        bool        space = false;
        for (const char c : text)
          if (c == ' ' || c == '\n' || c == '\t' || c == '\r')
            space = !out.empty();
          else
            {
              if (space)
                out += ' ';
              out += c;
              space = false;
            }
        return out;
      }

      std::string
      strip_comment(const std::string &line)
      {
        // A '#' starts a comment unless escaped with a backslash.
        std::string out;
        for (std::size_t i = 0; i < line.size(); ++i)
          {
            if (line[i] == '#' && (i == 0 || line[i - 1] != '\\'))
              break;
            out += line[i];
          }
        return out;
      }
    } // namespace



    unsigned int
    read_dimension(const std::string &filename)
    {
      std::ifstream in(filename);
      if (!in)
        throw InputError("cannot read parameter file '" + filename + "'");
      std::string  line;
      int          depth = 0;
      unsigned int dim   = 2;
      while (std::getline(in, line))
        {
          std::istringstream words(strip_comment(line));
          std::string        first;
          if (!(words >> first))
            continue;
          if (first == "subsection")
            ++depth;
          else if (first == "end")
            --depth;
          else if (first == "set" && depth == 0)
            {
              std::string rest;
              std::getline(words, rest);
              const auto equal = rest.find('=');
              if (equal == std::string::npos)
                continue;
              if (collapse_whitespace(rest.substr(0, equal)) != "Dimension")
                continue;
              const std::string value =
                collapse_whitespace(rest.substr(equal + 1));
              if (value == "2")
                dim = 2;
              else if (value == "3")
                dim = 3;
              else
                throw InputError(filename +
                                 ": Dimension: must be 2 or 3, got '" + value +
                                 "'");
            }
        }
      return dim;
    }



    void
    declare_dimension(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Dimension",
                        "2",
                        dealii::Patterns::Integer(2, 3),
                        "Space dimension of the scene: 2 (plane, per mm of "
                        "thickness) or 3. Read before everything else: the "
                        "entries of the bodies depend on it.");
    }



    void
    parse_file(dealii::ParameterHandler &prm, const std::string &filename)
    {
      std::ifstream in(filename);
      if (!in)
        throw InputError("cannot read parameter file '" + filename + "'");
      try
        {
          prm.parse_input(in, filename);
        }
      catch (const std::exception &e)
        {
          throw InputError(one_line_message(e));
        }
    }



    std::string
    one_line_message(const std::exception &e)
    {
      if (const auto *d = dynamic_cast<const dealii::ExceptionBase *>(&e))
        {
          std::ostringstream info;
          d->print_info(info);
          std::string message = collapse_whitespace(info.str());
          if (message.empty())
            message = d->get_exc_name();
          // The ParameterHandler's "Line <12> of file <a.prm>: ... <name>"
          // becomes "a.prm, line 12: ... 'name'".
          message =
            std::regex_replace(message,
                               std::regex(
                                 "^Line <([0-9]+)> of file <([^>:]*)>?:"),
                               "$2, line $1:");
          message =
            std::regex_replace(message, std::regex("<([^<>]*)>"), "'$1'");
          return message;
        }
      return collapse_whitespace(e.what());
    }
  } // namespace parameters
} // namespace dpana
