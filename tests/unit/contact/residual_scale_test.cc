// The scale of the shared residual (residual.h): a large gap of separated
// elements does not hide an unconverged state, the equality rows of
// floating bodies count in the residual, and every solver ends with one
// and the same classification of the elements.
#include <dpana/contact/residual.h>

#include <cmath>

#include "contact_test_tools.h"
#include <gtest/gtest.h>

using namespace dpana_test;

namespace
{
  // A random 2D or 3D problem whose last `far` elements are given the gap
  // `gap` (D_N = -gap), far beyond any displacement the loads of the others
  // produce: they stay separated, whatever gap they have.
  ContactProblem
  problem_with_far_elements(const unsigned int dim,
                            const unsigned int n,
                            const unsigned int far,
                            const double       gap,
                            const double       mu = 0.5)
  {
    ContactProblem p = random_problem(dim, n, mu, 23, ConeModel::disc);
    for (unsigned int j = n - far; j < n; ++j)
      p.D[dim * j] = -gap;
    return p;
  }

  // Every solver, at tolerance 1e-10, converges to the reference tractions
  // to 1e-7.
  void
  expect_every_solver_finds(const ContactProblem  &p,
                            const Eigen::VectorXd &reference)
  {
    for (const SolverType type : all_solvers())
      {
        const SolverResult s = solve(p, options_for(type, 1e-10));
        ASSERT_TRUE(s.converged) << to_string(type) << ": " << s.message;
        EXPECT_LE((s.r - reference).norm(), 1e-7 * reference.norm())
          << to_string(type);
      }
  }
} // namespace



// The iterate r* + delta (delta 1e-6 of r* on the pressed elements) is not a
// solution. Its residual must be the same whether the far elements are 10
// or 1e9 units away: their tractions are zero, so they add nothing to the
// numerator, and a gap is not a load, so it adds nothing to the scale. (The
// former scale ||r|| + rho ||D|| fell like 1 / gap: about 1e-14 at gap 1e9,
// below any tolerance.) And every solver, on the problem with the far
// elements, finds the solution of the problem with near ones (the same
// tractions: the far elements are separated in both).
TEST(ResidualScale, LargeGapDoesNotHideAnUnconvergedState)
{
  for (const unsigned int dim : {2u, 3u})
    {
      const ContactProblem near = problem_with_far_elements(dim, 12, 4, 10.0);
      const ContactProblem far  = problem_with_far_elements(dim, 12, 4, 1e9);
      const SolverResult   s =
        solve(near, options_for(SolverType::alart_curnier, 1e-14));
      ASSERT_TRUE(s.converged) << s.message;
      for (unsigned int j = 8; j < 12; ++j)
        ASSERT_EQ(s.status[j], ContactStatus::separated);

      Eigen::VectorXd r = s.r;
      for (Eigen::Index i = 0; i < r.size(); ++i)
        r[i] *= 1.0 + 1e-6 * ((i % 3) - 1.0);
      const double at_near =
        compute_residual(near, r, Eigen::VectorXd()).natural_map;
      const double at_far =
        compute_residual(far, r, Eigen::VectorXd()).natural_map;
      EXPECT_GT(at_near, 1e-8);
      EXPECT_NEAR(at_far, at_near, 1e-12 * at_near);
      // The per-element figures agree with it: none above the figure, the
      // largest within a factor sqrt(n) of it.
      const Eigen::VectorXd e = element_residuals(far, r, far.A * r + far.D);
      EXPECT_LE(e.maxCoeff(), at_far * (1.0 + 1e-12));
      EXPECT_GE(e.maxCoeff(), at_far / std::sqrt(12.0));

      expect_every_solver_finds(far, s.r);
    }
}



// A floating body whose elements are all separated: r = 0 meets the
// Signorini-Coulomb law on every element, but not the equilibrium G r = e
// (the body is loaded). The residual must say so (it was 0 when it did not
// include the equality rows), and equal (|e| / ||G||) / S at r = 0, S =
// ||(rho_j D_T,j)_j||.
TEST(ResidualScale, EqualityRowsCountInTheResidual)
{
  ContactProblem     p = random_problem(2, 5, 0.3, 3);
  const unsigned int n = p.n_elements();
  for (unsigned int j = 0; j < n; ++j)
    p.D[2 * j] = -1.0 - j; // all open, D^+ = (0, D_T)
  p.G = Eigen::MatrixXd::Zero(1, 2 * n);
  for (unsigned int j = 0; j < n; ++j)
    p.G(0, 2 * j) = 1.0;
  p.e                     = Eigen::VectorXd::Constant(1, -3.0);
  const Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * n);
  const Eigen::VectorXd u = p.A * r + p.D;
  EXPECT_EQ(element_residuals(p, r, u).maxCoeff(), 0.0);
  const Eigen::VectorXd rho = residual_rho(p);
  double                DT  = 0.0;
  for (unsigned int j = 0; j < n; ++j)
    DT += rho[j] * rho[j] * p.D[2 * j + 1] * p.D[2 * j + 1];
  const ResidualFigures f = compute_residual(p, r, Eigen::VectorXd::Zero(1));
  EXPECT_NEAR(f.natural_map,
              (3.0 / std::sqrt(double(n))) / std::sqrt(DT),
              1e-14);
  EXPECT_DOUBLE_EQ(f.equilibrium, 3.0);
}



