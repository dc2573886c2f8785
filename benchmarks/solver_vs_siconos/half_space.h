// FE-like contact problems for the benchmark solver_vs_siconos: the
// compliance of an elastic half-plane (2D) or half-space (3D) loaded by
// piecewise constant tractions on contact elements, and the load term of a
// rigid parabolic indenter pressed into it and pulled sideways.
//
// @sect3{Why these matrices}
//
// The condensed compliance A of the reference formulation is dense, symmetric
// positive definite, dominated by its diagonal but with slowly decaying
// off-diagonal entries (the Green's function of elasticity decays like log(1/r)
// in 2D and 1/r in 3D), and it couples normal and tangential unknowns. For a
// body much larger than the contact zone A tends to the influence matrix of a
// half-plane / half-space, which has closed forms: so these matrices have
// the structure and the conditioning of real condensed problems (the
// condition number grows with the number of elements) without a mesh.
//
// @sect3{2D: Flamant's solution (plane strain)}
//
// n elements of length h = 1/n cover the segment [-1/2, 1/2]; element j
// carries a uniform normal traction N_j and tangential traction T_j (force
// per unit length), centred at x_j. The surface displacements of a
// half-plane under line loads P (normal) and Q (tangential) at the origin
// are (K. L. Johnson, Contact Mechanics, CUP 1985, eqs. 2.19-2.20)
//   u_n(x) = -(2 (1 - nu^2) / (pi E)) P ln|x| + C,
//   u_t(x) = -(2 (1 - nu^2) / (pi E)) Q ln|x| + C',
// with the normal-tangential coupling
//   u_t(x) due to P, u_n(x) due to Q:  -/+ ((1 - 2 nu)(1 + nu) / (2 E)) sgn(x).
// The constants C, C' (a rigid displacement, undetermined in 2D) are fixed
// by measuring the logarithm relative to a length L = 4 (four times the
// loaded segment): ln|x| -> ln(|x| / L), which keeps A positive definite.
// Integrating over element j and multiplying by h (the work conjugate of a
// piecewise constant traction, as in the reference formulation's A = V^T K^{-1}
// V):
//   A_{N_i N_j} = A_{T_i T_j} = -h c_1 \int_{-h/2}^{h/2} ln(|x_i - x_j - s| /
//   L) ds, A_{T_i N_j} = A_{N_j T_i} = h^2 c_2 sgn(i - j)        (0 for i = j),
//   c_1 = 2 (1 - nu^2) / (pi E),  c_2 = beta (1 - 2 nu)(1 + nu) / (2 E),
// using \int_{-b}^{b} ln|x - s| ds = f(x + b) - f(x - b), f(u) = u ln|u| - u.
// The coupling is symmetric by Maxwell-Betti (the kernel is odd and the
// two cross terms have opposite signs). beta scales the coupling: 1 for an
// elastic body on a rigid base (as here), 0 for two identical bodies
// (Dundurs' second constant vanishes). In Fourier space the continuous
// operator is positive definite because 2 (1 - nu) > 1 - 2 nu.
//
// @sect3{3D: Boussinesq's and Cerruti's solutions}
//
// m x m square patches of side h = 1/m cover [-1/2, 1/2]^2; patch j carries
// uniform (N_j, T_{j,1}, T_{j,2}). The surface displacements of a half-space
// under a normal point load P and a tangential point load Q along x at the
// origin, at the point (x, y), rho = sqrt(x^2 + y^2), are (Johnson,
// eqs. 3.19 and 3.86-3.87)
//   u_n = (1 - nu^2)/(pi E) P / rho,
//   u_1 = (1 + nu)/(2 pi E) Q [ 2 (1 - nu)/rho + 2 nu x^2/rho^3 ],
//   u_2 = (1 + nu)/(2 pi E) Q [ 2 nu x y / rho^3 ],
// and the coupling (1 + nu)(1 - 2 nu)/(2 pi E) x/rho^2 (u_1 due to P, and
// with the opposite sign u_n due to Q). Integrated over a patch with the
// offsets (x, y) from its centre, each kernel has a closed primitive F with
// d^2 F / ds dt = f and \int\int f = F(x+a, y+a) - F(x+a, y-a) - F(x-a, y+a)
// + F(x-a, y-a), a = h/2:
//   f = 1/rho:      F = s ln(t + rho) + t ln(s + rho)   (Love, 1929),
//   f = s^2/rho^3:  F = t ln(s + rho),
//   f = t^2/rho^3:  F = s ln(t + rho),
//   f = s t/rho^3:  F = -rho,
//   f = s/rho^2:    F = s atan(t/s) + (t/2) ln(s^2 + t^2),
// (each checked against numerical quadrature when this file was written).
// The entries are these integrals at the centre of patch i times h^2, with
// the same factor beta on the coupling as in 2D. The patch-centre
// collocation makes A symmetric up to the collocation error only in the
// tangential-tangential block; we symmetrise A = (A + A^T)/2.
//
// @sect3{The load: a rigid indenter}
//
// A rigid parabolic punch of radius R = 1 pressed by delta into the body and
// shifted sideways by delta_t: with the gap g(x) = |x|^2 / (2 R) the load
// term is D_N = delta - g(x_j) (penetration at zero traction where
// positive), D_T = delta_t along the first tangent. With delta = 0.1 the
// contact zone covers a bit less than half of the segment in 2D and a disc
// of about a third of the square in 3D; the rest separates. With
// delta_t = 0.7 mu delta part of the contact zone sticks and part slips (the
// Cattaneo-Mindlin picture); the benchmark prints the counts.
#ifndef dpana_benchmarks_half_space_h
#define dpana_benchmarks_half_space_h

