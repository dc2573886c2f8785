// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/condensation/contact_problem.h>

#include <algorithm>

namespace dpana
{
  namespace condensation
  {
    // @sect3{The contact problem}
    //
    // Relative quantities add (A = A1 + A2, D = D1 + D2), the initial gap
    // enters the normal rows, the equality rows of the floating bodies are
    // stacked.
    template <int dim>
    contact::ContactProblem
    assemble_contact_problem(
      const std::vector<const Condenser<dim> *>  &condensers,
      const contact_surface::ContactSurface<dim> &surface,
      const double                                friction,
      const contact::ConeModel                    cone,
      const unsigned int                          polygon_sides)
    {
      const unsigned int      n = surface.n_elements();
      contact::ContactProblem problem;
      problem.dim           = dim;
      problem.A             = Eigen::MatrixXd::Zero(dim * n, dim * n);
      problem.D             = Eigen::VectorXd::Zero(dim * n);
      problem.mu            = Eigen::VectorXd::Constant(n, friction);
      problem.cone          = cone;
      problem.polygon_sides = polygon_sides;
      unsigned int m        = 0;
      for (const Condenser<dim> *c : condensers)
        {
          if (c->compliance().size() > 0) // empty off rank 0 (MPI route)
            problem.A += c->compliance();
          problem.D += c->load_term();
          m += c->n_free_modes();
        }
      for (unsigned int j = 0; j < n; ++j)
        problem.D(dim * j) -= surface.element(j).gap_integral;

      problem.G.resize(m, dim * n);
      problem.e.resize(m);
      unsigned int row = 0;
      for (const Condenser<dim> *c : condensers)
        {
          const unsigned int mb = c->n_free_modes();
          if (mb == 0)
            continue;
          problem.G.middleRows(row, mb) = c->equilibrium_matrix();
          problem.e.segment(row, mb)    = c->equilibrium_rhs();
          row += mb;
        }
      return problem;
    }



    template <int dim>
    double
    largest_asymmetry(const std::vector<const Condenser<dim> *> &condensers)
    {
      double asymmetry = 0;
      for (const Condenser<dim> *c : condensers)
        asymmetry = std::max(asymmetry, c->asymmetry());
      return asymmetry;
    }



    template contact::ContactProblem
    assemble_contact_problem(const std::vector<const Condenser<2> *> &,
                             const contact_surface::ContactSurface<2> &,
                             const double,
                             const contact::ConeModel,
                             const unsigned int);
    template contact::ContactProblem
    assemble_contact_problem(const std::vector<const Condenser<3> *> &,
                             const contact_surface::ContactSurface<3> &,
                             const double,
                             const contact::ConeModel,
                             const unsigned int);
    template double
    largest_asymmetry(const std::vector<const Condenser<2> *> &);
    template double
    largest_asymmetry(const std::vector<const Condenser<3> *> &);
  } // namespace condensation
} // namespace dpana
