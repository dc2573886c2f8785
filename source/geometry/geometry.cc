// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/geometry/annulus.h>
#include <dpana/geometry/brick.h>
#include <dpana/geometry/circle.h>
#include <dpana/geometry/disc.h>
#include <dpana/geometry/geometry.h>
#include <dpana/geometry/gmsh_file.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/patterns.h>

#include <algorithm>
#include <functional>
#include <vector>

namespace dpana
{
  namespace geometry
  {
    namespace
    {
      // One value of Type: the subsection of its entries, the dimension it
      // exists in (0: both) and the class that makes it.
      template <int dim>
      struct ShapeType
      {
        std::string                                     type;
        std::string                                     subsection;
        unsigned int                                    dimension;
        std::function<void(dealii::ParameterHandler &)> declare;
        std::function<std::unique_ptr<Shape<dim>>()>    create;
      };

      template <int dim>
      const std::vector<ShapeType<dim>> &
      shape_types()
      {
        static const std::vector<ShapeType<dim>> types = {
          {"rectangle",
           "Rectangle",
           2,
           &Brick<dim>::declare_parameters,
           [] { return std::make_unique<Brick<dim>>(); }},
          {"box",
           "Box",
           3,
           &Brick<dim>::declare_parameters,
           [] { return std::make_unique<Brick<dim>>(); }},
          {"disc",
           "Disc",
           2,
           &Circle<dim>::declare_parameters,
           [] { return std::make_unique<Circle<dim>>(false); }},
          {"right half disc",
           "Right half disc",
           2,
           &Circle<dim>::declare_parameters,
           [] { return std::make_unique<Circle<dim>>(true); }},
          {"half disc",
           "Half disc",
           2,
           &Disc<dim>::declare_parameters,
           [] { return std::make_unique<Disc<dim>>(false); }},
          {"quarter disc",
           "Quarter disc",
           2,
           &Disc<dim>::declare_parameters,
           [] { return std::make_unique<Disc<dim>>(true); }},
          {"half cylinder",
           "Half cylinder",
           3,
           &Disc<dim>::declare_parameters,
           [] { return std::make_unique<Disc<dim>>(false); }},
          {"half annulus",
           "Half annulus",
           2,
           &Annulus<dim>::declare_parameters,
           [] { return std::make_unique<Annulus<dim>>(false); }},
          {"quarter annulus",
           "Quarter annulus",
           2,
           &Annulus<dim>::declare_parameters,
           [] { return std::make_unique<Annulus<dim>>(true); }},
          {"gmsh", "Gmsh", 0, &GmshFile<dim>::declare_parameters, [] {
             return std::make_unique<GmshFile<dim>>();
           }}};
        return types;
      }



      template <int dim>
      bool
      exists_in_dim(const ShapeType<dim> &t)
      {
        return t.dimension == 0 || t.dimension == dim;
      }
    } // namespace



    template <int dim>
    Geometry<dim>::Geometry()
      : type_name(dim == 2 ? "rectangle" : "box")
      , n_global_refinements(0)
    {
    }



    // @sect3{Parameters}
    //
    // The shared entries, then one subsection per shape of this dimension.
    template <int dim>
    void
    Geometry<dim>::declare_parameters(dealii::ParameterHandler &prm)
    {
      std::string selection;
      for (const auto &t : shape_types<dim>())
        selection += (selection.empty() ? "" : "|") + t.type;
      prm.declare_entry(
        "Type",
        dim == 2 ? "rectangle" : "box",
        dealii::Patterns::Selection(selection),
        "The shape of the body. 2D: rectangle, disc, right half disc (the "
        "circular body and its half model x >= Centre_x), half disc, quarter "
        "disc (the D-shaped lower half of a disc and its half model), half "
        "annulus, quarter annulus, gmsh. 3D: box, half cylinder, gmsh. "
        "The entries of a shape are in the subsection named after its type "
        "(Rectangle, Half disc, ...). See doc/geometry.md for the boundary "
        "names of each type.");
      prm.declare_entry(
        "Global refinements",
        "0",
        dealii::Patterns::Integer(0, 10),
        "Number of uniform refinements; each one halves every edge. The "
        "curved types refine their quadrilateral mesh before it is split "
        "into simplices, so that new boundary vertices lie on the circles; "
        "rectangle, box and gmsh refine the simplex mesh.");
      for (const auto &t : shape_types<dim>())
        if (exists_in_dim(t))
          {
            prm.enter_subsection(t.subsection);
            t.declare(prm);
            prm.leave_subsection();
          }
    }



    template <int dim>
    void
    Geometry<dim>::parse_parameters(dealii::ParameterHandler &prm)
    {
      type_name         = prm.get("Type");
      const auto &types = shape_types<dim>();
      const auto  t     = std::find_if(types.begin(),
                                  types.end(),
                                  [this](const ShapeType<dim> &entry) {
                                    return entry.type == type_name;
                                  });
      Assert(t != types.end(), dealii::ExcInternalError());
      if (!exists_in_dim(*t))
        throw InputError(
          "Geometry: type '" + type_name + "' needs " +
          (t->dimension == 2 ? "Dimension = 2" : "Dimension = 3") +
          " (parameter Type)");
      n_global_refinements = prm.get_integer("Global refinements");

      std::unique_ptr<Shape<dim>> s = t->create();
      prm.enter_subsection(t->subsection);
      try
        {
          s->parse_parameters(prm, "Geometry / " + t->subsection);
          const auto [n_cells, parameter] =
            s->estimated_size(n_global_refinements);
          check_mesh_size(n_cells, parameter);
        }
      catch (...)
        {
          prm.leave_subsection();
          throw;
        }
      prm.leave_subsection();
      names = s->boundary_names();
      shape = std::move(s);
    }



    template <int dim>
    dealii::types::boundary_id
    Geometry<dim>::boundary_id(const std::string &name) const
    {
      const auto p = names.find(name);
      if (p == names.end())
        {
          std::string list;
          for (const auto &n : names)
            list += (list.empty() ? "" : ", ") + n.first;
          throw InputError("no boundary named " + parameters::quote(name) +
                           " (this geometry has: " + list + ")");
        }
      return p->second;
    }



    template <int dim>
    std::string
    Geometry<dim>::description() const
    {
      return type_name + (shape ? " " + shape->description() : "") + ", " +
             std::to_string(n_global_refinements) + " global refinements";
    }



    // @sect3{Creating the mesh}
    template <int dim>
    void
    Geometry<dim>::create_triangulation(dealii::Triangulation<dim> &tria) const
    {
      AssertThrow(shape != nullptr,
                  dealii::ExcMessage("Geometry::create_triangulation() needs "
                                     "the parameters of a Geometry "
                                     "subsection."));
      AssertThrow(tria.n_cells() == 0,
                  dealii::ExcMessage("The triangulation must be empty."));
      shape->create_triangulation(tria, n_global_refinements);
      tria.set_all_manifold_ids(dealii::numbers::flat_manifold_id);
      check_boundary_ids(tria);
    }



    // Every boundary face must carry one of the named ids: a face with an
    // unnamed id would silently escape every boundary condition.
    template <int dim>
    void
    Geometry<dim>::check_boundary_ids(
      const dealii::Triangulation<dim> &tria) const
    {
      const auto id = unnamed_boundary_id(tria, names);
      if (id)
        throw InputError("Geometry: boundary faces with id " +
                         std::to_string(*id) + " carry no boundary name (" +
                         description() + ")");
    }



    template class Geometry<2>;
    template class Geometry<3>;
  } // namespace geometry
} // namespace dpana