// One classification for every solver: on random 3D problems (disc and
// polygon) with mu = 0.3 and 1, and 2D ones, the four solvers, each at
// tolerance 1e-10, label every element alike. The classification uses u_T
// as well as T, so an element that slips is labelled slip even if an
// approximate solution leaves its traction a little inside the cone.
TEST(Classification, SameForEverySolver)
{
  struct Case
  {
    unsigned int dim;
    ConeModel    cone;
    double       mu;
  };
  for (const Case c : {Case{2, ConeModel::interval, 0.3},
                       Case{2, ConeModel::interval, 1.0},
                       Case{3, ConeModel::disc, 0.3},
                       Case{3, ConeModel::disc, 1.0},
                       Case{3, ConeModel::polygon, 1.0}})
    {
      const ContactProblem p = random_problem(c.dim, 30, c.mu, 7, c.cone);
      const SolverResult   reference =
        solve(p, options_for(SolverType::alart_curnier, 1e-14));
      ASSERT_TRUE(reference.converged);
      unsigned int counts[3] = {0, 0, 0};
      for (const ContactStatus s : reference.status)
        ++counts[static_cast<int>(s)];
      // A case with all three states, so that the comparison is not void.
      ASSERT_GT(counts[0] * counts[1] * counts[2], 0u);
      for (const SolverType type : all_solvers())
        {
          const SolverResult s = solve(p, options_for(type, 1e-10));
          ASSERT_TRUE(s.converged) << to_string(type);
          for (unsigned int j = 0; j < p.n_elements(); ++j)
            EXPECT_EQ(s.status[j], reference.status[j])
              << to_string(type) << ", element " << j << ", mu " << c.mu;
        }
    }
}



// An element that moves (u_T != 0) is slip even with its traction inside
// the cone; one that does not move is stick only if its traction is
// inside by more than the tolerance.
TEST(Classification, FromDisplacementAndTraction)
{
  ContactProblem p;
  p.dim  = 3;
  p.cone = ConeModel::disc;
  p.A    = Eigen::MatrixXd::Identity(3, 3);
  p.D    = Eigen::Vector3d(0.0, 0.0, 0.0);
  p.mu   = Eigen::VectorXd::Constant(1, 0.5);
  const FrictionSet set(p);
  const double      r_in[3] = {-1.0, 0.3, 0.0}, r_on[3] = {-1.0, 0.3, 0.4};
  const double u_still[3] = {0.0, 0.0, 0.0}, u_moving[3] = {0.0, -1e-3, 0.0};
  EXPECT_EQ(classify_element(set, 0.5, r_in, u_still, 1e-8, 1e-8),
            ContactStatus::stick);
  EXPECT_EQ(classify_element(set, 0.5, r_in, u_moving, 1e-8, 1e-8),
            ContactStatus::slip);
  EXPECT_EQ(classify_element(set, 0.5, r_on, u_still, 1e-8, 1e-8),
            ContactStatus::slip);
  // Inside by 1e-9 < tolerance 1e-8: on the boundary.
  const double r_near[3] = {-1.0, 0.3, 0.4 - 1e-9};
  EXPECT_EQ(classify_element(set, 0.5, r_near, u_still, 1e-8, 1e-8),
            ContactStatus::slip);
  const double r_free[3] = {1e-12, 0.0, 0.0};
  EXPECT_EQ(classify_element(set, 0.5, r_free, u_moving, 1e-8, 1e-8),
            ContactStatus::separated);
}



// A contrast of stiffness along the surface: A = S A_0 S with the elements
// of one half 1e6 times more compliant. The per-element rho_j makes the
// residual weigh the stiff elements' displacements as much as the soft
// ones': at tolerance 1e-10 every solver's tractions agree with a 1e-14
// reference to 1e-7 (with one rho for all, NSGS stopped with errors of
// 1e-4 on the half-plane of the hard-case benchmark with this contrast).
TEST(ResidualScale, StiffnessContrastAlongTheSurface)
{
  ContactProblem     p = random_problem(2, 16, 0.5, 11);
  const unsigned int n = p.n_elements();
  Eigen::VectorXd    S = Eigen::VectorXd::Ones(2 * n);
  for (unsigned int j = n / 2; j < n; ++j)
    S.segment<2>(2 * j).setConstant(1e3);
  p.A = (S.asDiagonal() * p.A * S.asDiagonal()).eval();
  p.D = (S.asDiagonal() * p.D).eval();
  const SolverResult reference =
    solve(p, options_for(SolverType::alart_curnier, 1e-14));
  ASSERT_TRUE(reference.converged) << reference.message;
  expect_every_solver_finds(p, reference.r);
}
