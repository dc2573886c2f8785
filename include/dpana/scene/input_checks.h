// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_scene_input_checks_h
#define dpana_scene_input_checks_h

#include <dpana/body/body.h>
#include <dpana/contact/problem.h>
#include <dpana/contact_surface/contact_surface.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  namespace scene
  {
    /**
     * The check, before the contact solve, that the bodies which float
     * (whose supports leave rigid motions free) can be held by the contact
     * at all: that compressive tractions inside the friction cones can
     * balance their loads on every free rigid motion (the equality rows
     * G r = e of @p problem, contact::check_feasibility()). The rows of
     * every body are measured against one load scale, the largest sum of
     * the absolute nodal loads of a body.
     *
     * If they cannot, no solver can converge, and the scene is bad input:
     * throws dpana::InputError with one line that names the bodies and the
     * free motions along which the unbalanced part of the loads acts, e.g.
     * "Body 1 cannot be held by the contact: the part of its loads along +y
     * cannot be balanced by compressive tractions within the friction cones
     * (Contact / Friction coefficient = 0.1); ...". The sign is that of the
     * net load of the loads and the best admissible tractions on the motion
     * (+y: upwards; +rotation: counterclockwise in 2D).
     */
    template <int dim>
    void
    check_held_by_contact(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
                          const contact::ContactProblem &problem);

    /**
     * The contact boundary of a body must be free to move: a symmetry,
     * fixed or prescribed condition on the boundary named by Contact /
     * Boundary b+1 would hold what the contact is to carry (a symmetry
     * condition on it gives a contact zone of width zero). Throws
     * dpana::InputError naming the condition's parameter and the boundary.
     */
    template <int dim>
    void
    check_contact_boundaries_free(
      const std::vector<std::unique_ptr<Body<dim>>> &bodies,
      const std::array<std::string, 2>              &contact_boundaries);

    /**
     * The coordinate axes ("x and z") along which the normal n of the
     * candidate surface @p surface (the contact direction, or without one
     * the mean outward normal) leans (|n_c| > 1e-3; not the axis of n's
     * largest component) while vertices of that surface are held along
     * them (u_c = 0: a symmetry plane normal to the axis, or a fixed side);
     * empty if none. A half or quarter model
     * leans away from its symmetry planes that way and needs the contact
     * direction: without it the quarter sphere of
     * prm/hertz_sphere_rigid.prm gives N_max 1.45 times Hertz's p0 and a_m
     * 70 % too large.
     */
    template <int dim>
    std::string
    leaning_axes(const Body<dim>                            &body,
                 const contact_surface::ContactSurface<dim> &surface);

    /**
     * The text of a warning if the contact normal of @p surface leans along
     * an axis along which vertices of that surface are held
     * (leaning_axes(): a symmetry line or plane); empty otherwise.
     * - Without a Contact direction, one body on the rigid plane
     *   (@p rigid_plane): the plane's normal is the mean outward normal,
     *   which a half or quarter model tilts away from its symmetry planes.
     *   (Between two bodies each element keeps its own normal.)
     * - With a Contact direction, one body or two: a direction off the
     *   symmetry planes makes the obstacle of a half model unsymmetric. The
     *   half disc of prm/hertz_rigid_mu0.prm with the direction 0.05, -1
     *   gives a 12.6 % above Hertz's and N_max 15.9 % below (with 0, -1:
     *   +1.1 % and +0.9 %), and its estimates mirror a pressure that is
     *   not symmetric.
     */
    template <int dim>
    std::string
    leaning_direction(const Body<dim>                            &body,
                      const contact_surface::ContactSurface<dim> &surface,
                      const bool                                  rigid_plane);

    /**
     * The text of a warning if the contact elements of @p surface are too
     * small for its surface vertices; empty otherwise.
     * - More elements than vertices (one triangle per element in 3D): the
     *   surface cannot resist every distribution of normal tractions, V_b
     *   lacks full column rank. On one body A is then singular; on two,
     *   A = A1 + A2 may not be, but the tractions may still oscillate.
     * - On Body 1's surface (@p first, whose faces the elements group),
     *   groups of faces with more than 3/4 as many elements as vertices
     *   (one edge per element in 2D, two triangles in 3D): a constant
     *   traction per face on linear displacements is not a stable pair, and
     *   the tractions oscillate from element to element. On the quarter
     *   sphere of prm/hertz_sphere_rigid.prm (level 3) two triangles per
     *   element give N_max 40 % above Hertz's p0 (4: +1.0 %, the default 8:
     *   +0.4 %; 0.98, 0.48 and 0.24 elements per vertex); on the receding
     *   block one edge per element gives tangential tractions that
     *   alternate in sign.
     * Vertex patches (one element per vertex, the traction form of nodal
     * conditions) are stable.
     */
    template <int dim>
    std::string
    surface_resolution(const contact_surface::ContactSurface<dim> &surface,
                       const bool                                  first);

    /**
     * The closest initial gap g of the candidate surface @p surface (the
     * smallest mean gap of its elements; negative: the bodies overlap) if
     * |g| exceeds a tenth of the surface's extent L (the largest of its
     * extents along its tangents); empty otherwise. Contact is linearised
     * about the initial configuration, so bodies that start that far apart
     * move by that rigid motion, and bodies that overlap that much are
     * pushed apart by strains of the overlap over the body: either answer
     * is far outside small displacements, and most likely a misplaced body,
     * Contact / Obstacle point or Contact direction. Returns the text of a
     * warning, e.g. "the closest initial gap of Body 1 is 1000 mm (apart),
     * 25 times the extent 40 mm of its candidate surface: ...".
     */
    template <int dim>
    std::string
    far_gap(const contact_surface::ContactSurface<dim> &surface);

    /**
     * The 3D Hertz reference measures its radii (the outer edge a and the
     * moment estimate a_m) about the axis through Contact / Candidate centre
     * x0 along the surface normal n. The text of a warning if x0 lies off
     * the point of the candidate surface @p surface nearest the obstacle
     * (the vertex of largest x . n: the spheres' axis, up to the
     * tessellation) by more than the longest edge of the faces at that
     * vertex; empty otherwise, and empty without a Contact direction (the
     * mean normal of a quarter model's cap leans off the axis; one body on
     * the plane is warned of that by leaning_axes()). A quarter sphere with x0
     * moved 2 mm off its axis along both symmetry planes gives a_m 40 % too
     * small.
     */
    template <int dim>
    std::string
    off_axis_centre(const contact_surface::ContactSurface<dim> &surface);

    /**
     * Whether @p body is held across the candidate centre @p centre: a
     * vertex of the candidate surface @p surface lies at the centre's
     * position s0 along the tangent tau_1 (to 1e-9 of the surface's
     * extent), and its displacement along the axis nearest tau_1 is held
     * at zero (a symmetry line or plane through the centre). A 2D surface
     * on one side of s0 is then the half model of a body symmetric about
     * s0 (scene::estimate_pressure_profile()).
     */
    template <int dim>
    bool
    held_across_centre(const Body<dim>                            &body,
                       const contact_surface::ContactSurface<dim> &surface,
                       const dealii::Point<dim>                   &centre);
  } // namespace scene
} // namespace dpana

#endif
