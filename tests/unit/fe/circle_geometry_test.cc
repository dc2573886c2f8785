// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Tests of the circular body (geometry types `disc` and `right half disc`):
// cell counts, boundary names, areas and boundary lengths against the exact
// values of the inscribed polygon whose vertices the refinement spreads
// evenly on the circle (n chords over an angle alpha: length
// 2 n R sin(alpha / 2n), area n R^2 sin(alpha / n) / 2), the contact and
// load patch refinements, and the errors for bad input. Measures as in
// geometry_test.cc (exact for the affine cells up to rounding).

#include <dpana/base/exceptions.h>

#include <deal.II/grid/tria.h>

#include <cmath>
#include <set>
#include <string>

#include "geometry_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dpana::test;

  const double pi = dealii::numbers::PI;

  // True if some vertex of @p tria lies at @p p.
  bool
  has_vertex(const dealii::Triangulation<2> &tria, const dealii::Point<2> p)
  {
    for (const auto &v : tria.get_vertices())
      if (v.distance(p) < 1e-12 * (1 + p.norm()))
        return true;
    return false;
  }
} // namespace



TEST(CircleGeometry, WholeDiscConvergesToTheCircle)
{
  const double R = 40.;
  for (unsigned int k = 0; k <= 3; ++k)
    {
      const auto geometry = make_geometry<2>(
        "set Type = disc\nset Global refinements = " + std::to_string(k) +
        "\n" + shape("Disc", "set Radius = 40\nset Centre = 0, 40\n"));
      EXPECT_EQ(names_of(geometry), (std::set<std::string>{"curved"}));
      dealii::Triangulation<2> tria;
      geometry.create_triangulation(tria);
      const Measures m = measure(tria);
      // 12 quadrilaterals, 4 triangles each, 4 children per refinement; 8
      // chords of 45 degrees before refinement.
      const unsigned int n = 8 << k;
      EXPECT_EQ(m.n_cells, 48u << (2 * k));
      EXPECT_GT(m.min_jxw, 0.);
      const boundary_id curved = geometry.boundary_id("curved");
      EXPECT_EQ(m.boundary_measure.size(), 1u);
      EXPECT_EQ(m.n_boundary_faces.at(curved), n);
      expect_relative(m.boundary_measure.at(curved),
                      2 * n * R * std::sin(pi / n));
      expect_relative(m.volume, n * R * R * std::sin(2 * pi / n) / 2);
      EXPECT_LT(distance_from_circle(tria, curved, {0, 40}, R), 1e-12 * R);
      // The contact point and the load point are vertices.
      EXPECT_TRUE(has_vertex(tria, {0, 0}));
      EXPECT_TRUE(has_vertex(tria, {0, 2 * R}));
    }
}



TEST(CircleGeometry, RightHalfDisc)
{
  const double R        = 2.;
  const auto   geometry = make_geometry<2>(
    "set Type = right half disc\nset Global refinements = 3\n" +
    shape("Right half disc", "set Radius = 2\nset Centre = 1, 1\n"));
  EXPECT_EQ(names_of(geometry), (std::set<std::string>{"curved", "axis"}));
  dealii::Triangulation<2> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  // 6 quadrilaterals -> 24 triangles, times 4^3; 4 chords of 45 degrees
  // before refinement.
  const unsigned int n = 4 << 3;
  EXPECT_EQ(m.n_cells, 24u * 64);
  EXPECT_GT(m.min_jxw, 0.);
  EXPECT_EQ(m.boundary_measure.size(), 2u);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("axis")), 2 * R);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("curved")),
                  2 * n * R * std::sin(pi / (2 * n)));
  expect_relative(m.volume, n * R * R * std::sin(pi / n) / 2);
  EXPECT_LT(
    distance_from_circle(tria, geometry.boundary_id("curved"), {1, 1}, R),
    1e-12 * R);
  EXPECT_TRUE(has_vertex(tria, {1, 1 - R}));
  EXPECT_TRUE(has_vertex(tria, {1, 1 + R}));
}



