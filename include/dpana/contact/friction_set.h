// Geometry of the friction set of one contact element.
//
// Every contact element j carries the set
// @f[
//   K_j = \{ (N, T) : N \le 0,\ \gamma(T) \le -\mu_j N \},
// @f]
// where gamma is the gauge of a unit tangential set P:
//   - 2D interval:  P = [-1, 1],                gamma(T) = |T|,
//   - 3D disc:      P = unit disc,              gamma(T) = ||T||,
//   - 3D polygon:   P = regular s-gon circumscribed about the unit disc, with
//                   outward facet normals n_i = (cos a_i, sin a_i),
//                   a_i = 2 (i-1) pi / s, gamma(T) = max_i n_i . T, and
//                   vertices v_i = (cos(a_i + pi/s), sin(a_i + pi/s)) /
//                   cos(pi/s) (between facets i and i+1).
// Its support function sigma(y) = max_{T in P} y . T is |y|, ||y|| and
// max_i v_i . y respectively. The support function is what the dissipation
// (and thus the modified velocity of the natural-map residual) needs.
//
// The class collects the small exact local operations that all the solvers
// share: Euclidean projection onto K_j (for the residual), Euclidean
// projection onto the tangential set c P with its derivative (for the
// semismooth Newton solver), and the exact minimiser of a strictly convex
// quadratic over c P (the local step of projected Gauss-Seidel).
#ifndef dpana_contact_friction_set_h
#define dpana_contact_friction_set_h

#include <dpana/contact/problem.h>

#include <Eigen/Dense>

#include <vector>

namespace dpana
{
  namespace contact
  {
    class FrictionSet
    {
    public:
      // Build the set of the problem (its dim, cone model and polygon sides).
      explicit FrictionSet(const ContactProblem &problem);

      FrictionSet(const unsigned int dim,
                  const ConeModel    cone,
                  const unsigned int polygon_sides);

      // Number of tangential components, d - 1.
      unsigned int
      tangential_dim() const
      {
        return dim - 1;
      }

      ConeModel
      model() const
      {
        return cone;
      }

      // Gauge gamma(T) of P (T has d - 1 entries).
      double
      gauge(const double *T) const;

      // Support function sigma(y) of P (y has d - 1 entries).
      double
      support(const double *y) const;

      // Euclidean projection of x = (N, T) onto K (friction coefficient mu),
      // written to p (both d entries; x and p may not alias).
      void
      project_cone(const double mu, const double *x, double *p) const;

      // Euclidean projection of y onto c P, c >= 0, written to p. Returns the
      // region of the result, used by the derivative:
      //   -1 interior, 0..s-1 facet i (polygon) or the boundary (disc,
      //   interval: 0), s..2s-1 vertex i-s (polygon).
      int
      project_tangential(const double c, const double *y, double *p) const;

      // Derivative J (row-major (d-1)x(d-1)) of the projection onto c P at y,
      // given the region returned by project_tangential (an element of the
      // generalised Jacobian at kinks).
      void
      projection_derivative(const double  c,
                            const double *y,
                            const int     region,
                            double       *J) const;

      // The same derivative in spectral form, J = sum_i lambda_i v_i v_i^T
      // (i < d - 1), with orthonormal v_i (written one after the other to
      // V, d - 1 entries each) and eigenvalues lambda_i in [0, 1]: the
      // derivative of a projection onto a convex set is symmetric. The
      // eigenvectors are the natural axes of the region (the Cartesian
      // axes inside, the normal and the tangent of the circle or of a
      // facet), so that eigenvalues 0 and 1 come out exactly, without an
      // eigenvalue computation and its round-off. The semismooth Newton
      // step of friction_qp.h uses this form to reduce its linear system to
      // a symmetric positive definite one.
      void
      projection_derivative_spectral(const double  c,
                                     const double *y,
                                     const int     region,
                                     double       *lambda,
                                     double       *V) const;

      // Derivative (d-1 entries) of the projection onto c P at y with
      // respect to the radius c: 0 inside, y/|y| on the circle, sign(y) at an
      // interval end, n_i on facet i, v_i at vertex i.
      void
      projection_radius_derivative(const double  c,
                                   const double *y,
                                   const int     region,
                                   double       *dc) const;

      // Exact minimiser of 1/2 T^T W T + g^T T over c P, W symmetric positive
      // definite ((d-1)x(d-1), row-major). Interval: clipping of the
      // unconstrained minimiser. Disc: if the unconstrained minimiser lies
      // outside, the KKT system (W + lambda I) T = -g, ||T|| = c is solved for
      // lambda > 0 by a safeguarded Newton iteration on the secular equation
      // 1/||T(lambda)|| = 1/c (monotone, converges to round-off). Polygon: the
      // minimiser is the unconstrained one, or lies on one facet line, or on
      // one vertex; all feasible candidates are formed exactly and the one of
      // least objective is kept (O(s) work).
      void
      minimise(const double  c,
               const double *W,
               const double *g,
               double       *T) const;

      // Outward facet normals and vertices of the unit polygon (empty unless
      // the model is polygon).
      const std::vector<Eigen::Vector2d> &
      normals() const
      {
        return facet_normals;
      }
      const std::vector<Eigen::Vector2d> &
      vertices() const
      {
        return polygon_vertices;
      }

    private:
      // The cases of project_cone() and minimise() (see friction_set.cc).
      void
      project_round_cone(const double mu, const double *x, double *p) const;

      void
      project_polygon_cone(const double mu, const double *x, double *p) const;

      void
      minimise_disc(const double  c,
                    const double *W,
                    const double *g,
                    double       *T) const;

      void
      minimise_polygon(const double  c,
                       const double *W,
                       const double *g,
                       const double *inverse,
                       const double *T0,
                       double       *T) const;

      unsigned int                 dim;
      ConeModel                    cone;
      unsigned int                 sides;
      std::vector<Eigen::Vector2d> facet_normals;
      std::vector<Eigen::Vector2d> polygon_vertices;
    };
  } // namespace contact
} // namespace dpana

#endif
