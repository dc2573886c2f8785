// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Tests of the sparse Cholesky factorisation: the blocked multi-right-hand
// side solve against single solves and against an independent dense
// factorisation (Eigen's LDL^T), the reduced (constrained) form against the
// explicit formula u = M K_r^{-1} M^T b, and the error for an indefinite or
// singular matrix.

#include <dpana/linear_algebra/sparse_cholesky.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <random>
#include <thread>

#include <gtest/gtest.h>

namespace
{
  using dpana::linear_algebra::LastBlockOrdering;
  using dpana::linear_algebra::SparseCholesky;
  using dpana::linear_algebra::to_string;

  // The five-point Laplacian on an n x n grid with Dirichlet conditions plus
  // a shift: a symmetric positive definite sparse matrix with a known
  // structure, stored both in deal.II form and as a dense Eigen matrix.
  struct TestMatrix
  {
    dealii::SparsityPattern      pattern;
    dealii::SparseMatrix<double> matrix;
    Eigen::MatrixXd              dense;

    TestMatrix(const unsigned int n, const double shift)
    {
      const unsigned int                                  N = n * n;
      dealii::DynamicSparsityPattern                      dsp(N, N);
      std::vector<std::tuple<unsigned, unsigned, double>> entries;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            const unsigned int k = i * n + j;
            entries.emplace_back(k, k, 4.0 + shift);
            if (i > 0)
              entries.emplace_back(k, k - n, -1.0);
            if (i + 1 < n)
              entries.emplace_back(k, k + n, -1.0);
            if (j > 0)
              entries.emplace_back(k, k - 1, -1.0);
            if (j + 1 < n)
              entries.emplace_back(k, k + 1, -1.0);
          }
      for (const auto &[r, c, v] : entries)
        dsp.add(r, c);
      pattern.copy_from(dsp);
      matrix.reinit(pattern);
      dense = Eigen::MatrixXd::Zero(N, N);
      for (const auto &[r, c, v] : entries)
        {
          matrix.add(r, c, v);
          dense(r, c) += v;
        }
    }
  };

  // The matrix of @p A and the right-hand side @p b assembled with
  // @p constraints as a body would: from "element" contributions, here the
  // diagonal entries and the off-diagonal pairs as 2 x 2 elements with zero
  // diagonal.
  struct CondensedSystem
  {
    dealii::SparsityPattern      pattern;
    dealii::SparseMatrix<double> K;
    dealii::Vector<double>       f;

    CondensedSystem(const TestMatrix                        &A,
                    const dealii::AffineConstraints<double> &constraints,
                    const Eigen::VectorXd                   &b)
    {
      const unsigned int             N = b.size();
      dealii::DynamicSparsityPattern dsp(N, N);
      for (unsigned int i = 0; i < N; ++i)
        for (unsigned int j = 0; j < N; ++j)
          if (A.dense(i, j) != 0.0)
            dsp.add(i, j);
      constraints.condense(dsp);
      pattern.copy_from(dsp);
      K.reinit(pattern);
      f.reinit(N);
      for (unsigned int i = 0; i < N; ++i)
        for (unsigned int j = i; j < N; ++j)
          if (A.dense(i, j) != 0.0)
            {
              std::vector<dealii::types::global_dof_index> dofs = {i};
              dealii::FullMatrix<double>                   local(1, 1);
              dealii::Vector<double>                       rhs(1);
              local(0, 0) = A.dense(i, i);
              rhs[0]      = b(i);
              if (j != i)
                {
                  dofs        = {i, j};
                  local       = dealii::FullMatrix<double>(2, 2);
                  local(0, 1) = local(1, 0) = A.dense(i, j);
                  rhs.reinit(2);
                }
              constraints.distribute_local_to_global(local, rhs, dofs, K, f);
            }
    }
  };



  Eigen::MatrixXd
  random_matrix(const unsigned int rows, const unsigned int cols)
  {
    std::mt19937                           rng(42);
    std::uniform_real_distribution<double> dist(-1.0, 1.0);
    Eigen::MatrixXd                        B(rows, cols);
    for (unsigned int i = 0; i < rows; ++i)
      for (unsigned int j = 0; j < cols; ++j)
        B(i, j) = dist(rng);
    return B;
  }
} // namespace



