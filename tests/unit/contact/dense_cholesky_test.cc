// The dense Cholesky factorisation of the active-set solvers
// (dense_cholesky.h) against Eigen's LLT, an independent implementation, on
// both sides of the size where it switches from Eigen to LAPACK; its
// inverse; its refusal of a matrix that is not positive definite; and its
// single precision factors.
#include <dpana/contact/dense_cholesky.h>

#include <random>

#include <gtest/gtest.h>

using dpana::contact::DenseCholesky;

namespace
{
  Eigen::MatrixXd
  random_spd(const Eigen::Index size, const unsigned int seed)
  {
    std::mt19937                     gen(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::MatrixXd                  B(size, size);
    for (Eigen::Index i = 0; i < size; ++i)
      for (Eigen::Index j = 0; j < size; ++j)
        B(i, j) = normal(gen);
    return B * B.transpose() / size +
           0.1 * Eigen::MatrixXd::Identity(size, size);
  }
} // namespace



TEST(DenseCholesky, AgreesWithEigenLltOnBothPaths)
{
  for (const Eigen::Index size : {5, 63, 64, 200})
    {
      const Eigen::MatrixXd            H = random_spd(size, 7 + size);
      Eigen::MatrixXd                  R(size, 3);
      std::mt19937                     gen(3);
      std::normal_distribution<double> normal(0.0, 1.0);
      for (Eigen::Index i = 0; i < R.size(); ++i)
        R.data()[i] = normal(gen);
      const Eigen::LLT<Eigen::MatrixXd> llt(H);
      DenseCholesky                     chol;
      ASSERT_TRUE(chol.compute(H)) << size;
      const Eigen::MatrixXd X = chol.solve(R);
      EXPECT_LE((X - llt.solve(R)).norm(), 1e-10 * X.norm()) << size;
      EXPECT_LE((H * X - R).norm(), 1e-10 * R.norm()) << size;
      // L^{-1} R and L^{-T} R: the triangular factor itself is unique.
      Eigen::MatrixXd lower = R, upper = R;
      chol.solve_lower_in_place(lower);
      chol.solve_upper_in_place(upper);
      const Eigen::MatrixXd L = llt.matrixL();
      EXPECT_LE((L * lower - R).norm(), 1e-10 * R.norm()) << size;
      EXPECT_LE((L.transpose() * upper - R).norm(), 1e-10 * R.norm()) << size;
      const Eigen::VectorXd x = chol.solve(Eigen::VectorXd(R.col(1)));
      EXPECT_LE((x - X.col(1)).norm(), 1e-14 * x.norm()) << size;
    }
}



// inverse() on both paths: H X = I, and X symmetric in full (dpotri writes
// one triangle only, the other is mirrored).
TEST(DenseCholesky, InverseOnBothPaths)
{
  for (const Eigen::Index size : {5, 63, 64, 200})
    {
      const Eigen::MatrixXd H = random_spd(size, 13 + size);
      DenseCholesky         chol;
      ASSERT_TRUE(chol.compute(H)) << size;
      const Eigen::MatrixXd X = chol.inverse();
      ASSERT_EQ(X.rows(), size);
      ASSERT_EQ(X.cols(), size);
      const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(size, size);
      EXPECT_LE((H * X - I).norm(), 1e-10 * std::sqrt(double(size))) << size;
      EXPECT_EQ((X - X.transpose()).norm(), 0.0) << size;
    }
}



TEST(DenseCholesky, RefusesAnIndefiniteMatrix)
{
  for (const Eigen::Index size : {10, 100})
    {
      Eigen::MatrixXd H     = random_spd(size, 1);
      H(size / 2, size / 2) = -1.0;
      DenseCholesky chol;
      EXPECT_FALSE(chol.compute(H)) << size;
      EXPECT_FALSE(chol.valid()) << size;
    }
}



// Single precision factors (set_single_precision(64): from the LAPACK path
// on): solves accurate to about cond(H) times the single precision epsilon
// (here cond(H) < 50: 1e-4 is a bound with a margin of about 10), one step
// of iterative refinement in double to about its square; the triangular
// solves likewise; inverse() refused. A matrix that is positive definite in
// double but singular once rounded to single precision (the 2 x 2 block
// [1 1; 1 1 + 1e-10] in an identity) is factored in double instead.
TEST(DenseCholesky, SinglePrecisionFactorsAndTheirFallback)
{
  for (const Eigen::Index size : {63, 64, 300})
    {
      const Eigen::MatrixXd H = random_spd(size, 29 + size);
      const Eigen::MatrixXd R = random_spd(size, 31).leftCols(2);
      DenseCholesky         chol;
      chol.set_single_precision(64);
      ASSERT_TRUE(chol.compute(H)) << size;
      EXPECT_EQ(chol.single_precision(), size >= 64) << size;
      const double          bound = (size >= 64) ? 1e-4 : 1e-10;
      const Eigen::MatrixXd X     = chol.solve(R);
      EXPECT_LE((H * X - R).norm(), bound * R.norm()) << size;
      const Eigen::MatrixXd refined =
        X + chol.solve(Eigen::MatrixXd(R - H * X));
      EXPECT_LE((H * refined - R).norm(), bound * bound * R.norm() + 1e-13)
        << size;
      const Eigen::LLT<Eigen::MatrixXd> llt(H);
      const Eigen::MatrixXd             L     = llt.matrixL();
      Eigen::MatrixXd                   lower = R;
      chol.solve_lower_in_place(lower);
      EXPECT_LE((L * lower - R).norm(), bound * R.norm()) << size;
      if (size >= 64)
        EXPECT_THROW(chol.inverse(), std::logic_error);
    }
  Eigen::MatrixXd H = Eigen::MatrixXd::Identity(100, 100);
  H(0, 1) = H(1, 0) = 1.0;
  H(1, 1)           = 1.0 + 1e-10;
  DenseCholesky chol;
  chol.set_single_precision(64);
  ASSERT_TRUE(chol.compute(H));
  EXPECT_FALSE(chol.single_precision());
  const Eigen::VectorXd r = Eigen::VectorXd::Ones(100);
  // x = (1, 0, 1, ..., 1) exactly; the solve in double loses cond(H) eps.
  const Eigen::VectorXd x = chol.solve(r);
  EXPECT_NEAR(x[0], 1.0, 1e-5);
  EXPECT_NEAR(x[1], 0.0, 1e-5);
}
