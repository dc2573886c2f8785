// Bad input: every check of ContactProblem::validate() and of the solver
// options throws std::invalid_argument with a one-line message that names
// the offending field.
#include <functional>
#include <utility>

#include "contact_test_tools.h"
#include <gtest/gtest.h>

using namespace dpana_test;

namespace
{
  void
  expect_error(const std::function<void()> &f, const std::string &word)
  {
    try
      {
        f();
        ADD_FAILURE() << "no exception; expected one naming '" << word << "'";
      }
    catch (const std::invalid_argument &e)
      {
        const std::string message = e.what();
        EXPECT_NE(message.find(word), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      }
  }

  ContactProblem
  good()
  {
    return random_problem(2, 3, 0.3, 5);
  }
} // namespace

TEST(Validation, Problem)
{
  EXPECT_NO_THROW(good().validate());
  const SolverOptions o;
  auto                check = [&](ContactProblem p, const std::string &word) {
    expect_error([&]() { p.validate(); }, word);
    expect_error([&]() { solve(p, o); }, word);
  };
  {
    auto p = good();
    p.dim  = 4;
    check(p, "dim");
  }
  {
    auto p = good();
    p.D.resize(5);
    check(p, "D");
  }
  {
    auto p = good();
    p.A.conservativeResize(5, 5);
    check(p, "A");
  }
  {
    auto p = good();
    p.A(0, 1) += 1.0;
    check(p, "symmetric");
  }
  {
    // Larger than one tile of the symmetry check (64 rows): an asymmetry
    // far from the diagonal, in either triangle, and a symmetric A of that
    // size that passes.
    auto big = random_problem(3, 70, 0.3, 7, ConeModel::disc);
    EXPECT_NO_THROW(big.validate());
    for (const auto &[i, j] : {std::pair{200, 3}, std::pair{5, 130}})
      {
        auto p = big;
        p.A(i, j) += 1e-3;
        check(p, "symmetric");
      }
  }
  {
    auto p  = good();
    p.mu[1] = -0.1;
    check(p, "mu[1]");
  }
  {
    auto p = good();
    p.mu.resize(2);
    check(p, "mu");
  }
  {
    auto p = good();
    p.D[2] = std::nan("");
    check(p, "D");
  }
  {
    auto p = good();
    p.cone = ConeModel::disc;
    check(p, "interval");
  }
  {
    auto p = random_problem(3, 3, 0.3, 5, ConeModel::interval);
    p.cone = ConeModel::interval;
    check(p, "interval");
  }
  {
    auto p          = random_problem(3, 3, 0.3, 5, ConeModel::polygon);
    p.polygon_sides = 2;
    check(p, "polygon_sides");
  }
  {
    auto p = good();
    p.G    = Eigen::MatrixXd::Ones(2, 6);
    p.e    = Eigen::VectorXd::Ones(3);
    check(p, "G");
  }
  {
    auto p = good();
    p.G    = Eigen::MatrixXd::Ones(2, 5);
    p.e    = Eigen::VectorXd::Ones(2);
    check(p, "columns");
  }
}

TEST(Validation, Options)
{
  const ContactProblem p = good();
  auto check = [&](const std::function<void(SolverOptions &)> &change,
                   const std::string                          &word) {
    SolverOptions o;
    change(o);
    expect_error([&]() { solve(p, o); }, word);
  };
  check([](SolverOptions &o) { o.tolerance = 0; }, "tolerance");
  check([](SolverOptions &o) { o.inner_tolerance = -1; }, "inner_tolerance");
  check([](SolverOptions &o) { o.max_iterations = 0; }, "max_iterations");
  check([](SolverOptions &o) { o.over_relaxation = 2.0; }, "over_relaxation");
  check([](SolverOptions &o) { o.augmentation = 0.0; }, "augmentation");
  expect_error([&]() { solver_type_from_string("newton"); }, "newton");
  EXPECT_EQ(solver_type_from_string("nsgs"), SolverType::nsgs);
  for (const SolverType t : all_solvers())
    EXPECT_EQ(solver_type_from_string(to_string(t)), t);
  EXPECT_EQ(solver_type_names(),
            "splitting_active_set|splitting_pgs|nsgs|alart_curnier");
  const Eigen::VectorXd wrong = Eigen::VectorXd::Zero(4);
  expect_error([&]() { solve(p, SolverOptions(), &wrong); }, "initial_r");
}



// The names of the cone models: one table gives to_string(),
// cone_model_from_string() and the Selection pattern of each dimension.
TEST(Validation, ConeModelNames)
{
  EXPECT_EQ(cone_model_names(2), "interval");
  EXPECT_EQ(cone_model_names(3), "disc|polygon");
  for (const ConeModel cone :
       {ConeModel::interval, ConeModel::disc, ConeModel::polygon})
    EXPECT_EQ(cone_model_from_string(to_string(cone)), cone);
  expect_error([]() { cone_model_from_string("square"); }, "square");
}
