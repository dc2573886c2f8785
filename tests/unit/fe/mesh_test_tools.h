// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Shared by the unit tests that build a body's mesh directly: a brick split
// into simplices with the boundary names of the rectangle/box geometry.
#ifndef dpana_tests_mesh_test_tools_h
#define dpana_tests_mesh_test_tools_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace dpana
{
  namespace test
  {
    /**
     * The brick [0, upper] with @p n cells per direction split into
     * simplices, with the boundary ids of the rectangle/box geometry set
     * from the face centres: left 0, right 1, bottom 2, top 3 (, front 4,
     * back 5). Returns the names of these ids.
     */
    template <int dim>
    std::map<std::string, dealii::types::boundary_id>
    make_named_brick(dealii::Triangulation<dim> &tria,
                     const unsigned int          n,
                     const dealii::Point<dim>   &upper)
    {
      dealii::GridGenerator::subdivided_hyper_rectangle_with_simplices(
        tria, std::vector<unsigned int>(dim, n), dealii::Point<dim>(), upper);
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
          {
            const auto c = face->center();
            for (unsigned int d = 0; d < dim; ++d)
              {
                if (std::abs(c[d]) < 1e-12)
                  face->set_boundary_id(2 * d);
                else if (std::abs(c[d] - upper[d]) < 1e-12)
                  face->set_boundary_id(2 * d + 1);
              }
          }
      std::map<std::string, dealii::types::boundary_id> names = {{"left", 0},
                                                                 {"right", 1},
                                                                 {"bottom", 2},
                                                                 {"top", 3}};
      if (dim == 3)
        {
          names["front"] = 4;
          names["back"]  = 5;
        }
      return names;
    }
  } // namespace test
} // namespace dpana

#endif
