// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Tests of the sphere fitted about a contact point
// (contact_surface/axial_sphere_fit.h) on faces whose vertices lie exactly on
// a circle, a sphere or a plane: the fit is exact there (its equation
// z = alpha |d|^2 + beta holds at every vertex), so the curvature 1/R and the
// offset are recovered to round-off, which the tests bound by 1e-12
// relative to 1/R.

#include <dpana/contact_surface/axial_sphere_fit.h>

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace
{
  using dpana::contact_surface::AxialSphereFit;
  using dpana::contact_surface::Face;
  using dpana::contact_surface::fit_axial_sphere;

  // The edges between consecutive points of the circle of centre
  // (0, centre_y) and radius R at the angles from -t to t about the
  // direction (0, side) from its centre (side = -1: the lowest points).
  std::vector<Face<2>>
  arc(const double       centre_y,
      const double       R,
      const double       side,
      const double       t,
      const unsigned int n)
  {
    std::vector<Face<2>> faces;
    auto                 point = [&](const unsigned int i) {
      const double phi = -t + 2 * t * i / n;
      return dealii::Point<2>(R * std::sin(phi),
                              centre_y + side * R * std::cos(phi));
    };
    for (unsigned int i = 0; i < n; ++i)
      {
        Face<2> f;
        f.points = {point(i), point(i + 1)};
        faces.push_back(f);
      }
    return faces;
  }

  const dealii::Point<2>     x0(0, 0);
  const dealii::Tensor<1, 2> down({0, -1});
} // namespace



// Body 1 of the Hertz scenes: the disc of radius 40 whose lowest point is
// x0, seen along its outward normal (0, -1): convex, 1/R = 1/40.
TEST(AxialSphereFit, DiscThroughThePoint)
{
  const AxialSphereFit fit =
    fit_axial_sphere(arc(40, 40, -1, 0.4, 16), x0, down, 100);
  ASSERT_TRUE(fit.available);
  EXPECT_NEAR(fit.curvature, 1 / 40., 1e-12 / 40);
  EXPECT_NEAR(fit.offset, 0, 1e-12 * 40);
}



// Body 2 of the cavity scenes: the seat of radius 120 about (0, 120), seen
// along its outward normal (0, 1): concave, 1/R = -1/120.
TEST(AxialSphereFit, Cavity)
{
  const AxialSphereFit fit =
    fit_axial_sphere(arc(120, 120, -1, 0.2, 16), x0, -down, 100);
  ASSERT_TRUE(fit.available);
  EXPECT_NEAR(fit.curvature, -1 / 120., 1e-12 / 120);
}



// A flat block 0.5 below x0 (an initial gap): curvature 0, offset 0.5
// along its outward normal (0, 1) is -0.5.
TEST(AxialSphereFit, PlaneBelowThePoint)
{
  std::vector<Face<2>> faces;
  for (int i = -4; i < 4; ++i)
    {
      Face<2> f;
      f.points = {dealii::Point<2>(i, -0.5), dealii::Point<2>(i + 1, -0.5)};
      faces.push_back(f);
    }
  const AxialSphereFit fit = fit_axial_sphere(faces, x0, -down, 100);
  ASSERT_TRUE(fit.available);
  EXPECT_NEAR(fit.curvature, 0, 1e-12 / 40);
  EXPECT_NEAR(fit.offset, -0.5, 1e-12);
}



// A disc of radius 30 whose lowest point lies 0.2 above x0: the fit
// does not need the surface to pass through x0.
TEST(AxialSphereFit, DiscAboveThePoint)
{
  const AxialSphereFit fit =
    fit_axial_sphere(arc(30.2, 30, -1, 0.5, 20), x0, down, 100);
  ASSERT_TRUE(fit.available);
  EXPECT_NEAR(fit.curvature, 1 / 30., 1e-12 / 30);
}



// Vertices beyond the reach are left out: the arc of radius 40 near x0
// joined by an arc of another circle far away.
TEST(AxialSphereFit, Reach)
{
  auto faces = arc(40, 40, -1, 0.3, 12);
  for (const auto &f : arc(-200, 300, 1, 0.1, 4))
    faces.push_back(f);
  const AxialSphereFit fit = fit_axial_sphere(faces, x0, down, 15);
  ASSERT_TRUE(fit.available);
  EXPECT_NEAR(fit.curvature, 1 / 40., 1e-12 / 40);
}



// The cap of a sphere of radius 40 about its lowest point x0 = 0, in
// triangles of vertices on the sphere.
TEST(AxialSphereFit, SphereCap)
{
  const double         R = 40;
  std::vector<Face<3>> faces;
  auto                 point = [&](const double theta, const double phi) {
    return dealii::Point<3>(R * std::sin(theta) * std::cos(phi),
                            R - R * std::cos(theta),
                            R * std::sin(theta) * std::sin(phi));
  };
  for (unsigned int i = 0; i < 4; ++i)
    for (unsigned int j = 0; j < 8; ++j)
      {
        const double t0 = 0.1 * i, t1 = 0.1 * (i + 1);
        const double p0 = 0.785 * j, p1 = 0.785 * (j + 1);
        Face<3>      f;
        f.points = {point(t0, p0), point(t1, p0), point(t1, p1)};
        faces.push_back(f);
      }
  const AxialSphereFit fit = fit_axial_sphere(faces,
                                              dealii::Point<3>(),
                                              dealii::Tensor<1, 3>({0, -1, 0}),
                                              100);
  ASSERT_TRUE(fit.available);
  EXPECT_NEAR(fit.curvature, 1 / R, 1e-12 / R);
  EXPECT_NEAR(fit.offset, 0, 1e-12 * R);
}



// All vertices at one distance from x0 do not determine the fit.
TEST(AxialSphereFit, UndeterminedWithoutDistinctDistances)
{
  Face<2> f;
  f.points = {dealii::Point<2>(-1, 0), dealii::Point<2>(1, 0)};
  EXPECT_FALSE(
    fit_axial_sphere(std::vector<Face<2>>{f}, x0, down, 10).available);
  EXPECT_FALSE(
    fit_axial_sphere(std::vector<Face<2>>{}, x0, down, 10).available);
}
