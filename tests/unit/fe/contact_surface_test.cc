// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Tests of the candidate contact surface: grouping of faces into contact
// elements, frames, pairing of two bodies.

#include <dpana/base/exceptions.h>
#include <dpana/scene/contact_scene.h>

#include <deal.II/base/parameter_handler.h>

#include <set>
#include <string>

#include "scene_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dpana;

  std::string
  box_prm(const std::string &faces_per_element)
  {
    return "set Dimension = 3\n"
           "subsection Body 1\n"
           "  subsection Geometry\n"
           "    set Type = box\n"
           "    set Lower corner = 0, 0, 0\n"
           "    set Upper corner = 8, 2, 4\n"
           "    set Subdivisions = 4, 1, 2\n"
           "  end\n"
           "  subsection Boundary conditions\n"
           "    set Fixed = top: x, y, z\n"
           "  end\n"
           "end\n"
           "subsection Contact\n"
           "  set Boundary 1 = bottom\n"
           "  set Faces per contact element = " +
           faces_per_element +
           "\n"
           "end\n";
  }

  using dpana::test::make_scene;
} // namespace



// A structured 3D base of 4 x 2 quadrilaterals of 2 x 2 mm, each split in
// two triangles: the default grouping gives 2 elements of 2 x 2
// quadrilaterals (8 triangles, 16 mm^2 each), with the outward normal
// (0, -1, 0) and a right-handed frame.
TEST(ContactSurface, StructuredPatchesOfEightTriangles)
{
  auto s = make_scene<3>(box_prm("0"));
  s->setup_bodies();
  s->setup_surfaces();
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



// A group size that is no lattice patch (6) falls back to the greedy
// agglomeration: every face in exactly one element, no element larger than
// 6 faces, every element connected (its faces linked by shared edges).
TEST(ContactSurface, GreedyAgglomerationCoversTheSurface)
{
  auto s = make_scene<3>(box_prm("6"));
  s->setup_bodies();
  s->setup_surfaces();
  const auto                 &surface = s->surface(0);
  const auto                 &faces   = surface.get_faces();
  std::multiset<unsigned int> used;
  double                      area = 0;
  for (const auto &e : surface.get_elements())
    {
      EXPECT_LE(e.faces.size(), 6u);
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



// Two bodies whose meshes do not match on the interface (2.5 mm edges on
// the block, 80/30 mm on the foundation) are refused with one line.
TEST(ContactSurface, NonMatchingPairIsRefused)
{
  const std::string text = "set Dimension = 2\n"
                           "set Number of bodies = 2\n"
                           "subsection Body 1\n"
                           "  subsection Geometry\n"
                           "    set Upper corner = 40, 40\n"
                           "    set Subdivisions = 16, 16\n"
                           "  end\n"
                           "  subsection Boundary conditions\n"
                           "    set Symmetry = left\n"
                           "  end\n"
                           "end\n"
                           "subsection Body 2\n"
                           "  subsection Geometry\n"
                           "    set Lower corner = 0, -80\n"
                           "    set Upper corner = 80, 0\n"
                           "    set Subdivisions = 30, 30\n"
                           "  end\n"
                           "  subsection Boundary conditions\n"
                           "    set Fixed = bottom: x, y\n"
                           "  end\n"
                           "end\n"
                           "subsection Contact\n"
                           "  set Candidate half width = 40\n"
                           "end\n";
  auto              s    = make_scene<2>(text, 2);
  s->setup_bodies();
  try
    {
      s->setup_surfaces();
      FAIL() << "non-matching surfaces were accepted";
    }
  catch (const InputError &e)
    {
      const std::string what = e.what();
      EXPECT_NE(what.find("do not match"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}
