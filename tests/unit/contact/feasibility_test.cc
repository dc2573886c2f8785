// The feasibility check of the equality rows (contact/feasibility.h) on a
// rigid block resting on two contact elements of unit area at x = -1 and
// x = 1. Its free motions are the translations along the normal and the
// tangent(s) and the rotation; the rows are
//   N_0 + N_1 = -P            (normal load P, compressive if P > 0),
//   T_0 + T_1 = Q             (side load Q),
//   -N_0 + N_1 = Mo           (moment Mo of the loads about x = 0).
// With N_j <= 0 and |T_j| <= -mu N_j these can be met exactly when P >= 0,
// |Q| <= mu P and |Mo| <= P (the statics of a block on two supports), which
// is the reference of every case below.
#include <dpana/contact/feasibility.h>

#include <cmath>
#include <cstdlib>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

using dpana::contact::ConeModel;
using dpana::contact::ContactProblem;

namespace
{
  // The block in 2D (unknowns N_0, T_0, N_1, T_1) or 3D (N, T_1, T_2 per
  // element; the side load (Q, Q2)).
  ContactProblem
  block(const unsigned int dim,
        const double       mu,
        const double       P,
        const double       Q,
        const double       Mo,
        const double       Q2 = 0)
  {
    ContactProblem p;
    p.dim                = dim;
    p.A                  = Eigen::MatrixXd::Identity(2 * dim, 2 * dim);
    p.D                  = Eigen::VectorXd::Zero(2 * dim);
    p.mu                 = Eigen::VectorXd::Constant(2, mu);
    p.cone               = dim == 2 ? ConeModel::interval : ConeModel::disc;
    const unsigned int m = dim + 1;
    p.G                  = Eigen::MatrixXd::Zero(m, 2 * dim);
    p.e                  = Eigen::VectorXd::Zero(m);
    for (unsigned int j = 0; j < 2; ++j)
      {
        p.G(0, dim * j)     = 1;
        p.G(1, dim * j + 1) = 1;
        if (dim == 3)
          p.G(2, dim * j + 2) = 1;
        p.G(m - 1, dim * j) = j == 0 ? -1 : 1;
      }
    p.e(0) = -P;
    p.e(1) = Q;
    if (dim == 3)
      p.e(2) = Q2;
    p.e(m - 1) = Mo;
    return p;
  }
} // namespace



TEST(Feasibility, BlockIn2DAgainstStatics)
{
  struct Case
  {
    double mu, P, Q, Mo;
    bool   feasible;
  };
  const std::vector<Case> cases = {{0.1, 50, 4.9, 0, true},
                                   {0.1, 50, 5.1, 0, false},
                                   {0.1, 50, -5.1, 0, false},
                                   {0, 50, 0, 0, true},
                                   {0, 50, 1e-3, 0, false},
                                   {0.3, -50, 0, 0, false},
                                   {0.3, 50, 0, 49, true},
                                   {0.3, 50, 0, -51, false},
                                   {1, 50, 49, 49, true},
                                   {0.3, 0, 0, 0, true}};
  for (const Case &c : cases)
    {
      const auto f =
        dpana::contact::check_feasibility(block(2, c.mu, c.P, c.Q, c.Mo),
                                          Eigen::VectorXd::Constant(3, 100.));
      EXPECT_EQ(f.feasible, c.feasible)
        << "mu " << c.mu << " P " << c.P << " Q " << c.Q << " Mo " << c.Mo
        << ": residual " << f.residual;
    }
}



// The unbalanced part G r - e at the best admissible r: for a pull the
// tractions can at best vanish, so the normal row is left with -e_0 = -50;
// for a side load Q = 8 with mu P = 5 the side row is left short by about
// 3 (a little less: the least squares optimum presses slightly harder to
// gain friction: the side row is left with 3 / (1 + mu^2)).
TEST(Feasibility, UnbalancedLoadNamesTheDirection)
{
  const Eigen::VectorXd scale = Eigen::VectorXd::Constant(3, 1.);
  const auto            pull =
    dpana::contact::check_feasibility(block(2, 0.3, -50, 0, 0), scale);
  EXPECT_FALSE(pull.feasible);
  EXPECT_NEAR(pull.unbalanced(0), -50, 1e-9);
  const auto side =
    dpana::contact::check_feasibility(block(2, 0.1, 50, 8, 0), scale);
  EXPECT_FALSE(side.feasible);
  EXPECT_LT(side.unbalanced(1), -2.9);
  EXPECT_NEAR(side.residual, 3 / 1.01, 1e-9);
}



