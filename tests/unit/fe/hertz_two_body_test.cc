// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Hertz contact between two elastic bodies (the reference formulation,
// section 4.3) through the 2D projection pairing of non-matching surfaces: a
// stiff foundation against the rigid plane, and the cylinder in a cavity under
// refinement.

#include <dpana/scene/scene.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "scene_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using dpana::test::hertz_prm;
  using dpana::test::make_scene;

  // The foundation of the Hertz scenes: the half model [0, 80] x [-80, 0],
  // a 64 x 64 grid graded towards the contact point (edges 0.08 mm at the
  // axis, 0.8 mm at 8 mm from it), symmetric on x = 0, fixed at its base.
  std::string
  foundation(const double E)
  {
    return "  subsection Geometry\n"
           "    set Global refinements = 1\n"
           "    subsection Rectangle\n"
           "      set Lower corner = 0, -80\n"
           "      set Upper corner = 80, 0\n"
           "      set Subdivisions = 32, 32\n"
           "      set Grading centre = 0, 0\n"
           "      set Grading exponents = 2, 2\n"
           "    end\n"
           "  end\n"
           "  subsection Material\n"
           "    set Young's modulus = " +
           std::to_string(E) +
           "\n"
           "  end\n"
           "  subsection Boundary conditions\n"
           "    set Symmetry = left\n"
           "    set Fixed = bottom: x, y\n"
           "  end\n";
  }
} // namespace



// A foundation a thousand times stiffer than the cylinder (E1/E2 = 1e-3,
// the reference formulation's model of a rigid foundation, table 4.2) must give
// nearly the tractions of the rigid plane y = 0 (the Signorini problem of the
// same cylinder mesh, solved without a second body). The two runs share the
// cylinder's mesh and contact elements; they differ by the foundation's
// compliance, 1e-3 of the cylinder's, and by the route: projection pairing
// with a condensed second body against a plane gap. The tractions are
// compared element by element, relative to N_max, with the tolerance 1e-2:
// ten times the compliance ratio, because the compliance of the foundation
// near the load (the log term of a 2D half-plane) is larger than its ratio
// of moduli.
TEST(HertzTwoBody, StiffFoundationApproachesRigidPlane)
{
  for (const double mu : {0.0, 1.0})
    {
      auto rigid = make_scene<2>(hertz_prm(4, 15, mu));
      auto stiff = make_scene<2>(hertz_prm(4, 15, mu, foundation(1.3e8)), 2);
      rigid->run(false);
      stiff->run(false);
      ASSERT_TRUE(rigid->summary().result.converged);
      ASSERT_TRUE(stiff->summary().result.converged);
      ASSERT_EQ(rigid->summary().n_elements, stiff->summary().n_elements);
      const double N_max = rigid->summary().max_pressure;
      double       dN = 0, dT = 0;
      for (unsigned int j = 0; j < rigid->summary().n_elements; ++j)
        {
          const auto [n, t] =
            dpana::test::traction_differences(*stiff, j, *rigid, j);
          dN = std::max(dN, n);
          dT = std::max(dT, t);
        }
      std::cout << "mu = " << mu
                << ": rigid plane a = " << rigid->summary().half_width
                << " mm, N_max = " << N_max
                << " MPa; stiff foundation a = " << stiff->summary().half_width
                << " mm, N_max = " << stiff->summary().max_pressure
                << " MPa; max |dN| / N_max = " << dN / N_max
                << ", max |dT| / N_max = " << dT / N_max << std::endl;
      EXPECT_LT(dN / N_max, 1e-2) << "mu = " << mu;
      EXPECT_LT(dT / N_max, 1e-2) << "mu = " << mu;
      EXPECT_EQ(rigid->summary().half_width, stiff->summary().half_width);
    }
}



