// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/contact_surface/parameters.h>
#include <dpana/parameters/list_syntax.h>

#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

namespace dpana
{
  namespace contact_surface
  {
    template <int dim>
    void
    Parameters<dim>::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Boundary 1",
                        "bottom",
                        Anything(),
                        "Named boundary of Body 1 that holds the candidate "
                        "contact surface Gamma_c.");
      prm.declare_entry("Boundary 2",
                        "top",
                        Anything(),
                        "Named boundary of Body 2 that holds Gamma_c (two "
                        "bodies only). Its faces need not match those of "
                        "Body 1: the faces that face Body 1 are projected "
                        "onto its contact elements along the contact "
                        "direction, and must cover them.");
      prm.declare_entry("Candidate centre",
                        dim == 2 ? "0, 0" : "0, 0, 0",
                        Anything(),
                        "Centre x0 of the candidate region (mm); also the "
                        "origin from which the contact half width is "
                        "measured.");
      prm.declare_entry("Candidate half width",
                        "0",
                        Double(0.),
                        "Half width w of the candidate region (mm): only the "
                        "faces whose centroid x has |x_d - x0_d| <= w in "
                        "every direction d are candidates. 0: the whole "
                        "boundary.");
      prm.declare_entry("Faces per contact element",
                        "0",
                        Integer(0),
                        "Number of faces grouped into one contact element "
                        "carrying constant tractions. 0: 2 edges in 2D, 8 "
                        "triangles (a 2 x 2 patch of split quadrilaterals) "
                        "in 3D. Take at least 2 in 2D and 4 in 3D: with "
                        "fewer, nearly as many tractions as surface "
                        "vertices oscillate from element to element (2 "
                        "triangles per element put N_max of the quarter "
                        "sphere 40 % above Hertz's p0), and one triangle "
                        "per element makes A singular (the log warns of "
                        "both).");
      prm.declare_entry(
        "Contact elements",
        "faces",
        Selection("faces|vertices"),
        "The parts of Gamma_c that carry one constant traction. faces: "
        "groups of Faces per contact element adjacent faces (the reference "
        "formulation). vertices (Faces per contact element = 0): one "
        "element around each vertex of Gamma_c, its median dual cell (in 2D "
        "the halves of the edges next to it; in 3D the part of each "
        "triangle at it bounded by the midpoints of its two edges there and "
        "its centroid); as many tractions as surface vertices, the "
        "traction form of nodal contact conditions, more accurate per "
        "degree of freedom on coarse meshes.");
      prm.declare_entry("Contact direction",
                        "",
                        Anything(),
                        "Unit normal n (pointing out of Body 1 towards the "
                        "obstacle) used by every contact element, e.g. "
                        "'0, -1': the normal of the tangent plane of an "
                        "increasing (Hertz) problem. Empty: on the rigid "
                        "plane every element uses the mean outward normal "
                        "of the candidate faces (the plane's normal); "
                        "between two bodies each element uses the mean "
                        "outward normal of its own faces. Give it for a "
                        "half or quarter model on a rigid plane, whose "
                        "candidate surface leans away from the symmetry "
                        "planes: without it the quarter sphere of "
                        "prm/hertz_sphere_rigid.prm gives N_max 1.45 times "
                        "Hertz's p0 and a_m 70 % too large.");
      prm.declare_entry("Obstacle point",
                        "",
                        Anything(),
                        "One body: a point (mm) of the rigid plane obstacle, "
                        "normal to the contact direction. Empty: the first "
                        "contact point (the candidate vertex farthest along "
                        "n), so that the initial gap is >= 0 and zero there.");
    }



    template <int dim>
    void
    Parameters<dim>::parse_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Utilities::trim;
      boundary = {{prm.get("Boundary 1"), prm.get("Boundary 2")}};
      region_centre =
        parameters::parse_point<dim>(prm.get("Candidate centre"),
                                     "Contact / Candidate centre");
      region_half_width = prm.get_double("Candidate half width");
      faces_per_element = prm.get_integer("Faces per contact element");
      shape             = prm.get("Contact elements") == "vertices" ?
                            ElementShape::vertex_patches :
                            ElementShape::face_groups;
      if (shape == ElementShape::vertex_patches && faces_per_element != 0)
        throw InputError("Contact / Faces per contact element = " +
                         std::to_string(faces_per_element) +
                         ": must be 0 with Contact elements = vertices (each "
                         "element is the patch around one vertex)");

      const std::string direction_text = trim(prm.get("Contact direction"));
      direction                        = dealii::Tensor<1, dim>();
      if (!direction_text.empty())
        {
          direction =
            parameters::parse_vector<dim>(direction_text,
                                          "Contact / Contact direction");
          if (direction.norm() == 0)
            throw InputError("Contact / Contact direction: must not be the "
                             "zero vector (leave it empty for the element "
                             "normals)");
        }

      const std::string obstacle_text = trim(prm.get("Obstacle point"));
      obstacle_point_given            = !obstacle_text.empty();
      obstacle_point                  = dealii::Point<dim>();
      if (obstacle_point_given)
        obstacle_point =
          parameters::parse_point<dim>(obstacle_text,
                                       "Contact / Obstacle point");
    }



    template <int dim>
    typename ContactSurface<dim>::Options
    Parameters<dim>::surface_options(
      const unsigned int                                       b,
      const std::string                                       &body,
      const std::map<std::string, dealii::types::boundary_id> &boundary_names)
      const
    {
      const auto it = boundary_names.find(boundary[b]);
      if (it == boundary_names.end())
        {
          std::string list;
          for (const auto &n : boundary_names)
            list += (list.empty() ? "" : ", ") + n.first;
          throw InputError("Contact / Boundary " + std::to_string(b + 1) +
                           ": " + body + " has no boundary named '" +
                           boundary[b] + "' (it has: " + list + ")");
        }
      typename ContactSurface<dim>::Options options;
      options.boundary          = boundary[b];
      options.boundary_id       = it->second;
      options.body              = body;
      options.region_centre     = region_centre;
      options.region_half_width = region_half_width;
      options.faces_per_element = faces_per_element;
      options.shape             = shape;
      options.direction         = b == 0 ? direction : -direction;
      return options;
    }



    template struct Parameters<2>;
    template struct Parameters<3>;
  } // namespace contact_surface
} // namespace dpana
