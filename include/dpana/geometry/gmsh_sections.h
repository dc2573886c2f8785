// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_gmsh_sections_h
#define dpana_geometry_gmsh_sections_h

#include <deal.II/base/types.h>

#include <array>
#include <istream>
#include <map>
#include <string>
#include <vector>

namespace dpana
{
  namespace geometry
  {
    /**
     * What an ASCII gmsh file of a body holds for dpana, read once by
     * read_gmsh_mesh(): the boundary names, the nodes, the cells and the
     * boundary elements with their physical tags. GmshFile builds the
     * Triangulation from it, as deal.II's GridIn::read_msh would from the
     * same file (the same vertices, cells, material and boundary ids).
     */
    struct GmshMesh
    {
      // The $PhysicalNames of dimension dim - 1: name -> tag.
      std::map<std::string, dealii::types::boundary_id> boundary_names;
      // The nodes, in the order of the file.
      std::vector<std::array<double, 3>> nodes;
      // The cells (triangles in 2D, tetrahedra in 3D): dim + 1 positions in
      // nodes each, and the physical tag of each (0: none).
      std::vector<unsigned int> cell_nodes, cell_tags;
      // The boundary elements (lines in 2D, triangles in 3D): dim positions
      // in nodes each, and the physical tag of each (0: none).
      std::vector<unsigned int> face_nodes, face_tags;

      unsigned long long
      n_cells() const
      {
        return cell_tags.size();
      }
    };

    /**
     * Reads and checks an ASCII gmsh file of format 2.2 or 4.1.
     *
     * The file is read line by line and refused, with a one-line
     * dpana::InputError that starts with @p error (e.g. "Geometry / Gmsh /
     * Mesh file: mesh file 'a.msh") and names the line, when
     *
     * - $MeshFormat is not ASCII of version 2.x or 4.1;
     * - a section does not have the layout of its version: the counts of
     *   its head and of its blocks (4.1) disagree with the lines that
     *   follow, a line holds too few or too many numbers, the section does
     *   not end with its $End line (a file whose header says 4.1 but whose
     *   sections are written in format 2.2, for instance);
     * - a coordinate is not a finite number, or a node tag is not positive,
     *   lies outside the range the head of a 4.1 section declares, or is
     *   given twice;
     * - an element has the wrong number of nodes for its type, or refers to
     *   a node that $Nodes does not define, or is of a type dpana does not
     *   read (it reads points, lines, triangles and tetrahedra; a
     *   quadrilateral, hexahedron, prism or pyramid makes the mesh one of
     *   other cells than simplices, which is refused without a line);
     * - a cell (a triangle in 2D, a tetrahedron in 3D) has zero measure:
     *   its area (volume) is below 1e-10 times the square (cube) of its
     *   longest edge;
     * - an entity of a 4.1 file belongs to more than one physical group;
     * - a $Nodes, $Elements or $Entities section comes a second time, or
     *   $Entities after $Elements (the cells refer to the nodes and
     *   entities read before them), a block has a negative count, or a
     *   physical tag is negative or too large for an id.
     *
     * The counts of the section heads are not trusted for more than
     * 2^22 nodes of reserved memory.
     *
     * The physical tag of an element is its first tag (2.2) or the physical
     * group of its entity (4.1), 0 if it has none. Points, and lines in 3D,
     * carry nothing dpana uses and are checked but not kept.
     */
    GmshMesh
    read_gmsh_mesh(std::istream      &in,
                   const unsigned int dim,
                   const std::string &error);
  } // namespace geometry
} // namespace dpana

#endif
