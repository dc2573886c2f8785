// The feasibility of the equality rows of floating bodies; see
// include/dpana/contact/feasibility.h.
#include <dpana/contact/feasibility.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace dpana
{
  namespace contact
  {
    namespace
    {
      // The least squares solution z of M_P z = b on the columns P.
      Eigen::VectorXd
      solve_on(const Eigen::MatrixXd           &M,
               const std::vector<Eigen::Index> &P,
               const Eigen::VectorXd           &b)
      {
        Eigen::MatrixXd MP(M.rows(), P.size());
        for (std::size_t k = 0; k < P.size(); ++k)
          MP.col(k) = M.col(P[k]);
        return MP.colPivHouseholderQr().solve(b);
      }



      // The generators of the cone of one contact element, in its local
      // coordinates (N, T_1[, T_2]); see the header.
      std::vector<Eigen::VectorXd>
      cone_generators(const ContactProblem &problem, const double mu)
      {
        const unsigned int           d = problem.dim;
        std::vector<Eigen::VectorXd> g;
        Eigen::VectorXd              normal = Eigen::VectorXd::Zero(d);
        normal(0)                           = -1;
        if (!(mu > 0))
          return {normal};
        if (d == 2)
          {
            for (const double sign : {1., -1.})
              {
                g.push_back(normal);
                g.back()(1) = sign * mu;
              }
            return g;
          }
        const unsigned int s =
          problem.cone == ConeModel::polygon ? problem.polygon_sides : 32;
        const double pi     = std::acos(-1.);
        const double radius = mu / std::cos(pi / s);
        for (unsigned int i = 0; i < s; ++i)
          {
            const double theta = (2 * i + 1) * pi / s;
            g.push_back(normal);
            g.back()(1) = radius * std::cos(theta);
            g.back()(2) = radius * std::sin(theta);
          }
        return g;
      }
    } // namespace



    // Lawson and Hanson, algorithm NNLS: the passive set P grows by the
    // column of largest gradient w = M^T (b - M x); when the unconstrained
    // solution on P leaves the orthant, x moves towards it as far as it
    // stays feasible and the columns that reach zero leave P.
    Eigen::VectorXd
    nonnegative_least_squares(const Eigen::MatrixXd &M,
                              const Eigen::VectorXd &b)
    {
      const Eigen::Index        n = M.cols();
      Eigen::VectorXd           x = Eigen::VectorXd::Zero(n);
      std::vector<bool>         passive(n, false);
      std::vector<Eigen::Index> P;
      if (n == 0)
        return x;
      // The gradient test, relative to the column lengths and to b.
      const double tolerance = 1e-12 * M.colwise().norm().maxCoeff() * b.norm();
      const unsigned int max_steps = 3 * static_cast<unsigned int>(n) + 30;
      for (unsigned int step = 0; step < max_steps; ++step)
        {
          const Eigen::VectorXd w = M.transpose() * (b - M * x);
          Eigen::Index          j = -1;
          for (Eigen::Index k = 0; k < n; ++k)
            if (!passive[k] && w(k) > tolerance && (j < 0 || w(k) > w(j)))
              j = k;
          if (j < 0)
            break;
          passive[j] = true;
          P.push_back(j);
          while (!P.empty())
            {
              const Eigen::VectorXd z     = solve_on(M, P, b);
              double                alpha = 1;
              for (std::size_t k = 0; k < P.size(); ++k)
                if (z(k) <= 0)
                  alpha = std::min(alpha, x(P[k]) / (x(P[k]) - z(k)));
              for (std::size_t k = 0; k < P.size(); ++k)
                x(P[k]) += alpha * (z(k) - x(P[k]));
              if (alpha == 1)
                break;
              std::vector<Eigen::Index> kept;
              for (const Eigen::Index k : P)
                if (x(k) > 0)
                  kept.push_back(k);
                else
                  x(k) = 0, passive[k] = false;
              P = kept;
            }
        }
      return x;
    }



    Feasibility
    check_feasibility(const ContactProblem  &problem,
                      const Eigen::VectorXd &row_scale,
                      const double           tolerance)
    {
      const Eigen::Index m = problem.G.rows();
      Feasibility        result;
      result.unbalanced = Eigen::VectorXd::Zero(m);
      if (m == 0)
        return result;
      Eigen::VectorXd scale = row_scale;
      if (scale.size() == 0)
        scale =
          Eigen::VectorXd::Constant(m, problem.e.lpNorm<Eigen::Infinity>());
      if (scale.size() != m)
        throw std::invalid_argument(
          "feasibility: row_scale has " + std::to_string(scale.size()) +
          " entries, the problem " + std::to_string(m) + " equality rows");
      if (scale.maxCoeff() == 0)
        return result;
      if (!(scale.minCoeff() > 0))
        throw std::invalid_argument("feasibility: row_scale must be positive");

      // M = W G [g_k], columns of unit length; r = sum_k lambda_k g_k. The
      // rows are weighted by the scale relative to its largest entry: the
      // columns are normalised anyway, and G scaled by 1/scale itself would
      // underflow for loads of 1e200 (their norms read 0, the columns were
      // dropped and a body pressed onto the obstacle was reported unheld).
      const unsigned int    d = problem.dim;
      const Eigen::MatrixXd WG =
        (scale / scale.maxCoeff()).cwiseInverse().asDiagonal() * problem.G;
      std::vector<Eigen::VectorXd> columns;
      for (unsigned int j = 0; j < problem.n_elements(); ++j)
        for (const auto &g : cone_generators(problem, problem.mu(j)))
          {
            const Eigen::VectorXd c = WG.middleCols(d * j, d) * g;
            if (c.norm() > 0)
              columns.push_back(c / c.norm());
          }
      Eigen::MatrixXd M(m, columns.size());
      for (std::size_t k = 0; k < columns.size(); ++k)
        M.col(k) = columns[k];
      const Eigen::VectorXd b = scale.cwiseInverse().cwiseProduct(problem.e);
      const Eigen::VectorXd lambda =
        columns.empty() ? Eigen::VectorXd() : nonnegative_least_squares(M, b);
      result.unbalanced =
        columns.empty() ? Eigen::VectorXd(-b) : Eigen::VectorXd(M * lambda - b);
      result.residual = result.unbalanced.lpNorm<Eigen::Infinity>();
      result.feasible = result.residual <= tolerance;
      return result;
    }
  } // namespace contact
} // namespace dpana
