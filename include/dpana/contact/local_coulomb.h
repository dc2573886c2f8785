// The exact local Signorini-Coulomb problem of one contact element, the
// building block of nonsmooth Gauss-Seidel (nsgs.h).
//
// Given the d x d diagonal block W = A_jj (SPD) and the displacement q due to
// everything else (u_j = W r_j + q), find r_j = (N, T) with
//   N <= 0, u_N <= 0, N u_N = 0, T in -mu N P,
//   stick: u_T = 0;  slip: -u_T in the normal cone of -mu N P at T.
// All cases are formed exactly and the first admissible one is returned:
//   - separated: r = 0, admissible iff q_N <= 0;
//   - stick: r = -W^{-1} q, admissible iff N < 0 and gamma(T) <= -mu N;
//   - 2D slip with direction s = +-1: T = s mu (-N) and u_N = 0 give N by one
//     division; admissible iff N < 0 and s u_T <= 0;
//   - 3D polygon, slip on facet i: the 4 x 4 linear system u_N = 0,
//     u_T = -lambda n_i, n_i . T = -mu N; admissible iff N < 0, lambda >= 0
//     and T inside the neighbouring facets; slip at vertex i: T = -mu N v_i,
//     u_N = 0 gives N, admissible iff -u_T = a n_i + b n_{i+1}, a, b >= 0;
//   - 3D disc, slip: T = mu p (cos t, sin t), p = -N, u_N = 0 gives p(t);
//     the slip direction t solves f(t) = e(t)^perp . u_T(t) = 0 with
//     e(t) . u_T(t) <= 0. A Newton iteration from the hint direction is tried
//     first; if it fails, f is sampled at 64 angles and every admissible sign
//     change is refined by bisection to round-off.
// If, because of round-off at case boundaries, no case passes the tests, the
// candidate with the smallest local natural-map residual is returned.
// For large mu the local problem can have several solutions; the order
// above (separated, stick, slip) decides.
#ifndef dpana_contact_local_coulomb_h
#define dpana_contact_local_coulomb_h

#include <dpana/contact/friction_set.h>

namespace dpana
{
  namespace contact
  {
    // W: row-major d x d; q, r: d entries. hint: in/out, the slip facet
    // (polygon) or an angle code (disc) of the previous solve, used to order
    // the search; pass 0 when unknown. Returns the status code: 0 separated,
    // 1 stick, 2 slip, 3 fallback (least residual).
    int
    solve_local_coulomb(const FrictionSet &set,
                        const double       mu,
                        const double      *W,
                        const double      *q,
                        double            *r,
                        double            &hint);
  } // namespace contact
} // namespace dpana

#endif
