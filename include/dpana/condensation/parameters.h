// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_condensation_parameters_h
#define dpana_condensation_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace dpana
{
  namespace condensation
  {
    /**
     * The parameters of the condensation: how many columns of the coupling
     * operator V are handed at once to the blocked sparse Cholesky solves
     * of Condenser::condense(). The number changes the time and the memory
     * of the condensation (a dense block of n_dofs x columns), not its
     * result beyond round-off. In a parameter file it is the entry
     *
     *     subsection Contact
     *       set Columns per solve = 256
     *     end
     *
     * declared by declare_parameters() and read by parse_parameters() in
     * the subsection the caller has entered (`Contact`).
     */
    struct Parameters
    {
      unsigned int columns_per_solve = 256;

      /**
       * Declare the entry Columns per solve in the current subsection of
       * @p prm.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * Read the entry Columns per solve from the current subsection of
       * @p prm.
       */
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace condensation
} // namespace dpana

#endif
