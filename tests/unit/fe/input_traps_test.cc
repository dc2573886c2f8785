// Setups that a user may well write and that gave a wrong or misleading
// answer without a word: each test runs one and checks that the answer is
// right or that the run says what is wrong.

#include <dpana/contact/problem.h>
#include <dpana/scene/input_checks.h>

#include <cmath>
#include <sstream>
#include <string>

#include "scene_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using dpana::contact::ContactStatus;

  // A full disc of radius 40 on the rigid plane y = 0, pressed by 200 kN/mm
  // at its top (a full model: no symmetry, no support), with the entries
  // @p contact added to the Contact subsection.
  std::string
  full_disc_prm(const std::string &contact)
  {
    return "subsection Body 1\n"
           "  subsection Geometry\n"
           "    set Type = disc\n"
           "    set Global refinements = 2\n"
           "    subsection Disc\n"
           "      set Radius = 40\n"
           "      set Centre = 0, 40\n"
           "      set Contact refinements = 3\n"
           "      set Contact refinement radius = 14\n"
           "    end\n"
           "  end\n"
           "  subsection Loads\n"
           "    set Concentrated forces = 0, 80: 0, -200000\n"
           "  end\n"
           "end\n"
           "subsection Contact\n"
           "  set Boundary 1 = curved\n"
           "  set Candidate half width = 15\n"
           "  set Friction coefficient = 0\n" +
           contact + "end\n";
  }

  // The receding block (tests/unit/fe/scene_test_tools.h) on the rigid
  // plane with the loads @p loads and the Contact entries @p contact.
  std::string
  block_prm(const std::string &loads, const std::string &contact)
  {
    std::string       prm     = dpana::test::receding_block(16, 16, "");
    const std::string shipped = "set Pressure = top: 50; right: 100";
    prm.replace(prm.find(shipped), shipped.size(), loads);
    return prm +
           "subsection Contact\n"
           "  set Boundary 1 = bottom\n"
           "  set Contact direction = 0, -1\n" +
           contact + "end\n";
  }
} // namespace



// One body on the rigid plane without a contact direction: every element
// takes the plane's normal, the mean outward normal of the candidate faces,
// which on the full disc is the axis 0, -1 (the mesh is symmetric about
// it, to round-off). So no gap is negative and the answer is that of the
// run with the direction. Each element used to take its own normal and
// measure its gap to the plane through the lowest point normal to it:
// gaps down to -2.7 mm, N_max 54 593 MPa against 14 681 MPa of Hertz, with
// exit status 0.
TEST(InputTraps, FullDiscWithoutContactDirection)
{
  auto own  = dpana::test::make_scene<2>(full_disc_prm(""));
  auto axis = dpana::test::make_scene<2>(
    full_disc_prm("  set Contact direction = 0, -1\n"));
  own->run(false);
  axis->run(false);
  ASSERT_TRUE(own->summary().result.converged);
  ASSERT_TRUE(axis->summary().result.converged);
  for (const auto &e : own->surface(0).get_elements())
    EXPECT_GE(e.mean_gap(), -1e-12 * 40) << "element at s = " << e.s;
  const double N_own  = own->summary().max_pressure;
  const double N_axis = axis->summary().max_pressure;
  EXPECT_LT(std::abs(N_own - N_axis) / N_axis, 1e-9)
    << N_own << " against " << N_axis;
}



// A solve to a looser tolerance must not turn sticking elements into
// slipping ones: the receding block with mu = 1 sticks near the symmetry
// plane (s < 17.5 mm at the default tolerance). With Tolerance = 1e-6 the
// sticking elements slid by up to 1e-9 mm, above the classification's
// 1e-8 relative bound, and every element was reported slipping.
TEST(InputTraps, LooseToleranceKeepsTheStickZone)
{
  const std::string loads = "set Pressure = top: 50; right: 100";
  auto              tight = dpana::test::make_scene<2>(
    block_prm(loads, "  set Friction coefficient = 1\n"));
  auto loose =
    dpana::test::make_scene<2>(block_prm(loads,
                                         "  set Friction coefficient = 1\n"
                                         "  set Tolerance = 1e-6\n"));
  tight->run(false);
  loose->run(false);
  ASSERT_TRUE(tight->summary().result.converged);
  ASSERT_TRUE(loose->summary().result.converged);
  const auto &a = tight->summary().result.status;
  const auto &b = loose->summary().result.status;
  ASSERT_EQ(a.size(), b.size());
  unsigned int n_stick = 0;
  for (std::size_t j = 0; j < a.size(); ++j)
    {
      EXPECT_EQ(a[j], b[j]) << "element " << j;
      n_stick += a[j] == ContactStatus::stick;
    }
  EXPECT_GT(n_stick, 0u);
}



