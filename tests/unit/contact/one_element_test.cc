// One contact element with answers derived by hand (in the comments). Every
// solver must reproduce them to round-off and report the right status.
#include "contact_test_tools.h"
#include <gtest/gtest.h>

using namespace dpana_test;

namespace
{
  void
  expect_all_solvers(const ContactProblem  &p,
                     const Eigen::VectorXd &expected,
                     const ContactStatus    status,
                     const double           tolerance = 1e-12)
  {
    for (const SolverType type : all_solvers())
      {
        // The splitting converges linearly: ask for a residual near round-off
        // so that the comparison can be made to 1e-12.
        const SolverResult res = solve(p, options_for(type, 1e-13));
        ASSERT_TRUE(res.converged) << to_string(type) << ": " << res.message;
        EXPECT_LE(res.residual, 1e-13);
        EXPECT_LE((res.r - expected).lpNorm<Eigen::Infinity>(),
                  tolerance * (1.0 + expected.lpNorm<Eigen::Infinity>()))
          << to_string(type) << "\n got " << res.r.transpose() << "\n expected "
          << expected.transpose();
        ASSERT_EQ(res.status.size(), 1u);
        EXPECT_EQ(res.status[0], status) << to_string(type);
      }
  }

  // 2D: A = [[2, 0.3], [0.3, 1]] (det 1.91).
  ContactProblem
  two_d(const double DN, const double DT, const double mu)
  {
    ContactProblem p;
    p.dim = 2;
    p.A.resize(2, 2);
    p.A << 2.0, 0.3, 0.3, 1.0;
    p.D.resize(2);
    p.D << DN, DT;
    p.mu = Eigen::VectorXd::Constant(1, mu);
    return p;
  }

  // 3D with no N-T coupling: A = diag(2, 1, 1). Then the N-step is exact
  // at once (N = -D_N / 2 when D_N > 0) and the T-problem is
  // min 1/2 ||T||^2 + D_T . T over the tangential set of radius -mu N, whose
  // solution is the Euclidean projection of -D_T onto that set.
  ContactProblem
  three_d(const Eigen::Vector3d &D, const double mu, const ConeModel cone)
  {
    ContactProblem p;
    p.dim           = 3;
    p.A             = Eigen::Vector3d(2.0, 1.0, 1.0).asDiagonal();
    p.D             = D;
    p.mu            = Eigen::VectorXd::Constant(1, mu);
    p.cone          = cone;
    p.polygon_sides = 8;
    return p;
  }
} // namespace

TEST(OneElement, TwoDSeparation)
{
  // D_N = -0.5 < 0: the gap stays open whatever D_T; r = 0, u = D.
  expect_all_solvers(two_d(-0.5, 3.0, 0.3),
                     Eigen::Vector2d(0.0, 0.0),
                     ContactStatus::separated);
}

TEST(OneElement, TwoDStick)
{
  // Stick: r = -A^{-1} D with D = (1, 0.1):
  //   N = -(1 * 1 - 0.3 * 0.1) / 1.91 = -0.97 / 1.91,
  //   T = -(-0.3 * 1 + 2 * 0.1) / 1.91 = 0.1 / 1.91,
  // and |T| = 0.052 < mu |N| = 0.5 * 0.508: strictly inside.
  expect_all_solvers(two_d(1.0, 0.1, 0.5),
                     Eigen::Vector2d(-0.97 / 1.91, 0.1 / 1.91),
                     ContactStatus::stick);
}

TEST(OneElement, TwoDSlip)
{
  // D = (1, 2), mu = 0.3. The stick trial T = -(-0.3 + 4) / 1.91 = -1.94
  // exceeds mu |N|, so the element slips backwards (s = -1): T = mu N and
  // u_N = 2 N + 0.3 T + 1 = 0 give N = -1 / (2 + 0.3 * 0.3) = -1 / 2.09,
  // T = 0.3 N; then u_T = 0.3 N + T + 2 = 1.71 > 0 = -lambda T with
  // lambda > 0, as slip requires.
  const double N = -1.0 / 2.09;
  expect_all_solvers(two_d(1.0, 2.0, 0.3),
                     Eigen::Vector2d(N, 0.3 * N),
                     ContactStatus::slip);
}

TEST(OneElement, TwoDFrictionless)
{
  // mu = 0: T = 0, N = -D_N / A_NN = -0.5.
  expect_all_solvers(two_d(1.0, 2.0, 0.0),
                     Eigen::Vector2d(-0.5, 0.0),
                     ContactStatus::slip);
}

