// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Tests of the candidate contact surface: grouping of faces into contact
// elements, frames, pairing of two bodies.

#include <dpana/base/exceptions.h>
#include <dpana/contact_surface/parameters.h>
#include <dpana/scene/scene.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "scene_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dpana;
  using dpana::test::brick_body;

  // The box [0, 8] x [0, 2] x [0, 4] of 4 x 1 x 2 cells, fixed on its top:
  // Body 1 of the 3D surface tests.
  const std::string box_body = brick_body("Body 1",
                                          "box",
                                          "0, 0, 0",
                                          "8, 2, 4",
                                          "4, 1, 2",
                                          "    set Fixed = top: x, y, z\n",
                                          "");

  std::string
  box_prm(const std::string &faces_per_element)
  {
    return "set Dimension = 3\n" + box_body +
           "subsection Contact\n"
           "  set Boundary 1 = bottom\n"
           "  set Faces per contact element = " +
           faces_per_element +
           "\n"
           "end\n";
  }

  using dpana::test::make_scene;

  // The gap integrals and areas of the elements of a scene paired with a
  // flat second body (`two`) must equal those of the same first body on
  // the rigid plane (`one`), to round-off relative to the size L of the
  // candidate region; some gap must be positive.
  template <int dim>
  void
  expect_same_gaps(const scene::Scene<dim> &one,
                   const scene::Scene<dim> &two,
                   const double             L)
  {
    const auto &rigid = one.surface(0), &paired = two.surface(0);
    ASSERT_EQ(rigid.n_elements(), paired.n_elements());
    double largest = 0;
    for (unsigned int j = 0; j < rigid.n_elements(); ++j)
      {
        largest = std::max(largest, rigid.element(j).gap_integral);
        EXPECT_NEAR(paired.element(j).gap_integral,
                    rigid.element(j).gap_integral,
                    1e-12 * std::pow(L, dim))
          << "element " << j;
        EXPECT_NEAR(two.surface(1).element(j).area,
                    rigid.element(j).area,
                    1e-12 * std::pow(L, dim - 1));
      }
    EXPECT_GT(largest, 0.0);
  }
} // namespace



// A structured 3D base of 4 x 2 quadrilaterals of 2 x 2 mm, each split in
// two triangles: the default grouping gives 2 elements of 2 x 2
// quadrilaterals (8 triangles, 16 mm^2 each), with the outward normal
// (0, -1, 0) and a right-handed frame.
TEST(ContactSurface, StructuredPatchesOfEightTriangles)
{
  auto s = make_scene<3>(box_prm("0"));
  s->assemble();
  s->build_contact_surface();
  const auto &surface = s->surface(0);
  ASSERT_EQ(surface.get_faces().size(), 16u);
  ASSERT_EQ(surface.n_elements(), 2u);
  for (const auto &e : surface.get_elements())
    {
      EXPECT_EQ(e.faces.size(), 8u);
      EXPECT_NEAR(e.area, 16.0, 1e-12);
      EXPECT_NEAR(e.normal[1], -1.0, 1e-12);
      EXPECT_NEAR(e.s_max - e.s_min, 4.0, 1e-12);
      EXPECT_NEAR(e.t_max - e.t_min, 4.0, 1e-12);
      EXPECT_NEAR(dealii::cross_product_3d(e.normal, e.tangents[0]) *
                    e.tangents[1],
                  1.0,
                  1e-12);
    }
}



// The vertices of the candidate faces: the 5 x 3 of the base. One triangle
// per element gives 16 elements, more than the vertices (Scene warns), two
// give 8.
TEST(ContactSurface, VerticesAgainstElements)
{
  for (const auto &[faces, elements] :
       std::vector<std::pair<std::string, unsigned int>>{{"1", 16u}, {"2", 8u}})
    {
      auto s = make_scene<3>(box_prm(faces));
      s->assemble();
      s->build_contact_surface();
      EXPECT_EQ(s->surface(0).n_vertices(), 15u);
      EXPECT_EQ(s->surface(0).n_elements(), elements);
    }
}



