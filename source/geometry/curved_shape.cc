// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/curved_shape.h>

#include <deal.II/base/patterns.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "refined_quadrilaterals.h"

namespace dpana
{
  namespace geometry
  {
    // @sect3{Contact refinement entries}
    void
    ContactRefinement::declare_parameters(dealii::ParameterHandler &prm,
                                          const std::string        &point)
    {
      prm.declare_entry("Contact refinements",
                        "0",
                        dealii::Patterns::Integer(0, 10),
                        "Extra refinements of the cells near " + point +
                          ". The cells within the Contact refinement radius "
                          "of that point end up 2^(this number) times "
                          "smaller than the others.");
      prm.declare_entry("Contact refinement radius",
                        "0.25",
                        dealii::Patterns::Double(0.),
                        "Radius (mm) of the zone around the contact point "
                        "refined by the Contact refinements.");
    }



    void
    ContactRefinement::parse_parameters(dealii::ParameterHandler &prm,
                                        const std::string        &path)
    {
      n_refinements = prm.get_integer("Contact refinements");
      radius        = prm.get_double("Contact refinement radius");
      if (n_refinements > 0 && !(radius > 0))
        throw InputError(path +
                         " / Contact refinement radius: must be positive "
                         "when Contact refinements > 0");
    }



    std::string
    ContactRefinement::description() const
    {
      if (n_refinements == 0)
        return "";
      return ", " + std::to_string(n_refinements) +
             " contact refinements within " + internal::format_number(radius);
    }



    // @sect3{From quadrilaterals to simplices}
    namespace
    {
      // The fan of triangles of one polygon around its centre vertex,
      // counterclockwise (positive Jacobian).
      void
      add_fan(const std::vector<dealii::Point<2>> &vertices,
              const unsigned int                   centre,
              const std::vector<unsigned int>     &polygon,
              std::vector<dealii::CellData<2>>    &triangles)
      {
        for (unsigned int i = 0; i < polygon.size(); ++i)
          {
            dealii::CellData<2> t(3);
            t.vertices = {centre,
                          polygon[i],
                          polygon[(i + 1) % polygon.size()]};
            const dealii::Tensor<1, 2> e1 =
              vertices[t.vertices[1]] - vertices[t.vertices[0]];
            const dealii::Tensor<1, 2> e2 =
              vertices[t.vertices[2]] - vertices[t.vertices[0]];
            if (e1[0] * e2[1] - e1[1] * e2[0] < 0)
              std::swap(t.vertices[1], t.vertices[2]);
            triangles.push_back(t);
          }
      }



      // Splits the active quadrilaterals into triangles as described in the
      // header. The vertices of the quadrilateral mesh keep their indices
      // (unused ones are removed later); the cell centres are appended.
      void
      quads_to_triangles(const internal::RefinedQuadrilaterals &refined,
                         std::vector<dealii::Point<2>>         &vertices,
                         std::vector<dealii::CellData<2>>      &triangles)
      {
        const dealii::Triangulation<2> &quads = refined.mesh();
        vertices                              = quads.get_vertices();
        triangles.clear();
        // The boundary of the reference square, counterclockwise: each entry
        // is (face, first vertex, second vertex).
        const unsigned int loop[4][3] = {{2, 0, 1},
                                         {1, 1, 3},
                                         {3, 3, 2},
                                         {0, 2, 0}};
        for (const auto &cell : quads.active_cell_iterators())
          {
            std::vector<unsigned int> polygon;
            for (const auto &side : loop)
              {
                polygon.push_back(cell->vertex_index(side[1]));
                const auto face = cell->face(side[0]);
                if (face->has_children())
                  {
                    // The midpoint is the vertex the two halves share,
                    // whatever the orientation of the face.
                    Assert(face->n_children() == 2, dealii::ExcInternalError());
                    Assert(!face->child(0)->has_children(),
                           dealii::ExcInternalError());
                    polygon.push_back(face->child(0)->vertex_index(1));
                  }
              }
            const unsigned int centre = vertices.size();
            vertices.push_back(refined.centre(cell));
            add_fan(vertices, centre, polygon, triangles);
          }
      }



