// Shared by the unit tests of the quarter sphere of
// prm/hertz_sphere_rigid.prm: its gmsh mesh written by the project's own
// generator (scripts/meshes/make_sphere.py), its parameter file, and the
// values of its Hertz comparison.
#ifndef dpana_tests_sphere_test_tools_h
#define dpana_tests_sphere_test_tools_h

#include <dpana/scene/contact_summary.h>

#include <cstdlib>
#include <map>
#include <string>

#include <gtest/gtest.h>

namespace dpana
{
  namespace test
  {
    // The mesh generator of the project, found from the path of this file.
    inline std::string
    mesh_script()
    {
      const std::string here = __FILE__;
      return here.substr(0, here.rfind("/tests/unit/fe/")) +
             "/scripts/meshes/make_sphere.py";
    }

    // Writes the mesh of level @p level of make_sphere.py for the tests.
    inline std::string
    sphere_mesh(const int level)
    {
      const std::string mesh =
        "meshes/unit_hertz_sphere_L" + std::to_string(level) + ".msh";
      const std::string command = "python3 " + mesh_script() + " " + mesh +
                                  " --level " + std::to_string(level) +
                                  " > /dev/null";
      EXPECT_EQ(std::system(command.c_str()), 0) << command;
      return mesh;
    }

    // The values of the comparison "hertz sphere" of a run, by name.
    inline std::map<std::string, double>
    hertz_sphere_values(const dpana::scene::ContactSummary &summary)
    {
      std::map<std::string, double> values;
      for (const auto &c : summary.comparisons)
        if (c.type == "hertz sphere")
          for (const auto &[name, value] : c.values)
            values[name] = value;
      return values;
    }

    // prm/hertz_sphere_rigid.prm on the mesh @p mesh_file.
    inline std::string
    sphere_prm(const std::string &mesh_file, const double mu)
    {
      return "set Dimension = 3\n"
             "subsection Body 1\n"
             "  subsection Geometry\n"
             "    set Type = gmsh\n"
             "    subsection Gmsh\n"
             "      set Mesh file = " +
             mesh_file +
             "\n"
             "    end\n"
             "  end\n"
             "  subsection Material\n"
             "    set Young's modulus = 130000\n"
             "    set Poisson's ratio = 0.2\n"
             "  end\n"
             "  subsection Boundary conditions\n"
             "    set Symmetry = symmetry_x, symmetry_z\n"
             "  end\n"
             "  subsection Loads\n"
             "    set Concentrated forces = 0, 80, 0: 0, -75000, 0\n"
             "  end\n"
             "end\n"
             "subsection Contact\n"
             "  set Boundary 1 = contact\n"
             "  set Contact direction = 0, -1, 0\n"
             "  set Friction coefficient = " +
             std::to_string(mu) +
             "\n"
             "  subsection Reference\n"
             "    set Type = hertz sphere\n"
             "    set Hertz load = 300000\n"
             "    set Radius 1 = 40\n"
             "    set Model fraction = 0.25\n"
             "  end\n"
             "end\n";
    }
  } // namespace test
} // namespace dpana

#endif
