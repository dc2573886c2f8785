// Can the floating bodies of a condensed contact problem be held at all?
//
// @sect3{The question}
//
// A body whose rigid motions are not all removed by its supports is held by
// the contact tractions alone: the equality rows G r = e of the contact
// problem (see problem.h) say that the tractions balance the loads on every
// free rigid motion. The tractions are admissible only if they press
// (N_j <= 0) and lie inside the friction cones (||T_j|| <= -mu_j N_j). If no
// admissible r meets G r = e, no solver can find a solution: the loads pull
// the body off the contact surface, push it sideways harder than friction
// can carry, or turn it in a way the contact cannot resist. This check
// answers the question before the solve, so that such a scene is reported
// as bad input rather than as a solver that did not converge.
//
// @sect3{The method}
//
// Every admissible traction of element j is a nonnegative combination of
// the generators of its cone: g = -e_N (mu_j = 0); g = -e_N +- mu_j e_T
// in 2D; in 3D the s vertices
// @f[
//   g_i = -e_N + \frac{\mu_j}{\cos(\pi/s)}
//         (\cos\theta_i e_{T1} + \sin\theta_i e_{T2}),
//   \quad \theta_i = (2i+1)\pi/s,
// @f]
// of the circumscribed polygon of the reference formulation (s =
// ContactProblem::polygon_sides for ConeModel::polygon; for the disc a
// 32-sided polygon, which contains the disc, so that the check rejects only
// what the disc cannot hold either). Writing r = sum_k lambda_k g_k, the
// question becomes whether M lambda = e has a solution lambda >= 0, M = G
// [g_k]. It is answered by the nonnegative least squares method of Lawson
// and Hanson (Solving Least Squares Problems, 1974, ch. 23) on the rows
// scaled by the load scale of their body and the columns scaled to unit
// length: the problem is feasible if the smallest residual
// ||W (M lambda - e)||_inf is below a tolerance. Otherwise the residual
// W (M lambda - e) = W (G r - e) at the minimiser is the generalised load
// that the contact cannot balance (Farkas: no admissible traction does
// positive work against it), and its largest components name the rigid
// motions along which the body escapes.
#ifndef dpana_contact_feasibility_h
#define dpana_contact_feasibility_h

#include <dpana/contact/problem.h>

#include <Eigen/Dense>

namespace dpana
{
  namespace contact
  {
    struct Feasibility
    {
      // Whether some admissible traction meets G r = e.
      bool feasible = true;

      // G r - e at the admissible r closest to meeting the rows (in the
      // scaled norm), divided by the row scales: the unbalanced generalised
      // load on each free rigid motion, relative to the load scale of its
      // body (a positive entry is a load in the positive sense of the
      // motion). Size m.
      Eigen::VectorXd unbalanced;

      // ||unbalanced||_inf.
      double residual = 0;
    };

    // The feasibility of the equality rows of @p problem (see above).
    // @p row_scale holds, for each equality row, a positive magnitude of
    // the loads of its body (e.g. the sum of the absolute values of the
    // body's nodal loads), against which the unbalanced part is measured;
    // empty means ||e||_inf for every row. The rows are feasible if every
    // scaled residual is at most @p tolerance. A problem without equality
    // rows is feasible. Throws std::invalid_argument if @p row_scale has
    // the wrong size or a non-positive entry.
    Feasibility
    check_feasibility(const ContactProblem  &problem,
                      const Eigen::VectorXd &row_scale = Eigen::VectorXd(),
                      const double           tolerance = 1e-8);

    // The nonnegative least squares problem min ||M x - b||_2, x >= 0, by
    // the active set method of Lawson and Hanson. Returns x.
    Eigen::VectorXd
    nonnegative_least_squares(const Eigen::MatrixXd &M,
                              const Eigen::VectorXd &b);
  } // namespace contact
} // namespace dpana

#endif
