// Test problems for the comparison of dpana's contact solvers with Siconos:
// random problems with a planted (known) solution and an independent check of
// the contact and friction laws.
//
// Nothing here needs Siconos: it is plain Eigen, shared by the unit tests in
// tests/unit/contact and by the benchmark.
#ifndef dpana_tests_contact_siconos_problems_h
#define dpana_tests_contact_siconos_problems_h

#include <dpana/contact/problem.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace dpana
{
  namespace contact
  {
    namespace test_problems
    {
      // @sect3{Random problems with a planted solution}
      //
      // We build A = Q diag(lambda) Q^T with Q a random orthogonal matrix
      // (Householder QR of a Gaussian matrix) and eigenvalues lambda spread
      // log-uniformly over [1, condition]: a dense SPD matrix that couples
      // every unknown with every other one, normal with tangential included,
      // as the condensed compliance of the reference formulation does.
      //
      // Rather than choosing D at random and hoping for a mixture of contact
      // states, we choose the solution first, element by element,
      //   - separated:  N = 0, T = 0, u_N < 0 (a gap), u_T arbitrary;
      //   - stick:      N < 0, ||T|| < -mu N (strictly inside), u = 0;
      //   - slip:       N < 0, ||T|| = -mu N, u_N = 0, u_T = -lambda T,
      //                 lambda > 0,
      // and set D = u - A r. The pair (r, u) then satisfies every law exactly,
      // so it is a solution of the problem (A, D, mu) by construction. (With
      // mu = 0 every contact is a "slip" with T = 0 and u_T free.) For small
      // mu the solution is unique; for large mu and strong normal-tangential
      // coupling the frictional problem may in principle have several
      // solutions, which the tests report if it happens.
      struct PlantedProblem
      {
        ContactProblem  problem;
        Eigen::VectorXd r; // the planted tractions
        Eigen::VectorXd u; // the planted displacements, u = A r + D
        unsigned int    n_separated = 0, n_stick = 0, n_slip = 0;
      };

      inline Eigen::MatrixXd
      random_spd(const Eigen::Index size,
                 const double       condition,
                 std::mt19937_64   &rng)
      {
        std::normal_distribution<double> gauss(0.0, 1.0);
        Eigen::MatrixXd                  G(size, size);
        for (Eigen::Index j = 0; j < size; ++j)
          for (Eigen::Index i = 0; i < size; ++i)
            G(i, j) = gauss(rng);
        const Eigen::MatrixXd Q =
          Eigen::HouseholderQR<Eigen::MatrixXd>(G).householderQ();
        Eigen::VectorXd                        lambda(size);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (Eigen::Index i = 0; i < size; ++i)
          lambda[i] = std::pow(condition, unit(rng));
        Eigen::MatrixXd A = Q * lambda.asDiagonal() * Q.transpose();
        // Symmetrise exactly (the product is symmetric up to round-off).
        return 0.5 * (A + A.transpose());
      }

      inline PlantedProblem
      planted_problem(const unsigned int dim,
                      const unsigned int n,
                      const double       mu,
                      const unsigned int seed,
                      const double       condition          = 100.0,
                      const double       separated_fraction = 0.3,
                      const double       slip_fraction      = 0.35)
      {
        if (dim != 2 && dim != 3)
          throw std::invalid_argument("planted_problem: dim must be 2 or 3");
        std::mt19937_64                        rng(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::normal_distribution<double>       gauss(0.0, 1.0);

        PlantedProblem p;
        p.problem.dim  = dim;
        p.problem.cone = (dim == 3 ? ConeModel::disc : ConeModel::interval);
        p.problem.A    = random_spd(dim * n, condition, rng);
        p.problem.mu   = Eigen::VectorXd::Constant(n, mu);
        p.r            = Eigen::VectorXd::Zero(dim * n);
        p.u            = Eigen::VectorXd::Zero(dim * n);

        const unsigned int nt = dim - 1;
        for (unsigned int j = 0; j < n; ++j)
          {
            const double draw = unit(rng);
            // A random unit tangential direction.
            Eigen::VectorXd t(nt);
            for (unsigned int k = 0; k < nt; ++k)
              t[k] = gauss(rng);
            t /= t.norm();

            if (draw < separated_fraction)
              {
                ++p.n_separated;
                p.u[dim * j] = -(0.1 + unit(rng)); // an open gap
                for (unsigned int k = 0; k < nt; ++k)
                  p.u[dim * j + 1 + k] = gauss(rng);
              }
            else if (draw < separated_fraction + slip_fraction || mu == 0.0)
              {
                ++p.n_slip;
                const double N      = -(0.2 + unit(rng));
                p.r[dim * j]        = N;
                const double lambda = 0.1 + unit(rng);
                for (unsigned int k = 0; k < nt; ++k)
                  {
                    // ||T|| = -mu N exactly; u_T = -lambda T (or, with
                    // mu = 0, a free tangential displacement).
                    const double T       = -mu * N * t[k];
                    p.r[dim * j + 1 + k] = T;
                    p.u[dim * j + 1 + k] = (mu > 0 ? -lambda * T : gauss(rng));
                  }
              }
            else
              {
                ++p.n_stick;
                const double N = -(0.2 + unit(rng));
                p.r[dim * j]   = N;
                // Strictly inside the cone, at most 80% of the capacity.
                const double radius = -mu * N * 0.8 * unit(rng);
                for (unsigned int k = 0; k < nt; ++k)
                  p.r[dim * j + 1 + k] = radius * t[k];
              }
          }
        p.problem.D = p.u - p.problem.A * p.r;
        p.problem.validate();
        return p;
      }

      // @sect3{An independent check of the contact and friction laws}
      //
      // This check is written from the laws in problem.h alone and does not
      // use dpana's residual, so that it can judge Siconos' solutions and
      // dpana's residual alike. For every element it measures, relative to
      // the scales R = max |r| and U = max |u| of the solution,
      //   - sign:            max(N, 0) / R,
      //   - penetration:     max(u_N, 0) / U,
      //   - complementarity: |N u_N| / (R U),
      //   - cone:            max(||T|| + mu N, 0) / R,
      //   - friction law:    in contact (N < 0) the part of u_T not of the
      //                      form -lambda T with lambda >= 0, and if the
      //                      element sticks strictly inside the cone, all of
      //                      u_T; relative to U.
      // The largest of these is returned.
      struct LawViolation
      {
        double sign            = 0;
        double penetration     = 0;
        double complementarity = 0;
        double cone            = 0;
        double friction        = 0;
        double
        max() const
        {
          return std::max({sign, penetration, complementarity, cone, friction});
        }
      };

      inline LawViolation
      check_laws(const ContactProblem  &problem,
                 const Eigen::VectorXd &r,
                 const Eigen::VectorXd &u)
      {
        const unsigned int dim = problem.dim;
        const unsigned int n   = problem.n_elements();
        const double       R   = std::max(r.cwiseAbs().maxCoeff(), 1e-300);
        const double       U   = std::max(u.cwiseAbs().maxCoeff(), 1e-300);
        LawViolation       v;
        for (unsigned int j = 0; j < n; ++j)
          {
            const double N  = r[dim * j];
            const double uN = u[dim * j];
            const auto   T  = r.segment(dim * j + 1, dim - 1);
            const auto   uT = u.segment(dim * j + 1, dim - 1);
            const double mu = problem.mu[j];
            v.sign          = std::max(v.sign, std::max(N, 0.0) / R);
            v.penetration   = std::max(v.penetration, std::max(uN, 0.0) / U);
            v.complementarity =
              std::max(v.complementarity, std::abs(N * uN) / (R * U));
            v.cone = std::max(v.cone, std::max(T.norm() + mu * N, 0.0) / R);

            // Friction law, only where the element carries a normal
            // traction; a separated element has no condition on u_T.
            if (N < -1e-9 * R)
              {
                const double capacity = -mu * N;
                double       violation;
                if (T.norm() < capacity - 1e-7 * R)
                  violation = uT.norm(); // strict stick: u_T = 0
                else if (T.norm() > 1e-9 * R)
                  {
                    // Slip: u_T = -lambda T; remove the component of u_T
                    // along -T (if lambda >= 0) and measure what is left.
                    const Eigen::VectorXd t     = T / T.norm();
                    const double          along = -uT.dot(t); // = lambda ||T||
                    violation = (uT + std::max(along, 0.0) * t).norm();
                  }
                else
                  violation = 0; // zero capacity (mu = 0): u_T is free
                v.friction = std::max(v.friction, violation / U);
              }
          }
        return v;
      }

    } // namespace test_problems
  }   // namespace contact
} // namespace dpana

#endif
