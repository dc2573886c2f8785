// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The $Elements section of a gmsh file: every element checked (its type,
// its nodes, the measure of a cell), the cells and boundary elements kept
// with their physical tags.

#include <cmath>
#include <limits>
#include <sstream>

#include "gmsh_reading.h"

namespace dpana
{
  namespace geometry
  {
    namespace gmsh_reading
    {
      namespace
      {
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
          // 2D: the z of the first triangle's nodes, which all share.
          double plane_z = std::numeric_limits<double>::quiet_NaN();

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
              lines.fail(element() + " is of gmsh type " +
                         std::to_string(type) +
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
                               (dim == 2 ? "triangles" : "tetrahedra") +
                               " only");
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
            // A 2D mesh lies in one plane z = const: the boundary
            // triangles of a 3D mesh would otherwise be read with z
            // dropped.
            for (unsigned int k = 0; dim == 2 && k <= dim; ++k)
              {
                const auto &x = *p[k];
                if (std::isnan(plane_z))
                  plane_z = x[2];
                if (std::abs(x[2] - plane_z) >
                    1e-9 *
                      (1 + std::abs(x[0]) + std::abs(x[1]) + std::abs(plane_z)))
                  {
                    std::ostringstream z;
                    z << "element " << tag
                      << " (a triangle) has a node at z = " << x[2]
                      << ", off the plane z = " << plane_z
                      << " of the triangles before it: a 2D mesh lies in one "
                         "plane (a 3D mesh needs Dimension = 3)";
                    lines.fail(z.str());
                  }
              }
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
      } // namespace



      void
      read_elements(Lines             &lines,
                    const bool         v41,
                    const EntityTags  &entity_tags,
                    const Nodes       &nodes,
                    const unsigned int dim,
                    const std::string &error,
                    GmshMesh          &mesh)
      {
        ElementReader     reader{lines, nodes, dim, error, mesh};
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
                const std::vector<long long> block = lines.block_head(
                  "a block head 'dimension entity type elements'", "elements");
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
            lines.check_blocks(section, n_read, head[1], "elements");
          }
        lines.next_in(section);
        lines.expect("$EndElements");
      }
    } // namespace gmsh_reading
  }   // namespace geometry
} // namespace dpana
