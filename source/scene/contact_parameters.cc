// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/scene/contact_parameters.h>

#include <deal.II/base/patterns.h>

namespace dpana
{
  namespace scene
  {
    void
    ContactLaw::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Friction coefficient",
                        "0",
                        Double(0.),
                        "Coulomb friction coefficient mu (dimensionless).");
      prm.declare_entry("Cone model",
                        "disc",
                        Selection(contact::cone_model_names(3)),
                        "3D friction set: the exact disc ||T|| <= -mu N, or "
                        "the polygon of the reference formulation, "
                        "circumscribed about the disc.");
      prm.declare_entry("Polygon sides",
                        "16",
                        Integer(3),
                        "Number of sides of the friction polygon (3D).");
    }



    void
    ContactLaw::parse_parameters(const dealii::ParameterHandler &prm,
                                 const unsigned int              dim)
    {
      friction = prm.get_double("Friction coefficient");
      if (dim == 2)
        cone = contact::ConeModel::interval;
      else
        cone = prm.get("Cone model") == "polygon" ?
                 contact::ConeModel::polygon :
                 contact::ConeModel::disc;
      polygon_sides = prm.get_integer("Polygon sides");
    }



    void
    SolverParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Solver",
                        "splitting_active_set",
                        Selection(contact::solver_type_names()),
                        "Contact solver (doc/contact_solvers.md).");
      prm.declare_entry("Tolerance",
                        "1e-10",
                        Double(0.),
                        "Tolerance on the natural-map residual "
                        "(dimensionless).");
      prm.declare_entry("Maximum iterations",
                        "1000",
                        Integer(1),
                        "Maximum number of outer iterations.");
      prm.declare_entry(
        "Fallback",
        "true",
        Bool(),
        "Splitting solvers only: if the splitting stops without converging "
        "(it cycles or stalls, as it may for large friction coefficients), "
        "solve again by alart_curnier and then by nsgs; the log and "
        "summary.json (contact.solved_by) name the solver of the answer.");
      prm.declare_entry(
        "Allow non-converged",
        "false",
        Bool(),
        "If false (default), a run whose contact solver does not reach the "
        "tolerance writes its output (marked \"converged\": false in "
        "summary.json), says so, and exits with status 2. If true, it "
        "exits with status 0.");
    }



    void
    SolverParameters::parse_parameters(const dealii::ParameterHandler &prm)
    {
      options.type      = contact::solver_type_from_string(prm.get("Solver"));
      options.tolerance = prm.get_double("Tolerance");
      options.max_iterations = prm.get_integer("Maximum iterations");
      options.fallback       = prm.get_bool("Fallback");
      allow_non_converged    = prm.get_bool("Allow non-converged");
      if (options.tolerance <= 0)
        throw InputError("Contact / Tolerance: must be positive");
    }
  } // namespace scene
} // namespace dpana
