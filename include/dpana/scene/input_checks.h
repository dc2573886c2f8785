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
     * prm/hertz_sphere_rigid.prm gives 3.6 times Hertz's p0.
     */
    template <int dim>
    std::string
    leaning_axes(const Body<dim>                            &body,
                 const contact_surface::ContactSurface<dim> &surface);
  } // namespace scene
} // namespace dpana

#endif
