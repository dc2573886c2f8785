// The sweep loop shared by the projected Gauss-Seidel inner solvers of
// dpana (normal LCP and friction QP; method_of_multipliers.h adds the
// equality rows).
#ifndef dpana_contact_projected_gauss_seidel_h
#define dpana_contact_projected_gauss_seidel_h

#include <dpana/contact/normal_lcp.h>

#include <cstdlib>
#include <string>

namespace dpana
{
  namespace contact
  {
    // Sweeps of projected Gauss-Seidel, at most @p max_sweeps of them. The
    // gradient w = matrix x + rhs is kept current by column updates within
    // a sweep. A sweep whose largest change of an entry is at most
    // tolerance times the largest entry stops the loop if it started from
    // a gradient computed from scratch; otherwise the gradient is
    // recomputed and the test repeated, so that accumulated round-off
    // cannot fake convergence.
    //
    // @p refresh() computes the gradient from scratch; @p sweep(change,
    // size) makes one sweep and raises change and size to the largest
    // change and the largest entry. Returns the number of sweeps, negative
    // if the loop hit max_sweeps.
    template <typename Refresh, typename Sweep>
    int
    projected_gauss_seidel(const double       tolerance,
                           const unsigned int max_sweeps,
                           Refresh          &&refresh,
                           Sweep            &&sweep)
    {
      refresh();
      bool fresh = true;
      for (unsigned int k = 1; k <= max_sweeps; ++k)
        {
          double change = 0.0, size = 0.0;
          sweep(change, size);
          if (change <= tolerance * size)
            {
              if (fresh)
                return static_cast<int>(k);
              refresh();
              fresh = true;
            }
          else
            fresh = false;
        }
      return -static_cast<int>(max_sweeps);
    }



    // The linear term q = w_j - W_j x_j of the local problem of one block
    // of k <= 3 entries (W_j its diagonal block, row-major; w_j and x_j its
    // entries of the gradient and of the unknowns): the gradient due to
    // the other blocks.
    inline void
    local_linear_term(const unsigned int k,
                      const double      *W_j,
                      const double      *w_j,
                      const double      *x_j,
                      double            *q)
    {
      for (unsigned int a = 0; a < k; ++a)
        {
          q[a] = w_j[a];
          for (unsigned int b = 0; b < k; ++b)
            q[a] -= W_j[k * a + b] * x_j[b];
        }
    }



    // The local update of one block of k <= 3 entries in a (projected or
    // nonsmooth) Gauss-Seidel sweep with relaxation omega: with omega != 1
    // the point (1 - omega) x + omega x_local is projected back onto the
    // block's set by @p project(z, x_local); then x_local replaces x and
    // delta = x_local - x (the old x) is written for the column update of
    // the gradient. Returns whether the block moved.
    template <typename Project>
    bool
    relaxed_block_update(const unsigned int k,
                         const double       omega,
                         double            *x,
                         double            *x_local,
                         double            *delta,
                         Project          &&project)
    {
      if (omega != 1.0)
        {
          double z[3];
          for (unsigned int a = 0; a < k; ++a)
            z[a] = (1.0 - omega) * x[a] + omega * x_local[a];
          project(z, x_local);
        }
      bool moved = false;
      for (unsigned int a = 0; a < k; ++a)
        {
          delta[a] = x_local[a] - x[a];
          moved    = moved || delta[a] != 0.0;
          x[a]     = x_local[a];
        }
      return moved;
    }



    // The result of a run of sweeps without equality rows (@p sweeps as
    // returned by projected_gauss_seidel(); name: "normal", "friction").
    inline InnerResult
    sweeps_result(const int sweeps, const std::string &name)
    {
      InnerResult result;
      result.converged  = sweeps > 0;
      result.iterations = static_cast<unsigned int>(std::abs(sweeps));
      if (!result.converged)
        result.message = name + " PGS: sweep limit reached";
      return result;
    }
  } // namespace contact
} // namespace dpana

#endif
