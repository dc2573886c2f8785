// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// MUMPS called directly (source/linear_algebra/mumps_direct.h) keeps the
// elimination order it is given: on an arrow matrix (a hub coupled to every
// other unknown) the hub eliminated first fills the whole triangle, n(n+1)/2
// factor entries, the hub eliminated last fills nothing, 2n - 1 entries
// (Duff, Erisman and Reid, Direct Methods for Sparse Matrices, 1986,
// section 1.6). The interior solve and the Schur complement are checked
// against dense ones.
#include <numeric>
#include <vector>

#include "../../../source/linear_algebra/mumps_direct.h"
#include <gtest/gtest.h>

namespace
{
  using dpana::linear_algebra::DirectMumps;

  // The arrow matrix of n unknowns, hub 0: diagonal n + 1, coupling -1.
  Eigen::MatrixXd
  arrow(const int n)
  {
    Eigen::MatrixXd K = Eigen::MatrixXd::Identity(n, n) * (n + 1.0);
    for (int i = 1; i < n; ++i)
      K(0, i) = K(i, 0) = -1.0;
    return K;
  }

  // Its upper triangle in compressed rows, analysed and factored by MUMPS
  // in @p order with the Schur complement on @p schur.
  void
  factor(DirectMumps             &mumps,
         const Eigen::MatrixXd   &K,
         const std::vector<long> &order,
         const std::vector<int>  &schur)
  {
    const int           n = K.rows();
    std::vector<int>    row_start(1, 0), columns;
    std::vector<double> values;
    for (int i = 0; i < n; ++i)
      {
        for (int j = i; j < n; ++j)
          if (K(i, j) != 0.0)
            {
              columns.push_back(j);
              values.push_back(K(i, j));
            }
        row_start.push_back(columns.size());
      }
    ASSERT_EQ(
      mumps.analyse(n, 0, row_start, columns, values, order, schur, "", 0), 0);
    ASSERT_EQ(mumps.factorize(), 0);
    EXPECT_EQ(mumps.infog(7), 1); // the given ordering
  }
} // namespace



TEST(DirectMumps, KeepsTheGivenOrdering)
{
  const int             n = 40;
  const Eigen::MatrixXd K = arrow(n);
  std::vector<long>     hub_first(n), hub_last(n);
  std::iota(hub_first.begin(), hub_first.end(), 0);
  std::iota(hub_last.begin(), hub_last.end() - 1, 1);
  hub_last.back() = 0;

  DirectMumps first(MPI_COMM_SELF), last(MPI_COMM_SELF);
  factor(first, K, hub_first, {});
  factor(last, K, hub_last, {});
  EXPECT_EQ(first.infog(29), n * (n + 1) / 2);
  EXPECT_EQ(last.infog(29), 2 * n - 1);

  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  const Eigen::VectorXd x = K.ldlt().solve(b);
  EXPECT_LT((first.solve_interior(b) - x).norm(), 1e-13 * x.norm());
  EXPECT_LT((last.solve_interior(b) - x).norm(), 1e-13 * x.norm());
}



// The Schur complement on the hub and one leaf, the two last in the order:
// S = K_GG - K_GI K_II^{-1} K_IG, its lower triangle; the interior solve
// is K_II^{-1} b_I, zero on the Schur unknowns.
TEST(DirectMumps, SchurComplementAndInteriorSolve)
{
  const int             n = 12;
  const Eigen::MatrixXd K = arrow(n);
  std::vector<long>     order;
  for (int i = 2; i < n; ++i)
    order.push_back(i);
  order.push_back(0);
  order.push_back(1);
  DirectMumps mumps(MPI_COMM_SELF);
  factor(mumps, K, order, {0, 1});

  const Eigen::MatrixXd K_II = K.bottomRightCorner(n - 2, n - 2);
  const Eigen::MatrixXd K_IG = K.bottomLeftCorner(n - 2, 2);
  const Eigen::MatrixXd S =
    K.topLeftCorner(2, 2) - K_IG.transpose() * K_II.ldlt().solve(K_IG);
  const Eigen::MatrixXd S_mumps = mumps.take_schur_complement();
  ASSERT_EQ(S_mumps.rows(), 2);
  EXPECT_NEAR(S_mumps(0, 0), S(0, 0), 1e-13 * S.norm());
  EXPECT_NEAR(S_mumps(1, 0), S(1, 0), 1e-13 * S.norm());
  EXPECT_NEAR(S_mumps(1, 1), S(1, 1), 1e-13 * S.norm());
  EXPECT_EQ(S_mumps(0, 1), 0.0);

  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  Eigen::VectorXd       y = Eigen::VectorXd::Zero(n);
  y.tail(n - 2)           = K_II.ldlt().solve(b.tail(n - 2));
  EXPECT_LT((mumps.solve_interior(b) - y).norm(), 1e-13 * y.norm());
}
