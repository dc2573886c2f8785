// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The 3D Hertz contact of a sphere: the formulas against a hand computation,
// the moment estimate of the contact radius against the exact elliptic
// pressure, and the quarter sphere of prm/hertz_sphere_rigid.prm, meshed by
// gmsh from scripts/meshes/sphere.geo, against the formulas.

#include <dpana/base/exceptions.h>
#include <dpana/scene/approach.h>
#include <dpana/scene/references.h>
#include <dpana/scene/scene.h>

#include <deal.II/base/function.h>

#include <deal.II/numerics/vector_tools_interpolate.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "scene_test_tools.h"
#include "sphere_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using dpana::scene::hertz_point_contact;
  using dpana::scene::moment_contact_radius;
  using dpana::scene::PressurePiece;
  using dpana::test::hertz_sphere_values;
  using dpana::test::sphere_mesh;
  using dpana::test::sphere_prm;
} // namespace



// The numbers are chosen so that the hand computation is exact: a sphere of
// R = 10 mm with E* = 150 000 MPa under P = 160 kN has
// a^3 = 3 P R / (4 E*) = 4.8e6 / 6e5 = 8 mm^3, a = 2 mm, p0 = 3 P / (2 pi
// a^2) = 60 000 / pi MPa, delta = a^2 / R = 0.4 mm. Two spheres of 20 mm
// (1/R = 1/20 + 1/20) whose compliances 1/300 000 MPa^-1 add up to
// 1/150 000, and a sphere of 5 mm in a seat of 10 mm (1/R = 1/5 - 1/10),
// have the same R and E*.
TEST(HertzSphere, FormulasAgainstHandComputation)
{
  const double                             pi = M_PI;
  const std::vector<std::array<double, 3>> cases{{{10, 0, 1 / 150000.}},
                                                 {{20, 20, 2 / 300000.}},
                                                 {{5, -10, 1 / 150000.}}};
  for (const auto &[R1, R2, c] : cases)
    {
      const auto H = hertz_point_contact(160000, c, R1, R2);
      EXPECT_NEAR(H.radius, 2.0, 1e-12);
      EXPECT_NEAR(H.max_pressure, 60000 / pi, 1e-9);
      EXPECT_NEAR(H.approach, 0.4, 1e-12);
    }
  // The scene of prm/hertz_sphere_rigid.prm: E = 130 000 MPa, nu = 0.2,
  // R = 40 mm, P = 300 kN: a^3 = 3 * 3e5 * 40 * 0.96 / (4 * 1.3e5)
  // = 66.4615... mm^3.
  const auto H = hertz_point_contact(300000, 0.96 / 130000, 40, 0);
  EXPECT_NEAR(H.radius, std::cbrt(3.456e7 / 5.2e5), 1e-12);
  EXPECT_NEAR(H.radius, 4.050638, 1e-6);
  EXPECT_NEAR(H.max_pressure, 8730.030, 1e-3);
}



// The elliptic pressure p0 sqrt(1 - r^2 / a^2) on n rings of equal width
// over the disc r <= a (and rings beyond it, unloaded): each ring carries
// its exact mean pressure and the exact integral of r^2 over it. The sums
// then differ from the integrals only by the variation of p within a ring,
// O(1/n^(3/2)) at the edge, so a_m recovers a to 1e-3 with 400 rings, and
// the same from a quarter of every ring. Without the factor 5/2 (e.g. the
// factor 2 of a plane strip's estimate squared) the result would be 10 %
// off.
TEST(HertzSphere, MomentRadiusOfTheEllipticPressure)
{
  const double       a = 3.7, p0 = 5000;
  const unsigned int n = 400;
  for (const double fraction : {1.0, 0.25})
    {
      std::vector<PressurePiece> pieces;
      for (unsigned int i = 0; i < n + 40; ++i)
        {
          const double r0 = a * i / n, r1 = a * (i + 1) / n;
          const double area = fraction * M_PI * (r1 * r1 - r0 * r0);
          const double r2 =
            fraction * M_PI * (std::pow(r1, 4) - std::pow(r0, 4)) / 2;
          // int p dA over the ring: 2 pi p0 a^2 / 3 [(1 - u)^(3/2)] from u1
          // to u0, u = r^2 / a^2, clipped at u = 1.
          const auto F = [&](const double r) {
            const double u = std::min(1.0, r * r / (a * a));
            return std::pow(1 - u, 1.5);
          };
          const double force =
            fraction * 2 * M_PI * p0 * a * a / 3 * (F(r0) - F(r1));
          pieces.push_back({area, r2, force / area});
        }
      EXPECT_NEAR(moment_contact_radius(pieces) / a, 1.0, 1e-3);
    }
  EXPECT_EQ(moment_contact_radius({{1.0, 1.0, 0.0}}), 0.0);
}



