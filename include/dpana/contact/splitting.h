// The D-PANA splitting of the reference formulation (chapter 2, section 2.2.1).
//
// With the blocks A_NN, A_NT, A_TT (extracted once per solve) repeat
//   T-step:  T_k = argmin 1/2 T^T A_TT T + T^T (D_T + A_TN N_{k-1})
//                  over ||T_j|| <= -mu_j N_{k-1,j}            (friction_qp.h)
//   N-step:  N_k = argmin 1/2 N^T A_NN N + N^T (D_N + A_NT T_k)
//                  over N <= 0                                 (normal_lcp.h)
// with projected Gauss-Seidel (splitting_pgs) or active-set (splitting_
// active_set) inner solvers, warm started from the previous iterate.
//
// Start: (N_0, T_0) from initial_r; otherwise the frictionless solution, an
// N-step at T = 0 made before the loop. (From N_0 = 0 the first T-step
// would give T = 0, the friction sets being points, so starting from zero is
// starting from the frictionless solution; doing the N-step first also keeps
// purely tangential equality rows, infeasible with zero friction radii, out
// of a degenerate first T-step.)
//
// Equality rows G r = e (floating bodies): a row with any normal entry is a
// "normal row" and is imposed in the N-step, G_N N = e - G_T T_k, with its
// multiplier computed there; those multipliers then enter the T-step as a
// fixed load G_T^T alpha. A row with tangential entries only is imposed in
// the T-step (G_T T = e) with its own multiplier. At a fixed point both
// subproblems' optimality conditions hold with one common alpha, which is the
// full problem; and since the N-step comes last, G r = e holds to the
// accuracy of the N-step (round-off for the active-set solver).
//
// Inner tolerance: with adaptive_inner_tolerance (default) the subproblems
// are solved to clamp(0.1 * last outer residual, inner_tolerance, 1e-4);
// should that stall the iterates, the remaining steps use inner_tolerance.
//
// Stopping (the shared tests of monitor.h): converged when the shared
// residual (residual.h) is <= tolerance and, with equality rows,
// ||G r - e||_inf <= tolerance (||G||_inf ||r||_inf + ||e||_inf).
// The relative change ||r_k - r_{k-1}||_inf / ||r_k||_inf is recorded; if it
// drops below 1e-15 while the residual is still above tolerance the loop
// stops as "stagnated" (the inner tolerance limits the attainable residual).
// Cycling or divergence (no new residual minimum by a factor 0.99 for
// stall_iterations steps) and the iteration cap stop with converged = false
// and a message. The splitting is a fixed-point iteration whose convergence
// is not guaranteed (large mu, strong A_NT coupling): it reports that
// honestly.
#ifndef dpana_contact_splitting_h
#define dpana_contact_splitting_h

#include <dpana/contact/solver.h>

namespace dpana
{
  namespace contact
  {
    SolverResult
    solve_splitting(const ContactProblem  &problem,
                    const SolverOptions   &options,
                    const Eigen::VectorXd *initial_r);
  } // namespace contact
} // namespace dpana

#endif
