// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// What the readers of the sections of a gmsh file share (gmsh_sections.cc
// reads the file and its sections, gmsh_elements.cc its $Elements): the
// lines of the file with the errors that name them, the nodes read, and
// the physical groups of the entities.

#ifndef dpana_geometry_gmsh_reading_h
#define dpana_geometry_gmsh_reading_h

#include <dpana/base/exceptions.h>
#include <dpana/geometry/gmsh_sections.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/utilities.h>

#include <array>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <istream>
#include <string>
#include <unordered_map>
#include <vector>

namespace dpana
{
  namespace geometry
  {
    namespace gmsh_reading
    {
      inline bool
      to_integer(const std::string &word, long long &value)
      {
        char *end;
        errno = 0;
        value = std::strtoll(word.c_str(), &end, 10);
        return !word.empty() && *end == '\0' && errno == 0;
      }



      // The lines of the file, counted, and the one-line errors that name
      // the current line.
      class Lines
      {
      public:
        Lines(std::istream &in, const std::string &error)
          : in(in)
          , error(error)
        {
        }

        // The next line, or false at the end of the file.
        bool
        next()
        {
          if (!std::getline(in, text))
            return false;
          ++number;
          return true;
        }

        // The next line, which must exist inside section @p section.
        void
        next_in(const std::string &section)
        {
          if (!next())
            fail("the file ends inside " + section);
        }

        [[noreturn]] void
        fail(const std::string &what) const
        {
          throw InputError(error + "', line " + std::to_string(number) + ": " +
                           what);
        }

        // The whitespace-separated words of the current line.
        std::vector<std::string>
        words() const
        {
          std::vector<std::string> w;
          for_each_word([&w](const char *begin, const char *end) {
            w.emplace_back(begin, end);
          });
          return w;
        }

        // The current line as @p n integers (any number if n == 0), in a
        // buffer that the next call overwrites (the elements and nodes of
        // a large mesh are read without an allocation per line).
        const std::vector<long long> &
        integers(const std::size_t n, const std::string &what)
        {
          values.clear();
          for_each_word([&](const char *begin, const char *end) {
            word.assign(begin, end);
            long long v;
            if (!to_integer(word, v))
              fail("expected " + what + ", got " + parameters::quote(text));
            values.push_back(v);
          });
          if ((n != 0 && values.size() != n) || values.empty())
            fail("expected " + what + ", got " + parameters::quote(text));
          return values;
        }

        // The head of a block of a 4.1 section, "... count" with
        // @p layout, whose count of @p items (its last number) must not be
        // negative.
        std::vector<long long>
        block_head(const std::string &layout, const std::string &items)
        {
          const std::vector<long long> block = integers(4, layout);
          if (block[3] < 0)
            fail("a block of " + std::to_string(block[3]) + " " + items);
          return block;
        }

        // The @p items that the blocks of @p section held against the count
        // of its head.
        void
        check_blocks(const std::string &section,
                     const long long    n_read,
                     const long long    n_head,
                     const std::string &items) const
        {
          if (n_read != n_head)
            fail("the blocks of " + section + " hold " +
                 std::to_string(n_read) + " " + items + ", its head says " +
                 std::to_string(n_head));
        }

        // The current line must be @p marker.
        void
        expect(const std::string &marker) const
        {
          if (dealii::Utilities::trim(text) != marker)
            fail("expected " + marker + ", got " + parameters::quote(text));
        }

        const std::string &
        line() const
        {
          return text;
        }

        unsigned int number = 0;

      private:
        std::istream          &in;
        const std::string      error;
        std::string            text, word;
        std::vector<long long> values;

        template <typename Visit>
        void
        for_each_word(const Visit &visit) const
        {
          const char *p = text.data(), *end = p + text.size();
          while (p != end)
            {
              while (p != end && std::isspace(static_cast<unsigned char>(*p)))
                ++p;
              const char *begin = p;
              while (p != end && !std::isspace(static_cast<unsigned char>(*p)))
                ++p;
              if (p != begin)
                visit(begin, p);
            }
        }
      };



      // The nodes read so far: their coordinates in the order of the file,
      // the line that defines each, and the position of each tag.
      struct Nodes
      {
        std::vector<std::array<double, 3>>          x;
        std::vector<unsigned int>                   line;
        std::unordered_map<long long, unsigned int> position;

        // The position of the node @p tag, or -1 if no node has it.
        long long
        find(const long long tag) const
        {
          const auto p = position.find(tag);
          return p == position.end() ? -1 : static_cast<long long>(p->second);
        }
      };

      // The physical group of each entity of a 4.1 file, by dimension:
      // entity tag -> physical tag.
      using EntityTags =
        std::array<std::unordered_map<long long, long long>, 4>;



      // Reads the $Elements section (its first line is next) into @p mesh:
      // the cells and boundary elements of dimension @p dim, checked against
      // @p nodes, with the physical tags of @p entity_tags (format 4.1).
      void
      read_elements(Lines             &lines,
                    const bool         v41,
                    const EntityTags  &entity_tags,
                    const Nodes       &nodes,
                    const unsigned int dim,
                    const std::string &error,
                    GmshMesh          &mesh);
    } // namespace gmsh_reading
  }   // namespace geometry
} // namespace dpana

#endif