// The elliptic fit recovers p0 and a from the squared Hertz law sampled
// exactly: pieces whose pressure squared is p0^2 (1 - r^2 / a^2) at their
// mean r^2 (a ring's r^2 integral over its area) lie on the fitted line
// A + C r^2, for the whole disc and for a quarter alike, and pieces beyond
// a carry no pressure and are left out. The piecewise constant ring
// means of the profile instead fit to within O(h) of p0 and a: bounds of
// 0.025 h / a, met with a margin (the fit of 40 rings: p0 +0.016 %,
// a -0.040 %; of 400: +0.0003 %, -0.0006 %). A uniform pressure (C = 0)
// and pieces at one radius have no fit.
TEST(HertzSphere, EllipticFitOfTheSampledPressure)
{
  using dpana::scene::elliptic_fit;
  const double a = 3.7, p0 = 5000;
  for (const unsigned int n : {40u, 400u})
    for (const double fraction : {1.0, 0.25})
      {
        std::vector<PressurePiece> exact, means;
        for (unsigned int i = 0; i < n + n / 10; ++i)
          {
            const double r0 = a * i / n, r1 = a * (i + 1) / n;
            const double area = fraction * M_PI * (r1 * r1 - r0 * r0);
            const double r2 =
              fraction * M_PI * (std::pow(r1, 4) - std::pow(r0, 4)) / 2;
            const double u = r2 / area / (a * a);
            exact.push_back({area, r2, u < 1 ? p0 * std::sqrt(1 - u) : 0.});
            const auto F = [&](const double r) {
              return std::pow(1 - std::min(1.0, r * r / (a * a)), 1.5);
            };
            means.push_back(
              {area,
               r2,
               fraction * 2 * M_PI * p0 * a * a / 3 * (F(r0) - F(r1)) / area});
          }
        const auto fit = elliptic_fit(exact);
        ASSERT_TRUE(fit.available);
        EXPECT_NEAR(fit.max_pressure / p0, 1.0, 1e-12);
        EXPECT_NEAR(fit.radius / a, 1.0, 1e-12);
        const auto mean_fit = elliptic_fit(means);
        ASSERT_TRUE(mean_fit.available);
        EXPECT_NEAR(mean_fit.max_pressure / p0, 1.0, 0.025 / n);
        EXPECT_NEAR(mean_fit.radius / a, 1.0, 0.025 / n);
      }
  EXPECT_FALSE(elliptic_fit({{1.0, 0.5, 7.0}, {3.0, 4.5, 7.0}}).available);
  EXPECT_FALSE(elliptic_fit({{1.0, 0.5, 7.0}, {2.0, 1.0, 3.0}}).available);
  EXPECT_FALSE(elliptic_fit({}).available);
}



