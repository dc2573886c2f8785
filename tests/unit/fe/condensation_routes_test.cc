// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The two routes of the condensation, through the Schur complement on the
// contact surface and by blocked solves, against each other; and the two
// back ends of the Schur route, CHOLMOD and MUMPS, against each other.

#include <dpana/condensation/condenser.h>
#include <dpana/condensation/parameters.h>
#include <dpana/linear_algebra/mumps_schur.h>
#include <dpana/scene/scene.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dpana;
  using dpana::test::hertz_prm;
  using dpana::test::make_scene;

  using linear_algebra::LastBlockOrdering;

  // Body b of an assembled scene with a contact surface, condensed anew by
  // the given method and back end (and, for the Schur route, the ordering
  // of its factorisation; none: MUMPS orders by itself).
  template <int dim>
  std::unique_ptr<condensation::Condenser<dim>>
  condensed(
    scene::Scene<dim>          &s,
    const unsigned int          b,
    const condensation::Method  method,
    const condensation::Backend backend = condensation::Backend::cholmod,
    const std::optional<LastBlockOrdering> &ordering =
      LastBlockOrdering::interior_nested_dissection)
  {
    condensation::Parameters parameters;
    parameters.method              = method;
    parameters.backend             = backend;
    parameters.mumps_orders_itself = !ordering.has_value();
    if (ordering)
      parameters.ordering = *ordering;
    auto c = std::make_unique<condensation::Condenser<dim>>(s.body(b),
                                                            s.surface(b),
                                                            parameters);
    c->factorize();
    c->assemble_coupling();
    c->condense(16);
    return c;
  }



  using condensation::Backend;
  using condensation::Method;

  // A Schur route (the surface dofs ordered last, A = W^T W with W the
  // solve with the factor of the Schur complement), by the back end
  // @p backend, and a second condensation (@p other_method by
  // @p other_backend) give the same A, s_o, G and e up to round-off (1e-12
  // relative), for every body of the scene and every ordering of the Schur
  // route's factorisation (with MUMPS also its own, AMD, and the ordering
  // MUMPS reports having used: 1 for a given one), and the same recovered
  // displacement.
  template <int dim>
  void
  expect_condensations_agree(scene::Scene<dim> &s,
                             const Backend      backend,
                             const Method       other_method,
                             const Backend      other_backend)
  {
    s.assemble();
    s.build_contact_surface();
    std::vector<std::optional<LastBlockOrdering>> orderings = {
      LastBlockOrdering::moved_last,
      LastBlockOrdering::constrained_amd,
      LastBlockOrdering::interior_nested_dissection};
    if (backend == Backend::mumps)
      orderings.push_back(std::nullopt);
    for (unsigned int b = 0; b < s.n_bodies(); ++b)
      for (const auto &ordering : orderings)
        {
          SCOPED_TRACE(ordering ? linear_algebra::to_string(*ordering) :
                                  "by MUMPS");
          const auto schur = condensed(s, b, Method::schur, backend, ordering);
          const auto other = condensed(s, b, other_method, other_backend);
          if (backend == Backend::mumps)
            {
              EXPECT_EQ(
                dynamic_cast<const linear_algebra::MumpsSchurFactorization &>(
                  schur->schur_factorization())
                  .ordering(),
                ordering ? 1 : 0);
            }
          const auto relative = [](const auto &x, const auto &y) {
            return y.norm() > 0 ? (x - y).norm() / y.norm() : x.norm();
          };
          EXPECT_LT(relative(schur->compliance(), other->compliance()), 1e-12);
          EXPECT_LT(relative(schur->load_term(), other->load_term()), 1e-12);
          EXPECT_LT(relative(schur->equilibrium_matrix(),
                             other->equilibrium_matrix()),
                    1e-12);
          EXPECT_LT(relative(schur->equilibrium_rhs(),
                             other->equilibrium_rhs()),
                    1e-12);
          EXPECT_EQ(schur->fictitious_supports(), other->fictitious_supports());
          EXPECT_EQ(schur->asymmetry(), 0.0);
          EXPECT_GT(schur->schur_factorization().schur_dofs().size(), 0u);
          EXPECT_TRUE(schur->compliance() == schur->compliance().transpose());

          const Eigen::VectorXd r =
            Eigen::VectorXd::LinSpaced(schur->compliance().rows(), -1.0, 1.0);
          const Eigen::VectorXd alpha =
            Eigen::VectorXd::Ones(schur->n_free_modes());
          const auto u1 = schur->recover(r, alpha);
          auto       u2 = other->recover(r, alpha);
          u2 -= u1;
          EXPECT_LT(u2.l2_norm(), 1e-12 * u1.l2_norm());
        }
  }

  // The Schur route of CHOLMOD against the blocked solves.
  template <int dim>
  void
  expect_routes_agree(scene::Scene<dim> &s)
  {
    expect_condensations_agree(s,
                               Backend::cholmod,
                               Method::blocked_solves,
                               Backend::cholmod);
  }

  // The Schur route of MUMPS against that of CHOLMOD.
  template <int dim>
  void
  expect_back_ends_agree(scene::Scene<dim> &s)
  {
    expect_condensations_agree(s,
                               Backend::mumps,
                               Method::schur,
                               Backend::cholmod);
  }



  // The 2D receding block: held only by its symmetry plane, floating along
  // the contact direction (one fictitious support).
  std::unique_ptr<scene::Scene<2>>
  floating_block_2d()
  {
    return make_scene<2>(dpana::test::receding_block(8, 8, "") +
                         "subsection Contact\n"
                         "  set Boundary 1 = bottom\n"
                         "  set Contact direction = 0, -1\n"
                         "end\n");
  }

  // The Hertz cylinder (locally refined: hanging nodes on the surface,
  // floating along its axis) on a floating foundation.
  std::unique_ptr<scene::Scene<2>>
  two_floating_bodies_2d()
  {
    const std::string foundation = dpana::test::floating_foundation();
    return make_scene<2>(hertz_prm(2, 15, 0.3, foundation), 2);
  }

  // A 3D block floating along the contact direction (symmetry planes only),
  // alone or on a held 3D foundation: the parameter file.
  std::string
  block_3d_text(const bool with_foundation)
  {
    using dpana::test::brick_body;
    const std::string block =
      brick_body("Body 1",
                 "box",
                 "0, 0, 0",
                 "40, 20, 20",
                 "8, 4, 4",
                 "    set Symmetry = left, front\n",
                 "    set Pressure = top: 50; right: 100\n");
    const std::string contact = "subsection Contact\n"
                                "  set Boundary 1 = bottom\n"
                                "  set Contact direction = 0, -1, 0\n";
    if (!with_foundation)
      return "set Dimension = 3\n" + block + contact + "end\n";
    const std::string foundation =
      brick_body("Body 2",
                 "box",
                 "0, -20, 0",
                 "40, 0, 20",
                 "8, 4, 4",
                 "    set Symmetry = left, front\n    set Fixed = bottom: y\n",
                 "");
    return "set Dimension = 3\nset Number of bodies = 2\n" + block +
           foundation + contact + "  set Boundary 2 = top\nend\n";
  }

  std::unique_ptr<scene::Scene<3>>
  block_3d(const bool with_foundation)
  {
    return make_scene<3>(block_3d_text(with_foundation),
                         with_foundation ? 2 : 1);
  }



  // The two bodies of the scene of @p text condensed at the same time
  // (Contact / Concurrent bodies = true, the default: each on a thread of
  // its own, the BLAS on that thread) and one after the other (false: the
  // BLAS on every core) give the same contact problem up to round-off
  // (1e-12 relative) and the same tractions (1e-10 relative), in the same
  // phases.
  template <int dim>
  void
  expect_concurrent_equals_one_after_the_other(const std::string &text)
  {
    auto concurrent = make_scene<dim>(text, 2);
    auto serial     = make_scene<dim>(text + "subsection Contact\n"
                                             "  set Concurrent bodies = false\n"
                                             "end\n",
                                  2);
    // The progress lines say which way each ran.
    std::vector<std::string> logs;
    for (auto *s : {concurrent.get(), serial.get()})
      {
        s->set_quiet(false);
        testing::internal::CaptureStdout();
        s->assemble();
        s->build_contact_surface();
        s->condense();
        s->solve();
        logs.push_back(testing::internal::GetCapturedStdout());
        ASSERT_TRUE(s->summary().result.converged);
      }
    for (const std::string phase : {"assembling", "factorising", "condensing"})
      {
        EXPECT_NE(logs[0].find(phase + " Body 1 and Body 2 concurrently"),
                  std::string::npos)
          << logs[0];
        EXPECT_NE(logs[1].find(phase + " Body 2 ..."), std::string::npos)
          << logs[1];
        EXPECT_EQ(logs[1].find("concurrently"), std::string::npos) << logs[1];
      }
    const auto relative = [](const auto &x, const auto &y) {
      return (x - y).norm() / y.norm();
    };
    const auto &p = concurrent->problem(), &q = serial->problem();
    EXPECT_LT(relative(p.A, q.A), 1e-12);
    EXPECT_LT(relative(p.D, q.D), 1e-12);
    EXPECT_EQ(p.G.rows(), q.G.rows());
    if (q.G.rows() > 0)
      {
        EXPECT_LT(relative(p.G, q.G), 1e-12);
        EXPECT_LT(relative(p.e, q.e), 1e-12);
      }
    EXPECT_LT(relative(concurrent->summary().result.r,
                       serial->summary().result.r),
              1e-10);
    for (unsigned int b = 0; b < 2; ++b)
      EXPECT_EQ(concurrent->condenser(b).fictitious_supports(),
                serial->condenser(b).fictitious_supports());
    const auto phases = [](const auto &s) {
      std::vector<std::string> names;
      for (const auto &[name, t] : s->phases().timings())
        names.push_back(name);
      return names;
    };
    EXPECT_EQ(phases(concurrent), phases(serial));
  }
} // namespace



