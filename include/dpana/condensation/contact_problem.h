// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_condensation_contact_problem_h
#define dpana_condensation_contact_problem_h

#include <dpana/condensation/condenser.h>
#include <dpana/contact/problem.h>
#include <dpana/contact_surface/contact_surface.h>

#include <vector>

namespace dpana
{
  namespace condensation
  {
    /**
     * The condensed contact problem of one body on a rigid obstacle or of
     * two bodies, from the condensations of the bodies on their candidate
     * surfaces (Condenser::condense() done for each).
     *
     * The contact elements are those of @p surface, the surface of Body 1;
     * Body 2's surface, if any, shares its elements with the frame negated
     * (ContactSurface::pair()). The unknowns are the tractions r on Body 1;
     * Body 2 carries -r in its own frame, that is the same components r in
     * its negated frame, so the displacements that the contact conditions
     * act on are the relative ones, u_1 - u_2 along Body 1's frame, and
     * they add:
     * @f[
     *   A = \sum_b A_b, \qquad
     *   D_{dj+k} = \sum_b (s_o)_{b, dj+k} - \delta_{k0} \int_{\Gamma_j} g_o ,
     * @f]
     * the initial gap g_o >= 0 of element j (ContactElement::gap_integral)
     * entering its normal row: contact closes it. A floating body b (free
     * rigid motions held by fictitious supports) adds its equilibrium rows
     * G_b r = e_b; the rows of all floating bodies are stacked in the order
     * of @p condensers, and the rigid displacements alpha of the solution
     * come in the same order. The friction coefficient @p friction is the
     * same on every element; @p cone and @p polygon_sides choose the
     * friction set (contact::ConeModel).
     *
     * The sums are taken in the order of @p condensers (Body 1 first), so
     * the result is the same to the last digit on every run.
     */
    template <int dim>
    contact::ContactProblem
    assemble_contact_problem(
      const std::vector<const Condenser<dim> *>  &condensers,
      const contact_surface::ContactSurface<dim> &surface,
      const double                                friction,
      const contact::ConeModel                    cone,
      const unsigned int                          polygon_sides);

    /**
     * Whether a constraint of @p body sets its degree of freedom @p i to zero
     * by a condition without entries: a symmetry plane normal to a
     * coordinate axis, or a fixed component.
     */
    template <int dim>
    bool
    held_to_zero(const Body<dim>                      &body,
                 const dealii::types::global_dof_index i);

    /**
     * Patches around the vertices (ContactSurface with
     * ElementShape::vertex_patches): the tangential unknowns (index
     * dim j + 1 + k for the tangent tau_k of element j) whose vertex has its
     * displacement along tau_k held to zero by a constraint of @p body
     * (Body 1): a vertex on a symmetry line or plane across the surface,
     * the axis of a half model, the planes of a quarter model. In the
     * mirrored whole model such a patch is the part of one that straddles
     * the symmetry line or plane, where the traction component across it
     * is odd: its constant value is zero. In the model that component acts
     * only through the neighbouring vertices, together with their own
     * patches, and is left undetermined (the friction solver would put it
     * on the edge of the friction set and its neighbour opposite);
     * hold_tangential_tractions() holds it at zero. Empty for groups of
     * faces. Throws dpana::InputError if a patch's vertex is held in every
     * direction (a fixed vertex): no free displacement would resist its
     * tractions, normal ones included.
     */
    template <int dim>
    std::vector<unsigned int>
    tangentially_held_unknowns(
      const Body<dim>                            &body,
      const contact_surface::ContactSurface<dim> &surface);

    /**
     * Hold the tangential tractions @p unknowns of @p problem at zero: their
     * rows and columns of A are cleared but for the diagonal, their rows of
     * D and their columns of the equilibrium rows G (so that the rigid
     * motion of a floating body does not enter their tangential
     * displacement). Such a tangential displacement is then u_t = A_tt T_t,
     * and since the friction set is symmetric under T_t -> -T_t the Coulomb
     * law allows only T_t = 0 and u_t = 0 (no slip across the symmetry
     * plane); the other unknowns solve the problem without these tractions.
     * Throws dpana::InputError for a friction polygon of an odd number of
     * sides and a held T_1, which that polygon is not symmetric in.
     */
    void
    hold_tangential_tractions(contact::ContactProblem         &problem,
                              const std::vector<unsigned int> &unknowns);

    /**
     * Groups of faces (ElementShape::face_groups) with the friction polygon
     * of @p sides sides in 3D: a part model is the whole body only if the
     * polygon of each element is symmetric about each symmetry plane across
     * the candidate surface. Such a plane holds the displacement component
     * c (its normal, a coordinate axis) of a vertex of a candidate face to
     * zero; with nu the angle of e_c in the element's tangential frame
     * (e_c . tau_1, e_c . tau_2), the plane mirrors T about the line at
     * nu + 90 degrees, which must be one of the polygon's mirror lines, at
     * the multiples of 180/s degrees from tau_1 (its facet normals lie at
     * the angles 2 pi i / s). Returns a one-line warning naming the first
     * plane that is not, empty otherwise (and for elements whose normal is
     * not normal to e_c, whose mirror image has a frame of its own).
     */
    template <int dim>
    std::string
    polygon_symmetry_warning(
      const Body<dim>                            &body,
      const contact_surface::ContactSurface<dim> &surface,
      const contact::ConeModel                    cone,
      const unsigned int                          sides);

    /**
     * The largest relative asymmetry ||A_b - A_b^T||_F / ||A_b||_F of the
     * compliance matrices of @p condensers before their symmetrisation
     * (Condenser::asymmetry()): a check of the blocked solves, near machine
     * precision when they are accurate.
     */
    template <int dim>
    double
    largest_asymmetry(const std::vector<const Condenser<dim> *> &condensers);
  } // namespace condensation
} // namespace dpana

#endif
