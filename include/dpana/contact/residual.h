// The one error measure shared by every contact solver of dpana.
//
// @sect3{The natural-map residual}
//
// With u = A r + D + G^T alpha and, per element j, the friction set
//   K_j = { (N, T) : N <= 0, gamma(T) <= -mu_j N }
// (gamma and its support function sigma: see friction_set.h), the reference
// formulation's law (Signorini + Coulomb, non-associated) holds at element j if
// and only if
// @f[
//   F_j(r) = r_j - \Pi_{K_j}\big( r_j - \rho_j\, \tilde u_j \big) = 0,
//   \qquad
//   \tilde u_j = \big( u_{N,j} - \mu_j\, \sigma(-u_{T,j}),\ u_{T,j} \big),
// @f]
// for any rho_j > 0. tilde u is the modified (bipotential) velocity of De
// Saxce and Feng written in the reference formulation's signs; for the disc and
// the interval sigma(-u_T) = ||u_T||, for the polygon it is max_i v_i . (-u_T)
// over the polygon vertices. Proof sketch: F_j = 0 iff -tilde u_j lies in the
// polar cone K_j^o = { y_N >= mu sigma(y_T) } (which is exactly u_N <= 0) and
// r_j . tilde u_j = 0, i.e. N u_N + [(-mu N) sigma(-u_T) - T . (-u_T)] = 0;
// both brackets are >= 0, so N u_N = 0 and -u_T lies in the normal cone of
// the tangential set -mu N P at T: stick (u_T = 0) inside, slip (u_T = -lambda
// n with n an outward normal, lambda >= 0) on the boundary. The plain
// projection residual (without the -mu sigma(-u_T) term) would instead
// characterise the associated law (with dilatancy) and is NOT used.
//
// @sect3{The scale}
//
// The measure is made independent of the units of forces and lengths, of
// contrasts of stiffness along the contact surface, and of the size of the
// gaps:
//   rho_j = d / trace(A_jj)  (inverse of the mean diagonal compliance of
//                              element j),
//   S(r)  = ||r||_2 + ||(rho_j D^+_j)_j||_2,
//   natural_map = sqrt( sum_j ||F_j||^2 + sum_i E_i^2 ) / S(r),
// with D^+ the load term whose normal entries are cut at zero,
// D^+_j = (max(D_N,j, 0), D_T,j), and E_i = (G_i r - e_i) / ||G_i||_2 the
// distance of r from the hyperplane of the i-th equality row (a traction;
// E is absent without equality rows, and a zero row counts with its raw
// defect). The figure is 0 when S and the numerator both vanish (r = 0 and
// nothing pushes the surfaces together, which is then the solution).
// Both numerator and denominator are tractions, and a rescaling of the loads
// or of the stiffness leaves the figure unchanged.
//
// Why rho_j per element: rho_j u_j is the traction that element j's own
// compliance turns into its displacement, so F_j weighs tractions and
// displacements alike on soft and stiff elements. One rho for all (the
// inverse of the mean compliance) would be set by the softest elements, and
// the displacements of the stiff ones would hardly count: on a surface whose
// compliance jumps by 10^6 a residual of 1e-10 left errors of 1e-4 in the
// tractions.
//
// Why D^+ and not D: a negative D_N,j is an open gap (an element far from
// the obstacle, or a body not yet pushed onto it). Scaling by rho ||D||
// would let a large gap (an obstacle 1000 mm away) swamp the residual of
// the elements that are in contact, and report an unconverged state as
// converged. A gap is not a load: whatever its size it adds nothing to the
// tractions, so it must not add to their scale either. The positive part of
// D_N (interference, a load pressing the surfaces together) and D_T (the
// tangential displacements of the loads) do produce tractions, and keep the
// scale positive before the first traction is known. So a problem's answer
// is accepted when the residual is small against its own tractions.
//
// @sect3{Per element}
//
// element_residuals() returns ||F_j|| / S(r): the share of element j in the
// shared figure, so that every one of them is <= natural_map, and
// natural_map <= tolerance means that every element meets the tolerance.
//
// @sect3{The separate figures} (raw, in the problem's units)
//   penetration     = max_j max(u_N,j, 0),
//   cone_violation  = max_j max(gamma(T_j) + mu_j N_j, N_j, 0),
//   complementarity = max_j |N_j u_N,j|            (units of work),
//   equilibrium     = ||G r - e||_inf               (0 without equality rows).
//
// @sect3{Contact status}
//
// One classification for every solver and every comparison (classify()).
// With a relative tolerance tau (SolverOptions::classification_tolerance,
// default 1e-8, raised to the solver's tolerance by solve()), t = tau
// max(||r||_inf, ||rho D^+||_inf) and v_j = tau S(r) / rho_j, element j is
//   separated  if N_j >= -t,
//   slip       otherwise, if it moves, ||u_T,j|| > v_j, or if its traction is
//              on the boundary of the friction set, gamma(T_j) >= -mu_j N_j
//              - t (so every contact with mu_j = 0 slips),
//   stick      otherwise (T_j strictly inside, u_T,j = 0 to the tolerance).
// Both tests are needed: an approximate solution may have a slipping
// element a little inside the cone (u_T != 0 shows it slips), and an exact
// one may stick with T on the boundary (impending slip, counted as slip).
// At a solution with natural_map <= tol, a sticking element has rho_j
// ||u_T,j|| <= tol S(r), so it is not taken for slipping as long as tol <=
// tau.
#ifndef dpana_contact_residual_h
#define dpana_contact_residual_h

