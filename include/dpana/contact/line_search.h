// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_contact_line_search_h
#define dpana_contact_line_search_h

namespace dpana
{
  namespace contact
  {
    /**
     * Armijo backtracking for the semismooth Newton methods (Alart–Curnier,
     * the friction step of the splitting): along a Newton direction dx of
     * the merit function phi(x) = 1/2 ||F(x)||^2, the step lengths
     * t = 1, 1/2, 1/4, ... are tried, at most @p max_steps of them, until
     *
     *   phi(x + t dx) <= (1 - 2e-4 t) phi(x),
     *
     * the sufficient decrease condition for the Newton direction (whose
     * directional derivative of phi is -2 phi). @p trial_merit(t) forms the
     * trial point x + t dx (the caller keeps it) and returns its merit.
     * Returns whether a step was accepted; the trial point of the last call
     * is then the accepted one.
     *
     * Non-monotone variant (Grippo, Lampariello and Lucidi, SIAM J. Numer.
     * Anal. 23, 1986): with @p phi_reference >= phi, the largest merit of
     * the last few iterates, the test is
     *
     *   phi(x + t dx) <= phi_reference - 2e-4 t phi(x),
     *
     * which lets a full Newton step through that raises the merit for a
     * moment (a few blocks crossing their stick / slip boundary) where the
     * monotone test would cut it to a sliver; the merit still decreases
     * over every window of steps.
     */
    template <typename TrialMerit>
    bool
    armijo_backtracking(const double       phi,
                        const unsigned int max_steps,
                        TrialMerit       &&trial_merit,
                        const double       phi_reference = -1.0)
    {
      const double reference = (phi_reference >= phi) ? phi_reference : phi;
      double       t         = 1.0;
      for (unsigned int k = 0; k < max_steps; ++k, t *= 0.5)
        if (trial_merit(t) <= reference - 2e-4 * t * phi)
          return true;
      return false;
    }
  } // namespace contact
} // namespace dpana

#endif
