#include <dpana/contact/friction_set.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace dpana
{
  namespace contact
  {
    FrictionSet::FrictionSet(const ContactProblem &problem)
      : FrictionSet(problem.dim, problem.cone, problem.polygon_sides)
    {
    }



    FrictionSet::FrictionSet(const unsigned int dim_,
                             const ConeModel    cone_,
                             const unsigned int polygon_sides)
      : dim(dim_)
      , cone(cone_)
      , sides(cone_ == ConeModel::polygon ? polygon_sides : 0)
    {
      if (dim != 2 && dim != 3)
        throw std::invalid_argument("FrictionSet: dim must be 2 or 3");
      if (cone == ConeModel::polygon)
        {
          if (sides < 3)
            throw std::invalid_argument(
              "FrictionSet: polygon_sides must be >= 3");
          // Facet i has the outward unit normal at angle a_i; the vertex
          // between facets i and i+1 sits at angle a_i + pi/s, at distance
          // 1/cos(pi/s) from the centre (the polygon circumscribes the unit
          // disc).
          const double h = M_PI / sides;
          for (unsigned int i = 0; i < sides; ++i)
            {
              const double a = 2.0 * i * h;
              facet_normals.emplace_back(std::cos(a), std::sin(a));
              polygon_vertices.emplace_back(std::cos(a + h) / std::cos(h),
                                            std::sin(a + h) / std::cos(h));
            }
        }
    }



    double
    FrictionSet::gauge(const double *T) const
    {
      if (dim == 2)
        return std::abs(T[0]);
      if (cone == ConeModel::disc)
        return std::hypot(T[0], T[1]);
      double g = -std::numeric_limits<double>::max();
      for (const auto &n : facet_normals)
        g = std::max(g, n[0] * T[0] + n[1] * T[1]);
      return g;
    }



    double
    FrictionSet::support(const double *y) const
    {
      if (dim == 2)
        return std::abs(y[0]);
      if (cone == ConeModel::disc)
        return std::hypot(y[0], y[1]);
      double s = -std::numeric_limits<double>::max();
      for (const auto &v : polygon_vertices)
        s = std::max(s, v[0] * y[0] + v[1] * y[1]);
      return s;
    }



    // @sect4{Projection onto the cone K}
    //
    // For the interval and the disc, K is (after the sign change p = -N) the
    // second order cone {||T|| <= mu p}, with the classical closed-form
    // projection. For mu = 0 the set degenerates to the half line
    // {T = 0, N <= 0}. For the polygon, K is a polyhedral cone with facets
    // a_i . x <= 0, a_i = (mu, n_i), and edges along e_i = (-1, mu v_i). The
    // projection of an outside point lies either on the plane of a facet
    // (and then inside that facet, which for a regular polygon only the two
    // neighbouring facets can cut off), on an edge ray, or at the apex. Each
    // candidate is feasible by construction, so the closest candidate is the
    // projection.
    void
    FrictionSet::project_cone(const double mu, const double *x, double *p) const
    {
      const unsigned int m = dim - 1;
      if (mu == 0.0)
        {
          p[0] = std::min(x[0], 0.0);
          for (unsigned int k = 0; k < m; ++k)
            p[1 + k] = 0.0;
          return;
        }
      if (cone == ConeModel::polygon)
        project_polygon_cone(mu, x, p);
      else
        project_round_cone(mu, x, p);
    }



    // Interval and disc: inside, in the polar cone (projection: the apex),
    // or onto the boundary ray through x.
    void
    FrictionSet::project_round_cone(const double  mu,
                                    const double *x,
                                    double       *p) const
    {
      const unsigned int m  = dim - 1;
      const double       pn = -x[0];
      const double       t = (m == 1) ? std::abs(x[1]) : std::hypot(x[1], x[2]);
      if (t <= mu * pn)
        {
          for (unsigned int k = 0; k <= m; ++k)
            p[k] = x[k];
        }
      else if (mu * t <= -pn)
        {
          for (unsigned int k = 0; k <= m; ++k)
            p[k] = 0.0;
        }
      else
        {
          const double a = (pn + mu * t) / (1.0 + mu * mu);
          p[0]           = -a;
          for (unsigned int k = 0; k < m; ++k)
            p[1 + k] = mu * a * x[1 + k] / t;
        }
    }



    // Polygon: the candidates of the comment above.
    void
    FrictionSet::project_polygon_cone(const double  mu,
                                      const double *x,
                                      double       *p) const
    {
      const unsigned int s        = sides;
      auto               violated = [&](const unsigned int i, const double *z) {
        const Eigen::Vector2d &n = facet_normals[i];
        return n[0] * z[1] + n[1] * z[2] + mu * z[0];
      };
      double worst = -std::numeric_limits<double>::max();
      for (unsigned int i = 0; i < s; ++i)
        worst = std::max(worst, violated(i, x));
      if (worst <= 0.0)
        {
          p[0] = x[0];
          p[1] = x[1];
          p[2] = x[2];
          return;
        }
      const double scale = std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2]);
      const double tol   = 1e-14 * scale;
      double       best  = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
      p[0] = p[1] = p[2] = 0.0; // the apex
      const double aa    = 1.0 + mu * mu;
      for (unsigned int i = 0; i < s; ++i)
        {
          // Facet plane.
          const double v = violated(i, x);
          if (v > 0.0)
            {
              const Eigen::Vector2d &n    = facet_normals[i];
              const double           f    = v / aa;
              const double           z[3] = {x[0] - f * mu,
                                             x[1] - f * n[0],
                                             x[2] - f * n[1]};
              if (violated((i + s - 1) % s, z) <= tol &&
                  violated((i + 1) % s, z) <= tol)
                {
                  const double dist = f * f * aa;
                  if (dist < best)
                    {
                      best = dist;
                      p[0] = z[0];
                      p[1] = z[1];
                      p[2] = z[2];
                    }
                }
            }
          // Edge ray between facets i and i+1.
          const Eigen::Vector2d &w  = polygon_vertices[i];
          const double           e0 = -1.0, e1 = mu * w[0], e2 = mu * w[1];
          const double           ee = e0 * e0 + e1 * e1 + e2 * e2;
          const double           xe = x[0] * e0 + x[1] * e1 + x[2] * e2;
          if (xe > 0.0)
            {
              const double t    = xe / ee;
              const double d0   = x[0] - t * e0;
              const double d1   = x[1] - t * e1;
              const double d2   = x[2] - t * e2;
              const double dist = d0 * d0 + d1 * d1 + d2 * d2;
              if (dist < best)
                {
                  best = dist;
                  p[0] = t * e0;
                  p[1] = t * e1;
                  p[2] = t * e2;
                }
            }
        }
    }



    // @sect4{Projection onto the tangential set c P}
    int
    FrictionSet::project_tangential(const double  c,
                                    const double *y,
                                    double       *p) const
    {
      if (dim == 2)
        {
          if (std::abs(y[0]) < c)
            {
              p[0] = y[0];
              return -1;
            }
          p[0] = std::clamp(y[0], -c, c);
          return 0;
        }
      if (cone == ConeModel::disc)
        {
          const double t = std::hypot(y[0], y[1]);
          if (t < c)
            {
              p[0] = y[0];
              p[1] = y[1];
              return -1;
            }
          if (t == 0.0)
            {
              p[0] = p[1] = 0.0;
              return 0;
            }
          p[0] = c * y[0] / t;
          p[1] = c * y[1] / t;
          return 0;
        }

      const int s = static_cast<int>(sides);
      if (c > 0.0 && gauge(y) < c)
        {
          p[0] = y[0];
          p[1] = y[1];
          return -1;
        }
      const double tol    = 1e-14 * (std::abs(y[0]) + std::abs(y[1]) + c);
      double       best   = std::numeric_limits<double>::max();
      int          region = s;
      for (int i = 0; i < s; ++i)
        {
          const Eigen::Vector2d &n = facet_normals[i];
          const double           v = n[0] * y[0] + n[1] * y[1] - c;
          if (c > 0.0 && v > 0.0)
            {
              const double           z0 = y[0] - v * n[0];
              const double           z1 = y[1] - v * n[1];
              const Eigen::Vector2d &a  = facet_normals[(i + s - 1) % s];
              const Eigen::Vector2d &b  = facet_normals[(i + 1) % s];
              if (a[0] * z0 + a[1] * z1 <= c + tol &&
                  b[0] * z0 + b[1] * z1 <= c + tol && v * v < best)
                {
                  best   = v * v;
                  p[0]   = z0;
                  p[1]   = z1;
                  region = i;
                }
            }
          const Eigen::Vector2d &w    = polygon_vertices[i];
          const double           d0   = y[0] - c * w[0];
          const double           d1   = y[1] - c * w[1];
          const double           dist = d0 * d0 + d1 * d1;
          if (dist < best)
            {
              best   = dist;
              p[0]   = c * w[0];
              p[1]   = c * w[1];
              region = s + i;
            }
        }
      return region;
    }



    void
    FrictionSet::projection_derivative(const double  c,
                                       const double *y,
                                       const int     region,
                                       double       *J) const
    {
      if (dim == 2)
        {
          J[0] = (region < 0) ? 1.0 : 0.0;
          return;
        }
      if (region < 0)
        {
          J[0] = 1.0;
          J[1] = 0.0;
          J[2] = 0.0;
          J[3] = 1.0;
          return;
        }
      if (cone == ConeModel::disc)
        {
          const double t = std::hypot(y[0], y[1]);
          if (t == 0.0 || c == 0.0)
            {
              J[0] = J[1] = J[2] = J[3] = 0.0;
              return;
            }
          // d/dy (c y/|y|) = (c/|y|) (I - y y^T / |y|^2).
          const double f  = c / t;
          const double u0 = y[0] / t, u1 = y[1] / t;
          J[0] = f * (1.0 - u0 * u0);
          J[1] = -f * u0 * u1;
          J[2] = J[1];
          J[3] = f * (1.0 - u1 * u1);
          return;
        }
      if (region < static_cast<int>(sides))
        {
          // Projection onto the facet line: I - n n^T.
          const Eigen::Vector2d &n = facet_normals[region];
          J[0]                     = 1.0 - n[0] * n[0];
          J[1]                     = -n[0] * n[1];
          J[2]                     = J[1];
          J[3]                     = 1.0 - n[1] * n[1];
          return;
        }
      J[0] = J[1] = J[2] = J[3] = 0.0;
    }



    void
    FrictionSet::projection_derivative_spectral(const double  c,
                                                const double *y,
                                                const int     region,
                                                double       *lambda,
                                                double       *V) const
    {
      if (dim == 2)
        {
          lambda[0] = (region < 0) ? 1.0 : 0.0;
          V[0]      = 1.0;
          return;
        }
      // Cartesian axes by default (interior: identity; vertex, zero radius:
      // zero).
      V[0] = 1.0;
      V[1] = 0.0;
      V[2] = 0.0;
      V[3] = 1.0;
      if (region < 0)
        {
          lambda[0] = lambda[1] = 1.0;
          return;
        }
      lambda[0] = lambda[1] = 0.0;
      if (cone == ConeModel::disc)
        {
          const double t = std::hypot(y[0], y[1]);
          if (t == 0.0 || c == 0.0)
            return;
          // (c/|y|) (I - y y^T/|y|^2): c/|y| along the tangent of the
          // circle, 0 along the radius y/|y|.
          const double u0 = y[0] / t, u1 = y[1] / t;
          lambda[0] = c / t;
          V[0]      = -u1;
          V[1]      = u0;
          V[2]      = u0;
          V[3]      = u1;
          return;
        }
      if (region < static_cast<int>(sides))
        {
          // I - n n^T: 1 along the facet, 0 along its normal n.
          const Eigen::Vector2d &n = facet_normals[region];
          lambda[0]                = 1.0;
          V[0]                     = -n[1];
          V[1]                     = n[0];
          V[2]                     = n[0];
          V[3]                     = n[1];
        }
    }



    void
    FrictionSet::projection_radius_derivative(const double  c,
                                              const double *y,
                                              const int     region,
                                              double       *dc) const
    {
      (void)c;
      const unsigned int m = dim - 1;
      for (unsigned int a = 0; a < m; ++a)
        dc[a] = 0.0;
      if (region < 0)
        return;
      if (dim == 2)
        {
          dc[0] = (y[0] > 0.0) ? 1.0 : (y[0] < 0.0 ? -1.0 : 0.0);
          return;
        }
      if (cone == ConeModel::disc)
        {
          const double t = std::hypot(y[0], y[1]);
          if (t > 0.0)
            {
              dc[0] = y[0] / t;
              dc[1] = y[1] / t;
            }
          return;
        }
      const int              s = static_cast<int>(sides);
      const Eigen::Vector2d &v =
        (region < s) ? facet_normals[region] : polygon_vertices[region - s];
      dc[0] = v[0];
      dc[1] = v[1];
    }



    // @sect4{Exact local minimisation over c P}
    void
    FrictionSet::minimise(const double  c,
                          const double *W,
                          const double *g,
                          double       *T) const
    {
      if (dim == 2)
        {
          T[0] = std::clamp(-g[0] / W[0], -c, c);
          return;
        }
      if (c <= 0.0)
        {
          T[0] = T[1] = 0.0;
          return;
        }
      // Unconstrained minimiser T0 = -W^{-1} g.
      const double det = W[0] * W[3] - W[1] * W[2];
      const double i00 = W[3] / det, i01 = -W[1] / det, i11 = W[0] / det;
      const double t0   = -(i00 * g[0] + i01 * g[1]);
      const double t1   = -(i01 * g[0] + i11 * g[1]);
      const double y[2] = {t0, t1};
      if (gauge(y) <= c)
        {
          T[0] = t0;
          T[1] = t1;
          return;
        }

      const double inverse[3] = {i00, i01, i11}, T0[2] = {t0, t1};
      if (cone == ConeModel::disc)
        minimise_disc(c, W, g, T);
      else
        minimise_polygon(c, W, g, inverse, T0, T);
    }



    // Disc: the secular equation 1/||T(lambda)|| = 1/c in the eigenbasis of
    // W, by a safeguarded Newton iteration.
    void
    FrictionSet::minimise_disc(const double  c,
                               const double *W,
                               const double *g,
                               double       *T) const
    {
      // Secular equation in the eigenbasis of W.
      Eigen::Matrix2d M;
      M << W[0], W[1], W[2], W[3];
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig;
      eig.computeDirect(M);
      const Eigen::Vector2d w = eig.eigenvalues();
      const Eigen::Vector2d gt =
        eig.eigenvectors().transpose() * Eigen::Vector2d(g[0], g[1]);
      double lambda = 0.0;
      for (unsigned int it = 0; it < 200; ++it)
        {
          const double a0  = gt[0] / (w[0] + lambda);
          const double a1  = gt[1] / (w[1] + lambda);
          const double n2  = a0 * a0 + a1 * a1;
          const double nt  = std::sqrt(n2);
          const double phi = 1.0 / nt - 1.0 / c;
          const double dphi =
            (a0 * a0 / (w[0] + lambda) + a1 * a1 / (w[1] + lambda)) / (n2 * nt);
          const double step = -phi / dphi;
          lambda += step;
          if (lambda < 0.0)
            lambda = 0.0;
          if (std::abs(step) <= 1e-15 * (lambda + w[0] + w[1]))
            break;
        }
      const Eigen::Vector2d Tt(-gt[0] / (w[0] + lambda),
                               -gt[1] / (w[1] + lambda));
      Eigen::Vector2d       Tv = eig.eigenvectors() * Tt;
      Tv *= c / Tv.norm();
      T[0] = Tv[0];
      T[1] = Tv[1];
    }



    // Polygon: facet-line minimisers and vertices. inverse: the entries
    // (0,0), (0,1), (1,1) of W^{-1}; T0 = -W^{-1} g.
    void
    FrictionSet::minimise_polygon(const double  c,
                                  const double *W,
                                  const double *g,
                                  const double *inverse,
                                  const double *T0,
                                  double       *T) const
    {
      const double i00 = inverse[0], i01 = inverse[1], i11 = inverse[2];
      const double t0 = T0[0], t1 = T0[1];
      const int    s         = static_cast<int>(sides);
      const double tol       = 1e-13 * c;
      auto         objective = [&](const double a0, const double a1) {
        return 0.5 *
                 (a0 * (W[0] * a0 + W[1] * a1) + a1 * (W[2] * a0 + W[3] * a1)) +
               g[0] * a0 + g[1] * a1;
      };
      double best = std::numeric_limits<double>::max();
      for (int i = 0; i < s; ++i)
        {
          const Eigen::Vector2d &n  = facet_normals[i];
          const double           k0 = i00 * n[0] + i01 * n[1];
          const double           k1 = i01 * n[0] + i11 * n[1];
          // T = T0 - lambda W^{-1} n with n . T = c.
          const double lambda =
            (n[0] * t0 + n[1] * t1 - c) / (n[0] * k0 + n[1] * k1);
          const double           z0 = t0 - lambda * k0;
          const double           z1 = t1 - lambda * k1;
          const Eigen::Vector2d &a  = facet_normals[(i + s - 1) % s];
          const Eigen::Vector2d &b  = facet_normals[(i + 1) % s];
          if (a[0] * z0 + a[1] * z1 <= c + tol &&
              b[0] * z0 + b[1] * z1 <= c + tol)
            {
              const double f = objective(z0, z1);
              if (f < best)
                {
                  best = f;
                  T[0] = z0;
                  T[1] = z1;
                }
            }
          const Eigen::Vector2d &v = polygon_vertices[i];
          const double           f = objective(c * v[0], c * v[1]);
          if (f < best)
            {
              best = f;
              T[0] = c * v[0];
              T[1] = c * v[1];
            }
        }
    }
  } // namespace contact
} // namespace dpana
