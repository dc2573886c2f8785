// The inner solvers of the splitting on their own: the spectral form of the
// projection derivative used by the Newton step of the friction QP, the
// agreement of the two independent inner solvers (projected Gauss-Seidel and
// active set / semismooth Newton) on random subproblems, with and without
// equality rows, and the agreement of the two forms of the normal active-set
// step (on the contact set, and through the separated set).
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



  // With one row in G (and e): the sum of the first tangential components
  // (a rigid tangential mode) set to a tenth of its value at T = radius,
  // a feasible equality row. Nothing with none.
  void
  tangential_equality_row(const unsigned int     m,
                          const Eigen::VectorXd &radius,
                          Eigen::MatrixXd       &G,
                          Eigen::VectorXd       &e)
  {
    if (G.rows() == 0)
      return;
    G.setZero();
    double sum = 0.0;
    for (Eigen::Index j = 0; j < radius.size(); ++j)
      {
        G(0, m * j) = 1.0;
        sum += radius[j];
      }
    e[0] = 0.1 * sum;
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
        tangential_equality_row(m, radius, G, e);
        InnerOptions options;
        options.tolerance      = 1e-13;
        options.max_iterations = 200000;
        // The exact Newton steps (the step count below is that of Newton's
        // method) and the default with chord steps.
        InnerOptions exact_options = options;
        exact_options.chord_steps  = false;
        FrictionQp pgs(M, G, set, options), newton(M, G, set, exact_options),
          chord(M, G, set, options);
        Eigen::VectorXd   T_pgs = Eigen::VectorXd::Zero(q), T_newton = T_pgs;
        Eigen::VectorXd   beta_pgs, beta_newton;
        const InnerResult r_pgs = pgs.solve_pgs(c, radius, e, T_pgs, beta_pgs);
        const InnerResult r_newton =
          newton.solve_active_set(c, radius, e, T_newton, beta_newton);
        Eigen::VectorXd   T_chord = Eigen::VectorXd::Zero(q), beta_chord;
        const InnerResult r_chord =
          chord.solve_active_set(c, radius, e, T_chord, beta_chord);
        ASSERT_TRUE(r_chord.converged) << r_chord.message;
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
        Eigen::VectorXd   T2_chord = T_chord, beta2_chord = beta_chord;
        const InnerResult r2_chord =
          chord.solve_active_set(c2, radius, e, T2_chord, beta2_chord);
        ASSERT_TRUE(r2_pgs.converged) << r2_pgs.message;
        ASSERT_TRUE(r2_newton.converged) << r2_newton.message;
        ASSERT_TRUE(r2_chord.converged) << r2_chord.message;
        // Chord steps end at the same minimiser (the stopping test is the
        // same natural map).
        EXPECT_LE(relative_difference(T_pgs, T_chord), 1e-8)
          << "dim " << model.dim << " rows " << rows << " (chord)";
        EXPECT_LE(relative_difference(T2_pgs, T2_chord), 1e-8)
          << "dim " << model.dim << " rows " << rows << " (chord, warm)";
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



// The normal active-set solver with its reduced problems solved through the
// separated set (InnerOptions::complement_size = 0) against the same solver
// solving them on the contact set (complement_size above n): the same
// active-set iterates, so the same steps and the same solution to
// round-off, which solves the LCP (N <= 0, w <= 0, N_j w_j = 0, G N = e).
// Compliance-like matrices (the inverse of a 1D stiffness, positive and
// slowly decaying, plus a random SPD part) and loads pressing most elements
// into contact, so that the contact set is the larger one and the
// separated-set form is taken; with and without an equality row (a body
// held by its contacts: the normal resultant prescribed), cold and warm
// started.
TEST(InnerSolvers, NormalActiveSetThroughSeparatedSetAgreesWithDirect)
{
  for (const unsigned int n : {40u, 150u})
    for (const unsigned int rows : {0u, 1u})
      {
        Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
        for (unsigned int i = 0; i < n; ++i)
          {
            K(i, i) = 2.2;
            if (i + 1 < n)
              K(i, i + 1) = K(i + 1, i) = -1.0;
          }
        const Eigen::MatrixXd M =
          Eigen::MatrixXd(K.inverse()) + 0.01 * random_spd(n, 29 + n + rows);
        std::mt19937                     gen(17 + rows);
        std::normal_distribution<double> normal(0.0, 1.0);
        Eigen::VectorXd                  b(n);
        for (unsigned int i = 0; i < n; ++i)
          b[i] = 6.0 + normal(gen);
        Eigen::MatrixXd G = Eigen::MatrixXd::Ones(rows, n);
        Eigen::VectorXd e = Eigen::VectorXd::Constant(rows, -3.0 * n);

        InnerOptions direct_options, complement_options;
        direct_options.complement_size      = n + 1;
        complement_options.complement_size  = 0;
        complement_options.complement_after = 0.0;
        NormalLcp       direct(M, G, direct_options);
        NormalLcp       complement(M, G, complement_options);
        Eigen::VectorXd N_direct     = Eigen::VectorXd::Zero(n);
        Eigen::VectorXd N_complement = N_direct, alpha_direct, alpha_complement;
        for (const unsigned int solve : {0u, 1u})
          {
            if (solve == 1)
              // Warm start on changed data, as in a splitting.
              for (unsigned int i = 0; i < n; ++i)
                b[i] += 0.5 * normal(gen);
            const InnerResult r_direct =
              direct.solve_active_set(b, e, N_direct, alpha_direct);
            const InnerResult r_complement =
              complement.solve_active_set(b, e, N_complement, alpha_complement);
            ASSERT_TRUE(r_direct.converged) << r_direct.message;
            ASSERT_TRUE(r_complement.converged) << r_complement.message;
            EXPECT_EQ(r_direct.iterations, r_complement.iterations);
            unsigned int in_contact = 0;
            for (unsigned int i = 0; i < n; ++i)
              in_contact += (N_complement[i] < 0.0);
            // The separated-set form is taken only for |C| > n / 2.
            EXPECT_GT(2 * in_contact, n) << "n " << n << " rows " << rows;
            EXPECT_GT(complement.complement_solves(), 0u);
            EXPECT_EQ(direct.complement_solves(), 0u);
            EXPECT_LT(in_contact, n) << "n " << n << " rows " << rows;
            const double scale = N_direct.lpNorm<Eigen::Infinity>();
            EXPECT_LE((N_direct - N_complement).lpNorm<Eigen::Infinity>(),
                      1e-12 * scale)
              << "n " << n << " rows " << rows << " solve " << solve;
            Eigen::VectorXd w = M * N_complement + b;
            if (rows > 0)
              {
                w += G.transpose() * alpha_complement;
                EXPECT_NEAR(alpha_complement[0],
                            alpha_direct[0],
                            1e-12 * std::abs(alpha_direct[0]));
                EXPECT_LE(std::abs((G * N_complement - e)[0]),
                          1e-12 * std::abs(e[0]));
              }
            const double w_scale = b.lpNorm<Eigen::Infinity>();
            for (unsigned int i = 0; i < n; ++i)
              {
                EXPECT_LE(N_complement[i], 0.0);
                EXPECT_LE(w[i], 1e-12 * w_scale) << i;
                EXPECT_LE(std::abs(N_complement[i] * w[i]),
                          1e-12 * scale * w_scale)
                  << i;
              }
          }
      }
}



// Newton matrices factored in single precision (InnerOptions::
// single_precision_size = 0: every matrix of at least 64 rows, the size
// where DenseCholesky leaves Eigen for LAPACK) against the same solver in
// double: the natural map and the stopping test are in double, so both must
// stop at the same minimiser (unique, M SPD) to the accuracy of the test,
// cold and warm started (chord steps, refined against the current matrix),
// with and without a tangential equality row. The Newton steps of the single
// precision solver are refined in double (two steps at most), so they stay
// close to exact ones: it may take a step or two more, not many (without the
// refinement a step is accurate only to about cond(H) 6e-8).
TEST(InnerSolvers, SinglePrecisionNewtonMatricesReachTheSameMinimiser)
{
  for (const unsigned int dim : {2u, 3u})
    for (const unsigned int rows : {0u, 1u})
      {
        const unsigned int n = 200, m = dim - 1, q = m * n;
        const FrictionSet  set(dim,
                              dim == 2 ? ConeModel::interval : ConeModel::disc,
                              16);
        // Eigenvalues from 1e-4 to 1 (cond(M) = 1e4, like a compliance of
        // 10^4 unknowns): single precision solves are then accurate to
        // about 1e-3 only, which Newton's convergence would show.
        const Eigen::MatrixXd Q =
          Eigen::HouseholderQR<Eigen::MatrixXd>(random_spd(q, 23 + dim + rows))
            .householderQ();
        Eigen::VectorXd spectrum(q);
        for (unsigned int i = 0; i < q; ++i)
          spectrum[i] = std::pow(1e-4, double(i) / (q - 1));
        const Eigen::MatrixXd M_raw = Q * spectrum.asDiagonal() * Q.transpose();
        const Eigen::MatrixXd M     = 0.5 * (M_raw + M_raw.transpose());
        std::mt19937          gen(17 + dim);
        std::uniform_real_distribution<double> uniform(-1.0, 1.0);
        Eigen::VectorXd                        c(q), radius(n);
        // c = -M t: the unconstrained minimiser t, of the size of the radii,
        // so that some blocks stick and some slip.
        Eigen::VectorXd t(q);
        for (unsigned int j = 0; j < n; ++j)
          {
            radius[j] = 0.5 + std::abs(uniform(gen));
            for (unsigned int a = 0; a < m; ++a)
              t[m * j + a] = 1.5 * radius[j] * uniform(gen);
          }
        c = -M * t;
        Eigen::MatrixXd G(rows, q);
        Eigen::VectorXd e(rows);
        tangential_equality_row(m, radius, G, e);
        InnerOptions in_double;
        in_double.tolerance             = 1e-13;
        in_double.max_iterations        = 2000;
        InnerOptions in_single          = in_double;
        in_single.single_precision_size = 0;
        FrictionQp        reference(M, G, set, in_double);
        FrictionQp        single(M, G, set, in_single);
        Eigen::VectorXd   T_ref = Eigen::VectorXd::Zero(q), T_single = T_ref;
        Eigen::VectorXd   beta_ref, beta_single;
        const InnerResult r_ref =
          reference.solve_active_set(c, radius, e, T_ref, beta_ref);
        const InnerResult r_single =
          single.solve_active_set(c, radius, e, T_single, beta_single);
        ASSERT_TRUE(r_ref.converged) << r_ref.message;
        ASSERT_TRUE(r_single.converged) << r_single.message;
        const std::string where =
          "dim " + std::to_string(dim) + " rows " + std::to_string(rows);
        EXPECT_GT(single.single_precision_factorisations(), 0u) << where;
        EXPECT_EQ(reference.single_precision_factorisations(), 0u) << where;
        EXPECT_LE(relative_difference(T_ref, T_single), 1e-9) << where;
        EXPECT_LE(r_single.iterations, r_ref.iterations + 2) << where;
        // Warm started with slightly changed data (the chord steps).
        Eigen::VectorXd c2 = c;
        for (unsigned int i = 0; i < q; ++i)
          c2[i] += 1e-3 * uniform(gen);
        const InnerResult r2_ref =
          reference.solve_active_set(c2, radius, e, T_ref, beta_ref);
        const InnerResult r2_single =
          single.solve_active_set(c2, radius, e, T_single, beta_single);
        ASSERT_TRUE(r2_ref.converged) << r2_ref.message;
        ASSERT_TRUE(r2_single.converged) << r2_single.message;
        EXPECT_LE(relative_difference(T_ref, T_single), 1e-9) << where;
        EXPECT_LE(r2_single.iterations, r2_ref.iterations + 2) << where;
        if (rows > 0)
          EXPECT_NEAR((G * T_single - e)[0], 0.0, 1e-10 * std::abs(e[0]));
      }
}