// Many right-hand sides in blocks (including a last, partial block) give the
// same result as one solve per column, and both agree with a dense LDL^T
// factorisation of the same matrix.
TEST(SparseCholesky, BlockSolveEqualsColumnSolves)
{
  TestMatrix     A(20, 0.01);
  SparseCholesky cholesky;
  cholesky.factorize(A.matrix);
  cholesky.set_block_size(16);
  ASSERT_EQ(cholesky.size(), 400u);
  ASSERT_FALSE(cholesky.is_reduced());

  const Eigen::MatrixXd B = random_matrix(400, 100);
  const Eigen::MatrixXd X = cholesky.solve(B);

  double max_difference = 0;
  for (int j = 0; j < B.cols(); ++j)
    {
      const Eigen::VectorXd x = cholesky.solve(Eigen::VectorXd(B.col(j)));
      max_difference          = std::max(max_difference, (X.col(j) - x).norm());
    }
  EXPECT_LT(max_difference, 1e-12 * X.norm());

  const Eigen::MatrixXd X_dense = A.dense.ldlt().solve(B);
  EXPECT_LT((X - X_dense).norm(), 1e-10 * X_dense.norm());
  EXPECT_LT((A.dense * X - B).norm(), 1e-10 * B.norm());
}



// The reduced form: with constraints u_0 = 0.5 u_1 + 0.5 u_2 (a linear
// combination) and u_{N-1} = 0 (a fixed value), solve(b) must equal
// M (M^T K M)^{-1} M^T b computed with dense matrices, satisfy the
// homogeneous constraints, and solve_condensed() must honour an
// inhomogeneity.
TEST(SparseCholesky, ReducedSystemMatchesExplicitElimination)
{
  const unsigned int n = 6, N = n * n;
  TestMatrix         A(n, 0.0);

  dealii::AffineConstraints<double> constraints;
  constraints.add_line(0);
  constraints.add_entry(0, 1, 0.5);
  constraints.add_entry(0, 2, 0.5);
  constraints.add_line(N - 1);
  constraints.set_inhomogeneity(N - 1, 0.25);
  constraints.close();

  const Eigen::MatrixXd         b = random_matrix(N, 1);
  CondensedSystem               system(A, constraints, b.col(0));
  dealii::SparseMatrix<double> &K = system.K;
  dealii::Vector<double>       &f = system.f;

  SparseCholesky cholesky;
  cholesky.factorize(K, constraints);
  ASSERT_TRUE(cholesky.is_reduced());
  ASSERT_EQ(cholesky.n_unknowns(), N - 2);

  // The explicit constraint matrix M (N x (N-2)) and inhomogeneity.
  Eigen::MatrixXd M     = Eigen::MatrixXd::Zero(N, N - 2);
  Eigen::VectorXd u_bar = Eigen::VectorXd::Zero(N);
  const auto     &free  = cholesky.free_dofs();
  for (unsigned int k = 0; k < free.size(); ++k)
    M(free[k], k) = 1.0;
  M.row(0)                  = 0.5 * M.row(1) + 0.5 * M.row(2);
  u_bar(N - 1)              = 0.25;
  const Eigen::MatrixXd K_r = M.transpose() * A.dense * M;

  const Eigen::VectorXd u = cholesky.solve(Eigen::VectorXd(b.col(0)));
  const Eigen::VectorXd u_reference =
    M * K_r.ldlt().solve(M.transpose() * b.col(0));
  EXPECT_LT((u - u_reference).norm(), 1e-12 * u_reference.norm());
  EXPECT_NEAR(u(0), 0.5 * (u(1) + u(2)), 1e-14);
  EXPECT_EQ(u(N - 1), 0.0);

  // With the inhomogeneity: u = M K_r^{-1} M^T (b - K u_bar) + u_bar.
  dealii::Vector<double> u_h;
  cholesky.solve_condensed(f, u_h);
  const Eigen::VectorXd u_inhom =
    M * K_r.ldlt().solve(M.transpose() * (b.col(0) - A.dense * u_bar)) + u_bar;
  for (unsigned int i = 0; i < N; ++i)
    EXPECT_NEAR(u_h[i], u_inhom(i), 1e-12 * u_inhom.norm()) << "dof " << i;
}