TEST(OneElement, ThreeDDiscStickAndSlip)
{
  // D = (1, 0.3, 0.4): N = -0.5, ||D_T|| = 0.5.
  // mu = 1.5: radius 0.75 > 0.5, stick, T = -D_T.
  expect_all_solvers(three_d({1.0, 0.3, 0.4}, 1.5, ConeModel::disc),
                     Eigen::Vector3d(-0.5, -0.3, -0.4),
                     ContactStatus::stick);
  // mu = 0.4: radius 0.2 < 0.5, slip, T = -0.2 D_T / ||D_T||.
  expect_all_solvers(three_d({1.0, 0.3, 0.4}, 0.4, ConeModel::disc),
                     Eigen::Vector3d(-0.5, -0.12, -0.16),
                     ContactStatus::slip);
  // Separation.
  expect_all_solvers(three_d({-1.0, 0.3, 0.4}, 0.4, ConeModel::disc),
                     Eigen::Vector3d(0.0, 0.0, 0.0),
                     ContactStatus::separated);
}

TEST(OneElement, ThreeDPolygon)
{
  // Octagon (s = 8): facet normals at k pi/4, vertices at pi/8 + k pi/4 at
  // distance 1/cos(pi/8).
  // Stick as for the disc.
  expect_all_solvers(three_d({1.0, 0.3, 0.4}, 1.5, ConeModel::polygon),
                     Eigen::Vector3d(-0.5, -0.3, -0.4),
                     ContactStatus::stick);
  // -D_T along the facet normal at angle pi: projection onto that facet,
  // T = (-0.2, 0), identical to the disc answer.
  expect_all_solvers(three_d({1.0, 0.5, 0.0}, 0.4, ConeModel::polygon),
                     Eigen::Vector3d(-0.5, -0.2, 0.0),
                     ContactStatus::slip);
  // -D_T along the vertex direction 9 pi / 8: the answer is that vertex,
  // T = 0.2 / cos(pi/8) (cos 9pi/8, sin 9pi/8), larger than the disc answer
  // by the factor 1/cos(pi/8) (the capacity overestimate of the polygon).
  const double    a = 9.0 * M_PI / 8.0, R = 0.2 / std::cos(M_PI / 8.0);
  Eigen::Vector3d D(1.0, -0.5 * std::cos(a), -0.5 * std::sin(a));
  expect_all_solvers(three_d(D, 0.4, ConeModel::polygon),
                     Eigen::Vector3d(-0.5, R * std::cos(a), R * std::sin(a)),
                     ContactStatus::slip);
}

TEST(OneElement, ThreeDCoupledDiscAgainstParametrisation)
{
  // A coupled 3D element: A = [[2, 0.4, -0.3], [0.4, 1.5, 0.2],
  // [-0.3, 0.2, 1]], D = (1, 1.5, -2), mu = 0.5. Independent reference: the
  // slip solution is T = mu p (cos t, sin t), N = -p, with u_N = 0 and
  // u_T parallel to -(cos t, sin t). Scan t on a fine grid (20000 points)
  // for the admissible zero of the cross product, refine by bisection.
  ContactProblem p;
  p.dim = 3;
  p.A.resize(3, 3);
  p.A << 2.0, 0.4, -0.3, 0.4, 1.5, 0.2, -0.3, 0.2, 1.0;
  p.D     = Eigen::Vector3d(1.0, 1.5, -2.0);
  p.mu    = Eigen::VectorXd::Constant(1, 0.5);
  p.cone  = ConeModel::disc;
  auto at = [&](const double t, Eigen::Vector3d &r) {
    const Eigen::Vector2d e(std::cos(t), std::sin(t));
    const double den = p.A(0, 0) - p.mu[0] * p.A.block<1, 2>(0, 1).dot(e);
    const double pp  = p.D[0] / den;
    r << -pp, p.mu[0] * pp * e;
    const Eigen::Vector3d u = p.A * r + p.D;
    return std::make_pair(-e[1] * u[1] + e[0] * u[2], e.dot(u.tail<2>()));
  };
  Eigen::Vector3d reference, r;
  bool            found = false;
  const int       K     = 20000;
  for (int k = 0; k < K && !found; ++k)
    {
      double a = 2 * M_PI * k / K, b = 2 * M_PI * (k + 1) / K;
      auto   fa = at(a, r), fb = at(b, r);
      if ((fa.first > 0) == (fb.first > 0) || fa.second > 0)
        continue;
      for (int it = 0; it < 200; ++it)
        {
          const double c  = 0.5 * (a + b);
          auto         fc = at(c, r);
          if ((fc.first > 0) == (fa.first > 0))
            a = c, fa = fc;
          else
            b = c;
        }
      at(0.5 * (a + b), reference);
      found = true;
    }
  ASSERT_TRUE(found);
  // The stick trial must be outside the disc for this to be the answer.
  const Eigen::Vector3d stick = -p.A.ldlt().solve(p.D);
  ASSERT_GT(stick.tail<2>().norm(), -p.mu[0] * stick[0]);
  expect_all_solvers(p, reference, ContactStatus::slip, 1e-10);
}
