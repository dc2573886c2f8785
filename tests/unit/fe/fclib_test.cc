// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Tests of the FCLIB local-problem reader and writer
// (include/dpana/io/fclib.h): exact round trips, the sign convention on a
// one-element problem whose solution is known in closed form, the other storage
// forms of FCLIB's sparse matrices, and one-line errors for bad files.

#include <dpana/base/exceptions.h>
#include <dpana/io/fclib.h>

#include <deal.II/base/hdf5.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "scratch_path.h"
#include <gtest/gtest.h>

namespace
{
  using dpana::contact::ConeModel;
  using dpana::contact::ContactProblem;

  // A scratch file for one test: its HDF5 file, removed at the end of the
  // test.
  struct ScratchFile : dpana::test::ScratchFile
  {
    explicit ScratchFile(const std::string &name)
      : dpana::test::ScratchFile("fclib_test_" + name + ".hdf5")
    {
    }
  };

  // A random symmetric positive definite problem, with a few exact zeros in
  // A (which the sparse storage drops and the reader restores) and a
  // different friction coefficient on every element.
  ContactProblem
  random_problem(const unsigned int dim,
                 const unsigned int n,
                 const unsigned int seed)
  {
    std::mt19937_64                        rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const unsigned int                     size = dim * n;
    Eigen::MatrixXd                        B(size, size);
    for (unsigned int i = 0; i < size; ++i)
      for (unsigned int j = 0; j < size; ++j)
        B(i, j) = unit(rng);
    ContactProblem p;
    p.dim = dim;
    p.A   = B * B.transpose() + size * Eigen::MatrixXd::Identity(size, size);
    // Exact zeros in symmetric positions.
    p.A(0, size - 1) = p.A(size - 1, 0) = 0.0;
    p.D                                 = Eigen::VectorXd(size);
    for (unsigned int i = 0; i < size; ++i)
      p.D[i] = unit(rng);
    p.mu = Eigen::VectorXd(n);
    for (unsigned int j = 0; j < n; ++j)
      p.mu[j] = 0.5 * (1.0 + unit(rng));
    p.cone = (dim == 3 ? ConeModel::disc : ConeModel::interval);
    return p;
  }

  void
  expect_identical(const ContactProblem &a, const ContactProblem &b)
  {
    EXPECT_EQ(a.dim, b.dim);
    ASSERT_EQ(a.A.rows(), b.A.rows());
    ASSERT_EQ(a.A.cols(), b.A.cols());
    // Exact equality: the file stores the doubles themselves.
    EXPECT_TRUE(a.A == b.A);
    EXPECT_TRUE(a.D == b.D);
    EXPECT_TRUE(a.mu == b.mu);
    EXPECT_TRUE(a.cone == b.cone);
    EXPECT_EQ(a.G.rows(), b.G.rows());
    if (a.G.size() > 0)
      {
        EXPECT_TRUE(a.G == b.G);
      }
    EXPECT_TRUE(a.e.size() == b.e.size() && (a.e.size() == 0 || a.e == b.e));
  }

  // @sect3{Round trips}

  TEST(Fclib, RoundTripIsExact2D3D)
  {
    for (const unsigned int dim : {2u, 3u})
      {
        ScratchFile          file("roundtrip" + std::to_string(dim));
        const ContactProblem p = random_problem(dim, 7, 42 + dim);
        dpana::io::FclibInfo info;
        info.title       = "random SPD test problem";
        info.description = "dim " + std::to_string(dim) + ", 7 elements";
        dpana::io::write_fclib_local(file.path, p, info);

        dpana::io::FclibInfo back_info;
        const ContactProblem q =
          dpana::io::read_fclib_local(file.path, &back_info);
        expect_identical(p, q);
        EXPECT_EQ(back_info.title, info.title);
        EXPECT_EQ(back_info.description, info.description);
        EXPECT_EQ(back_info.math_info, "");

        // The exact zero of A is not stored: nzmax = size^2 - 2.
        const dealii::HDF5::File h5(file.path,
                                    dealii::HDF5::File::FileAccessMode::open);
        const auto               nzmax = h5.open_group("fclib_local")
                             .open_group("W")
                             .open_dataset("nzmax")
                             .read<std::vector<int>>();
        ASSERT_EQ(nzmax.size(), 1u);
        EXPECT_EQ(nzmax[0], static_cast<int>(p.A.size()) - 2);
      }
  }