namespace
{
  void
  check_last_block(const LastBlockOrdering          ordering,
                   const SparseCholesky::FactorKind kind)
  {
    const unsigned int n = 12, N = n * n;
    TestMatrix         A(n, 0.0);

    dealii::AffineConstraints<double> constraints;
    constraints.add_line(N - 1);
    constraints.add_line(7 * n + 5);
    constraints.add_entry(7 * n + 5, 7 * n + 6, 1.0);
    constraints.close();
    const CondensedSystem system(A, constraints, Eigen::VectorXd::Zero(N));
    const auto           &K = system.K;

    std::vector<unsigned int> surface;
    for (unsigned int j = 0; j < n; ++j)
      surface.push_back(j);
    surface.push_back(4 * n + 3);
    surface.push_back(7 * n + 5);
    surface.push_back(N - 1);

    SparseCholesky cholesky;
    cholesky.set_last_block_ordering(ordering);
    cholesky.set_factor_kind(kind);
    cholesky.factorize_with_last(K, constraints, surface);
    EXPECT_EQ(cholesky.analysis().supernodal,
              kind == SparseCholesky::FactorKind::supernodal);
    if (ordering == LastBlockOrdering::automatic)
      EXPECT_EQ(cholesky.analysis().ordering.rfind("automatic: ", 0), 0u);
    else
      EXPECT_EQ(cholesky.analysis().ordering, to_string(ordering));
    EXPECT_EQ(cholesky.analysis().n_last, n + 2);
    const auto &dofs = cholesky.schur_dofs();
    ASSERT_EQ(dofs.size(), n + 2);
    std::vector<unsigned int> sorted(dofs);
    std::sort(sorted.begin(), sorted.end());
    std::vector<unsigned int> expected(surface.begin(), surface.begin() + n);
    expected.push_back(4 * n + 3);
    expected.push_back(7 * n + 6);
    EXPECT_EQ(sorted, expected);

    // The reduced matrix and its Schur complement on the surface, dense.
    const auto      &free = cholesky.free_dofs();
    Eigen::MatrixXd  M    = Eigen::MatrixXd::Zero(N, free.size());
    std::vector<int> position(N, -1);
    for (unsigned int k = 0; k < free.size(); ++k)
      {
        M(free[k], k)     = 1.0;
        position[free[k]] = k;
      }
    M.row(7 * n + 5)          = M.row(7 * n + 6);
    const Eigen::MatrixXd K_r = M.transpose() * A.dense * M;
    std::vector<int>      is_surface(free.size(), -1), interior;
    for (unsigned int k = 0; k < dofs.size(); ++k)
      is_surface[position[dofs[k]]] = k;
    for (unsigned int k = 0; k < free.size(); ++k)
      if (is_surface[k] < 0)
        interior.push_back(k);
    const unsigned int ng = dofs.size(), ni = interior.size();
    Eigen::MatrixXd    K_GG(ng, ng), K_GI(ng, ni), K_II(ni, ni);
    for (unsigned int a = 0; a < ng; ++a)
      {
        for (unsigned int b = 0; b < ng; ++b)
          K_GG(a, b) = K_r(position[dofs[a]], position[dofs[b]]);
        for (unsigned int b = 0; b < ni; ++b)
          K_GI(a, b) = K_r(position[dofs[a]], interior[b]);
      }
    for (unsigned int a = 0; a < ni; ++a)
      for (unsigned int b = 0; b < ni; ++b)
        K_II(a, b) = K_r(interior[a], interior[b]);
    const Eigen::MatrixXd S =
      K_GG - K_GI * K_II.llt().solve(Eigen::MatrixXd(K_GI.transpose()));
    const Eigen::MatrixXd L_S = S.llt().matrixL();

    const Eigen::MatrixXd L22 = cholesky.schur_factor();
    EXPECT_LT((L22 - L_S).norm(), 1e-12 * L_S.norm());
    EXPECT_EQ(
      Eigen::MatrixXd(L22.triangularView<Eigen::StrictlyUpper>()).norm(), 0.0);

    // The forward substitution on the factor equals the dense one.
    const Eigen::MatrixXd B = random_matrix(ng, 5);
    Eigen::MatrixXd       W = B;
    cholesky.solve_schur_factor(W);
    const Eigen::MatrixXd W_reference =
      L_S.triangularView<Eigen::Lower>().solve(B);
    EXPECT_LT((W - W_reference).norm(), 1e-12 * W_reference.norm());

    // Columns that begin at rows 0, 3, 3, 9 and ng - 1 (zeros above).
    const std::vector<int> first_rows  = {0, 3, 3, 9, int(ng) - 1};
    Eigen::MatrixXd        B_trapezoid = B;
    for (unsigned int j = 0; j < first_rows.size(); ++j)
      B_trapezoid.col(j).head(first_rows[j]).setZero();
    Eigen::MatrixXd W_trapezoid = B_trapezoid;
    cholesky.solve_schur_factor(W_trapezoid, first_rows);
    const Eigen::MatrixXd W_trapezoid_reference =
      L_S.triangularView<Eigen::Lower>().solve(B_trapezoid);
    EXPECT_LT((W_trapezoid - W_trapezoid_reference).norm(),
              1e-12 * W_trapezoid_reference.norm());

    const Eigen::MatrixXd b           = random_matrix(N, 3);
    const Eigen::MatrixXd u           = cholesky.solve(b);
    const Eigen::MatrixXd u_reference = M * K_r.llt().solve(M.transpose() * b);
    EXPECT_LT((u - u_reference).norm(), 1e-12 * u_reference.norm());
  }
} // namespace



