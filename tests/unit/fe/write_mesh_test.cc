// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Output / Write mesh: body_N.msh holds the mesh the run solved on, read
// back by deal.II's own gmsh reader: the same cells, every vertex to the
// last bit (a file written with the stream's default 6 digits fails), and
// the boundary faces with their boundary ids.

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "scene_test_tools.h"
#include "scratch_path.h"
#include <gtest/gtest.h>

namespace
{
  namespace fs = std::filesystem;

  // The used vertices of @p tria, sorted.
  std::vector<std::array<double, 2>>
  vertices(const dealii::Triangulation<2> &tria)
  {
    std::vector<std::array<double, 2>> v;
    for (unsigned int i = 0; i < tria.n_vertices(); ++i)
      if (tria.get_used_vertices()[i])
        v.push_back({{tria.get_vertices()[i][0], tria.get_vertices()[i][1]}});
    std::sort(v.begin(), v.end());
    return v;
  }

  // (boundary id, centre) of the boundary faces of nonzero id, sorted.
  std::vector<std::pair<unsigned int, std::array<double, 2>>>
  boundary_faces(const dealii::Triangulation<2> &tria)
  {
    std::vector<std::pair<unsigned int, std::array<double, 2>>> faces;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() != 0)
          faces.push_back(
            {face->boundary_id(), {{face->center()[0], face->center()[1]}}});
    std::sort(faces.begin(), faces.end());
    return faces;
  }
} // namespace



TEST(WriteMesh, GmshFileHoldsTheMeshesTheRunSolvedOn)
{
  const fs::path out = dpana::test::scratch_path("write_mesh");
  fs::remove_all(out);
  // The Hertz cylinder on a floating foundation: two bodies, a curved
  // boundary refined towards the contact, several boundary ids.
  auto s = dpana::test::make_scene<2>(
    dpana::test::hertz_prm(2, 15, 0, dpana::test::floating_foundation()) +
      "subsection Output\n"
      "  set Write mesh = true\n"
      "  set Write VTU  = false\n"
      "  set Plot       = false\n"
      "end\n",
    2);
  s->set_output_directory(out.string());
  s->run(true);
  for (unsigned int b = 0; b < 2; ++b)
    {
      const auto              &solved = s->body(b).triangulation();
      dealii::Triangulation<2> read;
      dealii::GridIn<2>        in(read);
      std::ifstream file(out / ("body_" + std::to_string(b + 1) + ".msh"));
      ASSERT_TRUE(file) << "body " << b + 1;
      in.read_msh(file);
      EXPECT_EQ(read.n_active_cells(), solved.n_active_cells());
      EXPECT_EQ(vertices(read), vertices(solved)) << "body " << b + 1;
      const auto faces = boundary_faces(solved);
      EXPECT_FALSE(faces.empty());
      const auto faces_read = boundary_faces(read);
      ASSERT_EQ(faces_read.size(), faces.size());
      for (unsigned int f = 0; f < faces.size(); ++f)
        {
          EXPECT_EQ(faces_read[f].first, faces[f].first);
          for (unsigned int d = 0; d < 2; ++d)
            EXPECT_NEAR(faces_read[f].second[d], faces[f].second[d], 1e-12);
        }
    }
  fs::remove_all(out);
}