// A group size that is no lattice patch (6) falls back to the greedy
// agglomeration: every face in exactly one element, every element of 3 to
// 12 faces (groups that stop below 6 / 2 = 3 faces join a neighbour, which
// may take in more than one of them, here one of 6 + 2 + 1), every element
// connected (its faces linked by shared edges).
TEST(ContactSurface, GreedyAgglomerationCoversTheSurface)
{
  auto s = make_scene<3>(box_prm("6"));
  s->assemble();
  s->build_contact_surface();
  const auto                 &surface = s->surface(0);
  const auto                 &faces   = surface.get_faces();
  std::multiset<unsigned int> used;
  double                      area = 0;
  for (const auto &e : surface.get_elements())
    {
      EXPECT_GE(e.faces.size(), 3u);
      EXPECT_LE(e.faces.size(), 12u);
      used.insert(e.faces.begin(), e.faces.end());
      area += e.area;
      // Connectivity by a flood fill over shared edges.
      std::set<unsigned int> reached{e.faces[0]};
      bool                   grown = true;
      while (grown)
        {
          grown = false;
          for (const unsigned int f : e.faces)
            if (!reached.count(f))
              for (const unsigned int g : reached)
                {
                  unsigned int shared = 0;
                  for (const unsigned int u : faces[f].vertices)
                    for (const unsigned int v : faces[g].vertices)
                      shared += (u == v);
                  if (shared >= 2)
                    {
                      reached.insert(f);
                      grown = true;
                      break;
                    }
                }
        }
      EXPECT_EQ(reached.size(), e.faces.size());
    }
  EXPECT_EQ(used.size(), faces.size());
  for (unsigned int f = 0; f < faces.size(); ++f)
    EXPECT_EQ(used.count(f), 1u);
  EXPECT_NEAR(area, 32.0, 1e-12);
}



namespace
{
  // The frictionless contact of the bottom of Body 1 with the top of Body 2
  // along @p direction, on the contact elements @p elements.
  std::string
  stacked_contact(const std::string &direction, const std::string &elements)
  {
    return "subsection Contact\n"
           "  set Boundary 1 = bottom\n"
           "  set Boundary 2 = top\n"
           "  set Contact direction = " +
           direction +
           "\n"
           "  set Friction coefficient = 0\n"
           "  set Contact elements = " +
           elements +
           "\n"
           "end\n";
  }

  // Two stacked rectangles in 2D: the block [0, 40] x [0, 40] with n1 x n1
  // cells on the foundation [0, 40] x [-40, 0] with n2 x n2 cells (n1 != n2:
  // non-matching interface), 50 MPa on the top of the block, 100 MPa on the
  // right sides of both, symmetry on the left sides, the base of the
  // foundation fixed vertically, frictionless.
  std::string
  stacked_prm(const unsigned int n1,
              const unsigned int n2,
              const std::string &elements = "faces")
  {
    return "set Dimension = 2\n"
           "set Number of bodies = 2\n" +
           brick_body("Body 1",
                      "rectangle",
                      "0, 0",
                      "40, 40",
                      std::to_string(n1) + ", " + std::to_string(n1),
                      "    set Symmetry = left\n",
                      "    set Pressure = top: 50; right: 100\n") +
           brick_body("Body 2",
                      "rectangle",
                      "0, -40",
                      "40, 0",
                      std::to_string(n2) + ", " + std::to_string(n2),
                      "    set Symmetry = left\n    set Fixed = bottom: y\n",
                      "    set Pressure = right: 100\n") +
           stacked_contact("0, -1", elements);
  }
} // namespace



