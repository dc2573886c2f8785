#include "problems.h"

#include <Eigen/Cholesky>

#include <cmath>
#include <stdexcept>

#include "half_space.h"

namespace dpana
{
  namespace benchmarks
  {
    namespace
    {
      // The centre of element j on [-1/2, 1/2]^(d-1).
      void
      centre(const IndenterSpec &spec,
             const unsigned int  j,
             double             &x,
             double             &y)
      {
        const double h = 1.0 / spec.m;
        x              = -0.5 + (j % spec.m + 0.5) * h;
        y              = (spec.dim == 3) ? -0.5 + (j / spec.m + 0.5) * h : 0.0;
      }

      // The compliance of the body. With a stiffness ratio k, the elements
      // of the right half (x > 0) are k times more compliant than those of
      // the left: A = S A_0 S with S = diag(1 on the left, sqrt(k) on the
      // right), symmetric positive definite like A_0, the compliance of a
      // contact surface that crosses from one material to another (a
      // rescaling of the whole of A would change nothing: the solvers and
      // the residual are invariant under it).
      Eigen::MatrixXd
      compliance(const IndenterSpec &spec)
      {
        const HalfSpaceOptions o{1.0, spec.nu, 1.0};
        Eigen::MatrixXd A = spec.dim == 2 ? half_plane_compliance(spec.m, o) :
                                            half_space_compliance(spec.m, o);
        if (spec.stiffness_ratio <= 0)
          return A;
        const unsigned int d = spec.dim;
        Eigen::VectorXd    S = Eigen::VectorXd::Ones(A.rows());
        for (Eigen::Index i = 0; i < A.rows(); ++i)
          {
            double x, y;
            centre(spec, static_cast<unsigned int>(i / d), x, y);
            if (x > 0)
              S[i] = std::sqrt(spec.stiffness_ratio);
          }
        return S.asDiagonal() * A * S.asDiagonal();
      }

      // The equality rows of the floating punches: per punch, the balance
      // of the normal tractions with -P and of the first tangential ones
      // with side mu P (and of the second with 0 in 3D), each traction
      // weighted by its element's area.
      void
      add_floating_rows(const IndenterSpec &spec, contact::ContactProblem &p)
      {
        const unsigned int d = spec.dim, n = p.n_elements();
        const double       area = std::pow(1.0 / spec.m, double(d - 1));
        const unsigned int rows = spec.floating * d;
        p.G                     = Eigen::MatrixXd::Zero(rows, d * n);
        p.e                     = Eigen::VectorXd::Zero(rows);
        for (unsigned int j = 0; j < n; ++j)
          {
            double x, y;
            centre(spec, j, x, y);
            const unsigned int punch = (spec.floating == 2 && x > 0) ? 1 : 0;
            for (unsigned int a = 0; a < d; ++a)
              p.G(d * punch + a, d * j + a) = area;
          }
        for (unsigned int punch = 0; punch < spec.floating; ++punch)
          {
            p.e[d * punch]     = -spec.force;
            p.e[d * punch + 1] = spec.side * spec.mu * spec.force;
          }
      }
    } // namespace



    contact::ContactProblem
    indenter(const IndenterSpec &spec)
    {
      contact::ContactProblem p;
      p.dim  = spec.dim;
      p.cone = (spec.dim == 3) ? spec.cone : contact::ConeModel::interval;
      p.polygon_sides      = spec.sides;
      p.A                  = compliance(spec);
      const unsigned int n = (spec.dim == 2) ? spec.m : spec.m * spec.m;
      p.D                  = Eigen::VectorXd::Zero(spec.dim * n);
      p.mu                 = Eigen::VectorXd::Constant(n, spec.mu);
      const double R       = 1.0;
      for (unsigned int j = 0; j < n; ++j)
        {
          double x, y;
          centre(spec, j, x, y);
          // A floating punch of two sits in the middle of its half.
          const double xc = (spec.floating == 2) ? (x < 0 ? -0.25 : 0.25) : 0;
          const double profile = ((x - xc) * (x - xc) + y * y) / (2.0 * R);
          if (spec.floating > 0)
            p.D[spec.dim * j] = -profile;
          else
            {
              p.D[spec.dim * j]     = spec.approach - profile;
              p.D[spec.dim * j + 1] = spec.tangential * spec.mu * spec.approach;
            }
          if (std::abs(x) > 0.25)
            p.D[spec.dim * j] -= spec.outer_gap;
        }
      if (spec.floating > 0)
        add_floating_rows(spec, p);
      if (Eigen::LLT<Eigen::MatrixXd>(p.A).info() != Eigen::Success)
        throw std::runtime_error("hard case: the compliance is not positive "
                                 "definite");
      p.validate();
      return p;
    }



