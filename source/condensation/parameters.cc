// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/condensation/parameters.h>

#include <deal.II/base/patterns.h>

namespace dpana
{
  namespace condensation
  {
    void
    Parameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Condensation method",
                        "schur",
                        dealii::Patterns::Selection("schur|blocked solves"),
                        "How A = V^T K^-1 V is formed: 'schur' through the "
                        "Cholesky factor of the Schur complement of K on the "
                        "contact surface (the surface dofs ordered last in "
                        "the factorisation), 'blocked solves' by solving for "
                        "the columns of V.");
      prm.declare_entry("Factorisation back end",
                        "cholmod",
                        dealii::Patterns::Selection("cholmod|mumps"),
                        "The sparse factorisation behind Condensation "
                        "method = schur: 'cholmod' (CHOLMOD's supernodal "
                        "Cholesky, the surface dofs ordered last) or 'mumps' "
                        "(MUMPS' Schur complement on the surface dofs, "
                        "through PETSc). The blocked solves use CHOLMOD.");
      prm.declare_entry("Columns per solve",
                        "256",
                        dealii::Patterns::Integer(1),
                        "Columns of V handed at once to the blocked sparse "
                        "Cholesky solves of the condensation (Condensation "
                        "method = blocked solves).");
    }



    void
    Parameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      method  = prm.get("Condensation method") == "schur" ?
                  Method::schur :
                  Method::blocked_solves;
      backend = prm.get("Factorisation back end") == "mumps" ? Backend::mumps :
                                                               Backend::cholmod;
      columns_per_solve = prm.get_integer("Columns per solve");
      if (backend == Backend::mumps && method != Method::schur)
        throw InputError("Contact / Factorisation back end = mumps needs "
                         "Contact / Condensation method = schur");
    }
  } // namespace condensation
} // namespace dpana
