// The per-element natural-map residual ||F_j|| / S(r) (residual.h), which
// the contact scenes write along the contact surface: hand-computed values
// on a two-element problem, and its relation to the shared figure
//   natural_map = sqrt( sum_j ||F_j||^2 + sum_i E_i^2 ) / S(r),
//   S(r) = ||r||_2 + rho ||D^+||_2.
#include <dpana/contact/residual.h>

#include <cmath>

#include "contact_test_tools.h"
#include <gtest/gtest.h>

using namespace dpana_test;

// Two uncoupled 2D elements, A = I (so rho_j = d / trace(A_jj) = 1), at the
// tractions r = (0, 0 | -1, 0), which solve neither element:
//
// Element 1, mu = 0, D_1 = (1, 0): u_1 = (1, 0), the point
//   x = r_1 - rho (u_N - mu sigma(-u_T), u_T) = (-1, 0) lies in
//   K = {N <= 0, T = 0}, so p = x and F_1 = r_1 - p = (1, 0), ||F_1|| = 1.
//
// Element 2, mu = 0.5, D_2 = (0.5, 2): u_2 = (-0.5, 2), sigma(-u_T) = 2,
//   tilde u_N = -0.5 - 0.5 * 2 = -1.5, x = (-1 + 1.5, -2) = (0.5, -2).
//   x is neither in K = {|T| <= -N / 2} nor in its polar cone
//   {N >= |T| / 2}; its projection is onto the ray of K through
//   e = (-1, -1/2) / sqrt(5/4): p = (x . e) e = (-0.4, -0.2), hence
//   F_2 = (-0.6, 0.2) and ||F_2|| = sqrt(0.4).
TEST(ElementResidual, HandComputedTwoElementProblem)
{
  ContactProblem p;
  p.dim  = 2;
  p.A    = Eigen::MatrixXd::Identity(4, 4);
  p.D    = Eigen::Vector4d(1.0, 0.0, 0.5, 2.0);
  p.mu   = Eigen::Vector2d(0.0, 0.5);
  p.cone = ConeModel::interval;
  const Eigen::Vector4d r(0.0, 0.0, -1.0, 0.0);
  const Eigen::VectorXd u = p.A * r + p.D;

  // S = ||r|| + rho ||D^+|| = 1 + sqrt(1 + 0.25 + 4) (no gap in D).
  const double          S = 1.0 + std::sqrt(5.25);
  const Eigen::VectorXd e = element_residuals(p, r, u);
  ASSERT_EQ(e.size(), 2);
  EXPECT_NEAR(e[0], 1.0 / S, 1e-15);
  EXPECT_NEAR(e[1], std::sqrt(0.4) / S, 1e-15);

  // The vector F_2 itself.
  const FrictionSet set(p);
  double            F[2];
  natural_map_element(set, 1.0, 0.5, r.data() + 2, u.data() + 2, F);
  EXPECT_NEAR(F[0], -0.6, 1e-15);
  EXPECT_NEAR(F[1], 0.2, 1e-15);

  // The shared figure: sqrt(1 + 0.4) / (||r|| + rho ||D||), ||r|| = 1,
  // ||D|| = sqrt(1 + 0.25 + 4).
  EXPECT_NEAR(compute_residual(p, r, Eigen::VectorXd()).natural_map,
              std::sqrt(1.4) / S,
              1e-15);
}



// On random problems (2D interval, 3D disc and polygon) at perturbed
// solutions, and on a problem with equality rows and rigid-mode amplitudes
// alpha, the per-element values squared and the equality defect add up to
// the square of the shared figure.
namespace
{
  void
  check_sum_of_squares(const ContactProblem  &p,
                       const Eigen::VectorXd &r,
                       const Eigen::VectorXd &alpha)
  {
    Eigen::VectorXd u = p.A * r + p.D;
    if (p.n_equalities() > 0)
      u += p.G.transpose() * alpha;
    const double          figure = compute_residual(p, r, alpha).natural_map;
    const Eigen::VectorXd e      = element_residuals(p, r, u);
    ASSERT_EQ(e.size(), p.n_elements());
    EXPECT_GT(figure, 1e-6); // a point that is not a solution
    const double equality =
      equality_defect(p, r) / residual_scale(p, residual_rho(p), r);
    EXPECT_NEAR(e.squaredNorm() + equality * equality,
                figure * figure,
                1e-12 * figure * figure);
    EXPECT_LE(e.maxCoeff(), figure);
    // The residual is spread over several elements, not concentrated in
    // one: the per-element split is not trivial.
    EXPECT_LT(e.maxCoeff(), e.norm() * (1.0 - 1e-3));
  }
} // namespace

TEST(ElementResidual, SquaresAddUpToTheSharedResidual)
{
  struct Case
  {
    unsigned int dim;
    ConeModel    cone;
  };
  for (const Case c : {Case{2, ConeModel::interval},
                       Case{3, ConeModel::disc},
                       Case{3, ConeModel::polygon}})
    {
      const ContactProblem p = random_problem(c.dim, 8, 0.4, 17, c.cone);
      const SolverResult   s = solve(p, options_for(SolverType::nsgs));
      ASSERT_TRUE(s.converged);
      Eigen::VectorXd r = s.r;
      for (int i = 0; i < r.size(); i += 3)
        r[i] += 0.01 * (i % 2 ? 1.0 : -1.0);
      check_sum_of_squares(p, r, Eigen::VectorXd());
    }
}

TEST(ElementResidual, SquaresAddUpWithEqualityRows)
{
  // A floating 2D body: its vertical translation is free, G r = e is the
  // balance of the normal tractions with a load of 2 per element (row of
  // ones on the normal components), alpha its amplitude.
  ContactProblem     p = random_problem(2, 6, 0.3, 5);
  const unsigned int n = p.n_elements();
  p.G                  = Eigen::MatrixXd::Zero(1, 2 * n);
  for (unsigned int j = 0; j < n; ++j)
    p.G(0, 2 * j) = 1.0;
  p.e = Eigen::VectorXd::Constant(1, -2.0 * n);
  Eigen::VectorXd r(2 * n);
  for (unsigned int j = 0; j < n; ++j)
    {
      r[2 * j]     = -2.0 - 0.1 * j;
      r[2 * j + 1] = 0.05 * j;
    }
  check_sum_of_squares(p, r, Eigen::VectorXd::Constant(1, 0.7));
}

TEST(ElementResidual, RejectsWrongSizes)
{
  const ContactProblem p = random_problem(2, 3, 0.3, 1);
  EXPECT_THROW(element_residuals(p, Eigen::VectorXd::Zero(5), p.D),
               std::invalid_argument);
}
