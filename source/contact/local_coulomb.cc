#include <dpana/contact/local_coulomb.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dpana
{
  namespace contact
  {
    namespace
    {
      // Local natural-map residual (residual.h with rho = d / tr W).
      double
      local_residual(const FrictionSet &set,
                     const double       mu,
                     const double      *W,
                     const double      *q,
                     const double      *r)
      {
        const unsigned int d    = set.tangential_dim() + 1;
        double             u[3] = {0.0, 0.0, 0.0}, x[3], p[3], tr = 0.0;
        for (unsigned int a = 0; a < d; ++a)
          {
            u[a] = q[a];
            for (unsigned int b = 0; b < d; ++b)
              u[a] += W[d * a + b] * r[b];
            tr += W[d * a + a];
          }
        const double rho        = d / tr;
        double       minus_u[2] = {-u[1], d == 3 ? -u[2] : 0.0};
        x[0] = r[0] - rho * (u[0] - mu * set.support(minus_u));
        for (unsigned int a = 1; a < d; ++a)
          x[a] = r[a] - rho * u[a];
        set.project_cone(mu, x, p);
        double s = 0.0;
        for (unsigned int a = 0; a < d; ++a)
          s += (r[a] - p[a]) * (r[a] - p[a]);
        return std::sqrt(s);
      }



      // Keeps the best candidate by local residual (used only as fallback).
      struct Best
      {
        double value = std::numeric_limits<double>::max();
        double r[3]  = {0, 0, 0};
        void
        offer(const FrictionSet &set,
              const double       mu,
              const double      *W,
              const double      *q,
              const double      *candidate)
        {
          if (!std::isfinite(candidate[0]))
            return;
          const double v = local_residual(set, mu, W, q, candidate);
          if (v < value)
            {
              value = v;
              std::copy(candidate, candidate + 3, r);
            }
        }
      };



      // 3D disc slip: data of the direction equation at angle t.
      struct DiscSlip
      {
        const double *W, *q;
        double        mu;
        // Returns false if the normal equation has no positive pressure.
        bool
        evaluate(const double t,
                 double      &f,
                 double      &df,
                 double      &along,
                 double      &p) const
        {
          const double c = std::cos(t), s = std::sin(t);
          const double den = W[0] - mu * (W[1] * c + W[2] * s);
          if (!(den > 0.0) || !(q[0] > 0.0))
            return false;
          p                 = q[0] / den;
          const double dden = -mu * (-W[1] * s + W[2] * c);
          const double dp   = -q[0] * dden / (den * den);
          const double a0   = -W[3] + mu * (W[4] * c + W[5] * s);
          const double a1   = -W[6] + mu * (W[7] * c + W[8] * s);
          const double da0  = mu * (-W[4] * s + W[5] * c);
          const double da1  = mu * (-W[7] * s + W[8] * c);
          const double u0   = p * a0 + q[1];
          const double u1   = p * a1 + q[2];
          const double du0  = dp * a0 + p * da0;
          const double du1  = dp * a1 + p * da1;
          f                 = -s * u0 + c * u1;
          df                = -(c * u0 + s * u1) + (-s * du0 + c * du1);
          along             = c * u0 + s * u1;
          return true;
        }
      };



      // The local problem of one element (see local_coulomb.h) and the cases
      // of its solution; solve() tries them in the order separated, stick,
      // slip.
      class LocalCoulomb
      {
      public:
        LocalCoulomb(const FrictionSet &set,
                     const double       mu,
                     const double      *W,
                     const double      *q);

        int
        solve(double *r, double &hint);

      private:
        // r = -W^{-1} q, written to stick.
        void
        form_stick();

        // Is the stick candidate inside the friction set?
        bool
        stick_admissible() const;

        // Slip cases; each returns true with r (and hint) set when one is
        // admissible, and offers its candidates to best.
        bool
        slip_2d(double *r, double &hint);

        bool
        slip_polygon(double *r, double &hint);

        bool
        slip_polygon_facet(const int i, double *r, double &hint);

        bool
        slip_polygon_vertex(const int i, double *r, double &hint);

        bool
        slip_disc(double *r, double &hint);

        // Is the disc slip at angle t admissible? (The candidate is offered
        // to best.)
        bool
        accept_disc_slip(const double t, double *r, double &hint);

        // Newton iteration on the slip direction from angle t0; false if it
        // breaks down. The end point is written to t.
        bool
        disc_newton(const double t0, double &t) const;

        // Bisection of a sign change of the direction equation on [a, b]
        // with f(a) = fa; returns the midpoint of the final bracket.
        double
        disc_bisection(double a, double b, double fa) const;

        const FrictionSet      &set;
        const double            mu;
        const double           *W, *q;
        const unsigned int      d;
        const double            qscale;
        static constexpr double tol      = 1e-13;
        double                  stick[3] = {0, 0, 0};
        Best                    best;
        DiscSlip                disc;
      };



      LocalCoulomb::LocalCoulomb(const FrictionSet &set,
                                 const double       mu,
                                 const double      *W,
                                 const double      *q)
        : set(set)
        , mu(mu)
        , W(W)
        , q(q)
        , d(set.tangential_dim() + 1)
        , qscale(std::abs(q[0]) + std::abs(q[1]) +
                 (d == 3 ? std::abs(q[2]) : 0.0))
        , disc{W, q, mu}
      {
      }



      void
      LocalCoulomb::form_stick()
      {
        if (d == 2)
          {
            const double det = W[0] * W[3] - W[1] * W[2];
            stick[0]         = -(W[3] * q[0] - W[1] * q[1]) / det;
            stick[1]         = -(-W[2] * q[0] + W[0] * q[1]) / det;
          }
        else
          {
            const Eigen::Matrix3d Wm =
              Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(W);
            const Eigen::Vector3d x =
              -Wm.llt().solve(Eigen::Map<const Eigen::Vector3d>(q));
            stick[0] = x[0];
            stick[1] = x[1];
            stick[2] = x[2];
          }
      }



      bool
      LocalCoulomb::stick_admissible() const
      {
        return stick[0] <= 0.0 && set.gauge(stick + 1) <=
                                    -mu * stick[0] + tol * (std::abs(stick[0]) +
                                                            std::abs(stick[1]) +
                                                            std::abs(stick[2]));
      }



      // 2D: slip forward / backward, T = -s mu N; the hint orders the two.
      bool
      LocalCoulomb::slip_2d(double *r, double &hint)
      {
        const double first = (hint < 0.0) ? -1.0 : 1.0;
        for (const double s : {first, -first})
          {
            const double den = W[0] - s * mu * W[1];
            double       c[3];
            c[0]            = -q[0] / den;
            c[1]            = -s * mu * c[0];
            c[2]            = 0.0;
            const double uT = W[2] * c[0] + W[3] * c[1] + q[1];
            if (den > 0.0 && c[0] <= 0.0 &&
                s * uT <= tol * (std::abs(W[2] * c[0]) + std::abs(q[1]) +
                                 std::abs(W[3] * c[1])))
              {
                r[0] = c[0];
                r[1] = c[1];
                hint = s;
                return true;
              }
            best.offer(set, mu, W, q, c);
          }
        return false;
      }



      // 3D polygon: slip on a facet or at a vertex, starting from the hint.
      bool
      LocalCoulomb::slip_polygon(double *r, double &hint)
      {
        const int s     = static_cast<int>(set.normals().size());
        int       start = static_cast<int>(hint);
        if (start < 0 || start >= 2 * s)
          start = 0;
        start %= s;
        for (int k = 0; k < s; ++k)
          {
            const int i = (start + k) % s;
            if (slip_polygon_facet(i, r, hint) ||
                slip_polygon_vertex(i, r, hint))
              return true;
          }
        return false;
      }



      // Facet i: u_N = 0, u_T = -lambda n_i, n_i . T = -mu N.
      bool
      LocalCoulomb::slip_polygon_facet(const int i, double *r, double &hint)
      {
        const auto            &normals = set.normals();
        const int              s       = static_cast<int>(normals.size());
        const Eigen::Vector2d &n       = normals[i];
        Eigen::Matrix4d        K;
        K << W[0], W[1], W[2], 0.0, W[3], W[4], W[5], n[0], W[6], W[7], W[8],
          n[1], mu, n[0], n[1], 0.0;
        const Eigen::Vector4d x =
          K.partialPivLu().solve(Eigen::Vector4d(-q[0], -q[1], -q[2], 0));
        const double           c[3] = {x[0], x[1], x[2]};
        const double           cap  = -mu * x[0];
        const double           tl   = tol * (cap + qscale / W[0]);
        const Eigen::Vector2d &na   = normals[(i + s - 1) % s];
        const Eigen::Vector2d &nb   = normals[(i + 1) % s];
        if (x[0] <= 0.0 && x[3] >= -tol * qscale &&
            na[0] * x[1] + na[1] * x[2] <= cap + tl &&
            nb[0] * x[1] + nb[1] * x[2] <= cap + tl)
          {
            std::copy(c, c + 3, r);
            hint = i;
            return true;
          }
        best.offer(set, mu, W, q, c);
        return false;
      }



      // Vertex i (between facets i and i+1): T = -mu N v_i, u_N = 0, and
      // -u_T in the cone of n_i and n_{i+1}.
      bool
      LocalCoulomb::slip_polygon_vertex(const int i, double *r, double &hint)
      {
        const auto            &normals = set.normals();
        const int              s       = static_cast<int>(normals.size());
        const Eigen::Vector2d &v       = set.vertices()[i];
        const double           den  = W[0] - mu * (W[1] * v[0] + W[2] * v[1]);
        const double           N    = -q[0] / den;
        const double           c[3] = {N, -mu * N * v[0], -mu * N * v[1]};
        if (den > 0.0 && N <= 0.0)
          {
            const Eigen::Matrix3d Wm =
              Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(W);
            const Eigen::Vector3d u = Wm * Eigen::Vector3d(c[0], c[1], c[2]) +
                                      Eigen::Vector3d(q[0], q[1], q[2]);
            const Eigen::Vector2d &n  = normals[i];
            const Eigen::Vector2d &nb = normals[(i + 1) % s];
            Eigen::Matrix2d        B;
            B << n[0], nb[0], n[1], nb[1];
            const Eigen::Vector2d ab =
              B.inverse() * Eigen::Vector2d(-u[1], -u[2]);
            const double tl = tol * (std::abs(u[1]) + std::abs(u[2]) + qscale);
            if (ab[0] >= -tl && ab[1] >= -tl)
              {
                std::copy(c, c + 3, r);
                hint = s + i;
                return true;
              }
          }
        best.offer(set, mu, W, q, c);
        return false;
      }



      bool
      LocalCoulomb::accept_disc_slip(const double t, double *r, double &hint)
      {
        double f, df, along, p;
        if (!disc.evaluate(t, f, df, along, p))
          return false;
        const double c[3] = {-p, mu * p * std::cos(t), mu * p * std::sin(t)};
        best.offer(set, mu, W, q, c);
        const double uscale = qscale + std::abs(W[0] * p);
        if (along <= tol * uscale && std::abs(f) <= 1e-10 * uscale)
          {
            std::copy(c, c + 3, r);
            hint = t;
            return true;
          }
        return false;
      }



      bool
      LocalCoulomb::disc_newton(const double t0, double &t) const
      {
        t = t0;
        for (unsigned int it = 0; it < 30; ++it)
          {
            double f, df, along, p;
            if (!disc.evaluate(t, f, df, along, p) || df == 0.0)
              return false;
            const double step = f / df;
            t -= step;
            if (std::abs(step) < 1e-15)
              break;
          }
        return true;
      }



      double
      LocalCoulomb::disc_bisection(double a, double b, double fa) const
      {
        for (unsigned int it = 0; it < 80 && b - a > 1e-16; ++it)
          {
            const double c = 0.5 * (a + b);
            double       fc, df, along, p;
            if (!disc.evaluate(c, fc, df, along, p))
              break;
            if ((fc > 0.0) == (fa > 0.0))
              {
                a  = c;
                fa = fc;
              }
            else
              b = c;
          }
        return 0.5 * (a + b);
      }



      // 3D disc: the slip direction t solves f(t) = 0 with e(t) . u_T <= 0.
      // Newton from the hint and from the stick trial direction; then f is
      // sampled at 64 angles and every sign change is bisected.
      bool
      LocalCoulomb::slip_disc(double *r, double &hint)
      {
        const double starts[2] = {hint, std::atan2(stick[2], stick[1])};
        for (const double t0 : starts)
          {
            double t;
            if (disc_newton(t0, t) && accept_disc_slip(t, r, hint))
              return true;
          }
        const unsigned int K = 64;
        double             ft[K + 1];
        bool               valid[K + 1];
        for (unsigned int k = 0; k <= K; ++k)
          {
            double df, along, p;
            valid[k] = disc.evaluate(2.0 * M_PI * k / K, ft[k], df, along, p);
          }
        for (unsigned int k = 0; k < K; ++k)
          {
            if (!valid[k] || !valid[k + 1] ||
                (ft[k] > 0.0) == (ft[k + 1] > 0.0))
              continue;
            const double t = disc_bisection(2.0 * M_PI * k / K,
                                            2.0 * M_PI * (k + 1) / K,
                                            ft[k]);
            if (accept_disc_slip(t, r, hint))
              return true;
          }
        return false;
      }



      int
      LocalCoulomb::solve(double *r, double &hint)
      {
        for (unsigned int a = 0; a < d; ++a)
          r[a] = 0.0;
        if (q[0] <= 0.0) // separated
          return 0;
        if (mu == 0.0) // without friction: T = 0 and u_N = 0
          {
            r[0] = -q[0] / W[0];
            return 2;
          }
        form_stick();
        if (stick_admissible())
          {
            std::copy(stick, stick + d, r);
            return 1;
          }
        best.offer(set, mu, W, q, stick);
        const bool slip = (d == 2) ? slip_2d(r, hint) :
                          (set.model() == ConeModel::polygon) ?
                                     slip_polygon(r, hint) :
                                     slip_disc(r, hint);
        if (slip)
          return 2;
        // No case passed its tests (round-off at case boundaries): the
        // candidate of least local residual.
        std::copy(best.r, best.r + d, r);
        return 3;
      }
    } // namespace



    int
    solve_local_coulomb(const FrictionSet &set,
                        const double       mu,
                        const double      *W,
                        const double      *q,
                        double            *r,
                        double            &hint)
    {
      return LocalCoulomb(set, mu, W, q).solve(r, hint);
    }
  } // namespace contact
} // namespace dpana