TEST(CircleGeometry, ContactAndLoadPatchRefinements)
{
  // R = 40 centred at (0, 40); 2 global refinements, 3 contact refinements
  // within 5 mm of the origin, a load patch of half width 2 mm at (0, 80)
  // refined 3 times.
  const double R        = 40.;
  const double w        = 2.;
  const auto   geometry = make_geometry<2>(
    "set Type = right half disc\nset Global refinements = 2\n" +
    shape("Right half disc",
          "set Radius = 40\nset Centre = 0, 40\nset Contact refinements = 3\n"
            "set Contact refinement radius = 5\nset Load patch half width = 2\n"
            "set Load patch refinements = 3\n"));
  EXPECT_EQ(names_of(geometry),
            (std::set<std::string>{"curved", "axis", "load patch"}));
  dealii::Triangulation<2> tria;
  geometry.create_triangulation(tria);
  const Measures m = measure(tria);
  EXPECT_GT(m.min_jxw, 0.);
  const boundary_id curved = geometry.boundary_id("curved");
  const boundary_id patch  = geometry.boundary_id("load patch");
  // A non-conforming triangle mesh would show interior faces as boundary
  // faces off the circle and an axis longer than 2R.
  EXPECT_LT(distance_from_circle(tria, curved, {0, 40}, R), 1e-12 * R);
  EXPECT_LT(distance_from_circle(tria, patch, {0, 40}, R), 1e-12 * R);
  expect_relative(m.boundary_measure.at(geometry.boundary_id("axis")), 2 * R);

  // Near both points the chords span 45 / 2^(2+3) degrees: the patch
  // faces are those chords whose centres lie within w of the axis.
  const double fine_chord   = 2 * R * std::sin(pi / 4 / 32 / 2);
  double       polygon_area = 0, patch_extent = 0;
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary() &&
        face->boundary_id() != geometry.boundary_id("axis"))
      {
        const double chord = face->vertex(0).distance(face->vertex(1));
        polygon_area += R * R * std::sin(2 * std::asin(chord / (2 * R))) / 2;
        const bool near_contact = face->center().distance({0, 0}) < 5;
        const bool near_load    = face->center().distance({0, 2 * R}) < w;
        if (near_contact || near_load)
          {
            EXPECT_NEAR(chord, fine_chord, 1e-9 * R);
          }
        EXPECT_EQ(face->boundary_id() == patch,
                  face->center()[1] > R && face->center()[0] < w);
        if (face->boundary_id() == patch)
          patch_extent =
            std::max({patch_extent, face->vertex(0)[0], face->vertex(1)[0]});
      }
  expect_relative(m.volume, polygon_area);
  // The patch is w rounded up to whole faces.
  EXPECT_GE(patch_extent, w - fine_chord / 2);
  EXPECT_LE(patch_extent, w + fine_chord / 2);
}



TEST(CircleGeometry, Errors)
{
  const auto message = [](const std::string &entries) {
    try
      {
        make_geometry<2>("set Type = disc\n" + shape("Disc", entries));
      }
    catch (const dpana::InputError &e)
      {
        return std::string(e.what());
      }
    return std::string("no error");
  };
  EXPECT_EQ(message("set Radius = 0\n"),
            "Geometry / Disc / Radius: must be positive");
  EXPECT_EQ(message("set Radius = 1\nset Load patch half width = 1\n"),
            "Geometry / Disc / Load patch half width: must be less than the "
            "Radius");
  EXPECT_EQ(message("set Radius = 1\nset Load patch refinements = 2\n"),
            "Geometry / Disc / Load patch refinements: need a positive Load "
            "patch half width");
  // Without a patch there is no boundary of that name.
  const auto geometry =
    make_geometry<2>("set Type = disc\n" + shape("Disc", "set Radius = 1\n"));
  EXPECT_THROW(geometry.boundary_id("load patch"), dpana::InputError);
}