// A block on the plane pressed only sideways, against its symmetry plane,
// expands upwards (Poisson): the exact tractions are zero and every element
// is separated, and there is no zone to estimate. Round-off tractions of
// 1e-12 MPa were classified against themselves and reported as a contact
// zone of half width 30 mm, with an elliptic fit of a_f = 24 mm.
TEST(InputTraps, NoNormalLoadNoContactZone)
{
  for (const double mu : {0.0, 1.0})
    {
      auto s = dpana::test::make_scene<2>(
        block_prm("set Pressure = right: 100",
                  "  set Friction coefficient = " + std::to_string(mu) + "\n"));
      s->run(false);
      ASSERT_TRUE(s->summary().result.converged);
      EXPECT_LT(s->summary().max_pressure, 1e-9);
      for (const auto status : s->summary().result.status)
        EXPECT_EQ(status, ContactStatus::separated) << "mu = " << mu;
      EXPECT_EQ(s->summary().half_width, 0.0) << "mu = " << mu;
      EXPECT_FALSE(s->summary().estimates.available) << "mu = " << mu;
    }
}



// Bodies that start far apart, or overlap deeply, are warned: the rigid
// plane 50 mm above the base of the 40 mm block (an Obstacle point
// misplaced) overlaps it by 50 mm, and the plane 1000 mm below it leaves a
// gap of 1000 mm that the floating block closes by a rigid motion. So are
// 5 mm, just above the bound of a tenth of the base; the plane at the base
// and 3 mm below it, within the bound, do not warn.
TEST(InputTraps, FarInitialGapIsWarned)
{
  for (const double y : {0.0, -3.0, -5.0, 50.0, -1000.0})
    {
      auto s = dpana::test::make_scene<2>(
        block_prm("set Pressure = top: 50; right: 100",
                  "  set Obstacle point = 0, " + std::to_string(y) + "\n"));
      const std::string log  = dpana::test::contact_surface_log(*s);
      const auto        line = log.find("warning: the closest initial gap");
      const bool        far  = std::abs(y) > 4;
      EXPECT_EQ(line != std::string::npos, far) << "y = " << y << "\n" << log;
      if (far && line != std::string::npos)
        {
          std::ostringstream expected;
          expected << -y << " mm (" << (y > 0 ? "an overlap" : "apart") << ")";
          EXPECT_NE(log.find(expected.str(), line), std::string::npos) << log;
        }
    }
}



// The block [0, 40]^2 without its symmetry line x = 0, held sideways by
// friction (mu = 1): 50 MPa on top, 10 MPa on the right side. It lies on
// one side of the candidate centre 0 but is a whole model: its pressure
// centroid is x_c = 16 mm by statics (moments about the origin: 20 * 2000
// = 20 * 400 + 2000 x_c). It used to be mirrored about x = 0 as a half
// model, its centroid reported as 0. With the symmetry line it is a half
// model, mirrored.
TEST(InputTraps, WholeModelOnOneSideIsNotMirrored)
{
  std::string       prm      = block_prm("set Pressure = top: 50; right: 10",
                              "  set Friction coefficient = 1\n");
  const std::string symmetry = "    set Symmetry = left\n";
  auto              half     = dpana::test::make_scene<2>(prm);
  prm.erase(prm.find(symmetry), symmetry.size());
  auto whole = dpana::test::make_scene<2>(prm);
  half->run(false);
  whole->run(false);
  ASSERT_TRUE(half->summary().result.converged);
  ASSERT_TRUE(whole->summary().result.converged);
  EXPECT_TRUE(half->summary().estimates.mirrored);
  const auto &est = whole->summary().estimates;
  ASSERT_TRUE(est.available);
  EXPECT_FALSE(est.mirrored);
  EXPECT_NEAR(est.resultant, 2000, 1e-6 * 2000);
  EXPECT_NEAR(est.centroid, 16, 0.05) << "statics: 16 mm";
}



// The receding block on an elastic foundation, the foundation named Body 1
// (Body 2 is the block [0, 40]^2 with the loads of receding_block()): the
// candidate region of the foundation's top spans the block's base, and the
// contact zone reaches its edge at x = 40, the block's corner. Beyond it
// the foundation's top goes on, but the block's base does not: the contact
// cannot grow past it, and a wider region would leave foundation faces
// without a partner (an input error). That run used to warn that the
// candidate surface may be too small; a region of 20 mm, which does cut
// the contact zone, must warn.
TEST(InputTraps, BlockOnFoundationNamedFirstIsNotWarned)
{
  std::string block = dpana::test::receding_block(8, 8, "");
  block.replace(block.find("Body 1"), 6, "Body 2");
  const std::string foundation = "set Number of bodies = 2\n"
                                 "subsection Body 1\n"
                                 "  subsection Geometry\n"
                                 "    set Type = rectangle\n"
                                 "    subsection Rectangle\n"
                                 "      set Lower corner = 0, -80\n"
                                 "      set Upper corner = 80, 0\n"
                                 "      set Subdivisions = 16, 16\n"
                                 "    end\n"
                                 "  end\n"
                                 "  subsection Boundary conditions\n"
                                 "    set Symmetry = left\n"
                                 "    set Fixed = bottom: x, y\n"
                                 "  end\n"
                                 "end\n";
  for (const double w : {40.0, 20.0})
    {
      auto s = dpana::test::make_scene<2>(foundation + block +
                                            "subsection Contact\n"
                                            "  set Boundary 1 = top\n"
                                            "  set Boundary 2 = bottom\n"
                                            "  set Candidate half width = " +
                                            std::to_string(w) +
                                            "\n"
                                            "  set Contact direction = 0, 1\n"
                                            "  set Friction coefficient = 1\n"
                                            "end\n",
                                          2);
      s->run(false);
      ASSERT_TRUE(s->summary().result.converged) << "w = " << w;
      EXPECT_NEAR(s->summary().half_width, w, 1e-9) << "w = " << w;
      EXPECT_EQ(s->summary().candidate_edge_warning, w < 40) << "w = " << w;
    }
}



