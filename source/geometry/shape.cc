// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/shape.h>

#include <cstdio>
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



    void
    check_mesh_size(const double n_cells, const std::string &parameter)
    {
      if (!(n_cells > max_cells))
        return;
      char estimate[64];
      std::snprintf(estimate,
                    sizeof(estimate),
                    "%.2g cells (about %.2g GB)",
                    n_cells,
                    n_cells * 1e3 / 1e9);
      throw InputError(parameter + ": the mesh would have " + estimate +
                       ", more than the 5e7 cells this program accepts");
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
