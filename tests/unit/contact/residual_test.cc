// The shared residual, the geometry of the friction sets and the exact local
// solvers.
#include <dpana/contact/friction_set.h>
#include <dpana/contact/local_coulomb.h>
#include <dpana/contact/residual.h>

#include "contact_test_tools.h"
#include <gtest/gtest.h>

using namespace dpana_test;

namespace
{
  // The one-element 2D slip problem of one_element_test.cc: A = [[2, 0.3],
  // [0.3, 1]], D = (1, 2), mu = 0.3, exact solution N = -1/2.09, T = 0.3 N.
  ContactProblem
  slip_problem()
  {
    ContactProblem p;
    p.dim = 2;
    p.A.resize(2, 2);
    p.A << 2.0, 0.3, 0.3, 1.0;
    p.D  = Eigen::Vector2d(1.0, 2.0);
    p.mu = Eigen::VectorXd::Constant(1, 0.3);
    return p;
  }
} // namespace

TEST(Residual, ModifiedVelocityVanishesAtCoulombSolution)
{
  const ContactProblem  p = slip_problem();
  const double          N = -1.0 / 2.09;
  const Eigen::Vector2d r(N, 0.3 * N);
  EXPECT_LE(compute_residual(p, r, Eigen::VectorXd()).natural_map, 1e-15);

  // The plain projection residual (associated law) does NOT vanish there:
  // u_N = 0 but u_T = 1.71, and r - Pi_K(r - rho u) != 0.
  const FrictionSet     set(p);
  const double          rho = residual_rho(p)[0];
  const Eigen::Vector2d u   = p.A * r + p.D;
  const Eigen::Vector2d x   = r - rho * u;
  Eigen::Vector2d       proj;
  set.project_cone(0.3, x.data(), proj.data());
  EXPECT_GT((r - proj).norm(), 1e-2);
}

TEST(Residual, RejectsTheAssociatedLawSolution)
{
  // The associated law is the QP min 1/2 r^T A r + D^T r over K; solve it by
  // projected gradient (step 1/lambda_max, 20000 steps: contraction) and
  // check that the shared residual sees it as wrong, while the solvers'
  // answer is right.
  const ContactProblem p = slip_problem();
  const FrictionSet    set(p);
  const double         step = 1.0 / 2.1; // lambda_max(A) ~ 2.08
  Eigen::Vector2d      r(0.0, 0.0), next;
  for (int it = 0; it < 20000; ++it)
    {
      const Eigen::Vector2d x = r - step * (p.A * r + p.D);
      set.project_cone(0.3, x.data(), next.data());
      r = next;
    }
  // r solves the associated law: the plain projection residual is ~0 ...
  const Eigen::Vector2d x = r - step * (p.A * r + p.D);
  set.project_cone(0.3, x.data(), next.data());
  ASSERT_LE((r - next).norm(), 1e-14);
  // ... but the shared residual is not.
  EXPECT_GT(compute_residual(p, r, Eigen::VectorXd()).natural_map, 1e-3);
}

TEST(Residual, ScaleInvariance)
{
  ContactProblem     p = random_problem(3, 10, 0.5, 99, ConeModel::disc);
  const SolverResult s = solve(p, options_for(SolverType::nsgs));
  Eigen::VectorXd    r = s.r;
  r[4] += 0.01; // a perturbed point, residual O(1e-3)
  const double f0 = compute_residual(p, r, Eigen::VectorXd()).natural_map;
  EXPECT_GT(f0, 1e-5);
  // Loads times lambda: tractions times lambda.
  ContactProblem q = p;
  q.D *= 7.0;
  EXPECT_NEAR(compute_residual(q, 7.0 * r, Eigen::VectorXd()).natural_map,
              f0,
              1e-12 * f0);
  // Compliance and loads times kappa (stiffness / unit change): same
  // tractions.
  q = p;
  q.A *= 1e-4;
  q.D *= 1e-4;
  EXPECT_NEAR(compute_residual(q, r, Eigen::VectorXd()).natural_map,
              f0,
              1e-10 * f0);
}

TEST(Residual, SeparateFiguresAndClassification)
{
  // Two 2D elements, A = I, D = (0.5, 0, -1, 0.3), mu = 0.3.
  ContactProblem p;
  p.dim = 2;
  p.A   = Eigen::MatrixXd::Identity(4, 4);
  p.D   = Eigen::Vector4d(0.5, 0.0, -1.0, 0.3);
  p.mu  = Eigen::VectorXd::Constant(2, 0.3);
  // Element 0: N = 0.2 > 0 (tension: cone violation 0.2), T = 0.1;
  // u_0 = (0.7, 0.1): penetration 0.7, |N u_N| = 0.14.
  // Element 1: N = -1, T = -0.3 (on the cone, slip), u_1 = (-2, 0).
  const Eigen::Vector4d r(0.2, 0.1, -1.0, -0.3);
  const ResidualFigures f = compute_residual(p, r, Eigen::VectorXd());
  EXPECT_DOUBLE_EQ(f.penetration, 0.7);
  EXPECT_DOUBLE_EQ(f.cone_violation, 0.2);
  EXPECT_DOUBLE_EQ(f.complementarity, 2.0); // element 1: |-1 * -2|
  EXPECT_EQ(f.equilibrium, 0.0);

  // Element 1 with T = -0.1 inside the cone: u_T = 0.2 != 0, it moves, so
  // it slips although its traction is inside; with T = -0.3 on the cone
  // (u_T = 0) it slips too; element 0 with T = 0.3 = -mu N on the cone
  // slips although u_T = 0; with T = 0.1 and u_T = 0 it sticks.
  const Eigen::Vector4d r2(0.0, 0.0, -1.0, -0.1), r3(-1.0, 0.3, -1.0, -0.3);
  const auto            s2 = classify(p, r2, p.A * r2 + p.D, 1e-8);
  EXPECT_EQ(s2[0], ContactStatus::separated);
  EXPECT_EQ(s2[1], ContactStatus::slip);
  const Eigen::Vector4d u3(0.0, 0.0, -2.0, 0.0);
  const auto            s3 = classify(p, r3, u3, 1e-8);
  EXPECT_EQ(s3[0], ContactStatus::slip);
  EXPECT_EQ(s3[1], ContactStatus::slip);
  const Eigen::Vector4d r4(-1.0, 0.1, -1.0, -0.1);
  const auto            s4 = classify(p, r4, u3, 1e-8);
  EXPECT_EQ(s4[0], ContactStatus::stick);
  EXPECT_EQ(s4[1], ContactStatus::stick);
}