#include <dpana/contact/friction_set.h>
#include <dpana/contact/problem.h>

#include <Eigen/Dense>

#include <vector>

namespace dpana
{
  namespace contact
  {
    struct ResidualFigures
    {
      double natural_map     = 0; // THE shared residual (see above)
      double penetration     = 0; // max_j max(u_N,j, 0)
      double cone_violation  = 0; // max_j max(gamma(T_j) + mu_j N_j, N_j, 0)
      double complementarity = 0; // max_j |N_j u_N,j|
      double equilibrium     = 0; // ||G r - e||_inf
    };

    // The rho_j = d / trace(A_jj) of every element (see above); throws
    // std::invalid_argument if a diagonal block has a non-positive trace.
    Eigen::VectorXd
    residual_rho(const ContactProblem &problem);

    // All the figures for tractions r and rigid-mode amplitudes alpha (alpha
    // may be empty when there are no equality rows).
    ResidualFigures
    compute_residual(const ContactProblem  &problem,
                     const Eigen::VectorXd &r,
                     const Eigen::VectorXd &alpha);

    // The same, from the displacements u = A r + D + G^T alpha already known
    // to the caller (no matrix-vector product).
    ResidualFigures
    compute_residual_from_u(const ContactProblem  &problem,
                            const FrictionSet     &set,
                            const Eigen::VectorXd &rho,
                            const Eigen::VectorXd &r,
                            const Eigen::VectorXd &u);

    // The natural-map vector of one element, F_j = r_j - Pi_{K_j}(r_j - rho
    // tilde u_j) (see above), written to F_j (d = set.tangential_dim() + 1
    // entries), from the d tractions r_j and displacements u_j of the
    // element and its friction coefficient mu_j. compute_residual_from_u()
    // sums the squares of these entries over all elements.
    void
    natural_map_element(const FrictionSet &set,
                        const double       rho,
                        const double       mu_j,
                        const double      *r_j,
                        const double      *u_j,
                        double            *F_j);

    // The scale S(r) = ||r||_2 + ||(rho_j D^+_j)_j||_2 of the shared
    // residual (see above), a traction; rho from residual_rho().
    double
    residual_scale(const ContactProblem  &problem,
                   const Eigen::VectorXd &rho,
                   const Eigen::VectorXd &r);

    // sqrt(sum_i E_i^2), E_i = (G_i r - e_i) / ||G_i||_2: the part of the
    // numerator of the shared residual due to the equality rows (0 without
    // them), a traction.
    double
    equality_defect(const ContactProblem &problem, const Eigen::VectorXd &r);

    // The relative residuals ||F_j|| / S(r) of every element, from the
    // displacements u = A r + D + G^T alpha. They relate to the shared
    // figure by
    //   natural_map^2 = sum_j e_j^2 + (equality_defect / S)^2,
    // so that each is <= natural_map, and they show where on the contact
    // surface the residual of a solution sits.
    Eigen::VectorXd
    element_residuals(const ContactProblem  &problem,
                      const Eigen::VectorXd &r,
                      const Eigen::VectorXd &u);

    // The status of one element (see "Contact status" above) from its
    // tractions r_j and displacements u_j, with the absolute tolerances
    // t (tractions) and v (tangential displacements).
    ContactStatus
    classify_element(const FrictionSet &set,
                     const double       mu_j,
                     const double      *r_j,
                     const double      *u_j,
                     const double       traction_tolerance,
                     const double       displacement_tolerance);

    // The status of every element (see "Contact status" above), u = A r + D
    // + G^T alpha, tolerance the relative tau. The one classification of
    // dpana: every solver's result and every comparison use it.
    std::vector<ContactStatus>
    classify(const ContactProblem  &problem,
             const Eigen::VectorXd &r,
             const Eigen::VectorXd &u,
             double                 tolerance);
  } // namespace contact
} // namespace dpana

#endif
