// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_contact_surface_parameters_h
#define dpana_contact_surface_parameters_h

#include <dpana/contact_surface/contact_surface.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <map>
#include <string>

namespace dpana
{
  namespace contact_surface
  {
    /**
     * The parameters of the candidate contact surfaces: which boundary of
     * each body holds Gamma_c, the candidate region, the size of the contact
     * elements, the contact direction and, for one body, the rigid plane
     * obstacle. In a parameter file they are entries of `subsection
     * Contact`:
     *
     *     subsection Contact
     *       set Boundary 1                = curved
     *       set Boundary 2                = top
     *       set Candidate centre          = 0, 0
     *       set Candidate half width      = 15
     *       set Faces per contact element = 0
     *       set Contact elements          = faces
     *       set Contact direction         = 0, -1
     *       set Obstacle point            =
     *     end
     *
     * declare_parameters() declares these entries, and parse_parameters()
     * reads them, in the subsection the caller has entered (the caller
     * enters `Contact` and declares the entries of the other components of
     * a contact run there as well). Points and vectors have exactly dim
     * finite coordinates. An empty Contact direction means that every
     * contact element uses the mean outward normal of the candidate faces
     * on the rigid plane, and of its own faces between two bodies; an empty
     * Obstacle point means the first contact point of Body 1's candidate
     * surface (ContactSurface::first_contact_point()).
     */
    template <int dim>
    struct Parameters
    {
      // The named boundaries of Body 1 and Body 2 that hold Gamma_c.
      std::array<std::string, 2> boundary = {{"bottom", "top"}};
      // Candidate region of Body 1: centre x0 and half width w (mm; w = 0:
      // the whole boundary).
      dealii::Point<dim> region_centre;
      double             region_half_width = 0;
      // Faces per contact element (0: 2 edges in 2D, 8 triangles in 3D).
      unsigned int faces_per_element = 0;
      // Groups of faces, or patches around the vertices.
      ElementShape shape = ElementShape::face_groups;
      // The contact direction n, out of Body 1 (zero: not given, the
      // element normals).
      dealii::Tensor<1, dim> direction;
      // One body: a point of the rigid plane, if given.
      bool               obstacle_point_given = false;
      dealii::Point<dim> obstacle_point;

      /**
       * Declare the entries Boundary 1, Boundary 2, Candidate centre,
       * Candidate half width, Faces per contact element, Contact elements,
       * Contact direction and Obstacle point, with their defaults and help
       * texts, in the
       * current subsection of @p prm.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * Read the entries declared by declare_parameters() from the current
       * subsection of @p prm. Throws dpana::InputError with a one-line
       * message naming the entry ("Contact / Contact direction: ...") for a
       * point or vector without exactly dim finite coordinates, for a
       * zero contact direction, and for Contact elements = vertices in 3D
       * or with a nonzero Faces per contact element.
       */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /**
       * The options of the candidate surface of body @p b (0: Body 1,
       * 1: Body 2) named @p body, whose mesh carries the boundaries
       * @p boundary_names: the boundary id of Boundary b+1, the candidate
       * region, the faces per element and the shape of the elements, and
       * the contact direction (negated for Body 2, whose normal points
       * towards Body 1). Throws
       * dpana::InputError if the body has no boundary of that name.
       */
      typename ContactSurface<dim>::Options
      surface_options(const unsigned int b,
                      const std::string &body,
                      const std::map<std::string, dealii::types::boundary_id>
                        &boundary_names) const;
    };
  } // namespace contact_surface
} // namespace dpana

#endif