// With the unknowns of a surface ordered last (factorize_with_last()), the
// last diagonal block L_22 of the factor is the Cholesky factor of the Schur
// complement S = K_GG - K_GI K_II^{-1} K_IG, checked against a dense
// Cholesky factorisation of S computed independently, in the order of
// schur_dofs(). The surface: the first grid row (as a contact surface on the
// boundary) and two scattered interior unknowns, one of them a constrained
// dof standing for its masters, one a Dirichlet dof standing for none. The
// solve with this ordering stays the plain K_r^{-1} b. Every ordering of
// LastBlockOrdering, on a supernodal and on a simplicial factor (the one
// CHOLMOD's rule takes for this small matrix); the solve that skips the
// leading zeros of the columns (first_rows) equals the dense one too.
TEST(SparseCholesky, LastBlockIsFactorOfSchurComplement)
{
  using Kind = SparseCholesky::FactorKind;
  for (const auto kind : {Kind::supernodal, Kind::simplicial})
    for (const auto ordering : {LastBlockOrdering::moved_last,
                                LastBlockOrdering::constrained_amd,
                                LastBlockOrdering::interior_nested_dissection,
                                LastBlockOrdering::automatic})
      {
        SCOPED_TRACE(to_string(ordering) + (kind == Kind::supernodal ?
                                              ", supernodal" :
                                              ", simplicial"));
        check_last_block(ordering, kind);
      }
}



namespace
{
  // The (2d + 1)-point Laplacian plus the identity on an n^d grid of unknowns
  // (d = 2, 3), without a dense copy.
  struct GridLaplacian
  {
    dealii::SparsityPattern      pattern;
    dealii::SparseMatrix<double> matrix;

    GridLaplacian(const unsigned int d, const unsigned int n)
    {
      const unsigned int N      = d == 2 ? n * n : n * n * n;
      const unsigned int step[] = {1, n, n * n};
      std::vector<std::tuple<unsigned, unsigned, double>> entries;
      for (unsigned int k = 0; k < N; ++k)
        {
          entries.emplace_back(k, k, 2.0 * d + 1.0);
          for (unsigned int a = 0; a < d; ++a)
            {
              const unsigned int i = (k / step[a]) % n;
              if (i > 0)
                entries.emplace_back(k, k - step[a], -1.0);
              if (i + 1 < n)
                entries.emplace_back(k, k + step[a], -1.0);
            }
        }
      dealii::DynamicSparsityPattern dsp(N, N);
      for (const auto &[r, c, v] : entries)
        dsp.add(r, c);
      pattern.copy_from(dsp);
      matrix.reinit(pattern);
      for (const auto &[r, c, v] : entries)
        matrix.add(r, c, v);
    }
  };

