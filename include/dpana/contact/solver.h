// The driver of the contact solvers of dpana: one problem (problem.h), one
// options structure, one function, one error measure (residual.h) with one
// stopping and stall test (monitor.h).
//
// Solvers (see doc/contact_solvers.md for the mathematics):
//   - splitting_pgs, splitting_active_set: the D-PANA splitting of the
//   reference formulation
//     (T-step at fixed N, N-step at fixed T, repeated to a fixed point), with
//     projected Gauss-Seidel or active-set / semismooth Newton inner solvers
//     (normal_lcp.h, friction_qp.h; the loop itself in splitting.h);
//   - nsgs: monolithic nonsmooth Gauss-Seidel over the contact elements with
//     exact local Signorini-Coulomb solves (local_coulomb.h, nsgs.h);
//   - alart_curnier: semismooth Newton on the Alart-Curnier equations with
//     an Armijo line search (alart_curnier.h); locally fast, not globally
//     convergent (reports a failed line search honestly).
//
// The default solver is robust: a splitting that stops without converging
// hands over to Alart-Curnier and then to NSGS (SolverOptions::fallback),
// and the result says which solver produced the answer.
#ifndef dpana_contact_solver_h
#define dpana_contact_solver_h

#include <dpana/contact/problem.h>
#include <dpana/contact/residual.h>

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace dpana
{
  namespace contact
  {
    enum class SolverType
    {
      splitting_pgs,        // D-PANA splitting, projected Gauss-Seidel inner
      splitting_active_set, // D-PANA splitting, active-set inner solvers
      nsgs,                 // monolithic nonsmooth Gauss-Seidel
      alart_curnier         // semismooth Newton on Alart-Curnier equations
    };

    // The solver of a name ("splitting_active_set", "splitting_pgs", "nsgs",
    // "alart_curnier"); throws std::invalid_argument for anything else.
    SolverType
    solver_type_from_string(const std::string &name);

    // The name of a solver, as solver_type_from_string() reads it.
    std::string
    to_string(SolverType type);

    // Every solver name, separated by '|', the default first:
    // "splitting_active_set|splitting_pgs|nsgs|alart_curnier" (the pattern
    // of a ParameterHandler Selection).
    std::string
    solver_type_names();

    struct SolverOptions
    {
      SolverType type = SolverType::splitting_active_set;
      // Stopping test on the shared residual (residual.h, natural_map).
      double tolerance = 1e-10;
      // Outer iterations: splitting steps (one T-step + one N-step) or NSGS
      // sweeps.
      unsigned int max_iterations = 1000;
      // Inner solvers: relative tolerance and iteration cap (sweeps for PGS,
      // Newton / active-set steps for the active-set solvers).
      double       inner_tolerance      = 1e-12;
      unsigned int inner_max_iterations = 10000;
      // Relaxation omega in (0, 2) of PGS and NSGS.
      double over_relaxation = 1.0;
      // Stall detection: stop (converged = false) when the residual has not
      // reached a new minimum (by a factor 0.99) for this many outer
      // iterations.
      unsigned int stall_iterations = 100;
      // Tolerance tau of the status classification (residual.h: relative
      // to max(||r||_inf, ||rho D^+||_inf)); a solve uses max(tau,
      // tolerance).
      double classification_tolerance = 1e-8;
      // Equality rows handled by an augmented Lagrangian (PGS, NSGS): the
      // penalty is augmentation * trace(A) / ||G||_F^2.
      double augmentation = 1.0;
      // NSGS only: on a stall, halve omega (at most six times) and go on
      // instead of stopping. Under-relaxation cures the cycling of NSGS seen
      // for large mu.
      bool adaptive_relaxation = true;
      // Splitting only: solve the subproblems to the relative tolerance
      // clamp(0.1 * last outer residual, inner_tolerance, 1e-4) instead of
      // inner_tolerance throughout.
      bool adaptive_inner_tolerance = true;
      // Splitting with active-set inner solvers only: before the Newton
      // steps of a T-step of at least partition_sweep_size tangential
      // unknowns, projected Gauss-Seidel sweeps (in chunks of five, until two
      // chunks in a row leave the stick / slip partition unchanged) find the
      // partition, at most partition_sweeps; 0: none (friction_qp.h). Below
      // that size a factorisation costs less than the sweeps: measured on the
      // 3D receding block (mu = 1, disc), the sweeps made the splitting 1.8
      // to 2.5 times slower at 512 tangential unknowns and 1.1 to 2.4 times
      // faster at 1152 and more.
      unsigned int partition_sweeps     = 200;
      unsigned int partition_sweep_size = 1000;
      // Splitting with active-set inner solvers only: the T-step's Newton
      // matrices of at least this many rows are factored in single
      // precision, each solve refined in double (friction_qp.cc); the
      // iterates, the residual and the stopping test stay in double.
      unsigned int single_precision_size = 1024;
      // Splitting with active-set inner solvers only: N-steps of at least
      // this many normal unknowns solve a contact set that holds more than
      // half of the elements through the inverse of A_NN and the separated
      // set (normal_lcp.h): a step then factors |F| rows instead of |C|.
      unsigned int normal_complement_size = 0;
      // Splitting only (the robust mode of the default solver): when the
      // splitting stops without converging (stall, cycling, stagnation,
      // iteration cap), solve again by Alart-Curnier from the splitting's
      // last iterate and, should that fail as well, by NSGS from the best
      // iterate so far, with 100 times max_iterations sweeps (NSGS converges
      // linearly, slowly where A is badly conditioned; its stall test stops
      // it early where it cycles). SolverResult::solver names the solver
      // whose answer is returned (the one with the smallest residual if none
      // converged), SolverResult::fallbacks the others with their stop
      // messages, SolverResult::iterations counts the iterations of the
      // answer's solver and residual_history those of all of them, in order.
      bool fallback = true;
    };

    struct SolverResult
    {
      Eigen::VectorXd            r;     // tractions, interleaved (N_j, T_j)
      Eigen::VectorXd            u;     // u = A r + D + G^T alpha
      Eigen::VectorXd            alpha; // rigid-mode amplitudes (size m)
      std::vector<ContactStatus> status;
      bool                       converged  = false;
      unsigned int               iterations = 0;
      double                     residual   = 0; // == figures.natural_map
      std::vector<double>        residual_history;
      ResidualFigures            figures;
      std::string                message; // why it stopped
      // Work of the inner solvers (sum over the outer iterations of the
      // splitting; 0 for NSGS).
      unsigned long inner_iterations = 0;
      // The solver whose answer this is: SolverOptions::type, or the
      // solver of a fallback (SolverOptions::fallback).
      SolverType solver = SolverType::splitting_active_set;
      // The solvers tried before it, each with its stop message, in order
      // (empty when the first solver's answer is returned).
      std::vector<std::string> fallbacks;
    };

    // Validate the problem (and the options: one-line std::invalid_argument
    // naming the field) and solve it. initial_r (size d n), when given,
    // is the starting point (NSGS, splitting: its normal part).
    SolverResult
    solve(const ContactProblem  &problem,
          const SolverOptions   &options,
          const Eigen::VectorXd *initial_r = nullptr);

    // Throws std::invalid_argument naming the offending option.
    void
    validate(const SolverOptions &options);
  } // namespace contact
} // namespace dpana

#endif