      // Extrudes triangles along z through the planes z_0 < ... < z_n into
      // prisms, three tetrahedra each, positively oriented.
      void
      extrude_triangles(const std::vector<dealii::Point<2>>    &vertices_2d,
                        const std::vector<dealii::CellData<2>> &triangles,
                        const std::vector<double>              &z,
                        std::vector<dealii::Point<3>>          &vertices,
                        std::vector<dealii::CellData<3>>       &tets)
      {
        const unsigned int n2 = vertices_2d.size();
        vertices.clear();
        tets.clear();
        for (const double zk : z)
          for (const auto &x : vertices_2d)
            vertices.emplace_back(x[0], x[1], zk);
        for (unsigned int k = 0; k + 1 < z.size(); ++k)
          for (const auto &t : triangles)
            {
              std::array<unsigned int, 3> v = {
                {t.vertices[0], t.vertices[1], t.vertices[2]}};
              std::sort(v.begin(), v.end());
              const unsigned int a = k * n2 + v[0], b = k * n2 + v[1],
                                 c  = k * n2 + v[2];
              const unsigned int a1 = a + n2, b1 = b + n2, c1 = c + n2;
              for (const auto &q :
                   {std::array<unsigned int, 4>{{a, b, c, c1}},
                    std::array<unsigned int, 4>{{a, b, b1, c1}},
                    std::array<unsigned int, 4>{{a, a1, b1, c1}}})
                {
                  dealii::CellData<3> tet(4);
                  tet.vertices = {q[0], q[1], q[2], q[3]};
                  const dealii::Tensor<1, 3> e1 =
                    vertices[q[1]] - vertices[q[0]];
                  const dealii::Tensor<1, 3> e2 =
                    vertices[q[2]] - vertices[q[0]];
                  const dealii::Tensor<1, 3> e3 =
                    vertices[q[3]] - vertices[q[0]];
                  if (dealii::cross_product_3d(e1, e2) * e3 < 0)
                    std::swap(tet.vertices[2], tet.vertices[3]);
                  tets.push_back(tet);
                }
            }
      }
    } // namespace



    template <int dim>
    CurvedShape<dim>::CurvedShape(const bool quarter)
      : quarter(quarter)
    {
    }



    template <int dim>
    std::vector<double>
    CurvedShape<dim>::z_planes(const unsigned int) const
    {
      Assert(false, dealii::ExcNotImplemented());
      return {};
    }



    template <int dim>
    std::vector<std::pair<dealii::Point<2>, ContactRefinement>>
    CurvedShape<dim>::further_refinements() const
    {
      return {};
    }



    // 4 triangles per quadrilateral (the fan around its centre), 4 children
    // per refinement, and in 3D 3 tetrahedra per prism of each layer. The
    // contact refinements, local, are left out of the estimate.
    template <int dim>
    std::pair<double, std::string>
    CurvedShape<dim>::estimated_size(
      const unsigned int n_global_refinements) const
    {
      dealii::Triangulation<2> quads;
      make_quadrilaterals(quads);
      double n_cells =
        4. * quads.n_active_cells() * std::pow(4., n_global_refinements);
      if constexpr (dim == 3)
        n_cells *=
          3. * (z_planes(0).size() - 1.) * std::pow(2., n_global_refinements);
      return {n_cells, "Geometry / Global refinements"};
    }



    template <int dim>
    void
    CurvedShape<dim>::create_triangulation(
      dealii::Triangulation<dim> &tria,
      const unsigned int          n_global_refinements) const
    {
      dealii::Triangulation<2> coarse(
        dealii::Triangulation<2>::limit_level_difference_at_vertices);
      make_quadrilaterals(coarse);
      internal::RefinedQuadrilaterals quads(coarse);
      quads.refine_global(n_global_refinements);
      quads.refine_near(contact_point(),
                        refinement.radius,
                        refinement.n_refinements);
      for (const auto &[point, zone] : further_refinements())
        quads.refine_near(point, zone.radius, zone.n_refinements);

      std::vector<dealii::Point<2>>    vertices_2d;
      std::vector<dealii::CellData<2>> triangles;
      quads_to_triangles(quads, vertices_2d, triangles);
      dealii::SubCellData subcell_data;
      dealii::GridTools::delete_unused_vertices(vertices_2d,
                                                triangles,
                                                subcell_data);
      if constexpr (dim == 2)
        tria.create_triangulation(vertices_2d, triangles, subcell_data);
      else
        {
          std::vector<dealii::Point<3>>    vertices;
          std::vector<dealii::CellData<3>> tets;
          extrude_triangles(vertices_2d,
                            triangles,
                            z_planes(n_global_refinements),
                            vertices,
                            tets);
          tria.create_triangulation(vertices, tets, dealii::SubCellData());
        }

      const auto names = this->boundary_names();
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
          face->set_boundary_id(names.at(boundary_name(face->center())));
    }



    template class CurvedShape<2>;
    template class CurvedShape<3>;
  } // namespace geometry
} // namespace dpana
