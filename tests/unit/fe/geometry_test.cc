// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Tests of the geometry component: cell counts, boundary names, areas,
// volumes and boundary lengths of every geometry type, and the errors for bad
// input.
//
// Measures are sums of cell (face) measures computed with a simplex
// quadrature and MappingFE of degree one, the mapping the solver uses
// (GridTools::volume assumes MappingQ1, which is wrong for simplices). The
// cells are affine, so these sums are exact up to rounding; the tolerance
// 1e-12 (relative) only absorbs rounding. The reference values are exact
// formulas: side lengths and areas of the bricks, and for the curved shapes
// the inscribed polygon whose vertices are spread evenly on the circle by
// the refinement (n chords over an angle alpha: length 2 n R sin(alpha/2n),
// area of the sector part n R^2 sin(alpha/n) / 2), which tends to the
// circle's values at the rate (alpha/n)^2.

#include <dpana/base/exceptions.h>
#include <dpana/geometry/geometry.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include "geometry_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dpana::test;
  using dealii::types::boundary_id;
  using dpana::geometry::Geometry;

  const double pi = dealii::numbers::PI;

  // The folder of the test meshes, found from the path of this file.
  std::string
  data_dir()
  {
#ifdef DPANA_SOURCE_DIR
    return std::string(DPANA_SOURCE_DIR) + "/tests/data/";
#else
    const std::string here = __FILE__;
    return here.substr(0, here.rfind("/unit/fe/")) + "/data/";
#endif
  }

  // The text of a Geometry subsection of type gmsh reading @p file.
  std::string
  gmsh(const std::string &file)
  {
    return "set Type = gmsh\n" +
           shape("Gmsh", "set Mesh file = " + file + "\n");
  }
} // namespace



// @sect3{Rectangle and box}

TEST(Geometry, RectangleCountsNamesMeasures)
{
  const auto geometry = make_geometry<2>(
    "set Type = rectangle\nset Global refinements = 1\n" +
    shape("Rectangle",
          "set Lower corner = -10, 5\nset Upper corner = 30, 45\n"
          "set Subdivisions = 4, 2\n"));
  EXPECT_EQ(names_of(geometry),
            (std::set<std::string>{"left", "right", "bottom", "top"}));
  dealii::Triangulation<2> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  // 4 x 2 rectangles, 2 triangles each, 4 children per refinement.
  EXPECT_EQ(m.n_cells, 4u * 2 * 2 * 4);
  EXPECT_GT(m.min_jxw, 0.);
  expect_relative(m.volume, 40. * 40.);
  for (const std::string side : {"left", "right", "bottom", "top"})
    expect_relative(m.boundary_measure.at(geometry.boundary_id(side)), 40.);
  // Each side has its subdivisions times 2 faces.
  EXPECT_EQ(m.n_boundary_faces.at(geometry.boundary_id("left")), 4u);
  EXPECT_EQ(m.n_boundary_faces.at(geometry.boundary_id("bottom")), 8u);
  EXPECT_EQ(geometry.description(),
            "rectangle 40 x 40, 4 x 2 subdivisions, 1 global refinements");
}



TEST(Geometry, RectangleGradingMovesVerticesAsDocumented)
{
  // Exponent 2 towards y = 0 with 4 layers: the vertex rows move from
  // y = 40 k/4 to y = 40 (k/4)^2 = 0, 2.5, 10, 22.5, 40. Along x, centre 20
  // and exponent 3 with 2 layers on each side: x = 0, 20 - 20/8, 20,
  // 20 + 20/8, 40.
  const auto geometry = make_geometry<2>(
    "set Type = rectangle\n" +
    shape("Rectangle",
          "set Upper corner = 40, 40\nset Subdivisions = 4, 4\n"
          "set Grading centre = 20, 0\nset Grading exponents = 3, 2\n"));
  dealii::Triangulation<2> tria;
  geometry.create_triangulation(tria);
  std::set<long> xs, ys;
  for (const auto &v : tria.get_vertices())
    {
      xs.insert(std::lround(v[0] * 1e6));
      ys.insert(std::lround(v[1] * 1e6));
    }
  EXPECT_EQ(ys, (std::set<long>{0, 2500000, 10000000, 22500000, 40000000}));
  EXPECT_EQ(xs, (std::set<long>{0, 17500000, 20000000, 22500000, 40000000}));
  const Measures m = measure(tria);
  EXPECT_GT(m.min_jxw, 0.);
  expect_relative(m.volume, 1600.);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("bottom")), 40.);
}



