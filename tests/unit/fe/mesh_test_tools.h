// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Shared by the unit tests that build a body's mesh directly: a brick split
// into simplices with the boundary names of the rectangle/box geometry.
#ifndef dpana_tests_mesh_test_tools_h
#define dpana_tests_mesh_test_tools_h

#include <dpana/geometry/geometry.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <deal.II/grid/tria.h>

#include <iomanip>
#include <map>
#include <sstream>
#include <string>

namespace dpana
{
  namespace test
  {
    /**
     * The brick [0, upper] with @p n cells per direction split into
     * simplices by the rectangle/box geometry, which names its boundaries
     * left 0, right 1, bottom 2, top 3 (, front 4, back 5). Returns the
     * names of these ids.
     */
    template <int dim>
    std::map<std::string, dealii::types::boundary_id>
    make_named_brick(dealii::Triangulation<dim> &tria,
                     const unsigned int          n,
                     const dealii::Point<dim>   &upper)
    {
      std::ostringstream text;
      text << std::setprecision(17) << "subsection "
           << (dim == 2 ? "Rectangle" : "Box") << "\nset Upper corner = ";
      for (unsigned int d = 0; d < dim; ++d)
        text << (d == 0 ? "" : ", ") << upper[d];
      text << "\nset Subdivisions = ";
      for (unsigned int d = 0; d < dim; ++d)
        text << (d == 0 ? "" : ", ") << n;
      text << "\nend\n";

      dealii::ParameterHandler prm;
      geometry::Geometry<dim>::declare_parameters(prm);
      prm.parse_input_from_string(text.str());
      geometry::Geometry<dim> brick;
      brick.parse_parameters(prm);
      brick.create_triangulation(tria);
      return brick.boundary_names();
    }
  } // namespace test
} // namespace dpana

#endif