// Patch test of the 2D mortar projection. The stacked blocks have the
// exact solution of the receding block (the reference formulation,
// section 4.2.1) in both bodies: the uniform stress sigma_xx = -100, sigma_yy =
// -50 MPa, with a linear displacement that P1 elements represent exactly, and a
// uniform contact pressure of 50 MPa. The interface discretisations do not
// match (16 edges against 13), yet the projection integrates the shape
// functions of both sides exactly, so every contact element must carry N = -50
// MPa, T = 0 up to round-off, and the forces on the two sides must balance: the
// columns of V1 and V2 add up to the element's projected length along +n and
// -n.
TEST(ContactSurface, NonMatchingPatchTest2D)
{
  auto s = make_scene<2>(stacked_prm(16, 13), 2);
  s->run(false);
  ASSERT_TRUE(s->summary().result.converged);
  ASSERT_EQ(s->summary().n_elements, 8u);
  for (unsigned int j = 0; j < s->summary().n_elements; ++j)
    {
      EXPECT_NEAR(s->normal_traction(j), -50.0, 50.0 * 1e-9) << j;
      EXPECT_NEAR(s->tangential_traction(j), 0.0, 50.0 * 1e-9) << j;
      EXPECT_NEAR(s->surface(0).element(j).mean_gap(), 0.0, 1e-12);
    }
  // The frames are n = (0, -1), tau = (1, 0) on body 1 and their negatives
  // on body 2; each column has non-zeros in one component only, so its sum
  // is the resultant of the unit traction: +-5 mm (2 edges of 2.5 mm).
  for (unsigned int b = 0; b < 2; ++b)
    {
      const auto &V = s->condenser(b).coupling();
      for (unsigned int j = 0; j < s->surface(b).n_elements(); ++j)
        for (unsigned int k = 0; k < 2; ++k)
          {
            const double sign = (b == 0) == (k == 0) ? -1.0 : 1.0;
            EXPECT_NEAR(Eigen::VectorXd(V.col(2 * j + k)).sum(),
                        sign * 5.0,
                        1e-12)
              << "body " << b << " element " << j << " component " << k;
          }
    }
}



namespace
{
  // The quarter disc of hertz_prm() (radius 40, touching the plane y = 0
  // at (0, 0), 2 contact refinements within 10 mm), its candidate surface
  // within 12 mm of the contact point: alone on the rigid plane (first),
  // and on the top of a rectangle below the plane (second), both with
  // their contact surfaces built (the tests of the geometry solve
  // nothing).
  std::pair<std::unique_ptr<dpana::scene::Scene<2>>,
            std::unique_ptr<dpana::scene::Scene<2>>>
  arc_on_plane(const std::string &elements)
  {
    const std::string text = dpana::test::hertz_prm(
      2, 12, 0, "", "top", 10, "  set Contact elements = " + elements + "\n");
    auto one = make_scene<2>(text, 1);
    one->assemble();
    one->build_contact_surface();
    auto two = make_scene<2>("set Number of bodies = 2\n" + text +
                               brick_body("Body 2",
                                          "rectangle",
                                          "0, -20",
                                          "30, 0",
                                          "7, 5",
                                          "    set Fixed = bottom: x, y\n",
                                          ""),
                             2);
    two->assemble();
    two->build_contact_surface();
    return {std::move(one), std::move(two)};
  }
} // namespace



// The gap of a curved body paired with a flat one: a quarter disc of
// radius 40 touching the top y = 0 of a rectangle at (0, 0). The gap
// integrals from the 2D projection (the second body's faces cut at the
// projections of the arc's vertices) must equal those of the rigid plane
// y = 0 computed face by face (ContactSurface::set_plane_gap()), which is
// the same integral by another route.
TEST(ContactSurface, ProjectedGapOfArcOnPlane)
{
  const auto [one, two] = arc_on_plane("faces");
  expect_same_gaps(*one, *two, 12);

  // The positions s along the surface are the projections x of the points
  // on the plane normal to the contact direction (the x axis), not arc
  // lengths R asin(x / R), which exceed them by 1 % at x = 0.25 R: the outer
  // edge of every element is the largest |x| of its vertices, and that of
  // the surface the largest |x| of all.
  const auto &surface = one->surface(0);
  double      x_max = 0, s_max = 0;
  for (const auto &e : surface.get_elements())
    {
      double x_e = 0;
      for (const unsigned int f : e.faces)
        for (const auto &x : surface.get_faces()[f].points)
          x_e = std::max(x_e, std::abs(x[0]));
      EXPECT_NEAR(std::max(std::abs(e.s_min), std::abs(e.s_max)), x_e, 1e-12);
      x_max = std::max(x_max, x_e);
      s_max = std::max({s_max, std::abs(e.s_min), std::abs(e.s_max)});
    }
  EXPECT_NEAR(s_max, x_max, 1e-12);
  EXPECT_GT(40 * std::asin(x_max / 40) - x_max, 1e-3 * x_max);
}