// The quarter sphere of prm/hertz_sphere_rigid.prm (a/R = 0.10) on the
// meshes of levels 1 and 2 of scripts/meshes/make_sphere.py (9000 and 17 500
// unknowns, 106 and 208 contact elements), made by gmsh for the test. The
// bands:
// - the resultant equals P to round-off (equilibrium of the floating
//   sphere: its fictitious support carries nothing);
// - the moment estimate a_m within 1.5 % of Hertz's a at both levels, and
//   closer at level 2: it errs by -1.0 % on these meshes and by -0.55 % at
//   level 4 (doc/contact.md), the rest of the error being the finite a/R
//   (of order (a/R)^2 = 1 %);
// - N_max, the largest element mean, within 1 % of p0: the central element
//   averages p over r < h (p0 (1 - h^2 / (4 a^2)) for the exact profile,
//   0.2 % below p0 at h = a/5) and the discrete solution overshoots it by a
//   few tenths of a percent;
// - the outer edge of the elements in contact within one element of a;
// - the centroid of the quarter's pressure at x = z = 3a/8 within 2 %:
//   the Hertz law over a quarter disc has int x p dA = p0 pi a^3 / 16 and
//   int p dA = pi p0 a^2 / 6; y, the height of the sphere above the plane
//   at the elements' centroids, r^2 / 2R, averaged with the weight p,
//   within 5 % of a^2 / 5R (the Hertz law's mean r^2 is 2 a^2 / 5);
// - the approach of the sphere's centre (at the depth R below the contact
//   point) within a/R = 10 % of Hertz's delta = a^2 / R and below it:
//   delta is the approach of the distant points of a half-space, and at
//   the depth R the half-space field of the contact has not decayed (its
//   Boussinesq displacement there, 0.69 a/R delta for nu = 0.2, is not part
//   of the centre's approach); the sphere's own compression between the
//   centre and the contact, of the order P / (pi E R) = 0.44 a/R delta, is
//   not modelled by Hertz. Hence also within 5 % (0.44 a/R, rounded up) of
//   delta less that Boussinesq displacement. Measured: -5.0 % and +2.1 %
//   at level 1 (doc/contact.md).
// A factor of the moment estimate, the model fraction, the compliance or
// the load path off by more than these bands fails the test.
TEST(HertzSphere, QuarterSphereOnRigidPlaneAgainstHertz)
{
  double previous_a_m_error = 1;
  for (const int level : {1, 2})
    {
      const std::string mesh  = sphere_mesh(level);
      auto              scene = dpana::test::make_scene<3>(sphere_prm(mesh, 0));
      scene->run(false);
      ASSERT_TRUE(scene->summary().result.converged);
      auto v = hertz_sphere_values(scene->summary());
      ASSERT_EQ(v.count("a_moment"), 1u);
      EXPECT_NEAR(v["a"], 4.050638, 1e-6);
      EXPECT_NEAR(v["resultant"] / 300000, 1.0, 1e-10);
      EXPECT_LT(std::abs(v["a_moment_error"]), 0.015) << "level " << level;
      EXPECT_LT(std::abs(v["a_moment_error"]), std::abs(previous_a_m_error));
      EXPECT_LT(std::abs(v["N_max_error"]), 0.01) << "level " << level;
      EXPECT_LE(std::abs(v["a_edge"] - v["a"]), v["a_edge_element"]);
      ASSERT_TRUE(scene->summary().estimates.approach_measured);
      EXPECT_EQ(v["approach_measured"], scene->summary().estimates.approach);
      EXPECT_LT(std::abs(v["approach_error"]), 0.10) << "level " << level;
      EXPECT_LT(v["approach_measured"], v["approach"]);
      EXPECT_LT(std::abs(v["approach_at_centres_error"]), 0.05)
        << "level " << level;
      previous_a_m_error = v["a_moment_error"];
      const auto &est    = scene->summary().estimates;
      ASSERT_TRUE(est.point_centroid_available);
      EXPECT_NEAR(est.resultant / 75000, 1.0, 1e-10);
      std::cout << "level " << level << ": centroid of the pressure ("
                << est.point_centroid[0] << ", " << est.point_centroid[1]
                << ", " << est.point_centroid[2]
                << "), 3a/8 = " << 3 * v["a"] / 8 << std::endl;
      for (const unsigned int c : {0u, 2u})
        EXPECT_NEAR(est.point_centroid[c] / (3 * v["a"] / 8), 1.0, 0.02)
          << "level " << level << ", component " << c;
      const double height = v["a"] * v["a"] / (5 * 40.);
      EXPECT_NEAR(est.point_centroid[1] / height, 1.0, 0.05)
        << "level " << level;
    }
}