    std::vector<HardCase>
    hard_cases(const bool quick)
    {
      std::vector<HardCase> cases;
      auto                  add = [&](const std::string  &family,
                     const std::string  &name,
                     const IndenterSpec &spec) {
        cases.push_back({family, name, indenter(spec)});
      };
      auto label = [](const char *what, const double x) {
        char buffer[64];
        std::snprintf(buffer, sizeof(buffer), "%s=%g", what, x);
        return std::string(buffer);
      };
      const std::vector<double> mus =
        quick ? std::vector<double>{0, 1, 100} :
                std::vector<double>{0, 0.1, 0.3, 1, 2, 5, 10, 100};
      for (const unsigned int dim : {2u, 3u})
        {
          const std::string d = std::to_string(dim) + "D ";
          IndenterSpec      base;
          base.dim = dim;
          base.m   = (dim == 2) ? (quick ? 32 : 64) : (quick ? 6 : 10);
          for (const double mu : mus)
            {
              IndenterSpec s = base;
              s.mu           = mu;
              add("friction", d + label("mu", mu), s);
            }
          for (const double ratio : {1e-6, 1e-3, 1.0, 1e3, 1e6})
            {
              if (quick && ratio != 1e-6 && ratio != 1e6)
                continue;
              IndenterSpec s    = base;
              s.stiffness_ratio = ratio;
              s.mu              = 1.0;
              add("stiffness ratio", d + label("k", ratio), s);
            }
          for (const double nu : {0.0, 0.3, 0.49, 0.4999})
            {
              if (quick && nu != 0.4999)
                continue;
              IndenterSpec s = base;
              s.nu           = nu;
              s.mu           = 1.0;
              add("Poisson", d + label("nu", nu), s);
            }
          for (const double gap : {1e3, -0.5})
            {
              // gap > 0: the outer half far from the obstacle; < 0: the
              // outer half pressed into it (interference).
              IndenterSpec s = base;
              s.mu           = 1.0;
              s.outer_gap    = gap;
              add("gap",
                  d + (gap > 0 ? label("outer gap", gap) :
                                 label("interference", -gap)),
                  s);
            }
          for (const unsigned int floating : {1u, 2u})
            for (const double mu : {0.3, 1.0, 5.0})
              {
                if (quick && mu != 1.0)
                  continue;
                IndenterSpec s = base;
                s.floating     = floating;
                s.mu           = mu;
                add("floating",
                    d + std::to_string(floating) + " floating, " +
                      label("mu", mu),
                    s);
              }
          const std::vector<unsigned int> fine =
            dim == 2 ? (quick ? std::vector<unsigned int>{128} :
                                std::vector<unsigned int>{256, 1024}) :
                       (quick ? std::vector<unsigned int>{12} :
                                std::vector<unsigned int>{16, 24});
          for (const unsigned int m : fine)
            {
              IndenterSpec s = base;
              s.m            = m;
              s.mu           = 1.0;
              add("fine surface",
                  d + std::to_string(dim == 2 ? m : m * m) + " elements",
                  s);
            }
        }
      for (const unsigned int sides : {4u, 8u, 16u, 32u, 64u})
        {
          if (quick && sides != 4)
            continue;
          IndenterSpec s;
          s.dim   = 3;
          s.m     = quick ? 6 : 10;
          s.mu    = 1.0;
          s.cone  = contact::ConeModel::polygon;
          s.sides = sides;
          add("polygon", "3D " + label("s", sides), s);
        }
      return cases;
    }
  } // namespace benchmarks
} // namespace dpana
