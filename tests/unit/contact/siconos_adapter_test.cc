// Tests of the mapping between dpana's contact problem and Siconos'
// friction contact problem (siconos_adapter.h), and of Siconos itself on
// problems whose solution is known by construction (siconos_problems.h).
//
// The first group needs only Eigen and always runs. The second calls
// Siconos and is compiled only with DPANA_WITH_SICONOS; it establishes that
// the peer, seen through the adapter, solves dpana's problems, before the
// cross-check (siconos_crosscheck.cc) uses it as a reference for dpana's own
// solvers.
#include <sstream>
#include <tuple>

#include "siconos_adapter.h"
#include "siconos_problems.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dpana::contact;
  namespace sa = dpana::contact::siconos_adapter;
  namespace tp = dpana::contact::test_problems;

  // @sect3{The sign mapping, without Siconos}

  // The planted problem of siconos_problems.h is solved by construction.
  // First make sure the construction is right: the planted (r, u) satisfies
  // u = A r + D and the laws of problem.h up to round-off.
  TEST(SiconosAdapter, PlantedSolutionSatisfiesTheLaws)
  {
    for (const unsigned int dim : {2u, 3u})
      for (const double mu : {0.0, 0.3, 1.0})
        {
          const tp::PlantedProblem p = tp::planted_problem(dim, 30, mu, 7);
          EXPECT_LT(
            (p.problem.A * p.r + p.problem.D - p.u).cwiseAbs().maxCoeff(),
            1e-12);
          EXPECT_LT(tp::check_laws(p.problem, p.r, p.u).max(), 1e-12);
          // A mixture of states, as the cross-check needs.
          EXPECT_GT(p.n_separated, 0u);
          EXPECT_GT(p.n_slip, 0u);
          if (mu > 0)
            {
              EXPECT_GT(p.n_stick, 0u);
            }
        }
  }

  // The independent law check must be able to fail: perturb the planted
  // solution in each of the ways it must detect.
  TEST(SiconosAdapter, LawCheckDetectsViolations)
  {
    const tp::PlantedProblem p = tp::planted_problem(3, 20, 0.3, 11);
    const unsigned int       d = 3;
    // Find one element of each kind.
    int separated = -1, contact = -1;
    for (unsigned int j = 0; j < 20; ++j)
      if (p.r[d * j] == 0.0 && separated < 0)
        separated = j;
      else if (p.r[d * j] < 0.0 && contact < 0)
        contact = j;
    ASSERT_GE(separated, 0);
    ASSERT_GE(contact, 0);

    auto violation = [&](Eigen::VectorXd r) {
      return tp::check_laws(p.problem, r, p.problem.A * r + p.problem.D).max();
    };
    Eigen::VectorXd r = p.r;
    r[d * separated]  = 1e-3; // tensile normal traction
    EXPECT_GT(violation(r), 1e-6);
    r = p.r;
    r[d * contact + 1] +=
      -p.problem.mu[contact] * p.r[d * contact]; // leaves the cone
    EXPECT_GT(violation(r), 1e-6);
    r = p.r;
    r[d * contact] *= 0.9; // changes u everywhere: penetration or gap opening
    EXPECT_GT(violation(r), 1e-6);
  }

  // dpana -> Siconos -> dpana is the identity, and the Siconos data is
  // (M, q) = (A, -D) exactly.
  TEST(SiconosAdapter, ProblemRoundTripIsExact)
  {
    for (const unsigned int dim : {2u, 3u})
      {
        const tp::PlantedProblem      p = tp::planted_problem(dim, 12, 0.5, 3);
        const sa::FrictionContactData data =
          sa::to_siconos_convention(p.problem);
        EXPECT_EQ(data.dim, dim);
        EXPECT_TRUE(data.M == p.problem.A);
        EXPECT_TRUE(data.q == -p.problem.D);
        EXPECT_TRUE(data.mu == p.problem.mu);
        const ContactProblem back = sa::from_siconos_convention(data);
        EXPECT_EQ(back.dim, dim);
        EXPECT_TRUE(back.A == p.problem.A);
        EXPECT_TRUE(back.D == p.problem.D);
        EXPECT_TRUE(back.mu == p.problem.mu);
        EXPECT_TRUE(back.cone == p.problem.cone);
      }
  }

  // In the Siconos convention the planted solution (r_s, u_s) = (-r, -u)
  // must satisfy the Siconos form of the laws: u_s = M r_s + q,
  // r_{s,N} >= 0, ||r_{s,T}|| <= mu r_{s,N}, u_{s,N} >= 0,
  // r_{s,N} u_{s,N} = 0, and at slip u_{s,T} = -lambda r_{s,T} (velocity
  // opposite to the friction reaction).
  TEST(SiconosAdapter, PlantedSolutionInSiconosConvention)
  {
    const tp::PlantedProblem      p    = tp::planted_problem(3, 25, 0.4, 5);
    const sa::FrictionContactData data = sa::to_siconos_convention(p.problem);
    const Eigen::VectorXd         rs   = sa::to_siconos_sign(p.r);
    const Eigen::VectorXd         us   = sa::to_siconos_sign(p.u);
    EXPECT_LT((data.M * rs + data.q - us).cwiseAbs().maxCoeff(), 1e-12);
    unsigned int n_slip_checked = 0;
    for (unsigned int j = 0; j < 25; ++j)
      {
        const double          rN = rs[3 * j], uN = us[3 * j];
        const Eigen::Vector2d rT = rs.segment<2>(3 * j + 1);
        const Eigen::Vector2d uT = us.segment<2>(3 * j + 1);
        EXPECT_GE(rN, 0.0);
        EXPECT_GE(uN, -1e-12);
        EXPECT_LT(std::abs(rN * uN), 1e-12);
        EXPECT_LE(rT.norm(), data.mu[j] * rN + 1e-12);
        if (rN > 0 && rT.norm() > data.mu[j] * rN - 1e-12 && rT.norm() > 0)
          {
            // u_{s,T} antiparallel to r_{s,T}: cross product zero, dot <= 0.
            EXPECT_LT(std::abs(uT[0] * rT[1] - uT[1] * rT[0]), 1e-10);
            EXPECT_LE(uT.dot(rT), 1e-12);
            ++n_slip_checked;
          }
      }
    EXPECT_GT(n_slip_checked, 0u);
  }

  TEST(SiconosAdapter, RejectsWhatSiconosCannotRepresent)
  {
    tp::PlantedProblem p       = tp::planted_problem(3, 4, 0.3, 1);
    ContactProblem     polygon = p.problem;
    polygon.cone               = ConeModel::polygon;
    EXPECT_THROW(sa::to_siconos_convention(polygon), std::invalid_argument);
    ContactProblem floating = p.problem;
    floating.G              = Eigen::MatrixXd::Ones(1, 12);
    floating.e              = Eigen::VectorXd::Zero(1);
    EXPECT_THROW(sa::to_siconos_convention(floating), std::invalid_argument);
  }