// The grouping of the unstructured cap (level 1: 1000 triangles) into
// contact elements of 8 triangles: every face in exactly one element, and
// no element of fewer than 4 triangles (the greedy agglomeration alone
// leaves groups of 1 to 3 triangles where a group cannot grow; they must
// have joined a neighbour; one that takes in two of them holds at most
// 8 + 3 + 3 = 14 faces).
TEST(HertzSphere, GroupingOfTheCapLeavesNoSmallElements)
{
  auto scene = dpana::test::make_scene<3>(sphere_prm(sphere_mesh(1), 0));
  scene->assemble();
  scene->build_contact_surface();
  const auto            &surface = scene->surface(0);
  std::set<unsigned int> used;
  unsigned int           n_faces = 0;
  for (const auto &e : surface.get_elements())
    {
      EXPECT_GE(e.faces.size(), 4u);
      EXPECT_LE(e.faces.size(), 14u);
      used.insert(e.faces.begin(), e.faces.end());
      n_faces += e.faces.size();
    }
  EXPECT_EQ(used.size(), surface.get_faces().size());
  EXPECT_EQ(n_faces, surface.get_faces().size());
}



// The approach on a displacement known in closed form: on the box
// [0, 8] x [0, 2] x [0, 4] the linear field u = (0.3 y, -0.01 y + 0.002,
// 0.05 z), which the P1 space holds exactly. Along n = (0, -1, 0), from the
// contact point (4, 0, 2) to the far point (4, 2, 2):
// (u(far) - u(contact)) . n = -(-0.01 * 2) = +0.02, whatever the rigid
// part (the constant 0.002) and the tangential parts; the partner's sign
// gives -0.02. And the Boussinesq displacement by hand: P = 2 pi, E = 1,
// nu = 0.5, z = 1: 2 pi * 1.5 * 2 / (2 pi) = 3.
TEST(HertzSphere, ApproachOfALinearDisplacement)
{
  auto scene = dpana::test::make_scene<3>(
    "set Dimension = 3\n" +
    dpana::test::brick_body("Body 1",
                            "box",
                            "0, 0, 0",
                            "8, 2, 4",
                            "4, 1, 2",
                            "    set Fixed = top: x, y, z\n",
                            ""));
  scene->assemble();
  auto &body = scene->body(0);
  struct Linear : dealii::Function<3>
  {
    Linear()
      : dealii::Function<3>(3)
    {
    }
    double
    value(const dealii::Point<3> &x, const unsigned int c) const override
    {
      return c == 0 ? 0.3 * x[1] : c == 1 ? -0.01 * x[1] + 0.002 : 0.05 * x[2];
    }
  };
  dealii::Vector<double> u(body.dof_handler().n_dofs());
  dealii::VectorTools::interpolate(body.mapping(),
                                   body.dof_handler(),
                                   Linear(),
                                   u);
  body.set_solution(u);
  const dealii::Point<3>     contact(4, 0, 2), far(4, 2, 2);
  const dealii::Tensor<1, 3> n({0, -1, 0});
  EXPECT_NEAR(dpana::scene::body_approach(body, contact, far, n, 1.),
              0.02,
              1e-14);
  EXPECT_NEAR(dpana::scene::body_approach(body, contact, far, n, -1.),
              -0.02,
              1e-14);
  EXPECT_NEAR(dpana::scene::boussinesq_axial_displacement(2 * M_PI, 1, 0.5, 1),
              3.0,
              1e-14);
}



