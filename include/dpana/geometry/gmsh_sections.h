// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_geometry_gmsh_sections_h
#define dpana_geometry_gmsh_sections_h

#include <deal.II/base/types.h>

#include <istream>
#include <map>
#include <string>

namespace dpana
{
  namespace geometry
  {
    /**
     * Reads an ASCII gmsh file once, before deal.II's GridIn::read_msh, and
     * checks what GridIn takes for granted; returns the boundary names (the
     * $PhysicalNames of dimension @p dim - 1, name -> tag) and the number of
     * cells.
     *
     * GridIn reads the counts at the head of the $Nodes and $Elements
     * sections and then as many numbers as they promise, without checking
     * what follows. A file whose header says 4.1 but whose sections are
     * written in format 2.2 therefore makes it write past the end of its
     * arrays; a node tag given twice silently moves a vertex; a triangle of
     * zero area becomes a cell with a singular Jacobian, noticed (if at
     * all) much later and far from its cause. Here the file is read line by
     * line and refused, with a one-line dpana::InputError that starts with
     * @p error (e.g. "Geometry / Gmsh / Mesh file: mesh file 'a.msh") and
     * names the line, when
     *
     * - $MeshFormat is not ASCII of version 2.x or 4.1;
     * - a section does not have the layout of its version: the counts of
     *   its head and of its blocks (4.1) disagree with the lines that
     *   follow, a line holds too few or too many numbers, the section does
     *   not end with its $End line;
     * - a coordinate is not a finite number, or a node tag is not positive,
     *   lies outside the range the head of a 4.1 section declares, or is
     *   given twice;
     * - an element of a type GridIn reads (points, lines, triangles,
     *   quadrilaterals, tetrahedra, hexahedra, prisms, pyramids) has the
     *   wrong number of nodes, or refers to a node that $Nodes does not
     *   define;
     * - a cell (a triangle in 2D, a tetrahedron in 3D) has zero measure:
     *   its area (volume) is below 1e-10 times the square (cube) of its
     *   longest edge.
     *
     * Element types GridIn does not read are left to GridIn, whose own
     * message then names the type.
     */
    struct GmshOutline
    {
      // The $PhysicalNames of dimension dim - 1: name -> tag.
      std::map<std::string, dealii::types::boundary_id> boundary_names;
      // The number of cells (triangles in 2D, tetrahedra in 3D).
      unsigned long long n_cells = 0;
    };

    GmshOutline
    read_gmsh_sections(std::istream      &in,
                       const unsigned int dim,
                       const std::string &error);
  } // namespace geometry
} // namespace dpana

#endif