namespace
{
  // The cylinder in a cavity of the reference formulation, section 4.3,
  // table 4.4 (as prm/hertz_cavity_mu0.prm): the cylinder of hertz_prm() with m
  // contact refinements within 21 mm of the origin, in the quarter ring 120 <=
  // r <= 360 around (0, 120) with m + 1 contact refinements there (its arc is 3
  // times longer per degree), frictionless, candidate surface the arc within 20
  // mm, Hertz reference for the cavity.
  std::string
  cavity_prm(const unsigned int m)
  {
    return hertz_prm(m,
                     20,
                     0,
                     "  subsection Geometry\n"
                     "    set Type = quarter annulus\n"
                     "    set Global refinements = 2\n"
                     "    subsection Quarter annulus\n"
                     "      set Inner radius = 120\n"
                     "      set Outer radius = 360\n"
                     "      set Centre = 0, 120\n"
                     "      set Contact refinements = " +
                       std::to_string(m + 1) +
                       "\n"
                       "      set Contact refinement radius = 21\n"
                       "    end\n"
                       "  end\n"
                       "  subsection Boundary conditions\n"
                       "    set Symmetry = y_axis\n"
                       "    set Fixed = outer: x, y; x_axis: y\n"
                       "  end\n",
                     "inner",
                     21,
                     "  subsection Reference\n"
                     "    set Type = hertz\n"
                     "    set Hertz load = 200000\n"
                     "    set Radius 1 = 40\n"
                     "    set Radius 2 = -120\n"
                     "  end\n");
  }
} // namespace



// The cylinder in the cavity under refinement of both arcs (contact
// elements of 2, 1 and 0.5 mm). Hertz (plane strain, 1/R = 1/R1 - 1/R2,
// R = 60 mm): a = 15.02 mm, N_max = 8476 MPa; the reference formulation's
// table 4.4 gives a = 13.96 mm, N_max = 8914.6 MPa for mu = 0. Here a / R1 is
// about 0.35, well beyond Hertz's small-contact assumption, and the finite ring
// is stiffer than the infinite plane with a hole, so the test asserts: (1)
// N_max converges: the last change is below 1 % and below the previous one; (2)
// N_max of the finest mesh lies within 3 % of the reference table and within 8
// % of Hertz; (3) a of every mesh agrees with the reference table within one
// contact element size (a is known to the element that ends the contact zone),
// and is below Hertz's.
TEST(HertzTwoBody, CylinderInCavityConverges)
{
  const double a_table = 13.96, N_table = 8914.6;
  // Hertz for the cavity, computed here from the formulas: k = (1 -
  // nu^2) / (pi E) for each body, 1/R = 1/R1 - 1/R2.
  const double        k = (1 - 0.2 * 0.2) / (M_PI * 130000), R = 40. * 120 / 80;
  const double        a_H = std::sqrt(4 * 200000 * 2 * k * R);
  const double        N_H = 2 * 200000 / (M_PI * a_H);
  std::vector<double> a, N, h;
  for (const unsigned int m : {3u, 4u, 5u})
    {
      auto s = make_scene<2>(cavity_prm(m), 2);
      s->run(false);
      ASSERT_TRUE(s->summary().result.converged);
      // The scene's own Hertz reference (printed and in summary.json).
      ASSERT_FALSE(s->summary().comparisons.empty());
      const auto &hertz = s->summary().comparisons[0];
      ASSERT_EQ(hertz.type, "hertz");
      EXPECT_NEAR(hertz.values[0].second, a_H, 1e-12 * a_H);
      EXPECT_NEAR(hertz.values[1].second, N_H, 1e-12 * N_H);
      a.push_back(s->summary().half_width);
      N.push_back(s->summary().max_pressure);
      const double size = dpana::test::contact_element_size(*s);
      h.push_back(size);
      std::cout << "Cylinder in cavity, contact refinements " << m
                << ": a = " << a.back() << " mm (element " << size
                << " mm), N_max = " << N.back()
                << " MPa; relative to the reference table "
                << a.back() / a_table - 1 << ", " << N.back() / N_table - 1
                << "; to Hertz " << a.back() / a_H - 1 << ", "
                << N.back() / N_H - 1 << std::endl;
    }
  EXPECT_LT(std::abs(N[2] - N[1]) / N[2], 0.01);
  EXPECT_LT(std::abs(N[2] - N[1]), std::abs(N[1] - N[0]));
  EXPECT_LT(std::abs(N[2] - N_table) / N_table, 0.03);
  EXPECT_LT(std::abs(N[2] - N_H) / N_H, 0.08);
  for (unsigned int i = 0; i < 3; ++i)
    {
      EXPECT_LE(std::abs(a[i] - a_table), h[i]) << "mesh " << i;
      EXPECT_LT(a[i], a_H) << "mesh " << i;
    }
}