// Patches around the vertices (Contact elements = vertices) on the arc:
// one element per vertex of the candidate edges, made of the halves of the
// edges next to it, its points at their midpoints with the barycentric
// coordinates 3/4 and 1/4 and weights half the projected lengths of the
// edges; its extent from the midpoint of one edge to that of the other.
// The elements cover the surface as the groups of faces do (the same total
// projected length), and the projection onto the rectangle gives the gaps
// of the rigid plane, as for the groups of faces.
TEST(ContactSurface, VertexPatchesOfTheArc)
{
  const auto [one, two] = arc_on_plane("vertices");
  expect_same_gaps(*one, *two, 12);

  const auto &surface = one->surface(0);
  const auto &faces   = surface.get_faces();
  ASSERT_EQ(surface.n_elements(), surface.n_vertices());
  const dealii::Tensor<1, 2> n({0., -1.});
  double                     length = 0, patches = 0;
  for (const auto &F : faces)
    length += F.area * (F.normal * n);
  for (const auto &e : surface.get_elements())
    {
      ASSERT_GE(e.points.size(), 1u);
      ASSERT_LE(e.points.size(), 2u);
      double s_lo = std::numeric_limits<double>::max(), s_hi = -s_lo;
      for (const auto &p : e.points)
        {
          const auto &F = faces[p.face];
          EXPECT_NEAR(std::max(p.barycentric[0], p.barycentric[1]), 0.75, 0);
          EXPECT_NEAR(p.barycentric[0] + p.barycentric[1], 1.0, 1e-15);
          EXPECT_NEAR(p.weight, 0.5 * F.area * (F.normal * n), 1e-14);
          // The vertex of the patch and the midpoint of the edge.
          const unsigned int v = p.barycentric[0] > 0.5 ? 0 : 1;
          for (const double x :
               {F.points[v][0], 0.5 * (F.points[0][0] + F.points[1][0])})
            {
              s_lo = std::min(s_lo, x);
              s_hi = std::max(s_hi, x);
            }
          patches += p.weight;
        }
      EXPECT_NEAR(e.s_min, s_lo, 1e-12);
      EXPECT_NEAR(e.s_max, s_hi, 1e-12);
    }
  EXPECT_NEAR(patches, length, 1e-12 * length);

  // The elements are numbered along the surface.
  for (unsigned int j = 1; j < surface.n_elements(); ++j)
    EXPECT_LT(surface.element(j - 1).s, surface.element(j).s);
}



// The patch test of the stacked blocks with patches around the vertices of
// the block's 16 edges: 17 elements, every one at N = -50 MPa, T = 0, and
// the columns of V adding up to the projected lengths of the patches
// (1.25 mm at the two ends, 2.5 mm inside) on both sides, so that the
// forces balance although the foundation's 13 edges do not match.
TEST(ContactSurface, VertexPatchesPassThePatchTest2D)
{
  auto s = make_scene<2>(stacked_prm(16, 13, "vertices"), 2);
  s->run(false);
  ASSERT_TRUE(s->summary().result.converged);
  const unsigned int n = s->summary().n_elements;
  ASSERT_EQ(n, 17u);
  for (unsigned int j = 0; j < n; ++j)
    {
      EXPECT_NEAR(s->normal_traction(j), -50.0, 50.0 * 1e-9) << j;
      EXPECT_NEAR(s->tangential_traction(j), 0.0, 50.0 * 1e-9) << j;
    }
  for (unsigned int b = 0; b < 2; ++b)
    {
      const auto &V = s->condenser(b).coupling();
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int k = 0; k < 2; ++k)
          {
            const double sign   = (b == 0) == (k == 0) ? -1.0 : 1.0;
            const double length = (j == 0 || j + 1 == n) ? 1.25 : 2.5;
            EXPECT_NEAR(Eigen::VectorXd(V.col(2 * j + k)).sum(),
                        sign * length,
                        1e-12)
              << "body " << b << " element " << j << " component " << k;
          }
    }
}