TEST(Condensation, SchurRouteEqualsBlockedSolves2DFloatingBody)
{
  expect_routes_agree(*floating_block_2d());
}



TEST(Condensation, SchurRouteEqualsBlockedSolves2DTwoFloatingBodies)
{
  expect_routes_agree(*two_floating_bodies_2d());
}



TEST(Condensation, SchurRouteEqualsBlockedSolves3D)
{
  expect_routes_agree(*block_3d(false));
  auto two = block_3d(true);
  expect_routes_agree(*two);
  EXPECT_EQ(condensed(*two, 0, Method::schur)->n_free_modes(), 1u);
  EXPECT_EQ(condensed(*two, 1, Method::schur)->n_free_modes(), 0u);
}



TEST(Condensation, ConcurrentBodiesEqualOneAfterTheOther)
{
  expect_concurrent_equals_one_after_the_other<2>(
    hertz_prm(2, 15, 0.3, dpana::test::floating_foundation()));
  expect_concurrent_equals_one_after_the_other<3>(block_3d_text(true));
}



// The memory check of bodies condensed at the same time: an estimate that
// fits with the grants so far is granted (its factor and dense blocks); one
// that fits alone but not with them is deferred; one that does not fit
// alone, with no grant outstanding, is refused (bytes).
TEST(Condensation, MemoryReservationsGrantDeferRefuse)
{
  condensation::MemoryEstimate m;
  m.current      = 1;
  m.factor       = 2;
  m.dense        = 1;
  using Decision = condensation::MemoryReservations::Decision;
  condensation::MemoryReservations grants;
  EXPECT_EQ(grants.request(m, 6), Decision::granted);  // 4 <= 6, 3 granted
  EXPECT_EQ(grants.request(m, 6), Decision::deferred); // 4 + 3 > 6
  EXPECT_EQ(grants.request(m, 7), Decision::granted);  // 4 + 3 <= 7
  condensation::MemoryReservations none;
  EXPECT_EQ(none.request(m, 3.5), Decision::refused); // 4 > 3.5 alone
}



