// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Detection of the rigid motions that the kinematic conditions leave free.
// The expected answers follow from the geometry: an unsupported body keeps
// all 3 (2D) or 6 (3D) rigid motions; a body with a fixed face keeps none;
// a face held only normally keeps the in-plane translations and the
// rotation about its normal (bottom is the face y = 0, as in the
// rectangle/box geometry); two perpendicular symmetry planes in 2D keep
// nothing. The stiffness matrix of a body that is not held must be refused
// by the Cholesky factorisation.

#include <dpana/base/exceptions.h>
#include <dpana/body/body.h>

#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>

#include "mesh_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dealii;

  // The brick [0, 2] x [0, 1] (x [0, 1.5]) of 3 cells per direction, with
  // the boundary names of the rectangle/box geometry.
  template <int dim>
  void
  make_body(dpana::Body<dim> &body)
  {
    body.set_boundary_names(
      dpana::test::make_named_brick(body.triangulation(),
                                    3,
                                    dim == 2 ? Point<dim>(2, 1) :
                                               Point<dim>(2, 1, 1.5)));
  }

  template <int dim>
  std::vector<std::string>
  free_modes(dpana::Body<dim> &body)
  {
    body.setup();
    std::vector<std::string> d;
    for (const auto &m : body.free_rigid_modes())
      d.push_back(m.description);
    return d;
  }

  // Every free mode must satisfy the homogeneous constraints, and the
  // nodal vectors of the rigid motions must be in the kernel of K.
  template <int dim>
  void
  check_modes_are_admissible_and_rigid(dpana::Body<dim> &body)
  {
    body.assemble();
    const auto &R = body.rigid_mode_vectors();
    for (const auto &m : body.free_rigid_modes())
      {
        const Eigen::VectorXd v = R * m.coefficients;
        for (const auto &line : body.constraints().get_lines())
          {
            double value = v(line.index);
            for (const auto &[j, a] : line.entries)
              value -= a * v(j);
            EXPECT_NEAR(value, 0.0, 1e-12);
          }
      }
    // K v = 0 on the free rows for every free mode v: the condensed matrix
    // is M^T K M on the free rows, and an admissible rigid motion is M v_r
    // with K M v_r = 0.
    Vector<double> v(R.rows()), Kv(R.rows());
    for (const auto &m : body.free_rigid_modes())
      {
        const Eigen::VectorXd vm = R * m.coefficients;
        for (int i = 0; i < R.rows(); ++i)
          v[i] = vm(i);
        body.system_matrix().vmult(Kv, v);
        for (int i = 0; i < R.rows(); ++i)
          if (!body.constraints().is_constrained(i))
            {
              EXPECT_NEAR(Kv[i], 0.0, 1e-8 * body.material().youngs_modulus())
                << "mode " << m.description;
            }
      }
  }
} // namespace



TEST(RigidModes, UnsupportedBody2D)
{
  dpana::Body<2> body;
  make_body(body);
  const auto modes = free_modes(body);
  EXPECT_EQ(modes, (std::vector<std::string>{"x", "y", "rotation"}));
  body.assemble();
  EXPECT_THROW(body.solve(), dpana::InputError);
  try
    {
      body.check_held();
    }
  catch (const dpana::InputError &e)
    {
      EXPECT_EQ(std::string(e.what()),
                "Body 1: not held: rigid motions x, y, rotation are free; "
                "add Dirichlet or symmetry conditions");
    }
  // The factorisation itself refuses the singular matrix.
  dpana::linear_algebra::SparseCholesky cholesky;
  EXPECT_THROW(cholesky.factorize(body.system_matrix(), body.constraints()),
               dpana::linear_algebra::NotPositiveDefiniteError);
}



TEST(RigidModes, UnsupportedBody3D)
{
  dpana::Body<3> body;
  make_body(body);
  EXPECT_EQ(free_modes(body).size(), 6u);
  check_modes_are_admissible_and_rigid(body);
}



TEST(RigidModes, FixedBottomHoldsTheBody)
{
  dpana::Body<2> body2;
  make_body(body2);
  body2.boundary_conditions().fixed.push_back({"bottom", {true, true}, "t"});
  EXPECT_TRUE(free_modes(body2).empty());
  EXPECT_NO_THROW(body2.check_held());

  dpana::Body<3> body3;
  make_body(body3);
  body3.boundary_conditions().fixed.push_back(
    {"bottom", {true, true, true}, "t"});
  EXPECT_TRUE(free_modes(body3).empty());
}