// Why the patches exist: on coarse meshes they are more accurate per
// degree of freedom than the groups of two edges. The D-shaped body of
// prm/hertz_rigid_mu0_d_shaped.prm (quarter disc R = 40 pressed by 100 kN/mm
// at its centre onto the rigid plane) on its mesh of 0 global and 5
// contact refinements (1638 unknowns, 33 candidate edges). Reference: the
// converged values of that family in benchmarks/convergence (dpana's
// extrapolation from groups of faces up to 1 125 986 unknowns: a_m =
// 8.343074 mm, N_max = 15222.32 MPa; GetFEM's nodal contact conditions
// converge to 8.341838 mm and 15228.14 MPa). Measured on this mesh: the
// patches a_m -0.03 %, N_max +0.05 %; the groups of two edges -0.59 % and
// -0.34 %. The bands: 0.1 % and 0.2 % for the patches, and the groups
// outside 0.4 % in a_m.
TEST(ContactSurface, VertexPatchesOnACoarseHertzMesh)
{
  const auto error = [](const std::string &elements) {
    std::string text = dpana::test::hertz_prm(
      5, 15, 0, "", "top", 14, "  set Contact elements = " + elements + "\n");
    const std::string global = "set Global refinements = 2";
    text.replace(text.find(global),
                 global.size(),
                 "set Global refinements = 0");
    auto scene = make_scene<2>(text);
    scene->run(false);
    EXPECT_TRUE(scene->summary().result.converged);
    EXPECT_EQ(scene->body(0).dof_handler().n_dofs(), 1638u);
    return std::make_pair(scene->summary().estimates.moment_half_width /
                              8.343074 -
                            1,
                          scene->summary().max_pressure / 15222.32 - 1);
  };
  const auto [a_m, N_max] = error("vertices");
  EXPECT_LT(std::abs(a_m), 1e-3) << a_m;
  EXPECT_LT(std::abs(N_max), 2e-3) << N_max;
  EXPECT_GT(std::abs(error("faces").first), 4e-3);
}



// With friction (mu = 1), the patch of the vertex on the axis of the half
// model: its tangential displacement is held by the symmetry condition, so
// in the mirrored whole model it is the half of a patch across the axis,
// whose constant T vanishes (T is odd in s). Its tangential traction is
// held at zero, it sticks, and the tangential tractions of the next
// patches grow from the axis as the stick zone's should (Spence's
// profile, odd and smooth). Without the hold the axis patch acts on the
// body only through its neighbour's vertex; measured on the cylinder of
// tests/prm/contact_hertz_rigid_vertices.prm, T = mu |N| on it and -1987
// MPa on its neighbour.
TEST(ContactSurface, VertexPatchOnTheAxisCarriesNoTangentialTraction)
{
  auto scene = make_scene<2>(dpana::test::hertz_prm(
    3, 15, 1, "", "top", 14, "  set Contact elements = vertices\n"));
  scene->run(false);
  ASSERT_TRUE(scene->summary().result.converged);
  const auto &result = scene->summary().result;
  ASSERT_EQ(scene->surface(0).element(0).s_min, 0.0);
  EXPECT_EQ(scene->tangential_traction(0), 0.0);
  EXPECT_EQ(result.status[0], contact::ContactStatus::stick);
  double previous = 0;
  for (unsigned int j = 1; j <= 3; ++j)
    {
      EXPECT_EQ(result.status[j], contact::ContactStatus::stick) << j;
      EXPECT_GT(scene->tangential_traction(j), previous) << j;
      previous = scene->tangential_traction(j);
    }

  // The same cylinder on the floating foundation, without a contact
  // direction: each element has its own normal, the axis patch's tangent
  // is tilted by half the angle of its edge, and the foundation's rigid
  // motion along y has a component along it. The patch is still held.
  std::string text =
    dpana::test::hertz_prm(3,
                           15,
                           1,
                           dpana::test::floating_foundation(),
                           "top",
                           14,
                           "  set Contact elements = vertices\n");
  const std::string entry = "  set Contact direction = 0, -1\n";
  text.erase(text.find(entry), entry.size());
  auto pair = make_scene<2>(text, 2);
  pair->run(false);
  ASSERT_TRUE(pair->summary().result.converged);
  EXPECT_GT(pair->surface(0).element(0).tangents[0][1] *
              pair->surface(0).element(0).tangents[0][1],
            1e-6);
  EXPECT_LT(pair->normal_traction(0), 0.0);
  EXPECT_EQ(pair->tangential_traction(0), 0.0);
  EXPECT_EQ(pair->summary().result.status[0], contact::ContactStatus::stick);
}



