// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/geometry/shape.h>

#include <set>

namespace dpana
{
  namespace geometry
  {
    template <int dim>
    std::optional<dealii::types::boundary_id>
    unnamed_boundary_id(
      const dealii::Triangulation<dim>                        &tria,
      const std::map<std::string, dealii::types::boundary_id> &names)
    {
      std::set<dealii::types::boundary_id> named;
      for (const auto &n : names)
        named.insert(n.second);
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary() && named.count(face->boundary_id()) == 0)
          return face->boundary_id();
      return std::nullopt;
    }



    template std::optional<dealii::types::boundary_id>
    unnamed_boundary_id(
      const dealii::Triangulation<2> &,
      const std::map<std::string, dealii::types::boundary_id> &);
    template std::optional<dealii::types::boundary_id>
    unnamed_boundary_id(
      const dealii::Triangulation<3> &,
      const std::map<std::string, dealii::types::boundary_id> &);
  } // namespace geometry
} // namespace dpana