  // Floating bodies: the equality rows G r = e travel as FCLIB's V = G^T,
  // R = 0, s = e; and a solution with its rigid-mode amplitudes.
  TEST(Fclib, RoundTripWithEqualityRowsAndSolution)
  {
    ScratchFile    file("equalities");
    ContactProblem p = random_problem(2, 5, 9);
    p.G              = Eigen::MatrixXd::Zero(2, 10);
    for (unsigned int j = 0; j < 5; ++j)
      {
        p.G(0, 2 * j)     = 1.0; // resultant of the normal tractions
        p.G(1, 2 * j + 1) = 1.0; // resultant of the tangential tractions
      }
    p.e = Eigen::Vector2d(-3.0, 0.25);
    dpana::io::write_fclib_local(file.path, p);
    expect_identical(p, dpana::io::read_fclib_local(file.path));

    const Eigen::VectorXd r     = Eigen::VectorXd::LinSpaced(10, -1.0, 0.0);
    const Eigen::VectorXd u     = p.A * r + p.D;
    const Eigen::VectorXd alpha = Eigen::Vector2d(0.5, -2.0);
    dpana::io::write_fclib_solution(file.path, r, u, alpha);
    Eigen::VectorXd r2, u2, alpha2;
    ASSERT_TRUE(dpana::io::read_fclib_solution(file.path, r2, u2, &alpha2));
    EXPECT_TRUE(r2 == r);
    EXPECT_TRUE(u2 == u);
    EXPECT_TRUE(alpha2 == alpha);

    // A second solution is refused with a one-line error.
    EXPECT_THROW(dpana::io::write_fclib_solution(file.path, r, u, alpha),
                 dpana::InputError);
  }

  // A problem written with the friction polygon is stored (and read back)
  // as the disc problem, and the file says so.
  TEST(Fclib, PolygonIsStoredAsDisc)
  {
    ScratchFile    file("polygon");
    ContactProblem p = random_problem(3, 3, 5);
    p.cone           = ConeModel::polygon;
    p.polygon_sides  = 32;
    dpana::io::write_fclib_local(file.path, p);
    dpana::io::FclibInfo info;
    const ContactProblem q = dpana::io::read_fclib_local(file.path, &info);
    EXPECT_TRUE(q.cone == ConeModel::disc);
    EXPECT_NE(info.math_info.find("32-sided"), std::string::npos);
  }