TEST(Condensation, MumpsSchurEqualsCholmodSchur2DFloatingBody)
{
  expect_back_ends_agree(*floating_block_2d());
}



TEST(Condensation, MumpsSchurEqualsCholmodSchur2DTwoFloatingBodies)
{
  expect_back_ends_agree(*two_floating_bodies_2d());
}



TEST(Condensation, MumpsSchurEqualsCholmodSchur3D)
{
  expect_back_ends_agree(*block_3d(false));
  expect_back_ends_agree(*block_3d(true));
}



// The Schur complement itself: S = L_S L_S^T of MUMPS (L_S the dense
// Cholesky factor of the S that MUMPS returns) equals L_22 L_22^T of CHOLMOD
// (the last block of its factor, checked against a dense Schur complement
// in the tests of SparseCholesky), row by row of the same dofs; and the
// solves of the recovery (homogeneous constraints) and of the load (with the
// inhomogeneities) of the two back ends agree. On the
// Hertz cylinder (hanging nodes on the surface) and the 3D block on its
// foundation.
TEST(Condensation, MumpsSchurComplementEqualsCholmodLastBlock)
{
  const auto check = [](auto &s) {
    s.assemble();
    s.build_contact_surface();
    for (unsigned int b = 0; b < s.n_bodies(); ++b)
      {
        const auto  mumps   = condensed(s, b, Method::schur, Backend::mumps);
        const auto  cholmod = condensed(s, b, Method::schur, Backend::cholmod);
        const auto &factor =
          dynamic_cast<const linear_algebra::MumpsSchurFactorization &>(
            mumps->schur_factorization());
        const auto &dofs_m = factor.schur_dofs();
        const auto &dofs_c = cholmod->factorization().schur_dofs();
        ASSERT_EQ(dofs_m.size(), dofs_c.size());
        std::vector<int> position(s.body(b).dof_handler().n_dofs(), -1);
        for (unsigned int k = 0; k < dofs_m.size(); ++k)
          position[dofs_m[k]] = k;
        Eigen::PermutationMatrix<Eigen::Dynamic> P(dofs_c.size());
        for (unsigned int k = 0; k < dofs_c.size(); ++k)
          {
            ASSERT_GE(position[dofs_c[k]], 0);
            P.indices()(k) = position[dofs_c[k]];
          }
        const Eigen::MatrixXd  L22 = cholmod->factorization().schur_factor();
        const Eigen::MatrixXd  S_c = P * L22 * L22.transpose() * P.transpose();
        const Eigen::MatrixXd &L_S = factor.schur_factor();
        const Eigen::MatrixXd  S_m = L_S * L_S.transpose();
        EXPECT_LT((S_m - S_c).norm(), 1e-12 * S_c.norm());

        const unsigned int    n   = s.body(b).dof_handler().n_dofs();
        const Eigen::VectorXd f   = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
        const Eigen::VectorXd u_m = factor.solve(f);
        const Eigen::VectorXd u_c = cholmod->schur_factorization().solve(f);
        EXPECT_LT((u_m - u_c).norm(), 1e-12 * u_c.norm());
        dealii::Vector<double> f_condensed(f.data(), f.data() + n), v_m, v_c;
        factor.solve_condensed(f_condensed, v_m);
        cholmod->factorization().solve_condensed(f_condensed, v_c);
        v_m -= v_c;
        EXPECT_LT(v_m.l2_norm(), 1e-12 * v_c.l2_norm());
      }
  };
  check(*two_floating_bodies_2d());
  check(*block_3d(true));
}