TEST(FrictionSetGeometry, ConeProjectionOptimality)
{
  // Projection p of x onto a closed convex cone K is characterised by
  // p in K, y = x - p in the polar cone, y . p = 0. The polar of K is
  // {y : y . g <= 0 for every generator g = (-1, mu w), w in P}.
  std::mt19937                           gen(7);
  std::uniform_real_distribution<double> U(-2.0, 2.0);
  for (const ConeModel cone : {ConeModel::disc, ConeModel::polygon})
    for (const unsigned int sides : {3u, 5u, 8u, 16u})
      {
        const FrictionSet set(3, cone, sides);
        for (int k = 0; k < 500; ++k)
          {
            const double mu   = (k % 5 == 0) ? 0.0 : std::abs(U(gen));
            double       x[3] = {U(gen), U(gen), U(gen)}, p[3];
            set.project_cone(mu, x, p);
            const double y[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
            const double tol =
              1e-12 * (1 + std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2]));
            // p in K.
            EXPECT_LE(p[0], tol);
            EXPECT_LE(set.gauge(p + 1), -mu * p[0] + tol);
            // y in the polar: y_N >= mu sigma(y_T) (sigma = support of P).
            EXPECT_GE(y[0], mu * set.support(y + 1) - tol);
            // Complementarity.
            EXPECT_NEAR(y[0] * p[0] + y[1] * p[1] + y[2] * p[2], 0.0, tol);
          }
      }
}

TEST(FrictionSetGeometry, LocalMinimiserBeatsSampling)
{
  // FrictionSet::minimise against 4000 random feasible points (and the
  // boundary) for random SPD 2x2 blocks.
  std::mt19937                           gen(11);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (const ConeModel cone : {ConeModel::disc, ConeModel::polygon})
    for (int k = 0; k < 40; ++k)
      {
        const FrictionSet set(3, cone, 8);
        Eigen::Matrix2d   B;
        B << U(gen), U(gen), U(gen), U(gen);
        const Eigen::Matrix2d W =
          B * B.transpose() + 0.1 * Eigen::Matrix2d::Identity();
        const double Wr[4] = {W(0, 0), W(0, 1), W(1, 0), W(1, 1)};
        const double g[2]  = {3 * U(gen), 3 * U(gen)};
        const double c     = 0.5 + 0.5 * U(gen);
        double       T[2];
        set.minimise(c, Wr, g, T);
        auto f = [&](const double a, const double b) {
          return 0.5 * (a * (W(0, 0) * a + W(0, 1) * b) +
                        b * (W(1, 0) * a + W(1, 1) * b)) +
                 g[0] * a + g[1] * b;
        };
        EXPECT_LE(set.gauge(T), c * (1 + 1e-12));
        const double best = f(T[0], T[1]);
        for (int s = 0; s < 4000; ++s)
          {
            double z[2] = {2 * c * U(gen), 2 * c * U(gen)}, pz[2];
            set.project_tangential(c, z, pz); // feasible sample
            EXPECT_GE(f(pz[0], pz[1]), best - 1e-12);
          }
      }
}

TEST(LocalCoulomb, RandomLocalProblemsAreSolvedExactly)
{
  // 300 random local problems per friction set: the exact local solver's
  // answer has a local natural-map residual at round-off, without falling
  // back to the least-residual candidate.
  std::mt19937                           gen(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (const unsigned int dim : {2u, 3u})
    for (const ConeModel cone :
         {ConeModel::interval, ConeModel::disc, ConeModel::polygon})
      {
        if ((dim == 2) != (cone == ConeModel::interval))
          continue;
        const FrictionSet set(dim, cone, 16);
        unsigned int      fallbacks = 0;
        for (int k = 0; k < 300; ++k)
          {
            Eigen::MatrixXd B(dim, dim);
            for (unsigned int a = 0; a < dim * dim; ++a)
              B(a) = U(gen);
            ContactProblem p;
            p.dim           = dim;
            p.cone          = cone;
            p.polygon_sides = 16;
            p.A = B * B.transpose() + 0.2 * Eigen::MatrixXd::Identity(dim, dim);
            p.D = Eigen::VectorXd(dim);
            for (unsigned int a = 0; a < dim; ++a)
              p.D[a] = 2 * U(gen);
            p.mu = Eigen::VectorXd::Constant(1, std::abs(U(gen)) * 0.8);
            Eigen::
              Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>
                      W    = p.A;
            double    hint = 0, r[3];
            const int code =
              solve_local_coulomb(set, p.mu[0], W.data(), p.D.data(), r, hint);
            fallbacks += (code == 3);
            const Eigen::VectorXd rv = Eigen::Map<Eigen::VectorXd>(r, dim);
            EXPECT_LE(compute_residual(p, rv, Eigen::VectorXd()).natural_map,
                      1e-13)
              << "dim " << dim << " code " << code << " k " << k;
          }
        EXPECT_EQ(fallbacks, 0u);
      }
}