namespace
{
  // The triangles of a mesh as sets of their vertices, rounded to 1e-9 mm,
  // after the map x -> a + b x of the first coordinate.
  std::set<std::set<std::pair<long, long>>>
  cells_mapped(const dealii::Triangulation<2> &tria,
               const double                    a,
               const double                    b)
  {
    std::set<std::set<std::pair<long, long>>> cells;
    for (const auto &cell : tria.active_cell_iterators())
      {
        std::set<std::pair<long, long>> v;
        for (const unsigned int i : cell->vertex_indices())
          v.emplace(std::lround((a + b * cell->vertex(i)[0]) * 1e9),
                    std::lround(cell->vertex(i)[1] * 1e9));
        cells.insert(v);
      }
    return cells;
  }
} // namespace



// Diagonals = alternating: a mesh mirror-symmetric about its grid lines (so
// that a half model and its mirror image form one checkerboard). On
// 6 x 3 rectangles the reflection about the middle line x = 30 (3 rectangles
// on each side) maps the mesh onto itself; with every diagonal running one
// way it maps each diagonal onto one the mesh does not have. The counts,
// the measures and the boundary faces stay those of the other split.
TEST(Geometry, RectangleAlternatingDiagonalsAreMirrorSymmetric)
{
  for (const std::string diagonals : {"alternating", "one direction"})
    {
      const auto geometry = make_geometry<2>(
        "set Type = rectangle\n" +
        shape("Rectangle",
              "set Lower corner = 0, 0\nset Upper corner = 60, 30\n"
              "set Subdivisions = 6, 3\nset Diagonals = " +
                diagonals + "\n"));
      dealii::Triangulation<2> tria;
      geometry.create_triangulation(tria);
      const Measures m = measure(tria);
      EXPECT_EQ(m.n_cells, 6u * 3 * 2);
      EXPECT_GT(m.min_jxw, 0.);
      expect_relative(m.volume, 60. * 30.);
      EXPECT_EQ(m.n_boundary_faces.at(geometry.boundary_id("bottom")), 6u);
      EXPECT_EQ(m.n_boundary_faces.at(geometry.boundary_id("left")), 3u);
      EXPECT_EQ(cells_mapped(tria, 60., -1.) == cells_mapped(tria, 0., 1.),
                diagonals == "alternating")
        << diagonals;
    }
  EXPECT_EQ(make_geometry<2>(
              "set Type = rectangle\n" +
              shape("Rectangle", "set Diagonals = alternating\n"))
              .description(),
            "rectangle 1 x 1, 1 x 1 subdivisions, alternating diagonals, 0 "
            "global refinements");
}



TEST(Geometry, BoxCountsNamesMeasures)
{
  const auto geometry = make_geometry<3>(
    "set Type = box\nset Global refinements = 1\n" +
    shape("Box",
          "set Lower corner = 0, 0, 0\nset Upper corner = 2, 1, 3\n"
          "set Subdivisions = 2, 1, 3\n"));
  EXPECT_EQ(
    names_of(geometry),
    (std::set<std::string>{"left", "right", "bottom", "top", "front", "back"}));
  dealii::Triangulation<3> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  // 6 bricks, 5 tetrahedra each, 8 children per refinement.
  EXPECT_EQ(m.n_cells, 6u * 5 * 8);
  EXPECT_GT(m.min_jxw, 0.);
  expect_relative(m.volume, 6.);
  // left/right: x = const (1 x 3); bottom/top: y = const (2 x 3);
  // front/back: z = const (2 x 1).
  const std::map<std::string, double> area = {{"left", 3.},
                                              {"right", 3.},
                                              {"bottom", 6.},
                                              {"top", 6.},
                                              {"front", 2.},
                                              {"back", 2.}};
  for (const auto &a : area)
    expect_relative(m.boundary_measure.at(geometry.boundary_id(a.first)),
                    a.second);
  EXPECT_EQ(m.boundary_measure.size(), 6u);
}



// @sect3{Half disc and quarter disc}

