// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <algorithm>
#include <cmath>
#include <limits>

#include "gmsh_reading.h"

namespace dpana
{
  namespace geometry
  {
    namespace
    {
      using namespace gmsh_reading;

      // The most nodes reserved for from a section's head, which a
      // damaged file may overstate.
      constexpr long long max_reserved = 1 << 22;



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
                const std::vector<long long> block = lines.block_head(
                  "a block head 'dimension entity parametric nodes'", "nodes");
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
            lines.check_blocks(section, n_read, head[1], "nodes");
          }
        lines.next_in(section);
        lines.expect("$EndNodes");
        return nodes;
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
      Nodes      nodes;
      EntityTags entity_tags;
      GmshMesh   mesh;
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
              read_elements(lines, v41, entity_tags, nodes, dim, error, mesh);
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