namespace
{
  // The stacked boxes of the 3D patch tests below, with the contact
  // elements @p elements (faces or vertices).
  std::string
  stacked_boxes_prm(const std::string &elements)
  {
    return "set Dimension = 3\n"
           "set Number of bodies = 2\n" +
           brick_body("Body 1",
                      "box",
                      "0, 0, 0",
                      "8, 4, 8",
                      "4, 2, 4",
                      "    set Symmetry = left; front\n",
                      "    set Pressure = top: 50; right: 100; back: 100\n") +
           brick_body(
             "Body 2",
             "box",
             "0, -4, 0",
             "8, 0, 8",
             "3, 2, 3",
             "    set Symmetry = left; front\n    set Fixed = bottom: y\n",
             "    set Pressure = right: 100; back: 100\n") +
           stacked_contact("0, -1, 0", elements);
  }
} // namespace



// Patch test of the projection in 3D: the stacked boxes [0, 8] x [0, 4] x
// [0, 8] (4 x 2 x 4 cells) on [0, 8] x [-4, 0] x [0, 8] (3 x 2 x 3 cells:
// the interface triangles do not match), symmetry on x = 0 and z = 0,
// 50 MPa on the top, 100 MPa on the sides x = 8 and z = 8 of both, the
// base of the foundation held vertically. The uniform stress sigma_xx =
// sigma_zz = -100, sigma_yy = -50 MPa is the exact solution in both bodies
// (linear displacement, exact for P1), so every element carries N = -50,
// T = 0 up to round-off, and each column of V adds up to +-16 mm^2, the
// element's area (2 x 2 cells of 2 x 2 mm).
TEST(ContactSurface, NonMatchingPatchTest3D)
{
  const std::string text = stacked_boxes_prm("faces");
  auto              s    = make_scene<3>(text, 2);
  s->run(false);
  ASSERT_TRUE(s->summary().result.converged);
  ASSERT_EQ(s->summary().n_elements, 4u);
  for (unsigned int j = 0; j < s->summary().n_elements; ++j)
    {
      EXPECT_NEAR(s->normal_traction(j), -50.0, 50.0 * 1e-9) << j;
      for (unsigned int k = 0; k < 2; ++k)
        EXPECT_NEAR(s->tangential_traction(j, k), 0.0, 50.0 * 1e-9) << j;
      EXPECT_NEAR(s->surface(0).element(j).mean_gap(), 0.0, 1e-12);
    }
  for (unsigned int b = 0; b < 2; ++b)
    {
      const auto &V = s->condenser(b).coupling();
      for (unsigned int j = 0; j < s->surface(b).n_elements(); ++j)
        {
          const auto  &e = s->surface(b).element(j);
          const double sum =
            Eigen::VectorXd(V.col(3 * j)).sum(); // unit traction along n
          EXPECT_NEAR(sum,
                      16.0 * (e.normal[0] + e.normal[1] + e.normal[2]),
                      1e-12)
            << "body " << b << " element " << j;
        }
    }
}



// The same patch test with patches around the vertices: one element per
// vertex of the 4 x 4 cells of the base (25), each at N = -50, T = 0, and
// each column of V adding up to +-the element's area on both sides although
// the foundation's triangles do not match. That area is a third of the
// areas of the element's triangles (the median dual cell of its vertex),
// and the areas add up to the base's 64 mm^2. The patches
// of the vertices on the symmetry planes hold their tangential traction
// across the plane, which the exact solution has zero anyway.
TEST(ContactSurface, VertexPatchesPassThePatchTest3D)
{
  auto s = make_scene<3>(stacked_boxes_prm("vertices"), 2);
  s->run(false);
  ASSERT_TRUE(s->summary().result.converged);
  ASSERT_EQ(s->summary().n_elements, 25u);
  double total = 0;
  for (unsigned int j = 0; j < s->summary().n_elements; ++j)
    {
      EXPECT_NEAR(s->normal_traction(j), -50.0, 50.0 * 1e-9) << j;
      for (unsigned int k = 0; k < 2; ++k)
        EXPECT_NEAR(s->tangential_traction(j, k), 0.0, 50.0 * 1e-9) << j;
      const auto &e     = s->surface(0).element(j);
      double      third = 0;
      for (const unsigned int f : e.faces)
        third += s->surface(0).get_faces()[f].area / 3;
      EXPECT_NEAR(e.area, third, 1e-12) << j;
      total += e.area;
      for (unsigned int b = 0; b < 2; ++b)
        {
          const auto  &V   = s->condenser(b).coupling();
          const double sum = Eigen::VectorXd(V.col(3 * j)).sum();
          EXPECT_NEAR(sum, b == 0 ? -e.area : e.area, 1e-12)
            << "body " << b << " element " << j;
        }
    }
  EXPECT_NEAR(total, 64.0, 1e-12);
}



