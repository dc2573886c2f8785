// The inner solvers of the splitting on their own: the spectral form of the
// projection derivative used by the Newton step of the friction QP, and the
// agreement of the two independent inner solvers (projected Gauss-Seidel and
// active set / semismooth Newton) on random subproblems, with and without
// equality rows.
#include <dpana/contact/friction_qp.h>
#include <dpana/contact/friction_set.h>
#include <dpana/contact/normal_lcp.h>

#include <random>

#include "contact_test_tools.h"
#include <gtest/gtest.h>

using namespace dpana_test;

namespace
{
  // A random SPD matrix of the given size (B B^T / size + shift I).
  Eigen::MatrixXd
  random_spd(const unsigned int size, const unsigned int seed)
  {
    std::mt19937                     gen(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::MatrixXd                  B(size, size);
    for (unsigned int i = 0; i < size; ++i)
      for (unsigned int j = 0; j < size; ++j)
        B(i, j) = normal(gen);
    Eigen::MatrixXd M =
      B * B.transpose() / size + 0.05 * Eigen::MatrixXd::Identity(size, size);
    return 0.5 * (M + M.transpose());
  }
} // namespace



// J = sum_i lambda_i v_i v_i^T must be the derivative that
// projection_derivative() returns, with orthonormal v_i and lambda_i in
// [0, 1], in every region of every set (inside, on the circle, on a facet,
// at a vertex, zero radius).
TEST(FrictionSetGeometry, SpectralDerivativeMatchesTheDerivative)
{
  std::mt19937                           gen(77);
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  struct Model
  {
    unsigned int dim;
    ConeModel    cone;
  };
  for (const Model model : {Model{2, ConeModel::interval},
                            Model{3, ConeModel::disc},
                            Model{3, ConeModel::polygon}})
    {
      const FrictionSet  set(model.dim, model.cone, 8);
      const unsigned int m               = model.dim - 1;
      unsigned int       regions_seen[3] = {0, 0, 0}; // inside, face, vertex
      for (unsigned int k = 0; k < 400; ++k)
        {
          const double c      = (k % 10 == 0) ? 0.0 : std::abs(uniform(gen));
          double       y[2]   = {uniform(gen), uniform(gen)}, p[2];
          const int    region = set.project_tangential(c, y, p);
          double       J[4], lambda[2], V[4];
          set.projection_derivative(c, y, region, J);
          set.projection_derivative_spectral(c, y, region, lambda, V);
          ++regions_seen[region < 0 ? 0 : (region < 8 ? 1 : 2)];
          for (unsigned int i = 0; i < m; ++i)
            {
              EXPECT_GE(lambda[i], 0.0);
              EXPECT_LE(lambda[i], 1.0 + 1e-15);
              for (unsigned int l = 0; l < m; ++l)
                {
                  double dot = 0.0;
                  for (unsigned int a = 0; a < m; ++a)
                    dot += V[m * i + a] * V[m * l + a];
                  EXPECT_NEAR(dot, i == l ? 1.0 : 0.0, 1e-15);
                }
            }
          for (unsigned int a = 0; a < m; ++a)
            for (unsigned int b = 0; b < m; ++b)
              {
                double value = 0.0;
                for (unsigned int i = 0; i < m; ++i)
                  value += lambda[i] * V[m * i + a] * V[m * i + b];
                EXPECT_NEAR(value, J[m * a + b], 1e-14)
                  << "dim " << model.dim << " region " << region;
              }
        }
      EXPECT_GT(regions_seen[0], 0u);
      EXPECT_GT(regions_seen[1], 0u);
      if (model.cone == ConeModel::polygon)
        EXPECT_GT(regions_seen[2], 0u);
    }
}



// The T-step min 1/2 T^T M T + c^T T over T_j in c_j P (and G T = e) solved
// by block PGS and by the semismooth Newton / active-set method: two
// independent algorithms must give the same minimiser (unique, M SPD) to the
// accuracy of their stopping tests. Disc, polygon and interval; radii with
// zeros (separated elements); with one purely tangential equality row (the
// Schur-complement path of the Newton step), whose right-hand side is taken
// from a feasible point so that the problem has a solution.
TEST(InnerSolvers, FrictionQpActiveSetAgreesWithPgs)
{
  struct Model
  {
    unsigned int dim;
    ConeModel    cone;
  };
  for (const Model model : {Model{2, ConeModel::interval},
                            Model{3, ConeModel::disc},
                            Model{3, ConeModel::polygon}})
    for (const unsigned int rows : {0u, 1u})
      {
        const unsigned int    n = 40, m = model.dim - 1, q = m * n;
        const FrictionSet     set(model.dim, model.cone, 16);
        const Eigen::MatrixXd M = random_spd(q, 11 + 3 * rows + model.dim);
        std::mt19937          gen(5 + rows);
        std::uniform_real_distribution<double> uniform(-1.0, 1.0);
        Eigen::VectorXd                        c(q), radius(n);
        for (unsigned int i = 0; i < q; ++i)
          c[i] = 2.0 * uniform(gen);
        for (unsigned int j = 0; j < n; ++j)
          radius[j] = (j % 7 == 0) ? 0.0 : 0.2 + 0.5 * std::abs(uniform(gen));
        Eigen::MatrixXd G(rows, q);
        Eigen::VectorXd e(rows);
        if (rows > 0)
          {
            // Sum of the first tangential components (a rigid tangential
            // mode), equal to half its value at T = radius (feasible).
            G.setZero();
            double sum = 0.0;
            for (unsigned int j = 0; j < n; ++j)
              {
                G(0, m * j) = 1.0;
                sum += radius[j];
              }
            e[0] = 0.1 * sum;
          }
        InnerOptions options;
        options.tolerance      = 1e-13;
        options.max_iterations = 200000;
        FrictionQp        pgs(M, G, set, options), newton(M, G, set, options);
        Eigen::VectorXd   T_pgs = Eigen::VectorXd::Zero(q), T_newton = T_pgs;
        Eigen::VectorXd   beta_pgs, beta_newton;
        const InnerResult r_pgs = pgs.solve_pgs(c, radius, e, T_pgs, beta_pgs);
        const InnerResult r_newton =
          newton.solve_active_set(c, radius, e, T_newton, beta_newton);
        ASSERT_TRUE(r_pgs.converged) << r_pgs.message;
        ASSERT_TRUE(r_newton.converged) << r_newton.message;
        // Mixed set of states (else the test would not exercise the
        // reduction): some interior, some on the boundary.
        unsigned int inside = 0, boundary = 0;
        for (unsigned int j = 0; j < n; ++j)
          if (radius[j] > 0.0)
            {
              const double g = set.gauge(T_newton.data() + m * j);
              (g < radius[j] * (1.0 - 1e-9) ? inside : boundary)++;
            }
        EXPECT_GT(inside, 2u) << "dim " << model.dim << " rows " << rows;
        EXPECT_GT(boundary, 2u) << "dim " << model.dim << " rows " << rows;
        EXPECT_LE(relative_difference(T_pgs, T_newton), 1e-8)
          << "dim " << model.dim << " rows " << rows;
        // A second, warm-started solve with slightly changed data, as in the
        // splitting: its first Newton step meets the partition of the last
        // step of the first solve and takes the blocked factorisation (kept
        // Cholesky of M_ss and Schur complement of the slip blocks).
        Eigen::VectorXd c2 = c;
        for (unsigned int i = 0; i < q; ++i)
          c2[i] += 1e-3 * uniform(gen);
        Eigen::VectorXd   T2_pgs = T_pgs, beta2_pgs = beta_pgs;
        Eigen::VectorXd   T2_newton = T_newton, beta2_newton = beta_newton;
        const InnerResult r2_pgs =
          pgs.solve_pgs(c2, radius, e, T2_pgs, beta2_pgs);
        const InnerResult r2_newton =
          newton.solve_active_set(c2, radius, e, T2_newton, beta2_newton);
        ASSERT_TRUE(r2_pgs.converged) << r2_pgs.message;
        ASSERT_TRUE(r2_newton.converged) << r2_newton.message;
        EXPECT_LE(relative_difference(T2_pgs, T2_newton), 1e-8)
          << "dim " << model.dim << " rows " << rows << " (warm)";
        // Exact Newton steps from a start this close: finite termination
        // (interval, polygon) or quadratic convergence (disc), measured 1-2
        // steps. A wrong step would still end at the minimiser (line search
        // and PGS fallback), only later: with a sign error in the blocked
        // elimination the disc needed 4 and 8 steps.
        EXPECT_LE(r2_newton.iterations, 3u)
          << "dim " << model.dim << " rows " << rows << " (warm)";
        EXPECT_GT(relative_difference(T_newton, T2_newton), 1e-6);
        if (rows > 0)
          {
            EXPECT_NEAR((G * T2_newton - e)[0], 0.0, 1e-10 * std::abs(e[0]));
            EXPECT_NEAR((G * T_newton - e)[0], 0.0, 1e-10 * std::abs(e[0]));
            EXPECT_NEAR(beta_newton[0],
                        beta_pgs[0],
                        1e-6 * (1.0 + std::abs(beta_newton[0])));
          }
      }
}