TEST(RigidModes, PartialSupports)
{
  // 2D: bottom held vertically only: the horizontal translation is free.
  dpana::Body<2> a;
  make_body(a);
  a.boundary_conditions().fixed.push_back({"bottom", {false, true}, "t"});
  EXPECT_EQ(free_modes(a), (std::vector<std::string>{"x"}));
  check_modes_are_admissible_and_rigid(a);

  // 2D: two perpendicular symmetry planes hold the body.
  dpana::Body<2> b;
  make_body(b);
  b.boundary_conditions().symmetry = {{"left", "t"}, {"bottom", "t"}};
  EXPECT_TRUE(free_modes(b).empty());

  // 3D: the bottom face y = 0 held normally only (symmetry): the in-plane
  // translations x, z and the rotation about the normal y are free.
  dpana::Body<3> c;
  make_body(c);
  c.boundary_conditions().symmetry = {{"bottom", "t"}};
  EXPECT_EQ(free_modes(c),
            (std::vector<std::string>{"x", "z", "rotation about y"}));
  check_modes_are_admissible_and_rigid(c);

  // 3D: symmetry planes x = 0 and y = 0: the rotation about z is stopped
  // by both planes, the translation along z is free.
  dpana::Body<3> d;
  make_body(d);
  d.boundary_conditions().symmetry = {{"left", "t"}, {"bottom", "t"}};
  EXPECT_EQ(free_modes(d), (std::vector<std::string>{"z"}));
}



// A free motion that is not one of the named ones: only the lowest face of
// the left edge (vertices (0, 0) and (0, 1/3)) is held, in y. Free are the
// translation along x and the rotations about points of the line x = 0;
// after the named x translation is taken out, the remaining free motion is
// reported as a rotation about a point with x = 0.
TEST(RigidModes, RotationAboutAPoint2D)
{
  dpana::Body<2> body;
  make_body(body);
  auto &tria = body.triangulation();
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary() && face->boundary_id() == 0 &&
        face->center()[1] < 1.0 / 3.0)
      face->set_boundary_id(10);
  auto names      = body.boundary_names();
  names["corner"] = 10;
  body.set_boundary_names(names);
  body.boundary_conditions().fixed.push_back({"corner", {false, true}, "t"});
  const auto modes = free_modes(body);
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_EQ(modes[0], "x");
  EXPECT_EQ(modes[1].substr(0, 18), "rotation about (0,");
}



// The rigid motions on their own, from the vertex dofs of a body without
// conditions: the translations are unit vectors, the largest nodal
// displacement of the rotation is 1, all motions are free without
// constraints, and a vertex held in x and y leaves the rotation about that
// vertex.
TEST(RigidModes, NodalVectorsAndAPinnedVertex2D)
{
  dpana::Body<2> body;
  make_body(body);
  body.setup();
  const dpana::RigidModes<2> rigid(body.triangulation(),
                                   body.vertex_dofs(),
                                   body.dof_handler().n_dofs());
  EXPECT_EQ(rigid.names(), (std::vector<std::string>{"x", "y", "rotation"}));

  const auto &R       = rigid.vectors();
  double      largest = 0;
  for (const auto &d : body.vertex_dofs())
    {
      EXPECT_EQ(R(d[0], 0), 1.0);
      EXPECT_EQ(R(d[1], 0), 0.0);
      EXPECT_EQ(R(d[0], 1), 0.0);
      EXPECT_EQ(R(d[1], 1), 1.0);
      largest = std::max(largest, std::hypot(R(d[0], 2), R(d[1], 2)));
    }
  EXPECT_NEAR(largest, 1.0, 1e-14);

  const auto all = rigid.free_modes(AffineConstraints<double>());
  ASSERT_EQ(all.size(), 3u);
  for (unsigned int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(all[k].description, rigid.names()[k]);
      EXPECT_EQ(all[k].coefficients, Eigen::VectorXd::Unit(3, k));
    }

  AffineConstraints<double> pinned;
  const auto               &vertices = body.triangulation().get_vertices();
  for (unsigned int v = 0; v < vertices.size(); ++v)
    if (vertices[v].distance(Point<2>(2, 1)) < 1e-12)
      for (const auto dof : body.vertex_dofs()[v])
        pinned.add_line(dof);
  pinned.close();
  ASSERT_EQ(pinned.n_constraints(), 2u);
  const auto modes = rigid.free_modes(pinned);
  ASSERT_EQ(modes.size(), 1u);
  EXPECT_EQ(modes[0].description, "rotation about (2, 1)");
}
