// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/base/exceptions.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

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

      // A byte as it may appear in a message: printable ASCII as itself,
      // anything else as \xNN.
      std::string
      printable(const char c)
      {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f)
          return std::string(1, c);
        const char *hex = "0123456789abcdef";
        return std::string("\\x") + hex[byte / 16] + hex[byte % 16];
      }

      // The last guard of every message printed: printable bytes only, and
      // no word (e.g. a number of a million digits that reached a message
      // unquoted) longer than 100 characters.
      std::string
      printable_line(const std::string &message)
      {
        const std::size_t max_word = 100;
        std::string       out;
        std::size_t       word = 0;
        for (const char c : message)
          {
            word = c == ' ' ? 0 : word + 1;
            if (word <= max_word)
              out += printable(c);
            else if (word == max_word + 1)
              out += "...";
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



    namespace
    {
      // One statement of a parameter file: a logical line (continuation
      // lines joined, comment stripped), its first word and the rest.
      struct Statement
      {
        unsigned int line;
        std::string  keyword;
        std::string  rest;
      };

      // The statements of a file, with the ParameterHandler's syntax: '#'
      // starts a comment unless escaped, a trailing backslash continues the
      // line. Blank lines are skipped.
      std::vector<Statement>
      read_statements(std::istream &in)
      {
        std::vector<Statement> statements;
        std::string            line, piece;
        unsigned int           line_number = 0, first_line = 1;
        while (std::getline(in, piece))
          {
            ++line_number;
            if (line.empty())
              first_line = line_number;
            line += dealii::Utilities::trim(piece);
            if (!line.empty() && line.back() == '\\')
              {
                line.pop_back();
                continue;
              }
            std::istringstream words(strip_comment(line));
            line.clear();
            Statement s{first_line, "", ""};
            if (!(words >> s.keyword))
              continue;
            std::getline(words, s.rest);
            statements.push_back(s);
          }
        return statements;
      }

      bool
      is_keyword(const Statement &s, const std::string &lower_case)
      {
        std::string upper = lower_case;
        for (char &c : upper)
          c = static_cast<char>(std::toupper(c));
        return s.keyword == lower_case || s.keyword == upper;
      }

      // The name and value of a "set NAME = VALUE" statement, whitespace
      // collapsed; no name if the statement has no '='.
      std::pair<std::string, std::string>
      entry_of(const Statement &s)
      {
        const auto equal = s.rest.find('=');
        if (equal == std::string::npos)
          return {"", ""};
        return {collapse_whitespace(s.rest.substr(0, equal)),
                collapse_whitespace(s.rest.substr(equal + 1))};
      }

      // "a.prm, line 12: ", as in the messages of the ParameterHandler.
      std::string
      where(const std::string &filename, const unsigned int line)
      {
        return filename + ", line " + std::to_string(line) + ": ";
      }
    } // namespace



    namespace
    {
      // The run a file describes must match its subsections: a second body
      // needs its subsection, and a one-body run has neither a Body 2 nor a
      // contact boundary of Body 2 (its obstacle is the rigid plane).
      void
      check_bodies(const std::string &filename,
                   const FileOutline &outline,
                   const unsigned int n_bodies_line,
                   const unsigned int body_2_line,
                   const unsigned int boundary_2_line,
                   const unsigned int obstacle_point_line)
      {
        if (outline.n_bodies == 2 && body_2_line == 0)
          throw InputError(where(filename, n_bodies_line) +
                           "Number of bodies = 2, but the file has no "
                           "subsection 'Body 2'");
        if (outline.n_bodies == 1 && body_2_line != 0)
          throw InputError(where(filename, body_2_line) +
                           "subsection 'Body 2' in a run with one body (set "
                           "Number of bodies = 2)");
        if (outline.n_bodies == 1 && boundary_2_line != 0)
          throw InputError(where(filename, boundary_2_line) +
                           "Contact / Boundary 2 is set in a run with one "
                           "body, whose obstacle is the rigid plane (set "
                           "Number of bodies = 2 for a second body)");
        if (outline.n_bodies == 2 && obstacle_point_line != 0)
          throw InputError(where(filename, obstacle_point_line) +
                           "Contact / Obstacle point is set in a run with two "
                           "bodies, whose gap is the distance between their "
                           "surfaces; the point places the rigid plane of a "
                           "run with one body (leave it empty)");
      }
    } // namespace



    // The top level of the file is read statement by statement; the path of
    // subsections tells the top-level statements from the others. The
    // values are checked here because they decide what is declared: a
    // wrong dimension would otherwise surface as a confusing list of
    // undeclared entries.
    FileOutline
    scan_file(const std::string &filename)
    {
      if (std::filesystem::is_directory(filename))
        throw InputError("parameter file " + quote(filename) +
                         " is a directory");
      std::ifstream in(filename);
      if (!in)
        throw InputError("cannot read parameter file " + quote(filename));
      const std::vector<Statement> statements = read_statements(in);
      if (statements.empty())
        throw InputError("parameter file " + quote(filename) +
                         " sets nothing (it is empty or all comments)");
      FileOutline              outline;
      std::vector<std::string> path;
      unsigned int n_bodies_line = 0, body_2_line = 0, boundary_2_line = 0,
                   obstacle_point_line = 0;
      for (const Statement &s : statements)
        if (is_keyword(s, "subsection"))
          {
            const std::string name = collapse_whitespace(s.rest);
            if (path.empty() && name == "Contact")
              outline.has_contact = true;
            if (path.empty() && name == "Body 2")
              body_2_line = s.line;
            path.push_back(name);
          }
        else if (is_keyword(s, "end") && !path.empty())
          path.pop_back();
        else if (is_keyword(s, "set") && path.size() == 1 &&
                 path[0] == "Contact" && entry_of(s).first == "Boundary 2")
          boundary_2_line = s.line;
        else if (is_keyword(s, "set") && path.size() == 1 &&
                 path[0] == "Contact" &&
                 entry_of(s).first == "Obstacle point" &&
                 !entry_of(s).second.empty())
          obstacle_point_line = s.line;
        else if (is_keyword(s, "set") && path.empty())
          {
            const auto [name, value] = entry_of(s);
            if (name == "Dimension")
              {
                if (value != "2" && value != "3")
                  throw InputError(where(filename, s.line) +
                                   "Dimension: must be 2 or 3, got " +
                                   quote(value));
                outline.dimension = value == "2" ? 2 : 3;
              }
            else if (name == "Number of bodies")
              {
                if (value != "1" && value != "2")
                  throw InputError(where(filename, s.line) +
                                   "Number of bodies: must be 1 or 2, got " +
                                   quote(value));
                outline.n_bodies = value == "1" ? 1 : 2;
                n_bodies_line    = s.line;
              }
          }
      check_bodies(filename,
                   outline,
                   n_bodies_line,
                   body_2_line,
                   boundary_2_line,
                   obstacle_point_line);
      return outline;
    }



    namespace
    {
      // Every entry is remembered with its subsection path and the line
      // that set it; the second "set" of the same entry in the same
      // subsection is an error. Subsections entered twice count as one, as
      // for the ParameterHandler.
      void
      check_entries_set_once(std::istream &in, const std::string &filename)
      {
        std::vector<std::string>            path;
        std::map<std::string, unsigned int> first_set;
        for (const Statement &s : read_statements(in))
          if (is_keyword(s, "subsection"))
            path.push_back(collapse_whitespace(s.rest));
          else if (is_keyword(s, "end") && !path.empty())
            path.pop_back();
          else if (is_keyword(s, "set"))
            {
              const std::string name = entry_of(s).first;
              std::string       key, section;
              for (const std::string &p : path)
                {
                  key += p + '\n';
                  section += (section.empty() ? "" : " / ") + p;
                }
              const auto [it, inserted] = first_set.emplace(key + name, s.line);
              if (!inserted)
                throw InputError(
                  where(filename, s.line) + "entry " + quote(name) +
                  (section.empty() ? "" : " of subsection " + quote(section)) +
                  " is set twice (first on line " + std::to_string(it->second) +
                  ")");
            }
      }
    } // namespace



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
      std::ifstream again(filename);
      check_entries_set_once(again, filename);
    }



    std::string
    quote(const std::string &text)
    {
      const std::size_t max_length = 60;
      std::string       out;
      for (const char c : text)
        {
          if (out.size() >= max_length)
            return "'" + out + "...'";
          out += printable(c);
        }
      return "'" + out + "'";
    }



    // The ParameterHandler's "Line <12> of file <a.prm>: ... <name>"
    // becomes "a.prm, line 12: ... 'name'": the text in angle brackets is
    // input (a value, an entry name) and goes through quote(), except the
    // descriptions of patterns ("<[Double 0...1 (inclusive)]>"), which are
    // the program's own.
    std::string
    one_line_message(const std::exception &e)
    {
      const auto *d = dynamic_cast<const dealii::ExceptionBase *>(&e);
      if (d == nullptr)
        return printable_line(collapse_whitespace(e.what()));
      std::ostringstream info;
      d->print_info(info);
      std::string message = collapse_whitespace(info.str());
      if (message.empty())
        message = d->get_exc_name();
      const std::string prefix = "Line <";
      const auto        file   = message.find("> of file <");
      // deal.II 9.4 leaves out the '>' after the file name in its message
      // of an unknown subsection ("... of file <a.prm: There is no such
      // subsection to be entered: Contakt").
      auto        colon = message.find(">:", file);
      std::size_t skip  = 2;
      if (file != std::string::npos && colon == std::string::npos)
        colon = message.find(": ", file), skip = 1;
      if (message.rfind(prefix, 0) == 0 && file != std::string::npos &&
          colon != std::string::npos)
        message = message.substr(file + 11, colon - file - 11) + ", line " +
                  message.substr(prefix.size(), file - prefix.size()) + ":" +
                  message.substr(colon + skip);
      const std::string no_subsection = "subsection to be entered: ";
      const auto        unknown       = message.find(no_subsection);
      if (unknown != std::string::npos)
        message = message.substr(0, unknown + no_subsection.size()) +
                  quote(message.substr(unknown + no_subsection.size()));
      std::string out;
      for (std::size_t i = 0; i < message.size(); ++i)
        {
          const auto close = message.find('>', i);
          const auto open  = message.find('<', i + 1);
          if (message[i] != '<' || close == std::string::npos ||
              (open != std::string::npos && open < close))
            out += message[i];
          else if (message[i + 1] == '[')
            out += message.substr(i + 1, close - i - 1), i = close;
          else
            out += quote(message.substr(i + 1, close - i - 1)), i = close;
        }
      return printable_line(out);
    }
  } // namespace parameters
} // namespace dpana