// The receding block with one edge per contact element: 16 elements on 17
// surface vertices, a constant traction per edge on linear displacements,
// which is not a stable pair. On prm/receding_2d_mu1.prm (32 edges) the
// tangential tractions of the stick zone then alternate in sign: -8.9,
// 13.2, -4.5, 17.6 MPa at s = 0.6 ... 4.4 mm, against 2.1, 6.5, 11.2 MPa at
// s = 1.25 ... 6.25 mm with two edges per element. It is warned; two edges
// (8 elements) and the patches around the vertices (17, the traction form
// of nodal conditions) are not.
TEST(InputTraps, OneEdgePerContactElementIsWarned)
{
  for (const std::string elements : {"  set Faces per contact element = 1\n",
                                     "  set Faces per contact element = 2\n",
                                     "  set Contact elements = vertices\n"})
    {
      auto s = dpana::test::make_scene<2>(
        block_prm("set Pressure = top: 50; right: 100",
                  elements + "  set Friction coefficient = 1\n"));
      s->assemble();
      s->build_contact_surface();
      const std::string warning =
        dpana::scene::surface_resolution(s->surface(0), true);
      const bool one_edge = elements.find("= 1") != std::string::npos;
      EXPECT_EQ(warning.empty(), !one_edge) << elements << warning;
      if (one_edge)
        {
          EXPECT_NE(warning.find("16 contact elements on 17 surface "
                                 "vertices of Body 1"),
                    std::string::npos)
            << warning;
        }
    }
}



// The receding block, a half model held on its symmetry line x = 0, with
// the contact direction tilted by 1 degree (0.0175, -1): the obstacle is
// no longer symmetric about that line, and the run is warned. The block
// with the direction 0, -1 is not.
TEST(InputTraps, TiltedDirectionOnAHalfModelIsWarned)
{
  for (const bool tilted : {false, true})
    {
      std::string       prm = block_prm("set Pressure = top: 50; right: 100",
                                  "  set Friction coefficient = 1\n");
      const std::string direction = "set Contact direction = 0, -1";
      if (tilted)
        prm.replace(prm.find(direction),
                    direction.size(),
                    "set Contact direction = 0.0175, -1");
      auto s = dpana::test::make_scene<2>(prm);
      s->assemble();
      s->build_contact_surface();
      const std::string warning =
        dpana::scene::leaning_direction(s->body(0), s->surface(0), true);
      EXPECT_EQ(warning.empty(), !tilted) << warning;
      if (tilted)
        {
          EXPECT_NE(warning.find("leans along x"), std::string::npos)
            << warning;
        }
    }
}



// Loads across the symmetry line x = 0 of the receding half block: a
// pressure of 30 MPa on that line (1200 N/mm over its 40 mm) and a side
// force of 500 N/mm at its top vertex. The symmetry condition takes them
// as a support would and the contact never feels them (the run used to
// give the answer without them, silently, with the summary listing them
// as applied). Each is warned with its size; the scene's own loads are
// not.
TEST(InputTraps, LoadAcrossTheSymmetryLineIsWarned)
{
  const std::string shipped = "set Pressure = top: 50; right: 100";
  for (const auto &[loads, across] :
       std::vector<std::pair<std::string, std::string>>{
         {shipped, ""},
         {shipped + "; left: 30", "loads of 1200 in all"},
         {shipped + "\n    set Concentrated forces = 0, 40: 500, 0",
          "loads of 500 in all"}})
    {
      auto s = dpana::test::make_scene<2>(block_prm(loads, ""));
      s->assemble();
      std::string warnings;
      for (const auto &w : s->body(0).warnings())
        warnings += w + "\n";
      if (across.empty())
        EXPECT_EQ(warnings, "") << loads;
      else
        {
          EXPECT_NE(warnings.find(across), std::string::npos) << warnings;
          EXPECT_NE(warnings.find("the symmetry boundary 'left'"),
                    std::string::npos)
            << warnings;
        }
    }
}
