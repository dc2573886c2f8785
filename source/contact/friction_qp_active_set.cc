#include <dpana/contact/friction_qp.h>
#include <dpana/contact/line_search.h>

#include <algorithm>

namespace dpana
{
  namespace contact
  {
    // @sect4{The active-set method of the T-step}
    //
    // solve_active_set is a semismooth Newton method on the natural map
    // F(T) = T - Pi(T - rho w) of the friction sets (friction_qp.cc: the
    // directions, the Newton step and its matrix). This file holds what
    // drives it: the line search, the start of a warm started solve
    // (predictor, partition sweeps) and the loop of steps.

    // @sect5{The line search}
    //
    // Along dx, either Armijo backtracking on 1/2 ||F||^2 (at most
    // max_steps halvings), non-monotone against the largest merit of the
    // last few accepted iterates (line_search.h: a full Newton step that
    // lets a few blocks cross their stick / slip boundary raises the merit
    // for a moment; the monotone test cut such steps to slivers, and on
    // the 10 092-unknown scale scene one T-step took 137 Newton steps of
    // 2-3 % decrease each), or, with contraction > 0, the full step only,
    // kept if it brings the merit below contraction times its value. An
    // accepted step moves (T, beta, F); w is that of (T, beta) on entry and
    // on return.
    bool
    FrictionQp::line_search(const Eigen::VectorXd &radius,
                            const Eigen::VectorXd &e,
                            const Eigen::VectorXd &dx,
                            Eigen::VectorXd       &T,
                            Eigen::VectorXd       &beta,
                            Eigen::VectorXd       &F,
                            const unsigned int     max_steps,
                            const double           contraction)
    {
      constexpr std::size_t window = 5;
      const Eigen::Index    q = T.size(), me = G.rows();
      F_trial.resize(q + me);
      w0           = w;
      dw.noalias() = M * dx.head(q);
      if (me > 0)
        dw.noalias() += G.transpose() * dx.tail(me);
      const double phi   = 0.5 * F.squaredNorm();
      const auto   trial = [&](const double t) {
        T_trial = T + t * dx.head(q);
        if (me > 0)
          beta_trial = beta + t * dx.tail(me);
        w = w0 + t * dw;
        natural_map_of_w(radius, e, T_trial, F_trial);
        return 0.5 * F_trial.squaredNorm();
      };
      const double reference =
        recent_merits.empty() ?
          phi :
          *std::max_element(recent_merits.begin(), recent_merits.end());
      const bool accepted =
        (contraction > 0.0) ?
          trial(1.0) <= contraction * phi :
          armijo_backtracking(phi, max_steps, trial, reference);
      if (!accepted)
        {
          w = w0;
          return false;
        }
      T.swap(T_trial);
      if (me > 0)
        beta.swap(beta_trial);
      F.swap(F_trial);
      recent_merits.push_back(0.5 * F.squaredNorm());
      if (recent_merits.size() > window)
        recent_merits.erase(recent_merits.begin());
      return true;
    }



    // @sect5{The predictor of a warm started solve}
    //
    // In a splitting the T-steps follow one another with data (c, radii)
    // that change less and less. Started from the last solution, the
    // natural map of the new data clips the points y_j = T_j - rho_j w_j of
    // many stick blocks onto their circles, and the partition then takes
    // several Newton steps, each with a new factorisation, to settle. The
    // predictor is one Newton step of the new data on the PREVIOUS
    // partition: the generalised Jacobian of the last Newton step of the
    // previous solve (its eigen-directions, from the radii and the points y
    // of that step), and the natural map with the blocks that stuck there
    // taken as sticking, F_j = T_j - y_j = rho_j w_j (no clipping). If the
    // partition is unchanged this is the exact step to the solution of the
    // new problem for the interval and the polygon, and a Newton step on the
    // slip circles for the disc. Its matrix is the one last factored (the
    // same directions), whose factors are used as they are. It is kept only
    // if it passes the Armijo test on the true natural map; otherwise the
    // solve goes on from the start point as before. False if there is no
    // previous step or the step could not be made.
    bool
    FrictionQp::predictor_step(const Eigen::VectorXd &F, Eigen::VectorXd &dx)
    {
      if (radius_last.size() != static_cast<Eigen::Index>(n))
        return false;
      Eigen::VectorXd F_previous = F;
      for (unsigned int j = 0; j < n; ++j)
        if (partition[j] == 2)
          for (unsigned int a = 0; a < m; ++a)
            F_previous[m * j + a] = rho[j] * w[m * j + a];
      y.swap(y_last);
      region.swap(region_last);
      const Eigen::VectorXd radius = radius_last;
      newton_directions(radius, F_previous, dx);
      const bool refactor = !(options.chord_steps && factors_fit());
      return newton_step(F_previous, dx, refactor).empty();
    }