#ifdef DPANA_WITH_SICONOS
  // @sect3{Siconos on problems with a known solution}
  //
  // Every Siconos solver is run at its own tolerance 1e-12 on a planted
  // problem. A peer solver may fail (it reports info != 0 or an error
  // above its tolerance); such failures are listed, not hidden, and are not
  // dpana's concern, but for every problem at least one Siconos solver must
  // succeed, and every successful one must return the planted solution
  // within a relative 1e-8 (in the max norm) and satisfy the laws (checked
  // independently) within 1e-8.
  class SiconosPlanted : public ::testing::TestWithParam<
                           std::tuple<unsigned int, unsigned int, double>>
  {
  };

  std::vector<sa::PeerSolver>
  peer_solvers(const unsigned int dim, const double mu)
  {
    if (dim == 2)
      return {sa::PeerSolver::fc2d_nsgs, sa::PeerSolver::fc2d_lemke};
    std::vector<sa::PeerSolver> s = {sa::PeerSolver::fc3d_nsgs,
                                     sa::PeerSolver::fc3d_nsn_ac,
                                     sa::PeerSolver::fc3d_pfp};
    // Siconos' natural map Newton method does not converge without
    // friction in this version (its generalized Jacobian is singular for
    // mu = 0); it is tried with friction only.
    if (mu > 0)
      s.push_back(sa::PeerSolver::fc3d_nsn_nm);
    return s;
  }

  TEST_P(SiconosPlanted, RecoversThePlantedSolution)
  {
    const auto [dim, n, mu]    = GetParam();
    const tp::PlantedProblem p = tp::planted_problem(dim, n, mu, 1000 + n);
    unsigned int             n_success = 0;
    std::ostringstream       failures;
    for (const sa::PeerSolver solver : peer_solvers(dim, mu))
      {
        sa::PeerOptions options;
        options.solver         = solver;
        options.tolerance      = 1e-12;
        options.max_iterations = 100000;
        if (solver == sa::PeerSolver::fc3d_nsn_ac ||
            solver == sa::PeerSolver::fc3d_nsn_nm)
          options.max_iterations = 200;
        const sa::PeerResult result = sa::solve(p.problem, options);
        if (result.info != 0 || !(result.peer_error <= options.tolerance))
          {
            failures << " " << sa::to_string(solver) << "(info " << result.info
                     << ", error " << result.peer_error << ")";
            continue;
          }
        ++n_success;
        const double error =
          (result.r - p.r).cwiseAbs().maxCoeff() / p.r.cwiseAbs().maxCoeff();
        EXPECT_LT(error, 1e-8) << sa::to_string(solver);
        EXPECT_LT(tp::check_laws(p.problem, result.r, result.u).max(), 1e-8)
          << sa::to_string(solver);
        // The signs after the back-mapping: N <= 0, u_N <= 0.
        for (unsigned int j = 0; j < n; ++j)
          {
            EXPECT_LE(result.r[dim * j], 1e-12);
            EXPECT_LE(result.u[dim * j], 1e-9);
          }
      }
    EXPECT_GE(n_success, 1u);
    if (!failures.str().empty())
      std::cout << "[ peer failures ]" << failures.str() << std::endl;
  }

  std::string
  grid_name(const ::testing::TestParamInfo<
            std::tuple<unsigned int, unsigned int, double>> &info)
  {
    return "d" + std::to_string(std::get<0>(info.param)) + "_n" +
           std::to_string(std::get<1>(info.param)) + "_mu" +
           std::to_string(static_cast<int>(std::get<2>(info.param) * 10));
  }

  INSTANTIATE_TEST_SUITE_P(Grid,
                           SiconosPlanted,
                           ::testing::Combine(::testing::Values(2u, 3u),
                                              ::testing::Values(5u, 20u, 60u),
                                              ::testing::Values(0.0, 0.3, 1.0)),
                           grid_name);

  // A solver of the wrong dimension is refused with a clear message.
  TEST(SiconosAdapter, RefusesSolverOfWrongDimension)
  {
    const tp::PlantedProblem p = tp::planted_problem(2, 4, 0.3, 1);
    sa::PeerOptions          options;
    options.solver = sa::PeerSolver::fc3d_nsgs;
    EXPECT_THROW(sa::solve(p.problem, options), std::invalid_argument);
  }
#endif
} // namespace