  // The analysis of the factorisation of @p A with its first n^(d-1)
  // unknowns (one face of the grid) last, under @p ordering.
  SparseCholesky::Analysis
  analysis_with_face_last(const GridLaplacian    &A,
                          const unsigned int      face,
                          const LastBlockOrdering ordering)
  {
    std::vector<unsigned int> last(face);
    for (unsigned int k = 0; k < face; ++k)
      last[k] = k;
    SparseCholesky cholesky;
    cholesky.set_last_block_ordering(ordering);
    cholesky.factorize_with_last(A.matrix,
                                 dealii::AffineConstraints<double>(),
                                 last);
    return cholesky.analysis();
  }
} // namespace



// The automatic ordering follows CHOLMOD's own default strategy
// (cholmod_core.h, Common->nmethods = 0): the minimum degree ordering (here
// CAMD, with the face last) is kept when its factor costs fewer than 500
// flops per entry or has fewer than 5 entries per entry of the matrix, and
// the nested dissection is taken otherwise. The 2D grid (60 x 60: 41 flops
// per entry) passes CHOLMOD's test and the 3D grid (24^3: 693 flops per
// entry, 49 entries per matrix entry) fails it, so that both branches are
// taken; on each, the automatic choice is the ordering the test names, with
// that ordering's factor.
TEST(SparseCholesky, AutomaticOrderingFollowsCholmodsTest)
{
  for (const auto &[d, n] : {std::pair{2u, 60u}, std::pair{3u, 24u}})
    {
      SCOPED_TRACE("dimension " + std::to_string(d));
      const GridLaplacian            A(d, n);
      const unsigned int             face = d == 2 ? n : n * n;
      const SparseCholesky::Analysis amd =
        analysis_with_face_last(A, face, LastBlockOrdering::constrained_amd);
      const bool amd_suffices =
        dpana::linear_algebra::minimum_degree_suffices(amd.factor_flops,
                                                       amd.factor_nonzeros,
                                                       amd.matrix_entries);
      EXPECT_EQ(amd_suffices, d == 2);
      const LastBlockOrdering expected =
        amd_suffices ? LastBlockOrdering::constrained_amd :
                       LastBlockOrdering::interior_nested_dissection;
      const SparseCholesky::Analysis by_hand =
        analysis_with_face_last(A, face, expected);
      const SparseCholesky::Analysis automatic =
        analysis_with_face_last(A, face, LastBlockOrdering::automatic);
      EXPECT_EQ(automatic.ordering, "automatic: " + to_string(expected));
      EXPECT_EQ(automatic.factor_nonzeros, by_hand.factor_nonzeros);
      EXPECT_EQ(automatic.factor_flops, by_hand.factor_flops);

      // The same choice where the ordering is computed alone (for MUMPS),
      // from the column counts of its own analysis.
      using dpana::linear_algebra::CholmodIndex;
      using dpana::linear_algebra::CholmodMatrix;
      std::vector<Eigen::Triplet<double, CholmodIndex>> entries;
      for (auto it = A.matrix.begin(); it != A.matrix.end(); ++it)
        if (it->column() <= it->row())
          entries.emplace_back(it->row(), it->column(), it->value());
      CholmodMatrix K_lower(A.matrix.m(), A.matrix.m());
      K_lower.setFromTriplets(entries.begin(), entries.end());
      std::vector<bool> is_last(A.matrix.m(), false);
      std::fill(is_last.begin(), is_last.begin() + face, true);
      cholmod_common common;
      cholmod_l_start(&common);
      using dpana::linear_algebra::order_last_block;
      EXPECT_EQ(order_last_block(
                  K_lower, is_last, LastBlockOrdering::automatic, common),
                order_last_block(K_lower, is_last, expected, common));
      cholmod_l_finish(&common);
    }
}