    // @sect5{Sweeps that find the partition}
    //
    // Started far from its solution (the first T-steps of a splitting, whose
    // normal tractions are still changing), the semismooth Newton method
    // finds the stick / slip partition a few blocks per step: on the 3D
    // receding block with 3888 contact unknowns the first T-steps took 22 to
    // 27 Newton steps each, each with a new partition, hence a new Cholesky
    // factorisation of H (f^3/3 flops), most of them changing fewer than 20
    // of 1296 blocks. Projected Gauss-Seidel sweeps (solve_pgs, a few q^2
    // flops each) move the same boundary without any factorisation. They are
    // made in chunks of five; after each chunk the natural map gives the
    // regions of the blocks (interior, circle or facet, vertex, zero
    // radius), and the sweeps stop when two chunks in a row have left all
    // of them unchanged. (One unchanged chunk is not enough where
    // Gauss-Seidel converges slowly: at 10 092 contact unknowns a T-step
    // stopped after 20 sweeps and its Newton steps then moved the partition
    // for 158 steps, 105 of them with a new factorisation; with the chord
    // steps and the non-monotone line search, stopping after one unchanged
    // chunk of five or of three still made that solve 20-40 % slower.) The
    // Newton steps then begin on (nearly) the right partition.
    unsigned int
    FrictionQp::settle_partition(const Eigen::VectorXd &c,
                                 const Eigen::VectorXd &radius,
                                 const Eigen::VectorXd &e,
                                 Eigen::VectorXd       &T,
                                 Eigen::VectorXd       &beta,
                                 Eigen::VectorXd       &F)
    {
      constexpr unsigned int chunk  = 5;
      const InnerOptions     saved  = options;
      std::vector<int>       before = region;
      unsigned int           sweeps = 0, unchanged = 0;
      options.max_iterations  = chunk;
      single_precision_sweeps = true;
      while (sweeps < saved.partition_sweeps && unchanged < 2)
        {
          solve_pgs(c, radius, e, T, beta);
          sweeps += chunk;
          natural_map(c, radius, e, T, beta, F);
          unchanged = (region == before) ? unchanged + 1 : 0;
          before    = region;
        }
      options                 = saved;
      single_precision_sweeps = false;
      return sweeps;
    }



    // @sect5{The start of a solve}
    //
    // Where sweeps are made (large problems), the predictor is tried first:
    // late in a splitting the partition has settled, the predictor lands on
    // it, and the sweeps (at least ten, each a pass over M) would only
    // confirm it. The predictor is kept if the line search accepts it and
    // the regions of the blocks at its point are those of the last Newton
    // step of the previous solve; otherwise the solve returns to the start
    // point, sweeps, and tries the predictor again from there (on the
    // 10 092-unknown scale scene, going on from a rejected predictor's
    // point instead made the sweeps settle on a partition that took 137
    // Newton steps). Without sweeps the predictor is tried once.
    void
    FrictionQp::start_active_set(const Eigen::VectorXd &c,
                                 const Eigen::VectorXd &radius,
                                 const Eigen::VectorXd &e,
                                 Eigen::VectorXd       &T,
                                 Eigen::VectorXd       &beta,
                                 Eigen::VectorXd       &F,
                                 Eigen::VectorXd       &dx)
    {
      if (active_set_converged(F, radius, e, T))
        return;
      if (options.partition_sweeps > 0 &&
          T.size() >= options.partition_sweep_size)
        {
          const Eigen::VectorXd T_start = T, beta_start = beta;
          if (predictor_step(F, dx) &&
              line_search(radius, e, dx, T, beta, F, 4) &&
              region == region_last)
            return;
          T    = T_start;
          beta = beta_start;
          recent_merits.clear();
          natural_map(c, radius, e, T, beta, F);
          if (active_set_converged(F, radius, e, T))
            return;
          settle_partition(c, radius, e, T, beta, F);
          if (active_set_converged(F, radius, e, T))
            return;
        }
      if (predictor_step(F, dx) && !line_search(radius, e, dx, T, beta, F, 4))
        natural_map(c, radius, e, T, beta, F); // y and region of T again
    }