// The 3D version of ProjectedGapOfArcOnPlane: a half cylinder of radius 40
// and length 8 on the top y = 0 of a box meshed independently (7 x 3 cells
// on its top). The gaps from the projection (the arc's triangles clipped by
// the box's) must equal those of the rigid plane y = 0 computed face by
// face, which checks the barycentric coordinates on the curved side.
TEST(ContactSurface, ProjectedGapOfCylinderOnPlane3D)
{
  const std::string cylinder = "subsection Body 1\n"
                               "  subsection Geometry\n"
                               "    set Type = half cylinder\n"
                               "    set Global refinements = 1\n"
                               "    subsection Half cylinder\n"
                               "      set Radius = 40\n"
                               "      set Centre = 0, 40, 0\n"
                               "      set Length = 8\n"
                               "      set Axial subdivisions = 2\n"
                               "      set Contact refinements = 1\n"
                               "      set Contact refinement radius = 10\n"
                               "    end\n"
                               "  end\n"
                               "  subsection Boundary conditions\n"
                               "    set Fixed = top: x, y, z\n"
                               "  end\n"
                               "end\n";
  const std::string contact  = "subsection Contact\n"
                               "  set Boundary 1 = curved\n"
                               "  set Boundary 2 = top\n"
                               "  set Candidate centre = 0, 0, 4\n"
                               "  set Candidate half width = 12\n"
                               "  set Contact direction = 0, -1, 0\n"
                               "end\n";
  auto one = make_scene<3>("set Dimension = 3\n" + cylinder + contact, 1);
  one->assemble();
  one->build_contact_surface();
  auto two =
    make_scene<3>("set Dimension = 3\nset Number of bodies = 2\n" + cylinder +
                    brick_body("Body 2",
                               "box",
                               "-30, -10, 0",
                               "30, 0, 8",
                               "7, 2, 3",
                               "    set Fixed = bottom: x, y, z\n",
                               "") +
                    contact,
                  2);
  two->assemble();
  two->build_contact_surface();
  expect_same_gaps(*one, *two, 12);
}