// The factor kind follows CHOLMOD's rule (cholmod_core.h, supernodal =
// CHOLMOD_AUTO, supernodal_switch = 40): supernodal where the factorisation
// costs at least 40 flops per nonzero of the factor, simplicial below. The
// 2D grid of 12 x 12 unknowns falls below (a body of a few hundred unknowns
// does too), the 3D grid of 24^3 above (693 flops per entry), so that both
// kinds are taken.
TEST(SparseCholesky, FactorKindFollowsCholmodsRule)
{
  std::vector<bool> kinds;
  for (const auto &[d, n] : {std::pair{2u, 12u}, std::pair{3u, 24u}})
    {
      SCOPED_TRACE("dimension " + std::to_string(d));
      const GridLaplacian            A(d, n);
      const SparseCholesky::Analysis a =
        analysis_with_face_last(A,
                                d == 2 ? n : n * n,
                                LastBlockOrdering::automatic);
      EXPECT_EQ(a.supernodal, a.factor_flops / a.factor_nonzeros >= 40.0);
      kinds.push_back(a.supernodal);
    }
  EXPECT_EQ(kinds, (std::vector<bool>{false, true}));
}



// CHOLMOD was compiled to run loops of its supernodal factorisation on 4
// OpenMP threads; dpana keeps them on the thread that factorises
// (blas_threads.h). OpenMP keeps the threads it started for a thread alive
// until that thread ends, so a factorisation on a new thread (whose OpenMP
// settings are the defaults) must leave the number of the process' threads
// as it found it. The matrix (1 600 unknowns) is large enough for CHOLMOD's
// loops to ask for their threads (more than 128 columns).
TEST(SparseCholesky, FactorisationStartsNoThread)
{
  const auto threads = [] {
    return std::distance(std::filesystem::directory_iterator("/proc/self/task"),
                         std::filesystem::directory_iterator{});
  };
  TestMatrix  A(40, 0.1);
  long        before = 0, after = 0;
  std::thread factorising([&] {
    before = threads();
    SparseCholesky cholesky;
    cholesky.set_factor_kind(SparseCholesky::FactorKind::supernodal);
    cholesky.factorize(A.matrix);
    after = threads();
  });
  factorising.join();
  EXPECT_EQ(after, before);
}



namespace
{
  void
  check_refusals(const SparseCholesky::FactorKind kind)
  {
    TestMatrix     indefinite(10, -1.0);
    SparseCholesky cholesky;
    cholesky.set_factor_kind(kind);
    EXPECT_THROW(cholesky.factorize(indefinite.matrix),
                 dpana::linear_algebra::NotPositiveDefiniteError);
    EXPECT_FALSE(cholesky.is_factorized());

    // Graph Laplacian of a path: L = tridiag(-1, 2, -1) with 1 at both ends.
    const unsigned int             N = 50;
    dealii::DynamicSparsityPattern dsp(N, N);
    for (unsigned int i = 0; i < N; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j <= std::min(i + 1, N - 1);
           ++j)
        dsp.add(i, j);
    dealii::SparsityPattern pattern;
    pattern.copy_from(dsp);
    dealii::SparseMatrix<double> L(pattern);
    for (unsigned int i = 0; i + 1 < N; ++i)
      {
        L.add(i, i, 1.0);
        L.add(i + 1, i + 1, 1.0);
        L.add(i, i + 1, -1.0);
        L.add(i + 1, i, -1.0);
      }
    EXPECT_THROW(cholesky.factorize(L),
                 dpana::linear_algebra::NotPositiveDefiniteError);

    // Fixing one end removes the kernel: now it must factor.
    dealii::AffineConstraints<double> constraints;
    constraints.add_line(0);
    constraints.close();
    EXPECT_NO_THROW(cholesky.factorize(L, constraints));
    EXPECT_TRUE(cholesky.is_factorized());
  }
} // namespace