TEST(Geometry, HalfDiscConvergesToTheCircle)
{
  // R = 40 centred at (0, 40): the lowest point is the origin.
  const double R          = 40.;
  double       last_error = 0;
  for (unsigned int k = 0; k <= 4; ++k)
    {
      const auto geometry = make_geometry<2>(
        "set Type = half disc\nset Global refinements = " + std::to_string(k) +
        "\n" + shape("Half disc", "set Radius = 40\nset Centre = 0, 40\n"));
      EXPECT_EQ(names_of(geometry), (std::set<std::string>{"top", "curved"}));
      dealii::Triangulation<2> tria;
      geometry.create_triangulation(tria);
      const Measures m = measure(tria);

      // 6 quadrilaterals, 4 triangles each, 4 children per refinement; the
      // curved side has 4 chords of 45 degrees before refinement.
      const unsigned int n = 4 << k;
      EXPECT_EQ(m.n_cells, 24u << (2 * k));
      EXPECT_GT(m.min_jxw, 0.);
      const boundary_id curved = geometry.boundary_id("curved");
      const boundary_id top    = geometry.boundary_id("top");
      EXPECT_EQ(m.n_boundary_faces.at(curved), n);
      EXPECT_EQ(m.boundary_measure.size(), 2u);
      expect_relative(m.boundary_measure.at(top), 2 * R);
      expect_relative(m.boundary_measure.at(curved),
                      2 * n * R * std::sin(pi / (2 * n)));
      expect_relative(m.volume, n * R * R * std::sin(pi / n) / 2);
      EXPECT_LT(distance_from_circle(tria, curved, {0, 40}, R), 1e-12 * R);

      // The polygon approaches the half disc at the rate (pi/n)^2 / 6.
      const double error = pi * R * R / 2 - m.volume;
      EXPECT_GT(error, 0.);
      EXPECT_LT(error, pi * R * R / 2 * std::pow(pi / n, 2) / 6);
      if (k > 0)
        {
          EXPECT_GT(last_error / error, 3.8);
          EXPECT_LT(last_error / error, 4.1);
        }
      last_error = error;

      // The contact point (0, 0) is a vertex.
      bool found = false;
      for (const auto &v : tria.get_vertices())
        found = found || v.norm() < 1e-12 * R;
      EXPECT_TRUE(found);
    }
}



TEST(Geometry, HalfDiscContactRefinement)
{
  // Two global and three contact refinements within 5 mm of the lowest
  // point (0, -40) of the circle of radius 40 centred at the origin.
  const double R        = 40.;
  const auto   geometry = make_geometry<2>(
    "set Type = half disc\nset Global refinements = 2\n" +
    shape("Half disc",
          "set Radius = 40\nset Centre = 0, 0\nset Contact refinements = 3\n"
            "set Contact refinement radius = 5\n"));
  dealii::Triangulation<2> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  EXPECT_GT(m.min_jxw, 0.);
  const boundary_id curved = geometry.boundary_id("curved");
  EXPECT_EQ(m.boundary_measure.size(), 2u);
  // Hanging nodes of the quadrilateral mesh must not leave holes: a
  // non-conforming triangle mesh would show interior faces as boundary
  // faces off the circle, and a total length of the top above 2R.
  EXPECT_LT(distance_from_circle(tria, curved, {0, 0}, R), 1e-12 * R);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("top")), 2 * R);

  // The area is that of the polygon of the curved boundary vertices: the
  // sum of the triangles (centre, chord), R^2 sin(angle) / 2 each.
  double polygon_area = 0, polygon_length = 0, finest_chord_near = 1e300,
         largest_chord_near = 0;
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary() && face->boundary_id() == curved)
      {
        const double chord = face->vertex(0).distance(face->vertex(1));
        const double angle = 2 * std::asin(chord / (2 * R));
        polygon_area += R * R * std::sin(angle) / 2;
        polygon_length += chord;
        if (face->center().distance(dealii::Point<2>(0, -R)) < 5.)
          {
            finest_chord_near  = std::min(finest_chord_near, chord);
            largest_chord_near = std::max(largest_chord_near, chord);
          }
      }
  expect_relative(m.volume, polygon_area);
  expect_relative(m.boundary_measure.at(curved), polygon_length);
  // Near the contact point the chords span 45 / 2^(2+3) degrees.
  const double fine_chord = 2 * R * std::sin(pi / 4 / 32 / 2);
  EXPECT_NEAR(finest_chord_near, fine_chord, 1e-9 * R);
  EXPECT_NEAR(largest_chord_near, fine_chord, 1e-9 * R);
  // More cells than the uniform mesh with two refinements (384), far fewer
  // than the uniform one with five (24576).
  EXPECT_GT(m.n_cells, 384u);
  EXPECT_LT(m.n_cells, 24576u / 4);
}



