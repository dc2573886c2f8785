// Writes plate_with_hole_v41.msh and plate_with_hole_v22.msh (tests/data),
// two real gmsh outputs used by tests/unit/fe/geometry_test.cc, with the gmsh
// API that ships with Debian's gmsh library. Not part of the build:
//   g++ -std=c++17 make_plate_with_hole.cc -o make_plate -lgmsh && ./make_plate
//   .
#include <string>

#include <gmsh.h>
int
main(int argc, char **argv)
{
  const std::string dir = argc > 1 ? argv[1] : ".";
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("plate");
  // The plate [0, 4] x [0, 2] with a hole of radius 0.5 at (2, 1).
  const int rect = gmsh::model::occ::addRectangle(0, 0, 0, 4, 2);
  const int disc = gmsh::model::occ::addDisk(2, 1, 0, 0.5, 0.5);
  std::vector<std::pair<int, int>>              out;
  std::vector<std::vector<std::pair<int, int>>> map;
  gmsh::model::occ::cut({{2, rect}}, {{2, disc}}, out, map);
  gmsh::model::occ::synchronize();
  std::vector<std::pair<int, int>> curves;
  gmsh::model::getEntities(curves, 1);
  std::vector<int> outer, hole;
  for (const auto &c : curves)
    {
      double xmin, ymin, zmin, xmax, ymax, zmax;
      gmsh::model::getBoundingBox(
        1, c.second, xmin, ymin, zmin, xmax, ymax, zmax);
      if (xmin > 1.4 && xmax < 2.6 && ymin > 0.4 && ymax < 1.6)
        hole.push_back(c.second);
      else
        outer.push_back(c.second);
    }
  gmsh::model::addPhysicalGroup(1, outer, 1);
  gmsh::model::setPhysicalName(1, 1, "outer");
  gmsh::model::addPhysicalGroup(1, hole, 2);
  gmsh::model::setPhysicalName(1, 2, "hole");
  gmsh::model::addPhysicalGroup(2, {out[0].second}, 3);
  gmsh::model::setPhysicalName(2, 3, "plate");
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.6);
  gmsh::model::mesh::generate(2);
  gmsh::option::setNumber("Mesh.Binary", 0);
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::write(dir + "/plate_with_hole_v41.msh");
  gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
  gmsh::write(dir + "/plate_with_hole_v22.msh");
  gmsh::model::remove();

  gmsh::model::add("column");
  // The column [0, 1] x [0, 1] x [0, 2].
  const int box = gmsh::model::occ::addBox(0, 0, 0, 1, 1, 2);
  gmsh::model::occ::synchronize();
  std::vector<std::pair<int, int>> surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::vector<int> bottom, top, sides;
  for (const auto &s : surfaces)
    {
      double xmin, ymin, zmin, xmax, ymax, zmax;
      gmsh::model::getBoundingBox(
        2, s.second, xmin, ymin, zmin, xmax, ymax, zmax);
      if (zmax < 0.1)
        bottom.push_back(s.second);
      else if (zmin > 1.9)
        top.push_back(s.second);
      else
        sides.push_back(s.second);
    }
  gmsh::model::addPhysicalGroup(2, bottom, 1);
  gmsh::model::setPhysicalName(2, 1, "bottom");
  gmsh::model::addPhysicalGroup(2, top, 2);
  gmsh::model::setPhysicalName(2, 2, "top");
  gmsh::model::addPhysicalGroup(2, sides, 3);
  gmsh::model::setPhysicalName(2, 3, "sides");
  gmsh::model::addPhysicalGroup(3, {box}, 4);
  gmsh::model::setPhysicalName(3, 4, "column");
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.9);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.9);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::model::mesh::generate(3);
  gmsh::option::setNumber("Mesh.Binary", 0);
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::write(dir + "/column_v41.msh");
  gmsh::finalize();
}
