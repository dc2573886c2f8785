// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_scene_contact_parameters_h
#define dpana_scene_contact_parameters_h

#include <dpana/contact/problem.h>
#include <dpana/contact/solver.h>

#include <deal.II/base/parameter_handler.h>

namespace dpana
{
  namespace scene
  {
    /**
     * The contact law of a run, entries of `subsection Contact`: the Coulomb
     * friction coefficient mu and, in 3D, the friction set (the exact disc
     * ||T|| <= -mu N, or the polygon with s sides circumscribed about it of
     * the reference formulation). The contact solver layer knows nothing of
     * parameter files, so this component of the finite element layer reads
     * them for it.
     */
    struct ContactLaw
    {
      double             friction      = 0;
      contact::ConeModel cone          = contact::ConeModel::disc;
      unsigned int       polygon_sides = 16;

      /**
       * Declares the entries into the current subsection (Contact).
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * Reads them; @p dim chooses the friction set (2D: the interval).
       */
      void
      parse_parameters(const dealii::ParameterHandler &prm,
                       const unsigned int              dim);
    };



    /**
     * The options of the contact solver, entries of `subsection Contact`:
     * which solver, its tolerance on the shared residual (the natural map,
     * contact/residual.h), its iteration cap, and whether a run that does
     * not converge may exit with status 0.
     */
    struct SolverParameters
    {
      contact::SolverOptions options;
      bool                   allow_non_converged = false;

      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * Reads them; throws dpana::InputError on a tolerance <= 0.
       */
      void
      parse_parameters(const dealii::ParameterHandler &prm);
    };
  } // namespace scene
} // namespace dpana

#endif