TEST(Geometry, QuarterDisc)
{
  const double R        = 2.;
  const auto   geometry = make_geometry<2>(
    "set Type = quarter disc\nset Global refinements = 3\n" +
    shape("Quarter disc", "set Radius = 2\nset Centre = 1, 1\n"));
  EXPECT_EQ(names_of(geometry),
            (std::set<std::string>{"top", "curved", "axis"}));
  dealii::Triangulation<2> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  // 3 quadrilaterals -> 12 triangles, times 4^3; 2 chords of 45 degrees
  // before refinement.
  const unsigned int n = 2 << 3;
  EXPECT_EQ(m.n_cells, 12u * 64);
  EXPECT_GT(m.min_jxw, 0.);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("top")), R);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("axis")), R);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("curved")),
                  2 * n * R * std::sin(pi / (4 * n)));
  expect_relative(m.volume, n * R * R * std::sin(pi / (2 * n)) / 2);
  EXPECT_LT(
    distance_from_circle(tria, geometry.boundary_id("curved"), {1, 1}, R),
    1e-12 * R);
}



// @sect3{Half cylinder}

TEST(Geometry, HalfCylinder)
{
  const double R = 40., L = 20.;
  const auto   geometry = make_geometry<3>(
    "set Type = half cylinder\nset Global refinements = 1\n" +
    shape("Half cylinder",
          "set Radius = 40\nset Centre = 0, 40, -5\nset Length = 20\n"
            "set Axial subdivisions = 2\n"));
  EXPECT_EQ(names_of(geometry),
            (std::set<std::string>{"top", "curved", "front", "back"}));
  dealii::Triangulation<3> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  // The cross-section has 24 * 4 = 96 triangles and 2 * 2 = 4 layers; each
  // prism is split into 3 tetrahedra.
  EXPECT_EQ(m.n_cells, 96u * 4 * 3);
  EXPECT_GT(m.min_jxw, 0.);
  const unsigned int n       = 8;
  const double       section = n * R * R * std::sin(pi / n) / 2;
  expect_relative(m.volume, section * L);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("front")),
                  section);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("back")), section);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("top")),
                  2 * R * L);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("curved")),
                  2 * n * R * std::sin(pi / (2 * n)) * L);
  EXPECT_EQ(m.boundary_measure.size(), 4u);
  EXPECT_LT(
    distance_from_circle(tria, geometry.boundary_id("curved"), {0, 40}, R),
    1e-12 * R);
}



TEST(Geometry, HalfCylinderContactRefinementIsConforming)
{
  // Hanging nodes in the cross-section: the extruded mesh must still close,
  // i.e. its volume is the cross-section area times the length and the
  // front face has the cross-section's area.
  const auto geometry = make_geometry<3>(
    "set Type = half cylinder\n" +
    shape(
      "Half cylinder",
      "set Radius = 1\nset Centre = 0, 0, 0\nset Length = 1\n"
      "set Contact refinements = 2\nset Contact refinement radius = 0.3\n"));
  dealii::Triangulation<3> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  EXPECT_GT(m.min_jxw, 0.);
  const double front = m.boundary_measure.at(geometry.boundary_id("front"));
  expect_relative(m.boundary_measure.at(geometry.boundary_id("back")), front);
  expect_relative(m.volume, front * 1.);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("top")), 2.);
  EXPECT_LT(
    distance_from_circle(tria, geometry.boundary_id("curved"), {0, 0}, 1.),
    1e-12);
  EXPECT_EQ(m.boundary_measure.size(), 4u);
}



// @sect3{Annuli}

