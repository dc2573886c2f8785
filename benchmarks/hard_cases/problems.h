// The condensed problems of the hard-case matrix (benchmarks/hard_cases):
// a rigid indenter on an elastic half-plane (2D) or half-space (3D), whose
// compliances (half_space.h of the solver_vs_siconos benchmark, Flamant,
// Boussinesq and Cerruti) have the structure and the conditioning of the
// condensed problems of real meshes, varied along every axis that makes a
// contact problem hard: the friction coefficient, a stiffness contrast
// along the contact surface, Poisson's ratio, the sides of the friction
// polygon, gaps and interference, floating bodies (held by contact alone:
// equality rows G r = e) and the fineness of the contact surface (the
// condition number of A grows like n in 2D and like sqrt(n) in 3D).
#ifndef dpana_benchmarks_hard_cases_problems_h
#define dpana_benchmarks_hard_cases_problems_h

#include <dpana/contact/problem.h>

#include <string>
#include <vector>

namespace dpana
{
  namespace benchmarks
  {
    // One cell of the matrix: the axis it varies (its family), its name and
    // its problem.
    struct HardCase
    {
      std::string             family;
      std::string             name;
      contact::ContactProblem problem;
    };

    // The description of an indenter problem, every axis of the matrix.
    struct IndenterSpec
    {
      unsigned int dim = 2;
      // Elements: n in 2D, m x m in 3D.
      unsigned int m  = 32;
      double       mu = 0.3;
      // Poisson's ratio of both bodies.
      double nu = 0.3;
      // Stiffness contrast k: the elements with x > 0 are k times more
      // compliant than the others (see compliance() in problems.cc); 0:
      // none.
      double stiffness_ratio = 0;
      // The friction set in 3D and the sides of its polygon.
      contact::ConeModel cone  = contact::ConeModel::disc;
      unsigned int       sides = 16;
      // Approach of the indenter (interference at the centre), and the
      // tangential displacement imposed with it, as a fraction of
      // mu times the approach.
      double approach = 0.1, tangential = 0.7;
      // An extra gap on the outer half of the surface (elements with
      // |x| > 1/4), as if the obstacle were far away there.
      double outer_gap = 0;
      // Floating punches held by contact alone: 0 (displacement driven),
      // 1 or 2 (the surface split in two halves, one punch each), pressed
      // by the force P and pushed by the side force `side` times mu P.
      unsigned int floating = 0;
      double       force = 0.05, side = 0.5;
    };

    contact::ContactProblem
    indenter(const IndenterSpec &spec);

    // The cells of the matrix; quick: a small subset of every family, for
    // the ctest.
    std::vector<HardCase>
    hard_cases(const bool quick);
  } // namespace benchmarks
} // namespace dpana

#endif
