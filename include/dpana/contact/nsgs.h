// Monolithic nonsmooth Gauss-Seidel (NSGS) over the contact elements.
//
// One sweep visits the elements in order; element j solves its local
// Signorini-Coulomb problem EXACTLY (local_coulomb.h) with the tractions of
// the other elements frozen: u_j = A_jj r_j + q_j, q_j = u_j - A_jj r_j. The
// displacements u = A r + D are kept current by column updates (a change of
// r_j adds A(:, j-block) times the change), so a sweep costs one dense
// matrix-vector product at most, less when elements stay separated. With
// omega != 1 the relaxed point (1 - omega) r_j + omega r_j^loc is projected
// back onto K_j.
//
// Equality rows (floating bodies) use an augmented Lagrangian: the sweeps
// work with A + rho G^T G and D + G^T (alpha - rho e), and after every sweep
// alpha <- alpha + rho (G r - e), rho = augmentation trace(A) / ||G||_F^2.
// Then u = A r + D + G^T alpha holds exactly for the new alpha and the sweep
// just made, the residual is evaluated there, and convergence requires in
// addition ||G r - e||_inf <= tolerance (||G||_inf ||r||_inf + ||e||_inf).
//
// Stops (the shared tests of monitor.h) when the shared residual is <=
// tolerance (after a check with a freshly computed u), when max_iterations
// sweeps are done, on a non-finite residual, or on a stall (no new residual
// minimum, by a factor 0.99, for stall_iterations sweeps).
// With adaptive_relaxation (the default) a stall first halves omega, up to
// six times (omega >= omega_0 / 64), and the sweeps go on: exact local
// solves can cycle for large mu (the local problems, whose solution is taken
// in the order separated / stick / slip, may have several solutions), and
// under-relaxation damps the cycle.
#ifndef dpana_contact_nsgs_h
#define dpana_contact_nsgs_h

#include <dpana/contact/solver.h>

namespace dpana
{
  namespace contact
  {
    SolverResult
    solve_nsgs(const ContactProblem  &problem,
               const SolverOptions   &options,
               const Eigen::VectorXd *initial_r);
  } // namespace contact
} // namespace dpana

#endif