TEST(Geometry, HalfAnnulus)
{
  // The cavity of the cylinder-in-a-cavity scene: Ri = 120, Ro = 240.
  const double Ri = 120., Ro = 240.;
  const auto   geometry =
    make_geometry<2>("set Type = half annulus\nset Global refinements = 2\n" +
                     shape("Half annulus",
                           "set Inner radius = 120\nset Outer radius = 240\n"
                           "set Centre = 0, 120\n"));
  EXPECT_EQ(names_of(geometry),
            (std::set<std::string>{"inner", "outer", "left", "right"}));
  dealii::Triangulation<2> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  EXPECT_GT(m.min_jxw, 0.);
  // Ro/Ri = 2: the polar grid has ceil(pi / ln 2) = 5 cells along the half
  // circle and round(ln 2 / (pi/5)) = 1 layer: 5 quadrilaterals, 20
  // triangles, times 4^2.
  EXPECT_EQ(m.n_cells, 20u * 16);
  const unsigned int n = 5 * 4;
  EXPECT_EQ(m.n_boundary_faces.at(geometry.boundary_id("inner")), n);
  EXPECT_EQ(m.n_boundary_faces.at(geometry.boundary_id("outer")), n);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("left")), Ro - Ri);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("right")),
                  Ro - Ri);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("inner")),
                  2 * n * Ri * std::sin(pi / (2 * n)));
  expect_relative(m.boundary_measure.at(geometry.boundary_id("outer")),
                  2 * n * Ro * std::sin(pi / (2 * n)));
  expect_relative(m.volume, n * (Ro * Ro - Ri * Ri) * std::sin(pi / n) / 2);
  EXPECT_LT(
    distance_from_circle(tria, geometry.boundary_id("inner"), {0, 120}, Ri),
    1e-12 * Ro);
  EXPECT_LT(
    distance_from_circle(tria, geometry.boundary_id("outer"), {0, 120}, Ro),
    1e-12 * Ro);
}



TEST(Geometry, HalfAnnulusContactRefinement)
{
  // Refinement around the lowest point (0, -Ri) of the inner circle.
  const double Ri = 40., Ro = 120.;
  const auto   geometry = make_geometry<2>(
    "set Type = half annulus\nset Global refinements = 1\n" +
    shape("Half annulus",
          "set Inner radius = 40\nset Outer radius = 120\n"
            "set Contact refinements = 2\nset Contact refinement radius = 10\n"));
  dealii::Triangulation<2> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  EXPECT_GT(m.min_jxw, 0.);
  // The area is the difference of the polygons of the outer and inner
  // boundary vertices.
  double area = 0, shortest_inner = 1e300, longest_outer = 0;
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary())
      {
        const double chord = face->vertex(0).distance(face->vertex(1));
        if (face->boundary_id() == geometry.boundary_id("inner"))
          {
            area -= Ri * Ri * std::sin(2 * std::asin(chord / (2 * Ri))) / 2;
            shortest_inner = std::min(shortest_inner, chord);
          }
        else if (face->boundary_id() == geometry.boundary_id("outer"))
          {
            area += Ro * Ro * std::sin(2 * std::asin(chord / (2 * Ro))) / 2;
            longest_outer = std::max(longest_outer, chord);
          }
      }
  expect_relative(m.volume, area);
  // Ro/Ri = 3: 4 cells along the half circle (at least 4), 1 layer; one
  // global and two contact refinements: the inner chords near the contact
  // point span 45/8 degrees, the outer ones 45/2.
  EXPECT_NEAR(shortest_inner, 2 * Ri * std::sin(pi / 4 / 8 / 2), 1e-9 * Ri);
  EXPECT_NEAR(longest_outer, 2 * Ro * std::sin(pi / 4 / 2 / 2), 1e-9 * Ro);
}



TEST(Geometry, QuarterAnnulusForLame)
{
  const double Ri = 1., Ro = 2.;
  const auto   geometry = make_geometry<2>(
    "set Type = quarter annulus\nset Global refinements = 3\n" +
    shape("Quarter annulus", "set Inner radius = 1\nset Outer radius = 2\n"));
  EXPECT_EQ(names_of(geometry),
            (std::set<std::string>{"inner", "outer", "x_axis", "y_axis"}));
  dealii::Triangulation<2> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  EXPECT_GT(m.min_jxw, 0.);
  // ceil((pi/2) / ln 2) = 3 cells along the quarter circle, 1 layer.
  const unsigned int n = 3 * 8;
  EXPECT_EQ(m.n_cells, 12u * 64);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("x_axis")), 1.);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("y_axis")), 1.);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("inner")),
                  2 * n * Ri * std::sin(pi / (4 * n)));
  expect_relative(m.volume,
                  n * (Ro * Ro - Ri * Ri) * std::sin(pi / (2 * n)) / 2);
  // The exact quarter annulus has area 3 pi / 4.
  EXPECT_NEAR(m.volume, 3 * pi / 4, 3 * pi / 4 * std::pow(pi / (2 * n), 2) / 6);
}