// The check does not depend on the loads' unit: the cases of
// BlockIn2DAgainstStatics with every load and its scale multiplied by
// 1e200 (an input of 1e200 MPa) or 1e-200 give the same answers. With G
// divided by a scale of 1e200 its columns used to underflow to norm 0 and
// be dropped: a block pressed onto the supports was reported unheld.
TEST(Feasibility, IndependentOfTheLoadsUnit)
{
  for (const double unit : {1e200, 1e-200})
    for (const auto &[mu, P, Q, feasible] :
         std::vector<std::tuple<double, double, double, bool>>{
           {0.1, 50, 4.9, true}, {0.1, 50, 5.1, false}, {0, 50, 0, true}})
      {
        const auto f = dpana::contact::check_feasibility(
          block(2, mu, unit * P, unit * Q, 0),
          Eigen::VectorXd::Constant(3, unit * 100.));
        EXPECT_EQ(f.feasible, feasible)
          << "unit " << unit << " mu " << mu << " P " << P << " Q " << Q
          << ": residual " << f.residual;
      }
}



// In 3D a side load at 45 degrees of 0.9 mu P per direction lies inside the
// square that circumscribes the friction disc (polygon, 4 sides) but outside
// the disc (|Q| = 1.27 mu P) and its 32-sided circumscribed polygon.
TEST(Feasibility, PolygonAndDiscIn3D)
{
  const Eigen::VectorXd scale = Eigen::VectorXd::Constant(4, 100.);
  ContactProblem        p     = block(3, 0.2, 50, 9, 0, 9);
  p.cone                      = ConeModel::polygon;
  p.polygon_sides             = 4;
  EXPECT_TRUE(dpana::contact::check_feasibility(p, scale).feasible);
  p.cone = ConeModel::disc;
  EXPECT_FALSE(dpana::contact::check_feasibility(p, scale).feasible);
  // Inside the disc: |Q| = 0.95 mu P.
  p = block(3, 0.2, 50, 9.5 / std::sqrt(2.), 0, 9.5 / std::sqrt(2.));
  EXPECT_TRUE(dpana::contact::check_feasibility(p, scale).feasible);
}



// Nonnegative least squares against the enumeration of all supports: for
// every subset of columns the unconstrained least squares solution, kept if
// nonnegative; the smallest residual among them is the optimum.
TEST(Feasibility, NonnegativeLeastSquaresAgainstEnumeration)
{
  for (unsigned int seed = 1; seed <= 20; ++seed)
    {
      std::srand(seed);
      const Eigen::MatrixXd M = Eigen::MatrixXd::Random(3, 5);
      const Eigen::VectorXd b = Eigen::VectorXd::Random(3);
      const Eigen::VectorXd x = dpana::contact::nonnegative_least_squares(M, b);
      ASSERT_GE(x.minCoeff(), 0);
      double best = b.norm();
      for (unsigned int set = 1; set < 32; ++set)
        {
          std::vector<int> cols;
          for (int k = 0; k < 5; ++k)
            if (set & (1u << k))
              cols.push_back(k);
          Eigen::MatrixXd MS(3, cols.size());
          for (std::size_t k = 0; k < cols.size(); ++k)
            MS.col(k) = M.col(cols[k]);
          const Eigen::VectorXd z = MS.colPivHouseholderQr().solve(b);
          if (z.minCoeff() >= 0)
            best = std::min(best, (MS * z - b).norm());
        }
      EXPECT_NEAR((M * x - b).norm(), best, 1e-10) << "seed " << seed;
    }
}
