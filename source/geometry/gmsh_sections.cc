// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/gmsh_sections.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
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

      // The most nodes reserved for from a section's head, which a
      // damaged file may overstate.
      constexpr long long max_reserved = 1 << 22;

      // The physical group of each entity of a 4.1 file, by dimension:
      // entity tag -> physical tag.
      using EntityTags =
        std::array<std::unordered_map<long long, long long>, 4>;



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
            if (tag < 0 || tag >= dealii::numbers::internal_face_boundary_id)
              lines.fail("physical tag " + std::to_string(tag) +
                         " is negative or too large for an id");
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
        std::array<double, 3> x;
        const char           *p = coordinates.c_str();
        std::string           word;
        for (double &xi : x)
          {
            while (std::isspace(static_cast<unsigned char>(*p)))
              ++p;
            const char *begin = p;
            while (*p != '\0' && !std::isspace(static_cast<unsigned char>(*p)))
              ++p;
            if (p == begin)
              lines.fail("node " + std::to_string(tag) +
                         " has fewer than 3 coordinates");
            word.assign(begin, p);
            char *end;
            xi = std::strtod(word.c_str(), &end);
            if (*end != '\0' || !std::isfinite(xi))
              lines.fail("coordinate " + parameters::quote(word) + " of node " +
                         std::to_string(tag) + " is not a finite number");
          }
        const auto [it, inserted] = nodes.position.emplace(tag, nodes.x.size());
        if (!inserted)
          lines.fail("node tag " + std::to_string(tag) +
                     " is given twice (first on line " +
                     std::to_string(nodes.line[it->second]) + ")");
        nodes.x.push_back(x);
        nodes.line.push_back(lines.number);
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
            nodes.position.reserve(std::clamp(n, 0LL, max_reserved));
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
            const std::vector<long long> head =
              lines.integers(4, "'blocks nodes min_tag max_tag' (format 4.1)");
            nodes.position.reserve(std::clamp(head[1], 0LL, max_reserved));
            long long n_read = 0;
            for (long long b = 0; b < head[0]; ++b)
              {
                lines.next_in(section);
                const std::vector<long long> block = lines.integers(
                  4, "a block head 'dimension entity parametric nodes'");
                if (block[3] < 0)
                  lines.fail("a block of " + std::to_string(block[3]) +
                             " nodes");
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



      // The number of nodes of the linear element types of gmsh (points,
      // lines, triangles, quadrilaterals, tetrahedra, hexahedra, prisms,
      // pyramids); 0 for the others.
      std::size_t
      nodes_of_type(const long long type)
      {
        switch (type)
          {
            case 15:
              return 1;
            case 1:
              return 2;
            case 2:
              return 3;
            case 3:
            case 4:
              return 4;
            case 5:
              return 8;
            case 6:
              return 6;
            case 7:
              return 5;
            default:
              return 0;
          }
      }



      // Zero measure of a triangle (2D) or tetrahedron (3D), relative to
      // its longest edge.
      bool
      degenerate(const std::array<const std::array<double, 3> *, 4> &p,
                 const unsigned int                                  dim)
      {
        std::array<std::array<double, 3>, 3> e;
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int d = 0; d < 3; ++d)
            e[k][d] = d < dim ? (*p[k + 1])[d] - (*p[0])[d] : 0.;
        double h = 0;
        for (unsigned int i = 0; i <= dim; ++i)
          for (unsigned int j = 0; j < i; ++j)
            {
              double l2 = 0;
              for (unsigned int d = 0; d < dim; ++d)
                l2 += std::pow((*p[i])[d] - (*p[j])[d], 2);
              h = std::max(h, std::sqrt(l2));
            }
        const double measure =
          dim == 2 ? e[0][0] * e[1][1] - e[0][1] * e[1][0] :
                     e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                       e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                       e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
        return !(std::abs(measure) > 1e-10 * std::pow(h, dim));
      }



      // The elements read so far into the mesh, with what they need to be
      // checked: the nodes, the dimension and the start of the errors that
      // name no line.
      struct ElementReader
      {
        Lines             &lines;
        const Nodes       &nodes;
        const unsigned int dim;
        const std::string &error;
        GmshMesh          &mesh;

        // One element of gmsh type @p type with the nodes @p node_tags and
        // the physical tag @p physical: checked, and kept if it is a cell or
        // a boundary element of this dimension.
        void
        add(const long long   tag,
            const long long   type,
            const long long  *node_tags,
            const std::size_t n_nodes,
            const long long   physical)
        {
          // The element's name, made only for an error.
          const auto element = [tag] {
            return "element " + std::to_string(tag);
          };
          const std::size_t n = nodes_of_type(type);
          if (n == 0)
            lines.fail(element() + " is of gmsh type " + std::to_string(type) +
                       ", which dpana does not read (it reads points, lines, "
                       "triangles and tetrahedra of the first order)");
          if (n_nodes != n)
            lines.fail(element() + " of type " + std::to_string(type) +
                       " has " + std::to_string(n_nodes) +
                       " nodes instead of " + std::to_string(n));
          std::array<unsigned int, 8> position;
          for (std::size_t k = 0; k < n; ++k)
            {
              const long long i = nodes.find(node_tags[k]);
              if (i < 0)
                lines.fail(element() + " refers to node " +
                           std::to_string(node_tags[k]) +
                           ", which $Nodes does not define");
              position[k] = i;
            }
          const long long cell_type = dim == 2 ? 2 : 4, face_type = dim - 1;
          if (type == cell_type)
            add_cell(tag, position, physical);
          else if (type == face_type)
            {
              mesh.face_nodes.insert(mesh.face_nodes.end(),
                                     position.begin(),
                                     position.begin() + dim);
              mesh.face_tags.push_back(id_of(physical));
            }
          else if (type == 3 || (type >= 5 && type <= 7) ||
                   (type == 4 && dim == 2))
            throw InputError(error + "' must contain " +
                             (dim == 2 ? "triangles" : "tetrahedra") + " only");
        }

      private:
        void
        add_cell(const long long                    tag,
                 const std::array<unsigned int, 8> &position,
                 const long long                    physical)
        {
          std::array<const std::array<double, 3> *, 4> p;
          for (unsigned int k = 0; k <= dim; ++k)
            p[k] = &nodes.x[position[k]];
          if (degenerate(p, dim))
            lines.fail("element " + std::to_string(tag) + " (a " +
                       (dim == 2 ? "triangle) has zero area" :
                                   "tetrahedron) has zero volume") +
                       ": a degenerate cell");
          mesh.cell_nodes.insert(mesh.cell_nodes.end(),
                                 position.begin(),
                                 position.begin() + dim + 1);
          mesh.cell_tags.push_back(id_of(physical));
        }

        // A physical tag as a material or boundary id.
        unsigned int
        id_of(const long long physical) const
        {
          if (physical < 0 ||
              physical >= dealii::numbers::internal_face_boundary_id)
            lines.fail("physical tag " + std::to_string(physical) +
                       " is negative or too large for an id");
          return physical;
        }
      };



      void
      read_elements(Lines            &lines,
                    const bool        v41,
                    const EntityTags &entity_tags,
                    ElementReader    &reader)
      {
        const std::string section = "$Elements";
        lines.next_in(section);
        if (!v41)
          {
            const long long n = lines.integers(1, "the number of elements")[0];
            const std::string layout = "an element 'tag type n_tags tags... "
                                       "nodes...'";
            for (long long i = 0; i < n; ++i)
              {
                lines.next_in(section);
                const auto &v = lines.integers(0, layout);
                if (v.size() < 3 || v[2] < 0 ||
                    v.size() < 3 + static_cast<std::size_t>(v[2]))
                  lines.fail("expected " + layout + ", got " +
                             parameters::quote(lines.line()));
                const std::size_t first = 3 + v[2];
                reader.add(v[0],
                           v[1],
                           v.data() + first,
                           v.size() - first,
                           v[2] > 0 ? v[3] : 0);
              }
          }
        else
          {
            const std::vector<long long> head =
              lines.integers(4,
                             "'blocks elements min_tag max_tag' (format 4.1)");
            long long n_read = 0;
            for (long long b = 0; b < head[0]; ++b)
              {
                lines.next_in(section);
                const std::vector<long long> block = lines.integers(
                  4, "a block head 'dimension entity type elements'");
                if (block[3] < 0)
                  lines.fail("a block of " + std::to_string(block[3]) +
                             " elements");
                if (block[0] < 0 || block[0] > 3)
                  lines.fail("a block of elements of an entity of dimension " +
                             std::to_string(block[0]));
                const auto      entity = entity_tags[block[0]].find(block[1]);
                const long long physical =
                  entity == entity_tags[block[0]].end() ? 0 : entity->second;
                for (long long i = 0; i < block[3]; ++i)
                  {
                    lines.next_in(section);
                    const auto &v =
                      lines.integers(0, "an element 'tag nodes...'");
                    reader.add(
                      v[0], block[2], v.data() + 1, v.size() - 1, physical);
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
      }



      // $Entities of format 4.1: the counts of points, curves, surfaces and
      // volumes, then one line per entity, "tag x y z n_physical
      // physical..." for a point and "tag box(6) n_physical physical...
      // n_bounding bounding..." for the others, every word a number. Returns
      // the physical group of each entity (none: not in the map).
      EntityTags
      read_entities(Lines &lines)
      {
        const std::string section = "$Entities";
        lines.next_in(section);
        const std::vector<long long> counts = lines.integers(
          4, "'points curves surfaces volumes' (format 4.1 $Entities)");
        EntityTags tags;
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
              long long tag = 0, n_physical = -1, n_bounding = 0;
              ok = ok && to_integer(w[0], tag) &&
                   to_integer(w[n_coordinates + 1], n_physical) &&
                   n_physical >= 0;
              const std::size_t next = n_coordinates + 2 + n_physical;
              if (ok && kind > 0)
                ok = w.size() > next && to_integer(w[next], n_bounding) &&
                     n_bounding >= 0;
              long long physical = 0;
              for (std::size_t k = n_coordinates + 2;
                   ok && k < next && k < w.size();
                   ++k)
                ok = to_integer(w[k], physical);
              if (!ok || w.size() != next + (kind > 0 ? 1 + n_bounding : 0))
                lines.fail("expected an entity of dimension " +
                           std::to_string(kind) + ", got " +
                           parameters::quote(lines.line()));
              if (n_physical > 1)
                lines.fail("entity " + std::to_string(tag) + " of dimension " +
                           std::to_string(kind) + " is in " +
                           std::to_string(n_physical) +
                           " physical groups; dpana reads one");
              if (n_physical == 1)
                tags[kind][tag] = physical;
            }
        lines.next_in(section);
        lines.expect("$EndEntities");
        return tags;
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



    GmshMesh
    read_gmsh_mesh(std::istream      &in,
                   const unsigned int dim,
                   const std::string &error)
    {
      Lines lines(in, error);
      bool  format_seen = false, v41 = false, nodes_seen = false,
           elements_seen = false, entities_seen = false;
      // The cells refer to the nodes read before them: a second $Nodes,
      // $Elements or $Entities, or $Entities after $Elements, is refused.
      const auto once = [&lines](const bool seen, const std::string &section) {
        if (seen)
          lines.fail("a second " + section + " section");
      };
      Nodes         nodes;
      EntityTags    entity_tags;
      GmshMesh      mesh;
      ElementReader reader{lines, nodes, dim, error, mesh};
      while (lines.next())
        {
          const std::string line = dealii::Utilities::trim(lines.line());
          if (line == "$MeshFormat")
            read_format(lines, v41), format_seen = true;
          else if (!format_seen && line.rfind("$", 0) == 0 &&
                   line.rfind("$End", 0) != 0)
            lines.fail(line + " comes before $MeshFormat");
          else if (line == "$PhysicalNames")
            read_physical_names(lines, dim, mesh.boundary_names);
          else if (line == "$Nodes")
            {
              once(nodes_seen, line);
              nodes = read_nodes(lines, v41), nodes_seen = true;
            }
          else if (line == "$Elements")
            {
              once(elements_seen, line);
              if (!nodes_seen)
                lines.fail("$Elements comes before $Nodes");
              read_elements(lines, v41, entity_tags, reader);
              elements_seen = true;
            }
          else if (line == "$Entities" && v41)
            {
              once(entities_seen, line);
              if (elements_seen)
                lines.fail("$Entities comes after $Elements");
              entity_tags = read_entities(lines), entities_seen = true;
            }
          else if (line.rfind("$", 0) == 0 && line.rfind("$End", 0) != 0)
            skip_section(lines, line);
        }
      if (!format_seen)
        throw InputError(error + "' has no $MeshFormat section, it is not a "
                                 "gmsh file");
      if (!nodes_seen || !elements_seen)
        throw InputError(error + "' has no " +
                         (nodes_seen ? "$Elements" : "$Nodes") + " section");
      mesh.nodes = std::move(nodes.x);
      return mesh;
    }
  } // namespace geometry
} // namespace dpana