// @sect3{Gmsh files}

TEST(Geometry, GmshFormat22And41)
{
  for (const std::string file :
       {"rectangle_2x1_v22.msh", "rectangle_2x1_v41.msh"})
    {
      SCOPED_TRACE(file);
      const auto geometry = make_geometry<2>(gmsh(data_dir() + file));
      // Names and tags as written in the file's $PhysicalNames; the surface
      // group "body" is not a boundary.
      EXPECT_EQ(geometry.boundary_names(),
                (std::map<std::string, boundary_id>{
                  {"bottom", 1}, {"right", 2}, {"top", 3}, {"left", 4}}));
      dealii::Triangulation<2> tria;
      geometry.create_triangulation(tria);
      const Measures m = measure(tria);
      EXPECT_EQ(m.n_cells, 4u);
      EXPECT_GT(m.min_jxw, 0.);
      expect_relative(m.volume, 2.);
      expect_relative(m.boundary_measure.at(1), 2.);
      expect_relative(m.boundary_measure.at(2), 1.);
      expect_relative(m.boundary_measure.at(3), 2.);
      expect_relative(m.boundary_measure.at(4), 1.);
      EXPECT_EQ(m.n_boundary_faces.at(1), 2u);
      EXPECT_EQ(m.n_boundary_faces.at(4), 1u);
    }
}



TEST(Geometry, GmshFilesWrittenByGmsh)
{
  // The plate [0, 4] x [0, 2] with a hole of radius 0.5 centred at (2, 1),
  // meshed by gmsh itself (tests/data/make_gmsh_meshes.cc) and saved in
  // both formats: several node and element blocks, point entities, curves
  // split in several entities.
  unsigned int n_cells = 0;
  for (const std::string file :
       {"plate_with_hole_v41.msh", "plate_with_hole_v22.msh"})
    {
      SCOPED_TRACE(file);
      const auto geometry = make_geometry<2>(gmsh(data_dir() + file));
      EXPECT_EQ(geometry.boundary_names(),
                (std::map<std::string, boundary_id>{{"outer", 1},
                                                    {"hole", 2}}));
      dealii::Triangulation<2> tria;
      geometry.create_triangulation(tria);
      const Measures m = measure(tria);
      EXPECT_GT(m.min_jxw, 0.);
      // The same mesh in both files.
      if (n_cells == 0)
        n_cells = m.n_cells;
      EXPECT_EQ(m.n_cells, n_cells);
      expect_relative(m.boundary_measure.at(1), 12.);
      // The hole is a polygon with its n vertices on the circle (to the
      // precision gmsh writes).
      const unsigned int n = m.n_boundary_faces.at(2);
      const double       r = 0.5;
      EXPECT_LT(distance_from_circle(tria, 2, {2, 1}, r), 1e-6);
      EXPECT_NEAR(m.boundary_measure.at(2), 2 * n * r * std::sin(pi / n), 1e-6);
      EXPECT_NEAR(m.volume, 8. - n * r * r * std::sin(2 * pi / n) / 2, 1e-6);
    }
  EXPECT_GT(n_cells, 20u);
}



TEST(Geometry, GmshRefined3D)
{
  const auto geometry = make_geometry<3>(gmsh(data_dir() + "cube_v22.msh") +
                                         "set Global refinements = 1\n");
  EXPECT_EQ(
    names_of(geometry),
    (std::set<std::string>{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}));
  dealii::Triangulation<3> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  // 6 tetrahedra, 8 children each; each face of the cube is 2 triangles,
  // 4 children each.
  EXPECT_EQ(m.n_cells, 48u);
  EXPECT_GT(m.min_jxw, 0.);
  expect_relative(m.volume, 1.);
  for (const auto &n : geometry.boundary_names())
    {
      expect_relative(m.boundary_measure.at(n.second), 1.);
      EXPECT_EQ(m.n_boundary_faces.at(n.second), 8u);
    }
}