  // @sect3{The sign convention on a problem with a known solution}
  //
  // One 2D element, A = diag(2, 4), D = (1, 3), mu = 0.5. By hand (the
  // reference formulation's convention): the element is pressed (D_N > 0), so
  // u_N = 2 N + 1 = 0 gives N = -1/2; sticking would need T = -D_T/4 = -3/4,
  // beyond the capacity -mu N = 1/4, so it slips with T = -1/4 (opposite to
  // D_T) and u_T = 4 T + 3 = 2 = -lambda T with lambda = 8 >= 0. Solution:
  //   r = (-1/2, -1/4),  u = (0, 2).
  // In FCLIB's convention the same state is r_s = (1/2, 1/4) (compression
  // positive, inside the cone r_{s,T} <= mu r_{s,N} with equality),
  // u_s = (0, -2) (velocity opposite to the friction reaction), and it must
  // satisfy u_s = W r_s + q with the W and q *as stored in the file*, read
  // here with the HDF5 wrappers directly, not with dpana's reader.
  TEST(Fclib, SignConventionOnOneElement)
  {
    ScratchFile    file("one_element");
    ContactProblem p;
    p.dim  = 2;
    p.A    = Eigen::Vector2d(2.0, 4.0).asDiagonal();
    p.D    = Eigen::Vector2d(1.0, 3.0);
    p.mu   = Eigen::VectorXd::Constant(1, 0.5);
    p.cone = ConeModel::interval;
    const Eigen::Vector2d r(-0.5, -0.25), u(0.0, 2.0);
    ASSERT_LT((p.A * r + p.D - u).norm(), 1e-15); // the hand solution
    dpana::io::write_fclib_local(file.path, p);
    dpana::io::write_fclib_solution(file.path, r, u);

    const dealii::HDF5::File  h5(file.path,
                                dealii::HDF5::File::FileAccessMode::open);
    const dealii::HDF5::Group local = h5.open_group("fclib_local");
    EXPECT_EQ(local.open_dataset("spacedim").read<std::vector<int>>(),
              std::vector<int>{2});
    const dealii::HDF5::Group W = local.open_group("W");
    EXPECT_EQ(W.open_dataset("nz").read<std::vector<int>>(),
              std::vector<int>{-1}); // compressed columns
    EXPECT_EQ(W.open_dataset("p").read<std::vector<int>>(),
              (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(W.open_dataset("i").read<std::vector<int>>(),
              (std::vector<int>{0, 1}));
    const std::vector<double> x =
      W.open_dataset("x").read<std::vector<double>>();
    const std::vector<double> q =
      local.open_group("vectors").open_dataset("q").read<std::vector<double>>();
    ASSERT_EQ(x.size(), 2u);
    ASSERT_EQ(q.size(), 2u);
    EXPECT_EQ(q[0], -1.0);
    EXPECT_EQ(q[1], -3.0);

    const std::vector<double> rs =
      h5.open_group("solution").open_dataset("r").read<std::vector<double>>();
    const std::vector<double> us =
      h5.open_group("solution").open_dataset("u").read<std::vector<double>>();
    EXPECT_EQ(rs, (std::vector<double>{0.5, 0.25}));
    EXPECT_EQ(us, (std::vector<double>{-0.0, -2.0}));
    // u_s = W r_s + q with the file's data.
    EXPECT_EQ(x[0] * rs[0] + q[0], us[0]);
    EXPECT_EQ(x[1] * rs[1] + q[1], us[1]);
    // Siconos/FCLIB laws: r_{s,N} >= 0, |r_{s,T}| <= mu r_{s,N} (slip: =),
    // u_{s,N} >= 0, r_{s,N} u_{s,N} = 0, u_{s,T} r_{s,T} <= 0.
    EXPECT_GT(rs[0], 0.0);
    EXPECT_EQ(std::abs(rs[1]), 0.5 * rs[0]);
    EXPECT_GE(us[0], 0.0);
    EXPECT_EQ(rs[0] * us[0], 0.0);
    EXPECT_LT(us[1] * rs[1], 0.0);
  }

  // @sect3{FCLIB's other sparse storage forms}
  //
  // FCLIB files written by other programs may store W as triplets
  // (nz >= 0) or compressed rows (nz = -2). We write such files here by
  // hand, with the HDF5 wrappers, and check that the reader builds the same
  // non-symmetric-looking-layout but symmetric matrix [[4, 1], [1, 3]].
  void
  write_by_hand(const std::string         &path,
                const int                  nz,
                const std::vector<int>    &p,
                const std::vector<int>    &i,
                const std::vector<double> &x)
  {
    dealii::HDF5::File  h5(path, dealii::HDF5::File::FileAccessMode::create);
    dealii::HDF5::Group local = h5.create_group("fclib_local");
    local.write_dataset("spacedim", std::vector<int>{2});
    dealii::HDF5::Group W = local.create_group("W");
    W.write_dataset("nzmax", std::vector<int>{static_cast<int>(x.size())});
    W.write_dataset("m", std::vector<int>{2});
    W.write_dataset("n", std::vector<int>{2});
    W.write_dataset("nz", std::vector<int>{nz});
    W.write_dataset("p", p);
    W.write_dataset("i", i);
    W.write_dataset("x", x);
    dealii::HDF5::Group vectors = local.create_group("vectors");
    vectors.write_dataset("q", std::vector<double>{-1.0, 0.5});
    vectors.write_dataset("mu", std::vector<double>{0.3});
  }

  TEST(Fclib, ReadsTripletAndCompressedRowStorage)
  {
    Eigen::Matrix2d expected;
    expected << 4, 1, 1, 3;
    {
      ScratchFile file("triplet");
      // Triplets (i rows, p columns), one entry split in two (summed).
      write_by_hand(
        file.path, 5, {0, 1, 0, 1, 1}, {0, 0, 1, 1, 1}, {4, 1, 1, 1, 2});
      const ContactProblem p = dpana::io::read_fclib_local(file.path);
      EXPECT_TRUE(p.A == expected);
      EXPECT_TRUE(p.D == Eigen::Vector2d(1.0, -0.5));
    }
    {
      ScratchFile file("csr");
      write_by_hand(file.path, -2, {0, 2, 4}, {0, 1, 0, 1}, {4, 1, 1, 3});
      EXPECT_TRUE(dpana::io::read_fclib_local(file.path).A == expected);
    }
    {
      ScratchFile file("bad_index");
      write_by_hand(file.path, -1, {0, 2, 4}, {0, 7, 0, 1}, {4, 1, 1, 3});
      EXPECT_THROW(dpana::io::read_fclib_local(file.path), dpana::InputError);
    }
  }

  // @sect3{Errors}
  //
  // Every error is a dpana::InputError whose message is one line and names
  // the file (and the missing item).
  std::string
  error_of(const std::string &path)
  {
    try
      {
        dpana::io::read_fclib_local(path);
      }
    catch (const dpana::InputError &e)
      {
        return e.what();
      }
    return "";
  }

  TEST(Fclib, OneLineErrors)
  {
    // A missing file.
    const std::string missing = "/nonexistent/dir/problem.hdf5";
    std::string       message = error_of(missing);
    EXPECT_NE(message.find(missing), std::string::npos) << message;
    EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;

    // A file that is not HDF5.
    {
      ScratchFile file("text");
      std::ofstream(file.path) << "not an HDF5 file\n";
      message = error_of(file.path);
      EXPECT_NE(message.find("not an HDF5 file"), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }

    // An HDF5 file without the /fclib_local group (e.g. a global problem).
    {
      ScratchFile file("global");
      {
        dealii::HDF5::File h5(file.path,
                              dealii::HDF5::File::FileAccessMode::create);
        h5.create_group("fclib_global");
      }
      message = error_of(file.path);
      EXPECT_NE(message.find("no /fclib_local group"), std::string::npos)
        << message;
      EXPECT_NE(message.find(file.path), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }

    // A local problem without mu.
    {
      ScratchFile file("no_mu");
      {
        dealii::HDF5::File  h5(file.path,
                              dealii::HDF5::File::FileAccessMode::create);
        dealii::HDF5::Group local = h5.create_group("fclib_local");
        local.write_dataset("spacedim", std::vector<int>{2});
        local.create_group("W");
        local.create_group("vectors").write_dataset("q",
                                                    std::vector<double>{0, 0});
      }
      message = error_of(file.path);
      EXPECT_NE(message.find("/fclib_local/vectors/mu"), std::string::npos)
        << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }

    // Writing into a directory that does not exist.
    try
      {
        dpana::io::write_fclib_local(missing, random_problem(2, 2, 1));
        ADD_FAILURE() << "no exception";
      }
    catch (const dpana::InputError &e)
      {
        message = e.what();
        EXPECT_NE(message.find("/nonexistent/dir"), std::string::npos);
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      }
  }
} // namespace
