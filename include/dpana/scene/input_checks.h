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
     * One body on the rigid plane without a contact direction: the
     * coordinate axes ("x and z") along which the mean outward normal of
     * its candidate surface @p surface leans (|n_c| > 1e-3) while vertices
     * of that surface are held along them (u_c = 0: a symmetry plane normal
     * to the axis, or a fixed side); empty if none. A half or quarter model
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
