#include <dpana/contact/residual.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dpana
{
  namespace contact
  {
    Eigen::VectorXd
    residual_rho(const ContactProblem &problem)
    {
      const unsigned int d = problem.dim;
      const unsigned int n = problem.n_elements();
      Eigen::VectorXd    rho(n);
      for (unsigned int j = 0; j < n; ++j)
        {
          const double tr = problem.A.block(d * j, d * j, d, d).trace();
          if (!(tr > 0.0))
            throw std::invalid_argument("contact problem: the diagonal block "
                                        "of A of element " +
                                        std::to_string(j) +
                                        " has a non-positive trace");
          rho[j] = d / tr;
        }
      return rho;
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



    namespace
    {
      // Entry i of rho D^+: the load term with the gaps (negative D_N) left
      // out, times rho_j of its element: the traction the load stands for.
      double
      load_traction(const ContactProblem  &problem,
                    const Eigen::VectorXd &rho,
                    const Eigen::Index     i)
      {
        const unsigned int d = problem.dim;
        return rho[i / d] *
               ((i % d == 0) ? std::max(problem.D[i], 0.0) : problem.D[i]);
      }
    } // namespace



    double
    residual_scale(const ContactProblem  &problem,
                   const Eigen::VectorXd &rho,
                   const Eigen::VectorXd &r)
    {
      // ||rho D^+||_2.
      double load = 0.0;
      for (Eigen::Index i = 0; i < problem.D.size(); ++i)
        {
          const double x = load_traction(problem, rho, i);
          load += x * x;
        }
      return r.norm() + std::sqrt(load);
    }



    double
    equality_defect(const ContactProblem &problem, const Eigen::VectorXd &r)
    {
      if (problem.n_equalities() == 0)
        return 0.0;
      const Eigen::VectorXd defect = problem.G * r - problem.e;
      double                sum    = 0.0;
      for (Eigen::Index i = 0; i < defect.size(); ++i)
        {
          const double row = problem.G.row(i).norm();
          const double x   = (row > 0.0) ? defect[i] / row : defect[i];
          sum += x * x;
        }
      return std::sqrt(sum);
    }



    Eigen::VectorXd
    element_residuals(const ContactProblem  &problem,
                      const Eigen::VectorXd &r,
                      const Eigen::VectorXd &u)
    {
      if (r.size() != problem.D.size() || u.size() != problem.D.size())
        throw std::invalid_argument(
          "element_residuals: r and u must have the size of D");
      const unsigned int    d = problem.dim;
      const unsigned int    n = problem.n_elements();
      const FrictionSet     set(problem);
      const Eigen::VectorXd rho = residual_rho(problem);
      Eigen::VectorXd       norms(n);
      for (unsigned int j = 0; j < n; ++j)
        {
          double F[3];
          natural_map_element(
            set, rho[j], problem.mu[j], r.data() + d * j, u.data() + d * j, F);
          double sum = 0.0;
          for (unsigned int k = 0; k < d; ++k)
            sum += F[k] * F[k];
          norms[j] = std::sqrt(sum);
        }
      const double scale = residual_scale(problem, rho, r);
      if (scale > 0.0)
        norms /= scale;
      return norms;
    }



    ResidualFigures
    compute_residual_from_u(const ContactProblem  &problem,
                            const FrictionSet     &set,
                            const Eigen::VectorXd &rho,
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
          natural_map_element(set, rho[j], mu, rj, uj, F);
          for (unsigned int k = 0; k < d; ++k)
            sum += F[k] * F[k];

          f.penetration = std::max(f.penetration, uj[0]);
          f.cone_violation =
            std::max({f.cone_violation, set.gauge(rj + 1) + mu * rj[0], rj[0]});
          f.complementarity =
            std::max(f.complementarity, std::abs(rj[0] * uj[0]));
        }
      if (problem.n_equalities() > 0)
        {
          f.equilibrium = (problem.G * r - problem.e).lpNorm<Eigen::Infinity>();
          const double defect = equality_defect(problem, r);
          sum += defect * defect;
        }
      const double scale = residual_scale(problem, rho, r);
      f.natural_map      = (scale > 0.0) ? std::sqrt(sum) / scale :
                           (sum > 0.0)   ? std::sqrt(sum) :
                                           0.0;
      return f;
    }



    ContactStatus
    classify_element(const FrictionSet &set,
                     const double       mu_j,
                     const double      *r_j,
                     const double      *u_j,
                     const double       traction_tolerance,
                     const double       displacement_tolerance)
    {
      const double N = r_j[0];
      if (N >= -traction_tolerance)
        return ContactStatus::separated;
      double slip_norm = 0.0;
      for (unsigned int k = 0; k < set.tangential_dim(); ++k)
        slip_norm += u_j[1 + k] * u_j[1 + k];
      const bool moves = std::sqrt(slip_norm) > displacement_tolerance;
      const bool on_boundary =
        set.gauge(r_j + 1) >= -mu_j * N - traction_tolerance;
      return (moves || on_boundary) ? ContactStatus::slip :
                                      ContactStatus::stick;
    }



    std::vector<ContactStatus>
    classify(const ContactProblem  &problem,
             const Eigen::VectorXd &r,
             const Eigen::VectorXd &u,
             const double           tolerance)
    {
      if (r.size() != problem.D.size() || u.size() != problem.D.size())
        throw std::invalid_argument(
          "classify: r and u must have the size of D");
      const unsigned int    d = problem.dim;
      const unsigned int    n = problem.n_elements();
      const FrictionSet     set(problem);
      const Eigen::VectorXd rho = residual_rho(problem);
      // Tolerances: tractions relative to the larger of ||r||_inf and
      // ||rho D^+||_inf (the tractions the loads stand for, the load part
      // of S(r)), displacements (times rho_j, a traction) relative to the
      // scale of the shared residual. The load part keeps round-off from
      // being taken for contact where the answer is r = 0: a block pressed
      // only sideways, which lifts off, had -N of 1e-12 MPa counted as
      // contact on half its base.
      double load = 0.0;
      for (Eigen::Index i = 0; i < problem.D.size(); ++i)
        load = std::max(load, std::abs(load_traction(problem, rho, i)));
      const double traction_tolerance =
        tolerance *
        std::max(r.size() > 0 ? r.lpNorm<Eigen::Infinity>() : 0.0, load);
      const double scale = tolerance * residual_scale(problem, rho, r);
      std::vector<ContactStatus> status(n, ContactStatus::separated);
      for (unsigned int j = 0; j < n; ++j)
        status[j] = classify_element(set,
                                     problem.mu[j],
                                     r.data() + d * j,
                                     u.data() + d * j,
                                     traction_tolerance,
                                     scale / rho[j]);
      return status;
    }
  } // namespace contact
} // namespace dpana
