// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/parameters/parameters.h>
#include <dpana/scene/contact_scene.templates.h>

#include <deal.II/base/patterns.h>

#include <iostream>

namespace dpana
{
  namespace scene
  {
    template class ContactScene<2>;
    template class ContactScene<3>;



    void
    declare_parameters(dealii::ParameterHandler &prm,
                       const unsigned int        dim,
                       const unsigned int        n_bodies)
    {
      using namespace dealii::Patterns;
      parameters::declare_dimension(prm);
      prm.declare_entry("Number of bodies",
                        "1",
                        Integer(1, 2),
                        "1: Body 1 against a rigid plane obstacle (Signorini); "
                        "2: Body 1 against Body 2.");
      for (unsigned int b = 0; b < n_bodies; ++b)
        {
          prm.enter_subsection("Body " + std::to_string(b + 1));
          if (dim == 2)
            Body<2>::declare_parameters(prm);
          else
            Body<3>::declare_parameters(prm);
          prm.leave_subsection();
        }

      const std::string zero = dim == 2 ? "0, 0" : "0, 0, 0";
      prm.enter_subsection("Contact");
      {
        prm.declare_entry("Boundary 1",
                          "bottom",
                          Anything(),
                          "Named boundary of Body 1 that holds the candidate "
                          "contact surface Gamma_c.");
        prm.declare_entry("Boundary 2",
                          "top",
                          Anything(),
                          "Named boundary of Body 2 that holds Gamma_c (two "
                          "bodies only); its faces must match those of Body 1 "
                          "one to one.");
        prm.declare_entry("Candidate centre",
                          zero,
                          Anything(),
                          "Centre x0 of the candidate region (mm); also the "
                          "origin from which the contact half width is "
                          "measured.");
        prm.declare_entry("Candidate half width",
                          "0",
                          Double(0.),
                          "Half width w of the candidate region (mm): only the "
                          "faces whose centroid x has |x_d - x0_d| <= w in "
                          "every direction d are candidates. 0: the whole "
                          "boundary.");
        prm.declare_entry("Faces per contact element",
                          "0",
                          Integer(0),
                          "Number of faces grouped into one contact element "
                          "carrying constant tractions. 0: 2 edges in 2D, 8 "
                          "triangles (a 2 x 2 patch of split quadrilaterals) "
                          "in 3D.");
        prm.declare_entry("Contact direction",
                          "",
                          Anything(),
                          "Unit normal n (pointing out of Body 1 towards the "
                          "obstacle) used by every contact element, e.g. "
                          "'0, -1': the normal of the tangent plane of an "
                          "increasing (Hertz) problem. Empty: each element "
                          "uses the mean outward normal of its faces.");
        prm.declare_entry(
          "Obstacle point",
          "",
          Anything(),
          "One body: a point (mm) of the rigid plane obstacle, "
          "normal to the contact direction. Empty: the first "
          "contact point (the candidate vertex farthest along "
          "n), so that the initial gap is >= 0 and zero there.");
        prm.declare_entry("Friction coefficient",
                          "0",
                          Double(0.),
                          "Coulomb friction coefficient mu (dimensionless).");
        prm.declare_entry("Cone model",
                          "disc",
                          Selection("disc|polygon"),
                          "3D friction set: the exact disc ||T|| <= -mu N, or "
                          "the circumscribed polygon of the seeds.");
        prm.declare_entry("Polygon sides",
                          "16",
                          Integer(3),
                          "Number of sides of the friction polygon (3D).");
        prm.declare_entry(
          "Solver",
          "splitting_active_set",
          Selection("splitting_active_set|splitting_pgs|nsgs|alart_curnier"),
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
          "Allow non-converged",
          "false",
          Bool(),
          "If false (default), a run whose contact solver does not reach the "
          "tolerance writes its output (marked \"converged\": false in "
          "summary.json), says so, and exits with status 2. If true, it "
          "exits with status 0.");
        prm.declare_entry("Columns per solve",
                          "256",
                          Integer(1),
                          "Columns of V handed at once to the blocked sparse "
                          "Cholesky solves of the condensation.");
        prm.enter_subsection("Reference");
        {
          prm.declare_entry("Type",
                            "none",
                            Selection("none|uniform|hertz"),
                            "Reference printed with the results: 'uniform' "
                            "(every element N = Uniform normal traction, "
                            "T = 0), 'hertz' (plane strain Hertz formulas).");
          prm.declare_entry("Uniform normal traction",
                            "-50",
                            Double(),
                            "Expected uniform N (MPa, compressive < 0).");
          prm.declare_entry("Hertz load",
                            "200000",
                            Double(0.),
                            "Load P per unit length of the whole (not half) "
                            "model (N/mm).");
          prm.declare_entry("Radius 1",
                            "40",
                            Double(0.),
                            "Radius of the cylinder (Body 1) (mm).");
          prm.declare_entry("Radius 2",
                            "0",
                            Double(),
                            "Radius of the other surface (mm): 0 flat, > 0 "
                            "convex, < 0 a cavity of radius |Radius 2|.");
          prm.declare_entry("Seed half width",
                            "0",
                            Double(0.),
                            "Contact half width of the seeds' table (mm), "
                            "0: none.");
          prm.declare_entry("Seed maximum pressure",
                            "0",
                            Double(0.),
                            "-N_max of the seeds' table (MPa), 0: none.");
          prm.declare_entry("Comparison file",
                            "",
                            Anything(),
                            "CSV of another run (columns s, N, T) compared "
                            "with this one, e.g. the 2D plane solution for a "
                            "3D run.");
        }
        prm.leave_subsection();
        prm.enter_subsection("Output");
        {
          prm.declare_entry("Directory",
                            "output/contact",
                            Anything(),
                            "Directory of the output files (created).");
          prm.declare_entry("Plot",
                            "true",
                            Bool(),
                            "Write contact.png with scripts/plot_contact.py.");
          prm.declare_entry("Write FCLIB",
                            "false",
                            Bool(),
                            "Write the condensed contact problem to "
                            "problem.hdf5 in the output directory, as an "
                            "FCLIB local problem (HDF5) for other contact "
                            "solvers.");
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }



    namespace
    {
      template <int dim>
      int
      run(const std::string &prm_file, const unsigned int n_bodies)
      {
        dealii::ParameterHandler prm;
        declare_parameters(prm, dim, n_bodies);
        parameters::parse_file(prm, prm_file);
        ContactScene<dim> scene;
        scene.parse_parameters(prm, n_bodies);
        scene.set_scene_file(prm_file);
        scene.run(true);

        // A run that did not converge has written its output, marked as
        // such, but must not pass for a result: it exits non-zero unless
        // the user accepted it explicitly.
        const auto &result = scene.summary().result;
        if (!result.converged && !scene.accepts_non_converged())
          {
            std::cerr << "dpana: error: the contact solver did not converge "
                      << "(residual " << result.residual << " after "
                      << result.iterations << " iterations: " << result.message
                      << "); set Contact / Allow non-converged = true to "
                      << "accept it" << std::endl;
            return exit_not_converged;
          }
        return 0;
      }
    } // namespace



    int
    run_contact(const std::string             &prm_file,
                const parameters::FileOutline &outline)
    {
      try
        {
          return outline.dimension == 2 ? run<2>(prm_file, outline.n_bodies) :
                                          run<3>(prm_file, outline.n_bodies);
        }
      catch (const InputError &e)
        {
          std::cerr << "dpana: error: " << e.what() << std::endl;
          return 1;
        }
    }
  } // namespace scene
} // namespace dpana