// A sphere whose centre the mesh does not hold (Radius 1 = 100 mm puts it at
// (0, 100, 0), outside the sphere of radius 40 meshed at level 0): the run
// completes, and the approach is not measured rather than taken from a
// point outside the body.
TEST(HertzSphere, ApproachNotMeasuredOutsideTheMesh)
{
  std::string prm = sphere_prm(sphere_mesh(0), 0);
  prm.replace(prm.find("Radius 1 = 40"), 13, "Radius 1 = 100");
  auto scene = dpana::test::make_scene<3>(prm);
  scene->run(false);
  ASSERT_TRUE(scene->summary().result.converged);
  EXPECT_FALSE(scene->summary().estimates.approach_measured);
  EXPECT_EQ(hertz_sphere_values(scene->summary()).count("approach_measured"),
            0u);
}



namespace
{
  // prm/hertz_sphere_rigid.prm on the mesh of level 0 with patches around
  // the vertices (Contact / Contact elements = vertices), run.
  std::unique_ptr<dpana::scene::Scene<3>>
  sphere_with_patches(const double mu)
  {
    std::string       prm   = sphere_prm(sphere_mesh(0), mu);
    const std::string entry = "  set Contact direction = 0, -1, 0\n";
    prm.insert(prm.find(entry) + entry.size(),
               "  set Contact elements = vertices\n");
    auto scene = dpana::test::make_scene<3>(prm);
    scene->run(false);
    EXPECT_TRUE(scene->summary().result.converged);
    return scene;
  }

  // The vertex of patch @p e: the first corner of its first piece.
  dealii::Point<3>
  patch_vertex(const dpana::contact_surface::ContactSurface<3> &surface,
               const dpana::contact_surface::ContactElement<3> &e)
  {
    return e.pieces[0].corner_points(surface.get_faces()[e.pieces[0].face])[0];
  }
} // namespace



// Patches around the vertices of the cap (level 0: 446 triangles, 252
// vertices), frictionless. Each patch is the median dual cell of its vertex,
// which takes exactly a third of every triangle at the vertex: its
// projected area must be a third of the projected areas of its faces, and
// all patches together the whole cap. The moment estimate a_m of the Hertz
// comparison is then taken over the pieces of the patches: recomputed here
// from the tractions, with the integral of r^2 over each piece by the rule
// of its edge midpoints (exact for a quadratic), it must agree to
// round-off; taken over whole faces (each face in three patches) it would
// not. Against Hertz: a_m within 2 % (measured -1.56 %: the patches give
// the groups' -1.37 % to within 0.2 %; benchmarks/convergence).
TEST(HertzSphere, VertexPatchesOfTheCap)
{
  auto        scene   = sphere_with_patches(0);
  const auto &surface = scene->surface(0);
  EXPECT_EQ(surface.n_elements(), surface.n_vertices());
  const dealii::Tensor<1, 3> n({0, -1, 0});
  double                     cap = 0, patches = 0, force = 0, moment = 0;
  for (const auto &F : surface.get_faces())
    cap += F.area * (F.normal * n);
  for (unsigned int j = 0; j < surface.n_elements(); ++j)
    {
      const auto &e     = surface.element(j);
      double      third = 0;
      for (const unsigned int f : e.faces)
        third +=
          surface.get_faces()[f].area * (surface.get_faces()[f].normal * n) / 3;
      EXPECT_NEAR(e.area, third, 1e-12 * third) << "element " << j;
      patches += e.area;
      for (const auto &piece : e.pieces)
        {
          const auto   x = piece.corner_points(surface.get_faces()[piece.face]);
          const double area = piece.fraction() *
                              surface.get_faces()[piece.face].area *
                              (surface.get_faces()[piece.face].normal * n);
          double r2 = 0;
          for (unsigned int k = 0; k < 3; ++k)
            {
              const dealii::Point<3> m = 0.5 * (x[k] + x[(k + 1) % 3]);
              r2 += (m[0] * m[0] + m[2] * m[2]) / 3;
            }
          force -= scene->normal_traction(j) * area;
          moment -= scene->normal_traction(j) * area * r2;
        }
    }
  EXPECT_NEAR(patches, cap, 1e-12 * cap);
  EXPECT_NEAR(force, 75000, 1e-9 * 75000);
  const auto v = hertz_sphere_values(scene->summary());
  EXPECT_NEAR(v.at("a_moment"), std::sqrt(2.5 * moment / force), 1e-12);
  EXPECT_LT(std::abs(v.at("a_moment_error")), 0.02);
}



