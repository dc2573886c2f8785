// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Shared by the geometry tests: a geometry read from the text of its
// subsection, the measures of a mesh (cell and face measures summed with a
// simplex quadrature and MappingFE of degree one, exact for affine cells up
// to rounding), and the checks of curved boundaries.
#ifndef dpana_tests_geometry_test_tools_h
#define dpana_tests_geometry_test_tools_h

#include <dpana/geometry/geometry.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

namespace dpana
{
  namespace test
  {
    using dealii::types::boundary_id;

    // The text of the subsection of a shape.
    inline std::string
    shape(const std::string &subsection, const std::string &entries)
    {
      return "subsection " + subsection + "\n" + entries + "end\n";
    }

    // A geometry read from the text of a "Geometry" subsection.
    template <int dim>
    geometry::Geometry<dim>
    make_geometry(const std::string &text)
    {
      dealii::ParameterHandler prm;
      geometry::Geometry<dim>::declare_parameters(prm);
      prm.parse_input_from_string(text);
      geometry::Geometry<dim> geometry;
      geometry.parse_parameters(prm);
      return geometry;
    }

    // Volume (area) of the mesh, measure and number of the boundary faces per
    // id, and the checks every mesh must pass: positive Jacobians, every
    // boundary face named.
    struct Measures
    {
      unsigned int                    n_cells = 0;
      double                          volume  = 0;
      std::map<boundary_id, double>   boundary_measure;
      std::map<boundary_id, unsigned> n_boundary_faces;
      double                          min_jxw = 1e300;
    };

    template <int dim>
    Measures
    measure(const dealii::Triangulation<dim> &tria)
    {
      const dealii::FE_SimplexP<dim>       fe(1);
      const dealii::MappingFE<dim>         mapping(fe);
      const dealii::QGaussSimplex<dim>     quadrature(2);
      const dealii::QGaussSimplex<dim - 1> face_quadrature(2);
      dealii::FEValues<dim>                fe_values(mapping,
                                      fe,
                                      quadrature,
                                      dealii::update_JxW_values |
                                        dealii::update_jacobians);
      dealii::FEFaceValues<dim>            fe_face_values(mapping,
                                               fe,
                                               face_quadrature,
                                               dealii::update_JxW_values);
      Measures                             m;
      m.n_cells = tria.n_active_cells();
      for (const auto &cell : tria.active_cell_iterators())
        {
          fe_values.reinit(cell);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              m.volume += fe_values.JxW(q);
              m.min_jxw =
                std::min(m.min_jxw, fe_values.jacobian(q).determinant());
            }
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                fe_face_values.reinit(cell, f);
                const boundary_id id = cell->face(f)->boundary_id();
                ++m.n_boundary_faces[id];
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  m.boundary_measure[id] += fe_face_values.JxW(q);
              }
        }
      return m;
    }

    template <int dim>
    std::set<std::string>
    names_of(const geometry::Geometry<dim> &geometry)
    {
      std::set<std::string> s;
      for (const auto &n : geometry.boundary_names())
        s.insert(n.first);
      return s;
    }

    // Every vertex of the faces with the given id lies on the circle
    // |(x, y) - c| = r: returns the largest deviation.
    template <int dim>
    double
    distance_from_circle(const dealii::Triangulation<dim> &tria,
                         const boundary_id                 id,
                         const dealii::Point<2>            c,
                         const double                      r)
    {
      double d = 0;
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          for (const unsigned int v : face->vertex_indices())
            d = std::max(d,
                         std::abs(std::hypot(face->vertex(v)[0] - c[0],
                                             face->vertex(v)[1] - c[1]) -
                                  r));
      return d;
    }

    inline void
    expect_relative(const double value, const double reference)
    {
      EXPECT_NEAR(value, reference, 1e-12 * std::abs(reference));
    }
  } // namespace test
} // namespace dpana

#endif
