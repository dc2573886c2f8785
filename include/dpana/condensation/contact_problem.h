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
