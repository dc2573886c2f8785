#include <dpana/contact/residual.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dpana
{
  namespace contact
  {
    double
    residual_rho(const ContactProblem &problem)
    {
      const double tr = problem.A.trace();
      if (!(tr > 0.0))
        throw std::invalid_argument(
          "contact problem: A has a non-positive trace");
      return static_cast<double>(problem.A.rows()) / tr;
    }



    ResidualFigures
    compute_residual(const ContactProblem  &problem,
                     const Eigen::VectorXd &r,
                     const Eigen::VectorXd &alpha)
    {
      if (r.size() != problem.D.size())
        throw std::invalid_argument("compute_residual: r has the wrong size");
      Eigen::VectorXd u = problem.A * r + problem.D;
      if (problem.n_equalities() > 0)
        {
          if (alpha.size() != problem.G.rows())
            throw std::invalid_argument(
              "compute_residual: alpha must have one entry per row of G");
          u.noalias() += problem.G.transpose() * alpha;
        }
      const FrictionSet set(problem);
      return compute_residual_from_u(problem, set, residual_rho(problem), r, u);
    }



    // @sect3{One element}
    //
    // The modified displacement tilde u_j = (u_N - mu sigma(-u_T), u_T), the
    // point x = r_j - rho tilde u_j and its projection p onto K_j give
    // F_j = r_j - p.
    void
    natural_map_element(const FrictionSet &set,
                        const double       rho,
                        const double       mu,
                        const double      *rj,
                        const double      *uj,
                        double            *F)
    {
      const unsigned int m           = set.tangential_dim();
      double             minus_uT[2] = {0.0, 0.0};
      for (unsigned int k = 0; k < m; ++k)
        minus_uT[k] = -uj[1 + k];
      const double sigma = set.support(minus_uT);
      double       x[3], p[3];
      x[0] = rj[0] - rho * (uj[0] - mu * sigma);
      for (unsigned int k = 0; k < m; ++k)
        x[1 + k] = rj[1 + k] - rho * uj[1 + k];
      set.project_cone(mu, x, p);
      for (unsigned int k = 0; k <= m; ++k)
        F[k] = rj[k] - p[k];
    }



    Eigen::VectorXd
    element_residuals(const ContactProblem  &problem,
                      const Eigen::VectorXd &r,
                      const Eigen::VectorXd &u)
    {
      if (r.size() != problem.D.size() || u.size() != problem.D.size())
        throw std::invalid_argument(
          "element_residuals: r and u must have the size of D");
      const unsigned int d = problem.dim;
      const unsigned int n = problem.n_elements();
      const FrictionSet  set(problem);
      const double       rho = residual_rho(problem);
      Eigen::VectorXd    norms(n);
      for (unsigned int j = 0; j < n; ++j)
        {
          double F[3];
          natural_map_element(
            set, rho, problem.mu[j], r.data() + d * j, u.data() + d * j, F);
          double sum = 0.0;
          for (unsigned int k = 0; k < d; ++k)
            sum += F[k] * F[k];
          norms[j] = std::sqrt(sum);
        }
      return norms;
    }



    ResidualFigures
    compute_residual_from_u(const ContactProblem  &problem,
                            const FrictionSet     &set,
                            const double           rho,
                            const Eigen::VectorXd &r,
                            const Eigen::VectorXd &u)
    {
      const unsigned int d = problem.dim;
      const unsigned int n = problem.n_elements();
      ResidualFigures    f;
      double             sum = 0.0;
      for (unsigned int j = 0; j < n; ++j)
        {
          const double *rj = r.data() + d * j;
          const double *uj = u.data() + d * j;
          const double  mu = problem.mu[j];
          double        F[3];
          natural_map_element(set, rho, mu, rj, uj, F);
          for (unsigned int k = 0; k < d; ++k)
            sum += F[k] * F[k];

          f.penetration = std::max(f.penetration, uj[0]);
          f.cone_violation =
            std::max({f.cone_violation, set.gauge(rj + 1) + mu * rj[0], rj[0]});
          f.complementarity =
            std::max(f.complementarity, std::abs(rj[0] * uj[0]));
        }
      const double denominator = r.norm() + rho * problem.D.norm();
      f.natural_map = (denominator > 0.0) ? std::sqrt(sum) / denominator :
                      (sum > 0.0)         ? std::sqrt(sum) :
                                            0.0;
      if (problem.n_equalities() > 0)
        f.equilibrium = (problem.G * r - problem.e).lpNorm<Eigen::Infinity>();
      return f;
    }



    std::vector<ContactStatus>
    classify(const ContactProblem  &problem,
             const Eigen::VectorXd &r,
             const Eigen::VectorXd &u,
             const double           tolerance)
    {
      (void)u;
      const unsigned int d = problem.dim;
      const unsigned int n = problem.n_elements();
      const FrictionSet  set(problem);
      const double       s = r.size() > 0 ? r.lpNorm<Eigen::Infinity>() : 0.0;
      std::vector<ContactStatus> status(n, ContactStatus::separated);
      for (unsigned int j = 0; j < n; ++j)
        {
          const double N = r[d * j];
          if (N >= -tolerance * s)
            status[j] = ContactStatus::separated;
          else if (set.gauge(r.data() + d * j + 1) >=
                   -problem.mu[j] * N - tolerance * s)
            status[j] = ContactStatus::slip;
          else
            status[j] = ContactStatus::stick;
        }
      return status;
    }
  } // namespace contact
} // namespace dpana