// The sphere is held only by the contact: its vertical translation gets a
// fictitious support, one free dof whose reaction the equality row drives
// to zero. The first vertex of the gmsh file lies on the cap (0, 0.45, 6).
// With the support there, one combination of the patches' normal
// tractions (as many as cap vertices) acts on the support alone and A_NN
// is singular: at level 1 the active set met a factor M_CC that was not
// positive definite, and the splitting handed over to Alart-Curnier. Off
// the cap the splitting converges in one iteration.
TEST(HertzSphere, FictitiousSupportOffTheCap)
{
  std::string       prm   = sphere_prm(sphere_mesh(1), 0);
  const std::string entry = "  set Contact direction = 0, -1, 0\n";
  prm.insert(prm.find(entry) + entry.size(),
             "  set Contact elements = vertices\n");
  auto scene = dpana::test::make_scene<3>(prm);
  scene->run(false);
  const auto &result = scene->summary().result;
  ASSERT_TRUE(result.converged);
  EXPECT_TRUE(result.fallbacks.empty()) << result.fallbacks[0];
  EXPECT_EQ(result.iterations, 1u);

  const auto &supports = scene->condenser(0).fictitious_supports();
  ASSERT_EQ(supports.size(), 1u);
  for (const auto &F : scene->surface(0).get_faces())
    for (const auto dof : F.dofs)
      EXPECT_NE(dof, supports[0]);
}



// With friction (mu = 0.3) and patches, the planes x = 0 and z = 0 of the
// quarter model are symmetry planes: across them the tangential traction is
// odd, so a patch whose vertex lies on one carries no tangential traction
// across it (condensation::tangentially_held_unknowns()), and the one at the
// contact point, on both, none at all. Along the plane it is free: the
// radial traction of the frictional Hertz contact points along it there. The
// frame of n = (0, -1, 0) is tau_1 = x, tau_2 = z.
TEST(HertzSphere, VertexPatchesOnTheSymmetryPlanes)
{
  auto         scene   = sphere_with_patches(0.3);
  const auto  &surface = scene->surface(0);
  unsigned int on_x = 0, on_z = 0, corner = 0;
  double       along_x = 0, along_z = 0;
  for (unsigned int j = 0; j < surface.n_elements(); ++j)
    {
      const auto &e = surface.element(j);
      ASSERT_NEAR(e.tangents[0][0], 1.0, 1e-15);
      ASSERT_NEAR(e.tangents[1][2], 1.0, 1e-15);
      const dealii::Point<3> x = patch_vertex(surface, e);
      if (std::abs(x[0]) < 1e-12)
        {
          EXPECT_EQ(scene->tangential_traction(j, 0), 0.0) << x;
          along_z =
            std::max(along_z, std::abs(scene->tangential_traction(j, 1)));
          ++on_x;
        }
      if (std::abs(x[2]) < 1e-12)
        {
          EXPECT_EQ(scene->tangential_traction(j, 1), 0.0) << x;
          along_x =
            std::max(along_x, std::abs(scene->tangential_traction(j, 0)));
          ++on_z;
        }
      corner += (std::abs(x[0]) < 1e-12 && std::abs(x[2]) < 1e-12) ? 1 : 0;
    }
  EXPECT_EQ(corner, 1u);
  EXPECT_GT(on_x, 5u);
  EXPECT_GT(on_z, 5u);
  // The tangential tractions along the planes are those of a frictional
  // contact: of the order of mu p0 = 2 600 MPa, not zero.
  EXPECT_GT(along_x, 100.0);
  EXPECT_GT(along_z, 100.0);
}