// An indefinite matrix (the Laplacian above, whose smallest eigenvalue is
// 4 - 4 cos(pi/11) ~ 0.16 for n = 10, shifted by -1) and a singular one (the
// graph Laplacian of a path, whose kernel is the constant vector, like a
// rigid translation of an unsupported body) must both be refused with
// NotPositiveDefiniteError, never "solved".
TEST(SparseCholesky, RefusesMatricesThatAreNotPositiveDefinite)
{
  using Kind = SparseCholesky::FactorKind;
  for (const auto kind : {Kind::supernodal, Kind::simplicial})
    {
      SCOPED_TRACE(kind == Kind::supernodal ? "supernodal" : "simplicial");
      check_refusals(kind);
    }
}



// The interior nested dissection orders the graph of the mesh vertices: the
// two components of each vertex of a vector Laplacian (the grid Laplacian
// times a 2 x 2 block, both components coupled to the same neighbours) are
// one weighted METIS vertex. The ordering is a permutation with the surface
// (the first grid row) last, the components of every interior vertex
// consecutive (each is the only child of the other in the postordered
// elimination tree), and its fill is that of METIS on the whole graph of the
// interior unknowns (CHOLMOD's cholmod_l_metis, the previous implementation,
// as the independent reference) within 10 %.
TEST(SparseCholesky, InteriorNestedDissectionOrdersVertices)
{
  using dpana::linear_algebra::CholmodIndex;
  using dpana::linear_algebra::CholmodMatrix;
  const unsigned int                                n = 40, N = 2 * n * n;
  const TestMatrix                                  grid(n, 0.5);
  std::vector<Eigen::Triplet<double, CholmodIndex>> entries;
  for (auto it = grid.matrix.begin(); it != grid.matrix.end(); ++it)
    if (it->column() <= it->row())
      for (unsigned int a = 0; a < 2; ++a)
        for (unsigned int b = 0; b < 2; ++b)
          if (2 * it->row() + a >= 2 * it->column() + b)
            entries.emplace_back(2 * it->row() + a,
                                 2 * it->column() + b,
                                 it->value() * (a == b ? 2.0 : 0.5));
  CholmodMatrix K_lower(N, N);
  K_lower.setFromTriplets(entries.begin(), entries.end());
  std::vector<bool> is_last(N, false);
  for (unsigned int k = 0; k < 2 * n; ++k)
    is_last[k] = true;

  cholmod_common common;
  cholmod_l_start(&common);
  const std::vector<CholmodIndex> order =
    dpana::linear_algebra::order_last_block(
      K_lower, is_last, LastBlockOrdering::interior_nested_dissection, common);
  ASSERT_EQ(order.size(), N);
  std::vector<CholmodIndex> sorted(order);
  std::sort(sorted.begin(), sorted.end());
  for (unsigned int k = 0; k < N; ++k)
    ASSERT_EQ(sorted[k], CholmodIndex(k));
  for (unsigned int k = 0; k < 2 * n; ++k)
    EXPECT_EQ(order[N - 2 * n + k], CholmodIndex(k));
  for (unsigned int k = 0; k + 2 * n < N; k += 2)
    EXPECT_EQ(order[k] / 2, order[k + 1] / 2) << "position " << k;

  // The fill of the factor of the interior block under both orderings.
  const unsigned int  n_interior = N - 2 * n;
  const CholmodMatrix K_II = K_lower.bottomRightCorner(n_interior, n_interior);
  cholmod_sparse      A =
    Eigen::viewAsCholmod(K_II.template selfadjointView<Eigen::Lower>());
  const auto fill = [&](std::vector<CholmodIndex> perm) {
    common.nmethods           = 1;
    common.method[0].ordering = CHOLMOD_GIVEN;
    cholmod_factor *L =
      cholmod_l_analyze_p(&A, perm.data(), nullptr, 0, &common);
    const double lnz = common.lnz;
    cholmod_l_free_factor(&L, &common);
    return lnz;
  };
  std::vector<CholmodIndex> interior_order;
  for (unsigned int k = 0; k < n_interior; ++k)
    interior_order.push_back(order[k] - 2 * n);
  std::vector<CholmodIndex> metis(n_interior);
  ASSERT_TRUE(cholmod_l_metis(&A, nullptr, 0, 1, metis.data(), &common));
  const double ours = fill(interior_order), reference = fill(metis);
  EXPECT_LT(ours, 1.1 * reference) << ours << " against " << reference;
  cholmod_l_finish(&common);
}
