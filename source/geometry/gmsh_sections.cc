// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/gmsh_sections.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/utilities.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace dpana
{
  namespace geometry
  {
    namespace
    {
      bool
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
          std::istringstream       s(text);
          std::vector<std::string> w;
          std::string              word;
          while (s >> word)
            w.push_back(word);
          return w;
        }

        // The current line as @p n integers (any number if n == 0).
        std::vector<long long>
        integers(const std::size_t n, const std::string &what) const
        {
          const auto             w = words();
          std::vector<long long> values;
          for (const std::string &word : w)
            {
              long long v;
              if (!to_integer(word, v))
                fail("expected " + what + ", got " + parameters::quote(text));
              values.push_back(v);
            }
          if ((n != 0 && values.size() != n) || values.empty())
            fail("expected " + what + ", got " + parameters::quote(text));
          return values;
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
        std::istream     &in;
        const std::string error;
        std::string       text;
      };



      // A node: its coordinates and the line that defines it.
      struct Node
      {
        std::array<double, 3> x;
        unsigned int          line;
      };
      using Nodes = std::unordered_map<long long, Node>;



      void
      read_format(Lines &lines, bool &v41)
      {
        lines.next_in("$MeshFormat");
        const auto  w       = lines.words();
        const char *message = "not an ASCII gmsh file of format 2.2 or 4.1";
        if (w.size() < 2 || w[1] != "0")
          lines.fail(message);
        if (w[0] == "4.1")
          v41 = true;
        else if (w[0].rfind("2.", 0) == 0 && w[0].size() == 3 &&
                 std::isdigit(static_cast<unsigned char>(w[0][2])))
          v41 = false;
        else
          lines.fail(message);
      }



      void
      read_physical_names(
        Lines                                             &lines,
        const unsigned int                                 dim,
        std::map<std::string, dealii::types::boundary_id> &names)
      {
        lines.next_in("$PhysicalNames");
        const long long n = lines.integers(1, "the number of names")[0];
        for (long long i = 0; i < n; ++i)
          {
            lines.next_in("$PhysicalNames");
            const auto  w     = lines.words();
            const auto &text  = lines.line();
            const auto  first = text.find('"');
            const auto  last  = text.rfind('"');
            long long   group_dim, tag;
            if (w.size() < 3 || !to_integer(w[0], group_dim) ||
                !to_integer(w[1], tag) || first == std::string::npos ||
                last == first)
              lines.fail("expected 'dimension tag \"name\"', got " +
                         parameters::quote(text));
            const std::string name = text.substr(first + 1, last - first - 1);
            if (group_dim != static_cast<long long>(dim) - 1)
              continue;
            if (names.count(name) != 0)
              lines.fail("a second boundary named " + parameters::quote(name));
            names[name] = static_cast<dealii::types::boundary_id>(tag);
          }
      }



      // One node line "tag x y z" (2.2) or the tag and coordinate lines of
      // a 4.1 block: the tag is positive, in [min, max] and new.
      void
      add_node(Lines             &lines,
               Nodes             &nodes,
               const long long    tag,
               const long long    min_tag,
               const long long    max_tag,
               const std::string &coordinates)
      {
        if (tag <= 0 || tag < min_tag || tag > max_tag)
          lines.fail("node tag " + std::to_string(tag) +
                     " is not positive or outside the range the section "
                     "declares");
        std::istringstream    s(coordinates);
        std::array<double, 3> x;
        std::string           word;
        for (double &xi : x)
          {
            char *end;
            if (!(s >> word))
              lines.fail("node " + std::to_string(tag) +
                         " has fewer than 3 coordinates");
            xi = std::strtod(word.c_str(), &end);
            if (*end != '\0' || !std::isfinite(xi))
              lines.fail("coordinate " + parameters::quote(word) + " of node " +
                         std::to_string(tag) + " is not a finite number");
          }
        const auto [it, inserted] = nodes.emplace(tag, Node{x, lines.number});
        if (!inserted)
          lines.fail("node tag " + std::to_string(tag) +
                     " is given twice (first on line " +
                     std::to_string(it->second.line) + ")");
      }



      Nodes
      read_nodes(Lines &lines, const bool v41)
      {
        const std::string section = "$Nodes";
        lines.next_in(section);
        Nodes nodes;
        if (!v41)
          {
            const long long n = lines.integers(1, "the number of nodes")[0];
            for (long long i = 0; i < n; ++i)
              {
                lines.next_in(section);
                const auto w = lines.words();
                long long  tag;
                if (w.size() != 4 || !to_integer(w[0], tag))
                  lines.fail("expected a node 'tag x y z', got " +
                             parameters::quote(lines.line()));
                add_node(lines,
                         nodes,
                         tag,
                         1,
                         std::numeric_limits<long long>::max(),
                         w[1] + " " + w[2] + " " + w[3]);
              }
          }
        else
          {
            const auto head =
              lines.integers(4, "'blocks nodes min_tag max_tag' (format 4.1)");
            long long n_read = 0;
            for (long long b = 0; b < head[0]; ++b)
              {
                lines.next_in(section);
                const auto block = lines.integers(
                  4, "a block head 'dimension entity parametric nodes'");
                std::vector<long long> tags;
                for (long long i = 0; i < block[3]; ++i)
                  {
                    lines.next_in(section);
                    tags.push_back(lines.integers(1, "one node tag")[0]);
                  }
                for (const long long tag : tags)
                  {
                    lines.next_in(section);
                    add_node(lines, nodes, tag, head[2], head[3], lines.line());
                  }
                n_read += block[3];
              }
            if (n_read != head[1])
              lines.fail("the blocks of $Nodes hold " + std::to_string(n_read) +
                         " nodes, its head says " + std::to_string(head[1]));
          }
        lines.next_in(section);
        lines.expect("$EndNodes");
        return nodes;
      }



      // The number of nodes of the element types GridIn reads; 0 for the
      // others.
      std::size_t
      nodes_of_type(const long long type)
      {
        const std::map<long long, std::size_t> n = {
          {1, 2}, {2, 3}, {3, 4}, {4, 4}, {5, 8}, {6, 6}, {7, 5}, {15, 1}};
        const auto p = n.find(type);
        return p == n.end() ? 0 : p->second;
      }



      // Zero measure of a triangle (2D) or tetrahedron (3D), relative to
      // its longest edge.
      bool
      degenerate(const std::vector<const Node *> &p, const unsigned int dim)
      {
        std::array<std::array<double, 3>, 3> e;
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int d = 0; d < 3; ++d)
            e[k][d] = d < dim ? p[k + 1]->x[d] - p[0]->x[d] : 0.;
        double h = 0;
        for (unsigned int i = 0; i <= dim; ++i)
          for (unsigned int j = 0; j < i; ++j)
            {
              double l2 = 0;
              for (unsigned int d = 0; d < dim; ++d)
                l2 += std::pow(p[i]->x[d] - p[j]->x[d], 2);
              h = std::max(h, std::sqrt(l2));
            }
        const double measure =
          dim == 2 ? e[0][0] * e[1][1] - e[0][1] * e[1][0] :
                     e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                       e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                       e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
        return !(std::abs(measure) > 1e-10 * std::pow(h, dim));
      }



      // One element: its node count (for the types GridIn reads), its
      // nodes, and the measure of the cells. True if it is a cell.
      bool
      check_element(const Lines                  &lines,
                    const Nodes                  &nodes,
                    const long long               tag,
                    const long long               type,
                    const std::vector<long long> &node_tags,
                    const unsigned int            dim)
      {
        const std::string element = "element " + std::to_string(tag);
        const std::size_t n       = nodes_of_type(type);
        if (n == 0)
          return false;
        if (node_tags.size() != n)
          lines.fail(element + " of type " + std::to_string(type) + " has " +
                     std::to_string(node_tags.size()) + " nodes instead of " +
                     std::to_string(n));
        std::vector<const Node *> p;
        for (const long long t : node_tags)
          {
            const auto node = nodes.find(t);
            if (node == nodes.end())
              lines.fail(element + " refers to node " + std::to_string(t) +
                         ", which $Nodes does not define");
            p.push_back(&node->second);
          }
        const long long cell_type = dim == 2 ? 2 : 4;
        if (type != cell_type)
          return false;
        if (degenerate(p, dim))
          lines.fail(element + " (a " +
                     (dim == 2 ? "triangle) has zero area" :
                                 "tetrahedron) has zero volume") +
                     ": a degenerate cell");
        return true;
      }



      // Returns the number of cells.
      unsigned long long
      read_elements(Lines             &lines,
                    const bool         v41,
                    const Nodes       &nodes,
                    const unsigned int dim)
      {
        const std::string section = "$Elements";
        lines.next_in(section);
        unsigned long long n_cells = 0;
        if (!v41)
          {
            const long long n = lines.integers(1, "the number of elements")[0];
            const std::string layout = "an element 'tag type n_tags tags... "
                                       "nodes...'";
            for (long long i = 0; i < n; ++i)
              {
                lines.next_in(section);
                const auto v = lines.integers(0, layout);
                if (v.size() < 3 || v[2] < 0 ||
                    v.size() < 3 + static_cast<std::size_t>(v[2]))
                  lines.fail("expected " + layout + ", got " +
                             parameters::quote(lines.line()));
                n_cells += check_element(lines,
                                         nodes,
                                         v[0],
                                         v[1],
                                         {v.begin() + 3 + v[2], v.end()},
                                         dim);
              }
          }
        else
          {
            const auto head =
              lines.integers(4,
                             "'blocks elements min_tag max_tag' (format 4.1)");
            long long n_read = 0;
            for (long long b = 0; b < head[0]; ++b)
              {
                lines.next_in(section);
                const auto block = lines.integers(
                  4, "a block head 'dimension entity type elements'");
                for (long long i = 0; i < block[3]; ++i)
                  {
                    lines.next_in(section);
                    const auto v =
                      lines.integers(0, "an element 'tag nodes...'");
                    n_cells += check_element(lines,
                                             nodes,
                                             v[0],
                                             block[2],
                                             {v.begin() + 1, v.end()},
                                             dim);
                  }
                n_read += block[3];
              }
            if (n_read != head[1])
              lines.fail("the blocks of $Elements hold " +
                         std::to_string(n_read) + " elements, its head says " +
                         std::to_string(head[1]));
          }
        lines.next_in(section);
        lines.expect("$EndElements");
        return n_cells;
      }



      // $Entities of format 4.1, which GridIn reads number by number: the
      // counts of points, curves, surfaces and volumes, then one line per
      // entity, "tag x y z n_physical physical..." for a point and "tag
      // box(6) n_physical physical... n_bounding bounding..." for the
      // others, every word a number.
      void
      read_entities(Lines &lines)
      {
        const std::string section = "$Entities";
        lines.next_in(section);
        const auto counts = lines.integers(
          4, "'points curves surfaces volumes' (format 4.1 $Entities)");
        for (unsigned int kind = 0; kind < 4; ++kind)
          for (long long i = 0; i < counts[kind]; ++i)
            {
              lines.next_in(section);
              const auto        w             = lines.words();
              const std::size_t n_coordinates = kind == 0 ? 3 : 6;
              bool              ok            = w.size() > n_coordinates + 1;
              for (const std::string &word : w)
                {
                  char *end;
                  std::strtod(word.c_str(), &end);
                  ok = ok && *end == '\0';
                }
              long long n_physical = -1, n_bounding = 0;
              ok = ok && to_integer(w[n_coordinates + 1], n_physical) &&
                   n_physical >= 0;
              const std::size_t next = n_coordinates + 2 + n_physical;
              if (ok && kind > 0)
                ok = w.size() > next && to_integer(w[next], n_bounding) &&
                     n_bounding >= 0;
              if (!ok || w.size() != next + (kind > 0 ? 1 + n_bounding : 0))
                lines.fail("expected an entity of dimension " +
                           std::to_string(kind) + ", got " +
                           parameters::quote(lines.line()));
            }
        lines.next_in(section);
        lines.expect("$EndEntities");
      }



      // A section this reader does not check must at least be closed.
      void
      skip_section(Lines &lines, const std::string &section)
      {
        const std::string end = "$End" + section.substr(1);
        do
          lines.next_in(section);
        while (dealii::Utilities::trim(lines.line()) != end);
      }
    } // namespace



    GmshOutline
    read_gmsh_sections(std::istream      &in,
                       const unsigned int dim,
                       const std::string &error)
    {
      Lines lines(in, error);
      bool  format_seen = false, v41 = false, nodes_seen = false,
           elements_seen = false;
      Nodes       nodes;
      GmshOutline outline;
      while (lines.next())
        {
          const std::string line = dealii::Utilities::trim(lines.line());
          if (line == "$MeshFormat")
            read_format(lines, v41), format_seen = true;
          else if (!format_seen && line.rfind("$", 0) == 0 &&
                   line.rfind("$End", 0) != 0)
            lines.fail(line + " comes before $MeshFormat");
          else if (line == "$PhysicalNames")
            read_physical_names(lines, dim, outline.boundary_names);
          else if (line == "$Nodes")
            nodes = read_nodes(lines, v41), nodes_seen = true;
          else if (line == "$Elements")
            {
              if (!nodes_seen)
                lines.fail("$Elements comes before $Nodes");
              outline.n_cells = read_elements(lines, v41, nodes, dim);
              elements_seen   = true;
            }
          else if (line == "$Entities" && v41)
            read_entities(lines);
          else if (line.rfind("$", 0) == 0 && line.rfind("$End", 0) != 0)
            skip_section(lines, line);
        }
      if (!format_seen)
        throw InputError(error + "' has no $MeshFormat section, it is not a "
                                 "gmsh file");
      if (!nodes_seen || !elements_seen)
        throw InputError(error + "' has no " +
                         (nodes_seen ? "$Elements" : "$Nodes") + " section");
      return outline;
    }
  } // namespace geometry
} // namespace dpana
