// Shared tools of the contact solver tests: random problems, an independent
// brute-force solver for small 2D problems, and comparison helpers.
#ifndef dpana_tests_contact_test_tools_h
#define dpana_tests_contact_test_tools_h

#include <dpana/contact/problem.h>
#include <dpana/contact/solver.h>

#include <Eigen/Dense>

#include <cmath>
#include <random>
#include <vector>

namespace dpana_test
{
  using namespace dpana::contact;

  // A random SPD compliance matrix in the interleaved ordering:
  // A = B B^T / (d n) + shift I with B standard normal, which gives a
  // condition number of order 10 - 100 and a full N-T coupling. D_N uniform
  // in [-1, 1] (so that roughly half of the elements are pressed into
  // contact), D_T uniform in [-1, 1].
  inline ContactProblem
  random_problem(const unsigned int dim,
                 const unsigned int n,
                 const double       mu,
                 const unsigned int seed,
                 const ConeModel    cone  = ConeModel::interval,
                 const double       shift = 0.2)
  {
    std::mt19937                           gen(seed);
    std::normal_distribution<double>       normal(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const unsigned int                     size = dim * n;
    Eigen::MatrixXd                        B(size, size);
    for (unsigned int i = 0; i < size; ++i)
      for (unsigned int j = 0; j < size; ++j)
        B(i, j) = normal(gen);
    ContactProblem p;
    p.dim = dim;
    p.A =
      B * B.transpose() / size + shift * Eigen::MatrixXd::Identity(size, size);
    p.A = 0.5 * (p.A + p.A.transpose()).eval();
    p.D.resize(size);
    for (unsigned int i = 0; i < size; ++i)
      p.D[i] = uniform(gen);
    p.mu   = Eigen::VectorXd::Constant(n, mu);
    p.cone = (dim == 2) ? ConeModel::interval : cone;
    return p;
  }

  // Independent reference for 2D problems: enumerate every combination of
  // {separated, stick, slip+, slip-} per element, solve the linear system of
  // each combination (separated: N = T = 0; stick: u_N = u_T = 0; slip s:
  // u_N = 0 and T = -s mu N) and keep the combinations whose solution
  // satisfies every sign condition (N <= 0, u_N <= 0, |T| <= -mu N,
  // s u_T <= 0) within a relative tolerance. Returns all admissible r.
  inline std::vector<Eigen::VectorXd>
  enumerate_2d(const ContactProblem &p, const double tol = 1e-9)
  {
    const unsigned int           n = p.n_elements();
    std::vector<Eigen::VectorXd> solutions;
    unsigned int                 combinations = 1;
    for (unsigned int j = 0; j < n; ++j)
      combinations *= 4;
    const double scale = 1.0 + p.D.lpNorm<Eigen::Infinity>();
    for (unsigned int code = 0; code < combinations; ++code)
      {
        std::vector<int> c(n);
        unsigned int     x = code;
        for (unsigned int j = 0; j < n; ++j, x /= 4)
          c[j] = x % 4;
        // Unknowns r (2n); equations: one pair per element.
        Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * n, 2 * n);
        Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * n);
        for (unsigned int j = 0; j < n; ++j)
          {
            const unsigned int iN = 2 * j, iT = 2 * j + 1;
            if (c[j] == 0)
              {
                K(iN, iN) = 1;
                K(iT, iT) = 1;
              }
            else if (c[j] == 1)
              {
                K.row(iN) = p.A.row(iN);
                f[iN]     = -p.D[iN];
                K.row(iT) = p.A.row(iT);
                f[iT]     = -p.D[iT];
              }
            else
              {
                const double s = (c[j] == 2) ? 1.0 : -1.0;
                K.row(iN)      = p.A.row(iN);
                f[iN]          = -p.D[iN];
                K(iT, iT)      = 1.0; // T + s mu N = 0
                K(iT, iN)      = s * p.mu[j];
              }
          }
        Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
        if (!lu.isInvertible())
          continue;
        const Eigen::VectorXd r  = lu.solve(f);
        const Eigen::VectorXd u  = p.A * r + p.D;
        bool                  ok = true;
        for (unsigned int j = 0; j < n && ok; ++j)
          {
            const double N = r[2 * j], T = r[2 * j + 1];
            const double uN = u[2 * j], uT = u[2 * j + 1];
            ok = N <= tol * scale && uN <= tol * scale &&
                 std::abs(T) <= -p.mu[j] * N + tol * scale;
            if (c[j] >= 2)
              {
                const double s = (c[j] == 2) ? 1.0 : -1.0;
                ok             = ok && s * uT <= tol * scale;
              }
          }
        if (ok)
          {
            bool duplicate = false;
            for (const auto &s : solutions)
              duplicate =
                duplicate || (s - r).lpNorm<Eigen::Infinity>() <= 1e-8 * scale;
            if (!duplicate)
              solutions.push_back(r);
          }
      }
    return solutions;
  }

  inline double
  relative_difference(const Eigen::VectorXd &a, const Eigen::VectorXd &b)
  {
    const double s = std::max(a.lpNorm<Eigen::Infinity>(), 1e-300);
    return (a - b).lpNorm<Eigen::Infinity>() / s;
  }

  inline SolverOptions
  options_for(const SolverType type, const double tolerance = 1e-10)
  {
    SolverOptions o;
    o.type           = type;
    o.tolerance      = tolerance;
    o.max_iterations = 20000;
    return o;
  }

  inline const std::vector<SolverType> &
  all_solvers()
  {
    static const std::vector<SolverType> s = {SolverType::splitting_pgs,
                                              SolverType::splitting_active_set,
                                              SolverType::nsgs,
                                              SolverType::alart_curnier};
    return s;
  }
} // namespace dpana_test

#endif