// The candidate surface of the first body must lie over the second body:
// a box base of 8 x 4 mm on a foundation top of 8 x 3 mm is refused with
// one line.
TEST(ContactSurface, UncoveredSurfaceIsRefusedIn3D)
{
  const std::string text = "set Dimension = 3\n"
                           "set Number of bodies = 2\n" +
                           box_body +
                           brick_body("Body 2",
                                      "box",
                                      "0, -2, 0",
                                      "8, 0, 3",
                                      "3, 1, 2",
                                      "    set Fixed = bottom: x, y, z\n",
                                      "") +
                           "subsection Contact\n"
                           "  set Contact direction = 0, -1, 0\n"
                           "end\n";
  auto s = make_scene<3>(text, 2);
  s->assemble();
  try
    {
      s->build_contact_surface();
      FAIL() << "an uncovered candidate surface was accepted";
    }
  catch (const InputError &e)
    {
      const std::string what = e.what();
      EXPECT_NE(what.find("is not covered by"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}



namespace
{
  // Parameters of the contact surface read from the entries @p entries of
  // a Contact subsection where only the contact surface declared its own.
  template <int dim>
  contact_surface::Parameters<dim>
  parse_surface_parameters(const std::string &entries)
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection("Contact");
    contact_surface::Parameters<dim>::declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string("subsection Contact\n" + entries + "end\n");
    prm.enter_subsection("Contact");
    contact_surface::Parameters<dim> parameters;
    parameters.parse_parameters(prm);
    prm.leave_subsection();
    return parameters;
  }

  // The message of the error that parsing @p entries throws, or "".
  template <int dim>
  std::string
  surface_parameter_error(const std::string &entries)
  {
    try
      {
        parse_surface_parameters<dim>(entries);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace



// The contact surface declares and parses its own entries of the Contact
// subsection; an empty contact direction or obstacle point means "not
// given", and the options of the second body's surface carry the negated
// direction.
TEST(ContactSurface, ParametersDeclaredAndParsed)
{
  const auto defaults = parse_surface_parameters<3>("");
  EXPECT_EQ(defaults.boundary[0], "bottom");
  EXPECT_EQ(defaults.boundary[1], "top");
  EXPECT_EQ(defaults.region_centre, dealii::Point<3>());
  EXPECT_EQ(defaults.region_half_width, 0.0);
  EXPECT_EQ(defaults.faces_per_element, 0u);
  EXPECT_EQ(defaults.shape, contact_surface::ElementShape::face_groups);
  EXPECT_EQ(defaults.direction.norm(), 0.0);
  EXPECT_FALSE(defaults.obstacle_point_given);

  const auto p =
    parse_surface_parameters<2>("set Boundary 1 = curved\n"
                                "set Boundary 2 = floor\n"
                                "set Candidate centre = 1, 2\n"
                                "set Candidate half width = 15\n"
                                "set Faces per contact element = 4\n"
                                "set Contact direction = 0, -2\n"
                                "set Obstacle point = 0, -0.5\n");
  EXPECT_EQ(p.region_centre, dealii::Point<2>(1, 2));
  EXPECT_EQ(p.region_half_width, 15.0);
  EXPECT_EQ(p.faces_per_element, 4u);
  EXPECT_EQ(p.direction, dealii::Point<2>(0, -2));
  EXPECT_TRUE(p.obstacle_point_given);
  EXPECT_EQ(p.obstacle_point, dealii::Point<2>(0, -0.5));

  const auto first = p.surface_options(0, "Body 1", {{"curved", 3}});
  EXPECT_EQ(first.boundary, "curved");
  EXPECT_EQ(first.boundary_id, 3);
  EXPECT_EQ(first.body, "Body 1");
  EXPECT_EQ(first.region_centre, p.region_centre);
  EXPECT_EQ(first.region_half_width, 15.0);
  EXPECT_EQ(first.faces_per_element, 4u);
  EXPECT_EQ(first.shape, contact_surface::ElementShape::face_groups);
  EXPECT_EQ(parse_surface_parameters<2>("set Contact elements = vertices\n")
              .surface_options(0, "Body 1", {{"bottom", 0}})
              .shape,
            contact_surface::ElementShape::vertex_patches);
  EXPECT_EQ(first.direction, p.direction);
  const auto second =
    p.surface_options(1, "Body 2", {{"floor", 5}, {"left", 1}});
  EXPECT_EQ(second.boundary_id, 5);
  EXPECT_EQ(second.direction, -p.direction);
  try
    {
      p.surface_options(1, "Body 2", {{"bottom", 0}, {"left", 1}});
      FAIL() << "an unknown boundary was accepted";
    }
  catch (const InputError &e)
    {
      EXPECT_EQ(std::string(e.what()),
                "Contact / Boundary 2: Body 2 has no boundary named 'floor' "
                "(it has: bottom, left)");
    }
}



// Bad points and vectors are refused with one line that names the entry by
// its full path.
TEST(ContactSurface, ParameterErrorsNameTheEntry)
{
  EXPECT_EQ(surface_parameter_error<2>("set Contact direction = 0, 0\n"),
            "Contact / Contact direction: must not be the zero vector "
            "(leave it empty for the element normals)");
  EXPECT_EQ(surface_parameter_error<3>("set Contact elements = vertices\n"),
            "");
  EXPECT_EQ(surface_parameter_error<2>("set Contact elements = vertices\n"
                                       "set Faces per contact element = 3\n"),
            "Contact / Faces per contact element = 3: must be 0 with Contact "
            "elements = vertices (each element is the patch around one "
            "vertex)");
  EXPECT_EQ(surface_parameter_error<2>("set Contact elements = vertices\n"),
            "");
  for (const auto &[entry, value] :
       std::vector<std::pair<std::string, std::string>>{
         {"Contact direction", "0, nan"},
         {"Contact direction", "0, -1, 0"},
         {"Candidate centre", "inf, 0"},
         {"Candidate centre", ""},
         {"Obstacle point", "1"}})
    {
      const std::string what =
        surface_parameter_error<2>("set " + entry + " = " + value + "\n");
      EXPECT_EQ(what.rfind("Contact / " + entry + ": ", 0), 0u)
        << entry << " = " << value << ": " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}