    // @sect5{The steps}
    //
    // Each step finds the directions of the generalised Jacobian at the
    // current point. When the partition is that of the last factored Newton
    // matrix, a chord step with that matrix's factors comes first: it costs
    // a product with M and two triangular solves where a factorisation
    // costs f^3/3 flops (f up to 6000 directions at 10 092 unknowns), and
    // it is kept if it halves ||F||. A chord step that reduced ||F|| less
    // than tenfold is followed by an exact step, so that a slow linear tail
    // cannot replace Newton's quadratic convergence. Late in a splitting
    // most T-steps then need no factorisation at all.
    InnerResult
    FrictionQp::solve_active_set(const Eigen::VectorXd &c,
                                 const Eigen::VectorXd &radius,
                                 const Eigen::VectorXd &e,
                                 Eigen::VectorXd       &T,
                                 Eigen::VectorXd       &beta)
    {
      const Eigen::Index q  = T.size();
      const Eigen::Index me = G.rows();
      InnerResult        result;
      if (beta.size() != me)
        beta = Eigen::VectorXd::Zero(me);
      project_onto_sets(radius, T);

      Eigen::VectorXd F(q + me), dx(q + me);
      v.resize(q);
      recent_merits.clear();
      natural_map(c, radius, e, T, beta, F);
      start_active_set(c, radius, e, T, beta, F, dx);

      unsigned int failures = 0;
      bool         chord    = options.chord_steps;
      for (unsigned int step = 0; step <= options.max_iterations; ++step)
        {
          result.iterations = step;
          // Converged on the updated w? Then again on w afresh, so that the
          // round-off of the updates cannot fake convergence.
          if (active_set_converged(F, radius, e, T))
            {
              natural_map(c, radius, e, T, beta, F);
              if (active_set_converged(F, radius, e, T))
                {
                  result.converged = true;
                  return result;
                }
            }
          if (step == options.max_iterations)
            break;

          newton_directions(radius, F, dx);
          if (chord && factors_fit())
            {
              const double merit = F.squaredNorm();
              if (newton_step(F, dx, false).empty() &&
                  line_search(radius, e, dx, T, beta, F, 1, 0.25))
                {
                  chord = F.squaredNorm() <= 1e-2 * merit;
                  continue;
                }
              natural_map_of_w(radius, e, T, F); // y and region of T again
              newton_directions(radius, F, dx);
            }
          chord          = options.chord_steps;
          result.message = newton_step(F, dx);
          if (!result.message.empty())
            return result;
          if (line_search(radius, e, dx, T, beta, F, 40))
            continue;
          // Globalisation fallback: a few PGS sweeps.
          if (++failures > 50)
            {
              result.message = "friction active set: line search failed";
              return result;
            }
          InnerOptions saved     = options;
          options.max_iterations = 10 * failures;
          solve_pgs(c, radius, e, T, beta);
          options = saved;
          recent_merits.clear();
          natural_map(c, radius, e, T, beta, F);
        }
      result.iterations = options.max_iterations;
      result.message    = "friction active set: step limit reached";
      return result;
    }
  } // namespace contact
} // namespace dpana
