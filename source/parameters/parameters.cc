// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/base/exceptions.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

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



    // The top level of the file is read line by line; a subsection counter
    // tells the top-level lines from the others. The values are checked
    // here because they decide what is declared: a wrong dimension would
    // otherwise surface as a confusing list of undeclared entries.
    FileOutline
    scan_file(const std::string &filename)
    {
      std::ifstream in(filename);
      if (!in)
        throw InputError("cannot read parameter file '" + filename + "'");
      // "a.prm, line 12: ", as in the messages of parse_file().
      const auto where = [&filename](const unsigned int n) {
        return filename + ", line " + std::to_string(n) + ": ";
      };
      FileOutline  outline;
      std::string  line, piece;
      unsigned int depth = 0, line_number = 0, first_line = 1;
      while (std::getline(in, piece))
        {
          ++line_number;
          if (line.empty())
            first_line = line_number;
          // A line ending in a backslash continues on the next one.
          line += dealii::Utilities::trim(piece);
          if (!line.empty() && line.back() == '\\')
            {
              line.pop_back();
              continue;
            }
          std::istringstream words(strip_comment(line));
          line.clear();
          std::string first;
          if (!(words >> first))
            continue;
          std::string rest;
          std::getline(words, rest);
          if (first == "subsection" || first == "SUBSECTION")
            {
              if (depth == 0 && collapse_whitespace(rest) == "Contact")
                outline.has_contact = true;
              ++depth;
            }
          else if ((first == "end" || first == "END") && depth > 0)
            --depth;
          else if ((first == "set" || first == "SET") && depth == 0)
            {
              const auto equal = rest.find('=');
              if (equal == std::string::npos)
                continue;
              const std::string name =
                collapse_whitespace(rest.substr(0, equal));
              const std::string value =
                collapse_whitespace(rest.substr(equal + 1));
              if (name == "Dimension")
                {
                  if (value != "2" && value != "3")
                    throw InputError(where(first_line) +
                                     "Dimension: must be 2 or 3, got '" +
                                     value + "'");
                  outline.dimension = value == "2" ? 2 : 3;
                }
              else if (name == "Number of bodies")
                {
                  if (value != "1" && value != "2")
                    throw InputError(where(first_line) +
                                     "Number of bodies: must be 1 or 2, got '" +
                                     value + "'");
                  outline.n_bodies = value == "1" ? 1 : 2;
                }
            }
        }
      return outline;
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
