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
//   F_j(r) = r_j - \Pi_{K_j}\big( r_j - \rho\, \tilde u_j \big) = 0,
//   \qquad
//   \tilde u_j = \big( u_{N,j} - \mu_j\, \sigma(-u_{T,j}),\ u_{T,j} \big),
// @f]
// for any rho > 0. tilde u is the modified (bipotential) velocity of De
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
// The measure is made independent of the units of forces and lengths:
//   rho     = (d n) / trace(A)  (inverse of the mean diagonal compliance),
//   natural_map = sqrt( sum_j ||F_j||^2 ) / ( ||r||_2 + rho ||D||_2 ),
// (0 when the denominator vanishes, i.e. r = 0 and D = 0, which is the
// solution). Both numerator and denominator are forces, and a rescaling of
// the loads or of the stiffness leaves the figure unchanged.
//
// @sect3{The separate figures} (raw, in the problem's units)
//   penetration     = max_j max(u_N,j, 0),
//   cone_violation  = max_j max(gamma(T_j) + mu_j N_j, N_j, 0),
//   complementarity = max_j |N_j u_N,j|            (units of work),
//   equilibrium     = ||G r - e||_inf               (0 without equality rows).
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

    // The scalar rho of the residual: (d n) / trace(A).
    double
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
                            const double           rho,
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

    // The norms ||F_j|| of every element (units of the tractions), from the
    // displacements u = A r + D + G^T alpha. They relate to the shared
    // figure by
    //   natural_map = sqrt( sum_j ||F_j||^2 ) / ( ||r||_2 + rho ||D||_2 )
    // (when the denominator is positive), so that they show where on the
    // contact surface the residual of a solution sits.
    Eigen::VectorXd
    element_residuals(const ContactProblem  &problem,
                      const Eigen::VectorXd &r,
                      const Eigen::VectorXd &u);

    // Status of each element. With s = ||r||_inf: separated if
    // N_j >= -tolerance s; otherwise slip if gamma(T_j) >= -mu_j N_j -
    // tolerance s (for mu_j = 0 every contact is slip), otherwise stick.
    std::vector<ContactStatus>
    classify(const ContactProblem  &problem,
             const Eigen::VectorXd &r,
             const Eigen::VectorXd &u,
             double                 tolerance);
  } // namespace contact
} // namespace dpana

#endif