// The hold of T_1 on the plane x = 0 relies on the friction set being
// symmetric under T_1 -> -T_1. The polygon of the reference formulation
// (facet normals at the angles 2 pi i / s from tau_1) is for even s only:
// with s = 5 the held T_1 would be pushed off zero by the polygon's
// asymmetry (measured: up to 902 MPa on slipping patches), so the scene is
// refused in one line; with s = 6 the held T_1 stays at round-off.
TEST(HertzSphere, VertexPatchesNeedAnEvenPolygon)
{
  const auto run = [](const unsigned int sides) {
    std::string       prm   = sphere_prm(sphere_mesh(0), 0.3);
    const std::string entry = "  set Contact direction = 0, -1, 0\n";
    prm.insert(prm.find(entry) + entry.size(),
               "  set Contact elements = vertices\n"
               "  set Cone model = polygon\n"
               "  set Polygon sides = " +
                 std::to_string(sides) + "\n");
    auto scene = dpana::test::make_scene<3>(prm);
    scene->run(false);
    return scene;
  };
  try
    {
      run(5);
      FAIL() << "an odd polygon with held T_1 was accepted";
    }
  catch (const dpana::InputError &e)
    {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("Contact / Polygon sides = 5: ", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  auto        scene   = run(6);
  const auto &surface = scene->surface(0);
  ASSERT_TRUE(scene->summary().result.converged);
  for (unsigned int j = 0; j < surface.n_elements(); ++j)
    {
      const auto x = patch_vertex(surface, surface.element(j));
      if (std::abs(x[0]) < 1e-12)
        {
          EXPECT_LT(std::abs(scene->tangential_traction(j, 0)), 1e-6) << j;
        }
    }
}



// The quarter sphere without a contact direction: the mean outward normal
// of its cap leans along x and z, away from the symmetry planes, on which
// vertices of the cap are held; the rigid plane, normal to that mean
// normal, then tilts, and the run gives N_max = 12 638 MPa, 1.45 times p0,
// and a_m 70 % too large (prm/hertz_sphere_rigid.prm's mesh). The log
// warns, naming both axes; with the direction it does not.
TEST(HertzSphere, MissingContactDirectionOnTheQuarterModelIsWarned)
{
  for (const bool given : {false, true})
    {
      std::string prm = sphere_prm(sphere_mesh(0), 0);
      if (!given)
        {
          const std::string entry = "  set Contact direction = 0, -1, 0\n";
          prm.erase(prm.find(entry), entry.size());
        }
      auto              scene = dpana::test::make_scene<3>(prm);
      const std::string log   = dpana::test::contact_surface_log(*scene);
      const auto        line = log.find("warning: Contact / Contact direction");
      EXPECT_EQ(line != std::string::npos, !given) << log;
      if (!given && line != std::string::npos)
        {
          EXPECT_NE(log.find("leans along x and z", line), std::string::npos)
            << log;
        }
    }
}



// The candidate surface of the quarter sphere is the whole named boundary
// "contact", a cap of radius 6 mm around the contact point; beyond it the
// boundary "sphere" goes on towards the plane. Under four times the load
// the Hertz radius (3PR/4E*)^(1/3) grows by 4^(1/3) from 4.05 to 6.43 mm,
// past the cap: the summary warns. Under the scene's load it does not,
// although contact reaches the symmetry planes, which meet the cap at a
// right angle.
TEST(HertzSphere, ContactBeyondTheNamedCapIsWarned)
{
  for (const double factor : {1.0, 4.0})
    {
      std::string       prm   = sphere_prm(sphere_mesh(0), 0);
      const std::string entry = "0, -75000, 0";
      prm.replace(prm.find(entry),
                  entry.size(),
                  "0, " + std::to_string(-75000 * factor) + ", 0");
      auto scene = dpana::test::make_scene<3>(prm);
      scene->run(false);
      ASSERT_TRUE(scene->summary().result.converged);
      EXPECT_EQ(scene->summary().candidate_edge_warning, factor > 1)
        << "load factor " << factor;
    }
}