TEST(Geometry, GmshTetrahedraFormat41)
{
  // The column [0, 1] x [0, 1] x [0, 2] meshed by gmsh with tetrahedra,
  // format 4.1, boundary groups bottom (z = 0), top (z = 2) and sides.
  for (const unsigned int k : {0u, 1u})
    {
      const auto geometry = make_geometry<3>(
        gmsh(data_dir() + "column_v41.msh") +
        "set Global refinements = " + std::to_string(k) + "\n");
      EXPECT_EQ(geometry.boundary_names(),
                (std::map<std::string, boundary_id>{{"bottom", 1},
                                                    {"top", 2},
                                                    {"sides", 3}}));
      dealii::Triangulation<3> tria;
      geometry.create_triangulation(tria);
      const Measures m = measure(tria);
      EXPECT_GT(m.n_cells, 10u);
      EXPECT_GT(m.min_jxw, 0.);
      expect_relative(m.volume, 2.);
      expect_relative(m.boundary_measure.at(1), 1.);
      expect_relative(m.boundary_measure.at(2), 1.);
      expect_relative(m.boundary_measure.at(3), 8.);
      EXPECT_EQ(m.boundary_measure.size(), 3u);
    }
}



// dpana reads gmsh files itself, once, and builds the triangulation from
// what it read. The independent reference is deal.II's own reader,
// GridIn::read_msh, on the same file: as many vertices of cells, the same
// cells in the same order with the same vertices (in the same
// orientation), the same material ids, and the same boundary id on every
// boundary face. (A node that no cell uses, as the one of
// rectangle_2x1_points.msh that only a point element names, is dropped by
// dpana; GridIn keeps it, as a vertex of no cell.) Files of both formats, in 2D
// and 3D, written by hand and by gmsh.
template <int dim>
void
expect_same_mesh_as_grid_in(const std::string &file)
{
  SCOPED_TRACE(file);
  const auto                 geometry = make_geometry<dim>(gmsh(file));
  dealii::Triangulation<dim> ours, reference;
  geometry.create_triangulation(ours);
  dealii::GridIn<dim> grid_in;
  grid_in.attach_triangulation(reference);
  std::ifstream in(file);
  grid_in.read_msh(in);

  const auto vertices_of_cells = [](const dealii::Triangulation<dim> &t) {
    std::set<unsigned int> vertices;
    for (const auto &cell : t.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        vertices.insert(cell->vertex_index(v));
    return vertices.size();
  };
  EXPECT_EQ(vertices_of_cells(ours), vertices_of_cells(reference));
  EXPECT_EQ(ours.n_vertices(), vertices_of_cells(ours));
  ASSERT_EQ(ours.n_active_cells(), reference.n_active_cells());
  auto c = reference.begin_active();
  for (const auto &cell : ours.active_cell_iterators())
    {
      EXPECT_EQ(cell->material_id(), c->material_id());
      for (const unsigned int v : cell->vertex_indices())
        EXPECT_EQ(cell->vertex(v), c->vertex(v));
      for (const unsigned int f : cell->face_indices())
        {
          EXPECT_EQ(cell->face(f)->at_boundary(), c->face(f)->at_boundary());
          if (cell->face(f)->at_boundary())
            {
              EXPECT_EQ(cell->face(f)->boundary_id(),
                        c->face(f)->boundary_id());
            }
        }
      ++c;
    }
}

TEST(Geometry, GmshMeshIsTheMeshOfGridIn)
{
  for (const std::string file : {"rectangle_2x1_v22.msh",
                                 "rectangle_2x1_points.msh",
                                 "rectangle_2x1_v41.msh",
                                 "plate_with_hole_v22.msh",
                                 "plate_with_hole_v41.msh",
                                 "../prm/contact_hertz_ratio_graded_block."
                                 "files/hertz_block_L0_rho17.msh"})
    expect_same_mesh_as_grid_in<2>(data_dir() + file);
  for (const std::string file :
       {"cube_v22.msh",
        "column_v41.msh",
        "../prm/contact_hertz_sphere_rigid.files/hertz_sphere_coarse.msh"})
    expect_same_mesh_as_grid_in<3>(data_dir() + file);
}



// @sect3{Errors}

template <typename F>
std::string
input_error_of(const F &f)
{
  try
    {
      f();
    }
  catch (const dpana::InputError &e)
    {
      return e.what();
    }
  catch (const std::exception &e)
    {
      return std::string("wrong exception type: ") + e.what();
    }
  return "no exception";
}

TEST(Geometry, Errors)
{
  EXPECT_EQ(input_error_of(
              [] { make_geometry<2>(gmsh("/nonexistent/x.msh")); }),
            "Geometry / Gmsh / Mesh file: mesh file '/nonexistent/x.msh' not "
            "found");
  EXPECT_EQ(input_error_of([] { make_geometry<2>("set Type = gmsh\n"); }),
            "Geometry / Gmsh / Mesh file: mesh file '' not found");

  const std::string no_names = data_dir() + "rectangle_2x1_no_names.msh";
  EXPECT_EQ(input_error_of([&] { make_geometry<2>(gmsh(no_names)); }),
            "Geometry / Gmsh / Mesh file: mesh file '" + no_names +
              "' names no boundary: give every boundary a physical group "
              "with a name, of dimension 1");

  // A side of the rectangle in no physical group.
  const std::string open_side = data_dir() + "rectangle_2x1_open_side.msh";
  EXPECT_EQ(input_error_of([&] {
              const auto               g = make_geometry<2>(gmsh(open_side));
              dealii::Triangulation<2> tria;
              g.create_triangulation(tria);
            }),
            "Geometry / Gmsh / Mesh file: mesh file '" + open_side +
              "' has boundary faces in no physical group");

  // A 2D file read as a 3D mesh.
  EXPECT_NE(input_error_of([&] {
              const auto g =
                make_geometry<3>(gmsh(data_dir() + "rectangle_2x1_v22.msh"));
              dealii::Triangulation<3> tria;
              g.create_triangulation(tria);
            }).find("Geometry / Gmsh / Mesh file: mesh file"),
            std::string::npos);

  const auto rectangle = make_geometry<2>("set Type = rectangle\n");
  EXPECT_EQ(input_error_of([&] { rectangle.boundary_id("front"); }),
            "no boundary named 'front' (this geometry has: bottom, left, "
            "right, top)");
  EXPECT_EQ(input_error_of([] { make_geometry<2>("set Type = box\n"); }),
            "Geometry: type 'box' needs Dimension = 3 (parameter Type)");
  EXPECT_EQ(input_error_of([] { make_geometry<3>("set Type = half disc\n"); }),
            "Geometry: type 'half disc' needs Dimension = 2 (parameter Type)");
  EXPECT_EQ(input_error_of([] {
              make_geometry<2>(
                "set Type = half annulus\n" +
                shape("Half annulus",
                      "set Inner radius = 2\nset Outer radius = 1\n"));
            }),
            "Geometry / Half annulus: need 0 < Inner radius < Outer radius");
  EXPECT_EQ(input_error_of([] {
              make_geometry<2>("set Type = rectangle\n" +
                               shape("Rectangle",
                                     "set Lower corner = 0, 1\n"
                                     "set Upper corner = 1, 1\n"));
            }),
            "Geometry / Rectangle / Upper corner: must exceed Lower corner in "
            "every coordinate");
  EXPECT_EQ(input_error_of([] {
              make_geometry<2>("set Type = rectangle\n" +
                               shape("Rectangle",
                                     "set Grading centre = 2, 0\n"
                                     "set Grading exponents = 2, 1\n"));
            }),
            "Geometry / Rectangle / Grading centre: must lie between Lower "
            "corner and Upper corner in every graded direction");
  EXPECT_EQ(input_error_of([] {
              make_geometry<2>("set Type = quarter disc\n" +
                               shape("Quarter disc", "set Radius = 0\n"));
            }),
            "Geometry / Quarter disc / Radius: must be positive");
  EXPECT_EQ(input_error_of([] {
              make_geometry<3>("set Type = half cylinder\n" +
                               shape("Half cylinder",
                                     "set Contact refinements = 1\n"
                                     "set Contact refinement radius = 0\n"));
            }),
            "Geometry / Half cylinder / Contact refinement radius: must be "
            "positive when Contact refinements > 0");
}



// The entries of one shape live in its own subsection only: another shape's
// entry is unknown there, and the subsections of the other dimension are
// not declared.
TEST(Geometry, EachShapeHasItsOwnEntries)
{
  EXPECT_ANY_THROW(make_geometry<2>(
    "set Type = half disc\n" + shape("Half disc", "set Inner radius = 1\n")));
  EXPECT_ANY_THROW(make_geometry<2>("set Type = half disc\nset Radius = 1\n"));
  EXPECT_ANY_THROW(make_geometry<2>(
    "set Type = rectangle\n" + shape("Box", "set Upper corner = 1, 1, 1\n")));
  EXPECT_ANY_THROW(make_geometry<2>("set Type = rectangle\n" +
                                    shape("Rectangle", "set Length = 1\n")));
}