// MUMPS factors a symmetric positive definite matrix without pivoting and
// only counts the negative pivots: the back end refuses a matrix with any
// (here the negated stiffness of the held 3D foundation) with
// NotPositiveDefiniteError, as CHOLMOD does.
TEST(Condensation, MumpsRefusesAMatrixThatIsNotPositiveDefinite)
{
  auto s = block_3d(true);
  s->assemble();
  const auto                  &body = s->body(1);
  dealii::SparseMatrix<double> K(body.system_matrix().get_sparsity_pattern());
  K.copy_from(body.system_matrix());
  K *= -1.0;
  // MUMPS' own ordering (through PETSc), then a given one (MUMPS called
  // directly).
  for (const bool given : {false, true})
    {
      linear_algebra::MumpsSchurFactorization factor;
      if (given)
        factor.set_ordering(LastBlockOrdering::interior_nested_dissection);
      EXPECT_THROW(factor.factorize(K, body.constraints(), {}),
                   linear_algebra::NotPositiveDefiniteError);
      EXPECT_NO_THROW(
        factor.factorize(body.system_matrix(), body.constraints(), {}));
      EXPECT_TRUE(factor.schur_dofs().empty());
      EXPECT_EQ(factor.ordering() == 1, given);
    }
}



// The check of MumpsAnalysisCheckComesBeforeTheFactorisation on the
// matrix of @p body.
template <int dim>
void
expect_analysis_check_before_factorisation(
  const dpana::Body<dim>                  &body,
  linear_algebra::MumpsSchurFactorization &factor)
{
  using Statistics = linear_algebra::MumpsSchurFactorization::Statistics;
  Statistics seen;
  factor.set_analysis_check([&seen](const Statistics &analysis) {
    seen = analysis;
    throw std::runtime_error("refused after the analysis");
  });
  EXPECT_THROW(factor.factorize(body.system_matrix(), body.constraints(), {}),
               std::runtime_error);
  EXPECT_GT(seen.estimated_flops, 0.0);
  EXPECT_GT(seen.estimated_factor_entries, 0);
  EXPECT_GT(seen.estimated_total_mb, 0);

  factor.set_analysis_check(
    [&seen](const Statistics &analysis) { seen = analysis; });
  factor.factorize(body.system_matrix(), body.constraints(), {});
  const Statistics made = factor.statistics();
  EXPECT_NEAR(made.flops / seen.estimated_flops, 1.0, 1e-6);
  EXPECT_EQ(made.factor_entries, seen.estimated_factor_entries);
  EXPECT_GT(made.used_total_mb, 0);
}



