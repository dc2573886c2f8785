// The method of multipliers shared by the projected Gauss-Seidel inner
// solvers of dpana (normal LCP and friction QP) for the equality rows of
// floating bodies.
#ifndef dpana_contact_method_of_multipliers_h
#define dpana_contact_method_of_multipliers_h

#include <dpana/contact/normal_lcp.h>

#include <Eigen/Dense>

#include <string>

namespace dpana
{
  namespace contact
  {
    // Solve min ½ xᵀ M x + xᵀ c over the convex set of x subject to
    // G x = e by the method of multipliers (augmented Lagrangian): each
    // outer step minimises, by PGS sweeps, the augmented function
    // @f[
    //   ½ xᵀ (M + ρ GᵀG) x + xᵀ (c + Gᵀ(λ - ρ e))
    // @f]
    // over the set, then updates λ += ρ (G x - e). It stops when the sweeps
    // converged and |G x - e|_∞ <= tolerance (|G|_∞ |x|_∞ + |e|_∞).
    //
    // @p sweeps(rhs, max_sweeps) runs the PGS sweeps on the augmented matrix
    // with linear term rhs, updating x in place, and returns the number of
    // sweeps (negative if it hit max_sweeps). @p rhs is work space.
    template <typename Sweeps>
    InnerResult
    solve_with_multipliers(const Eigen::MatrixXd &G,
                           const Eigen::VectorXd &e,
                           const double           penalty,
                           const Eigen::VectorXd &c,
                           const InnerOptions    &options,
                           const std::string     &name,
                           Sweeps               &&sweeps,
                           Eigen::VectorXd       &rhs,
                           Eigen::VectorXd       &x,
                           Eigen::VectorXd       &multiplier)
    {
      InnerResult result;
      if (multiplier.size() != G.rows())
        multiplier = Eigen::VectorXd::Zero(G.rows());
      unsigned int total = 0;
      while (total < options.max_iterations)
        {
          rhs = c;
          rhs.noalias() += G.transpose() * (multiplier - penalty * e);
          const int s = sweeps(rhs, options.max_iterations - total);
          total += static_cast<unsigned int>(std::abs(s));
          const Eigen::VectorXd violation = G * x - e;
          multiplier += penalty * violation;
          const double scale =
            G.lpNorm<Eigen::Infinity>() * x.lpNorm<Eigen::Infinity>() +
            e.lpNorm<Eigen::Infinity>();
          if (s > 0 &&
              violation.lpNorm<Eigen::Infinity>() <= options.tolerance * scale)
            {
              result.converged  = true;
              result.iterations = total;
              return result;
            }
          if (s < 0)
            break;
        }
      result.iterations = total;
      result.message    = name + " PGS: sweep limit reached with equality rows";
      return result;
    }
  } // namespace contact
} // namespace dpana

#endif
