// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The 3D Hertz reference measures the contact radii about the axis through
// Contact / Candidate centre: a centre off the sphere's axis is warned.

#include <dpana/scene/input_checks.h>

#include <string>

#include "scene_test_tools.h"
#include "sphere_test_tools.h"
#include <gtest/gtest.h>

// The quarter sphere of prm/hertz_sphere_rigid.prm (its axis is the y
// axis) with the candidate centre moved along both symmetry planes by
// 0, 0.05 mm (less than the faces at the contact point are wide) and 2 mm.
// The moment radius about the moved centre takes in only the part of the
// quarter disc that lies beyond it: at 2 mm a_m is about 40 % short of
// Hertz's. That run warns, in the log of the run and through
// off_axis_centre(); the others do not.
TEST(HertzSphereCentre, CentreOffTheAxisIsWarned)
{
  const std::string mesh = dpana::test::sphere_mesh(0);
  for (const double offset : {0.0, 0.05, 2.0})
    {
      const std::string o   = std::to_string(offset);
      const std::string prm = dpana::test::sphere_prm(mesh, 0) +
                              "subsection Contact\n"
                              "  set Candidate centre = " +
                              o + ", 0, " + o + "\nend\n";
      auto scene = dpana::test::make_scene<3>(prm);
      testing::internal::CaptureStderr();
      scene->run(false);
      const std::string log  = testing::internal::GetCapturedStderr();
      const bool        off  = offset > 1;
      const std::string text = dpana::scene::off_axis_centre(scene->surface(0));
      ASSERT_TRUE(scene->summary().result.converged);
      EXPECT_EQ(!text.empty(), off) << "offset " << offset << ": " << text;
      EXPECT_EQ(log.find("off the axis through the point of Body 1") !=
                  std::string::npos,
                off)
        << "offset " << offset << "\n"
        << log;
      const double a_m_error =
        dpana::test::hertz_sphere_values(scene->summary())["a_moment_error"];
      if (off)
        EXPECT_LT(a_m_error, -0.3) << "the error the warning is about";
      else
        EXPECT_GT(a_m_error, -0.05) << "offset " << offset;
    }
}



// Without a contact direction the axis of the reference is the mean normal
// of the cap, which leans off the sphere's axis on a quarter model (the run
// is warned of that apart): its nearest vertex is not the pole, and the
// centre on the axis must not be called off it.
TEST(HertzSphereCentre, NoCentreWarningWithoutContactDirection)
{
  std::string prm = dpana::test::sphere_prm(dpana::test::sphere_mesh(0), 0);
  const std::string direction = "  set Contact direction = 0, -1, 0\n";
  ASSERT_NE(prm.find(direction), std::string::npos);
  prm.erase(prm.find(direction), direction.size());
  auto scene = dpana::test::make_scene<3>(prm);
  scene->assemble();
  scene->build_contact_surface();
  EXPECT_EQ(dpana::scene::off_axis_centre(scene->surface(0)), "");
}