// MUMPS' analysis is handed to set_analysis_check() before the numerical
// factorisation: a check that throws stops factorize() with its exception,
// and the estimates it saw (flops RINFOG(1), factor entries INFOG(20)) are
// those the factorisation then makes (RINFOG(3), INFOG(29)): no pivot of a
// positive definite matrix is delayed. On the held 3D foundation.
TEST(Condensation, MumpsAnalysisCheckComesBeforeTheFactorisation)
{
  auto s = block_3d(true);
  s->assemble();
  for (const bool given : {false, true})
    {
      SCOPED_TRACE(given ? "given ordering" : "MUMPS' ordering");
      linear_algebra::MumpsSchurFactorization factor;
      if (given)
        factor.set_ordering(LastBlockOrdering::interior_nested_dissection);
      expect_analysis_check_before_factorisation(s->body(1), factor);
    }
}



// MUMPS out of core (Contact / Out-of-core directory): while the
// factorisation lives its factor is in files of the directory, the
// statistics say out of core, with an out-of-core workspace (INFOG(26)) no
// larger than the in-core one (INFOG(16)); the condensation (A, s_o) and the
// recovered displacement equal those of the same factorisation in memory to
// round-off (1e-12 relative); destroying the factorisation removes the
// files. On the 3D block and its foundation.
TEST(Condensation, MumpsOutOfCoreEqualsInCore)
{
  auto s = block_3d(true);
  s->assemble();
  s->build_contact_surface();
  const std::filesystem::path directory = "mumps_out_of_core_test";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directory(directory);
  condensation::Parameters parameters;
  parameters.backend               = Backend::mumps;
  parameters.out_of_core_directory = directory.string();
  for (unsigned int b = 0; b < s->n_bodies(); ++b)
    {
      const auto in_core = condensed(*s, b, Method::schur, Backend::mumps);
      {
        condensation::Condenser<3> ooc(s->body(b), s->surface(b), parameters);
        ooc.factorize();
        EXPECT_FALSE(std::filesystem::is_empty(directory));
        ooc.assemble_coupling();
        ooc.condense(16);
        const auto statistics =
          dynamic_cast<const linear_algebra::MumpsSchurFactorization &>(
            ooc.schur_factorization())
            .statistics();
        EXPECT_TRUE(statistics.out_of_core);
        EXPECT_GT(statistics.estimated_ooc_max_mb, 0);
        EXPECT_LE(statistics.estimated_ooc_max_mb, statistics.estimated_max_mb);
        EXPECT_FALSE(
          dynamic_cast<const linear_algebra::MumpsSchurFactorization &>(
            in_core->schur_factorization())
            .statistics()
            .out_of_core);
        const auto relative = [](const auto &x, const auto &y) {
          return y.norm() > 0 ? (x - y).norm() / y.norm() : x.norm();
        };
        EXPECT_LT(relative(ooc.compliance(), in_core->compliance()), 1e-12);
        EXPECT_LT(relative(ooc.load_term(), in_core->load_term()), 1e-12);
        const Eigen::VectorXd r =
          Eigen::VectorXd::LinSpaced(ooc.compliance().rows(), -1.0, 1.0);
        const Eigen::VectorXd alpha = Eigen::VectorXd::Ones(ooc.n_free_modes());
        const auto            u1    = in_core->recover(r, alpha);
        auto                  u2    = ooc.recover(r, alpha);
        u2 -= u1;
        EXPECT_LT(u2.l2_norm(), 1e-12 * u1.l2_norm());
      }
      EXPECT_TRUE(std::filesystem::is_empty(directory));
    }
  std::filesystem::remove_all(directory);
}