#include <dpana/contact/problem.h>

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace dpana
{
  namespace benchmarks
  {
    struct HalfSpaceOptions
    {
      double young   = 1.0;
      double poisson = 0.3;
      // beta: scale of the normal-tangential coupling (see above).
      double coupling = 1.0;
    };

    namespace internal
    {
      // \int_{-b}^{b} ln|x - s| ds.
      inline double
      log_integral(const double x, const double b)
      {
        auto f = [](const double u) {
          return u == 0.0 ? 0.0 : u * std::log(std::abs(u)) - u;
        };
        return f(x + b) - f(x - b);
      }

      // The rectangle rule of the primitives: \int\int f over the patch
      // [x-a, x+a] x [y-a, y+a] of the offset variables.
      template <typename Primitive>
      double
      patch_integral(const Primitive &F,
                     const double     x,
                     const double     y,
                     const double     a)
      {
        return F(x + a, y + a) - F(x + a, y - a) - F(x - a, y + a) +
               F(x - a, y - a);
      }

      inline double
      F_inv_rho(const double s, const double t)
      {
        const double rho = std::hypot(s, t);
        double       v   = 0;
        if (s != 0.0 && t + rho > 0)
          v += s * std::log(t + rho);
        if (t != 0.0 && s + rho > 0)
          v += t * std::log(s + rho);
        return v;
      }
      inline double
      F_ss_rho3(const double s, const double t)
      {
        const double rho = std::hypot(s, t);
        return (t != 0.0 && s + rho > 0) ? t * std::log(s + rho) : 0.0;
      }
      inline double
      F_tt_rho3(const double s, const double t)
      {
        const double rho = std::hypot(s, t);
        return (s != 0.0 && t + rho > 0) ? s * std::log(t + rho) : 0.0;
      }
      inline double
      F_st_rho3(const double s, const double t)
      {
        return -std::hypot(s, t);
      }
      inline double
      F_s_rho2(const double s, const double t)
      {
        double v = 0;
        if (s != 0.0)
          v += s * std::atan(t / s);
        if (s * s + t * t > 0)
          v += 0.5 * t * std::log(s * s + t * t);
        return v;
      }
    } // namespace internal

    // The (2n) x (2n) compliance of n elements along a line, interleaved
    // (N_j, T_j).
    inline Eigen::MatrixXd
    half_plane_compliance(const unsigned int n, const HalfSpaceOptions &o = {})
    {
      const double h = 1.0 / n, b = 0.5 * h, L = 4.0;
      const double E = o.young, nu = o.poisson;
      const double c1 = 2.0 * (1.0 - nu * nu) / (M_PI * E);
      const double c2 = o.coupling * (1.0 - 2.0 * nu) * (1.0 + nu) / (2.0 * E);
      Eigen::MatrixXd A(2 * n, 2 * n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            const double x = (static_cast<double>(i) - j) * h;
            const double ll =
              -c1 * (internal::log_integral(x, b) - 2.0 * b * std::log(L));
            const double sg         = (i == j ? 0.0 : (i > j ? 1.0 : -1.0));
            A(2 * i, 2 * j)         = h * ll;
            A(2 * i + 1, 2 * j + 1) = h * ll;
            A(2 * i + 1, 2 * j)     = h * h * c2 * sg;  // u_T(i) due to N(j)
            A(2 * i, 2 * j + 1)     = -h * h * c2 * sg; // u_N(i) due to T(j)
          }
      return A;
    }

    // The (3 m^2) x (3 m^2) compliance of an m x m grid of square patches,
    // interleaved (N_j, T_{j,1}, T_{j,2}), patches numbered row by row.
    inline Eigen::MatrixXd
    half_space_compliance(const unsigned int m, const HalfSpaceOptions &o = {})
    {
      const unsigned int n = m * m;
      const double       h = 1.0 / m, a = 0.5 * h;
      const double       E = o.young, nu = o.poisson;
      const double       cn = (1.0 - nu * nu) / (M_PI * E);
      const double       ct = (1.0 + nu) / (M_PI * E);
      const double       cc =
        o.coupling * (1.0 + nu) * (1.0 - 2.0 * nu) / (2 * M_PI * E);
      Eigen::MatrixXd A(3 * n, 3 * n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            using namespace internal;
            const double x   = (static_cast<double>(i % m) - double(j % m)) * h;
            const double y   = (static_cast<double>(i / m) - double(j / m)) * h;
            const double I1  = patch_integral(F_inv_rho, x, y, a);
            const double Iss = patch_integral(F_ss_rho3, x, y, a);
            const double Itt = patch_integral(F_tt_rho3, x, y, a);
            const double Ist = patch_integral(F_st_rho3, x, y, a);
            const double Ixs = patch_integral(F_s_rho2, x, y, a);
            const double Iys = patch_integral(F_s_rho2, y, x, a);
            const double w   = h * h;
            A(3 * i, 3 * j)  = w * cn * I1;
            A(3 * i + 1, 3 * j + 1) = w * ct * ((1.0 - nu) * I1 + nu * Iss);
            A(3 * i + 2, 3 * j + 2) = w * ct * ((1.0 - nu) * I1 + nu * Itt);
            A(3 * i + 1, 3 * j + 2) = w * ct * nu * Ist;
            A(3 * i + 2, 3 * j + 1) = w * ct * nu * Ist;
            A(3 * i + 1, 3 * j)     = w * cc * Ixs;  // u_T1(i) due to N(j)
            A(3 * i + 2, 3 * j)     = w * cc * Iys;  // u_T2(i) due to N(j)
            A(3 * i, 3 * j + 1)     = -w * cc * Ixs; // u_N(i) due to T1(j)
            A(3 * i, 3 * j + 2)     = -w * cc * Iys; // u_N(i) due to T2(j)
          }
      return 0.5 * (A + A.transpose());
    }

    // The indenter problem on the half-plane (dim = 2, n elements) or the
    // half-space (dim = 3, m x m patches, n = m^2).
    inline contact::ContactProblem
    indenter_problem(const unsigned int dim,
                     const unsigned int m,
                     const double       mu,
                     const double       delta = 0.1)
    {
      contact::ContactProblem p;
      p.dim = dim;
      p.cone =
        (dim == 3 ? contact::ConeModel::disc : contact::ConeModel::interval);
      p.A = (dim == 2 ? half_plane_compliance(m) : half_space_compliance(m));
      const unsigned int n = (dim == 2 ? m : m * m);
      p.D                  = Eigen::VectorXd::Zero(dim * n);
      p.mu                 = Eigen::VectorXd::Constant(n, mu);
      const double h = 1.0 / m, R = 1.0, delta_t = 0.7 * mu * delta;
      for (unsigned int j = 0; j < n; ++j)
        {
          const double x   = -0.5 + (j % m + 0.5) * h;
          const double y   = (dim == 3 ? -0.5 + (j / m + 0.5) * h : 0.0);
          p.D[dim * j]     = delta - (x * x + y * y) / (2.0 * R);
          p.D[dim * j + 1] = delta_t;
        }
      if (Eigen::LLT<Eigen::MatrixXd>(p.A).info() != Eigen::Success)
        throw std::runtime_error("indenter_problem: the compliance is not "
                                 "positive definite");
      p.validate();
      return p;
    }
  } // namespace benchmarks
} // namespace dpana

#endif
