// Semismooth Newton method on the Alart-Curnier equations, for every
// friction set (interval, disc, polygon).
//
// With u = A r + D + G^T alpha and, per element j, rho_j = d / tr(A_jj),
//   y_N = N - rho_j u_N,          F_N = N - min(0, y_N),
//   c   = mu_j max(0, -y_N),      (the friction radius of the augmented
//                                  normal traction)
//   y_T = T - rho_j u_T,          F_T = T - Pi_{c P}(y_T),
// plus the rows G r - e. F = 0 if and only if r solves the (non-associated)
// Signorini-Coulomb law: F_N = 0 is N <= 0, u_N <= 0, N u_N = 0, and then
// c = -mu N, so F_T = 0 says -u_T lies in the normal cone of -mu N P at T.
//
// The generalised Jacobian uses the derivatives of min(0, .), of the
// projection onto c P with respect to y (identity inside; the tangent
// projector on a facet; (c/|y|)(I - yy^T/|y|^2) on the circle; zero at a
// vertex or interval end) and with respect to the radius c
// (FrictionSet::projection_radius_derivative). Each step solves the dense
// system by LU, after eliminating the elements that are not pressed and have
// a zero projection derivative (their step is -F outright), and is globalised
// by Armijo backtracking on 1/2 ||F||^2; a singular Jacobian (e.g. at r = 0
// with equality rows, when alpha does not yet enter any pressed row) gets the
// minimum-norm least-squares step. The method converges locally superlinearly
// but not globally: when the line search fails, 20 k NSGS sweeps (k = 1, 2,
// ...) are made from the current point (the alpha of NSGS's augmented
// Lagrangian is taken over) and Newton resumes; after 10 failures it stops with
// converged = false and says so. SolverResult::inner_iterations counts those
// NSGS sweeps.
//
// Start: initial_r, or the frictionless solution is NOT computed: r = 0.
// Stops (the shared tests of monitor.h) when the shared residual
// (residual.h) is <= tolerance and ||G r - e||_inf <= tolerance (||G||_inf
// ||r||_inf + ||e||_inf).
#ifndef dpana_contact_alart_curnier_h
#define dpana_contact_alart_curnier_h

#include <dpana/contact/solver.h>

namespace dpana
{
  namespace contact
  {
    SolverResult
    solve_alart_curnier(const ContactProblem  &problem,
                        const SolverOptions   &options,
                        const Eigen::VectorXd *initial_r);
  } // namespace contact
} // namespace dpana

#endif
