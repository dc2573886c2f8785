// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_scene_scene_h
#define dpana_scene_scene_h

#include <dpana/base/phase_log.h>
#include <dpana/body/body.h>
#include <dpana/condensation/condenser.h>
#include <dpana/condensation/parameters.h>
#include <dpana/contact/problem.h>
#include <dpana/contact_surface/contact_surface.h>
#include <dpana/contact_surface/parameters.h>
#include <dpana/output/output.h>
#include <dpana/output/output_directory.h>
#include <dpana/scene/contact_parameters.h>
#include <dpana/scene/contact_summary.h>
#include <dpana/scene/references.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  namespace scene
  {
    /**
     * One run of dpana: one or two linear elastic bodies and, if the
     * parameter file has a `subsection Contact`, the frictional contact
     * between Body 1 and a rigid plane (one body) or Body 2. A run without
     * contact is the same run with the contact phases left out.
     *
     * The phases, each timed by one TimerOutput (PhaseLog) with the peak
     * memory after it, and each callable alone from a test or a tutorial:
     *
     * 1. assemble(): the mesh, the constraints, the stiffness matrix K and
     *    the load vector f of every body (and, without contact, the check
     *    that every body is held);
     * 2. build_contact_surface(): the candidate faces of Γc grouped into
     *    contact elements with their local frames, the pairing with Body 2
     *    or the rigid plane, and the initial gaps;
     * 3. condense(): one factorisation per body, the compliance A = V^T K^-1
     *    V and the load term on Γc, the equilibrium rows of the floating
     *    bodies, and the condensed contact problem (A, D, mu, G, e); two
     *    bodies are assembled, factorised and condensed at the same time,
     *    one thread each (Contact / Concurrent bodies, concurrent_bodies.cc);
     * 4. solve(): the contact problem by the chosen solver (without contact:
     *    K u = f for every body);
     * 5. recover(): u = K^-1 (f + V r) and the stresses of every body, the
     *    half width, zones and comparisons with the references;
     * 6. write_output(): VTU of the bodies and of the contact surface,
     *    contact.csv, summary.json, the plot, written all at once
     *    (output::OutputDirectory).
     */
    template <int dim>
    class Scene
    {
    public:
      Scene();
      ~Scene();

      /**
       * Declares the subsections of the bodies, `Contact` if
       * @p with_contact, and `Output` (not the top-level entries Dimension
       * and Number of bodies, see scene::declare_parameters()).
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         const unsigned int        n_bodies,
                         const bool                with_contact);

      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const unsigned int        n_bodies,
                       const bool                with_contact);

      /**
       * All phases; writes the output unless @p write_output is false.
       */
      void
      run(const bool write_output = true);

      void
      assemble();
      void
      build_contact_surface();
      void
      condense();
      void
      solve();
      void
      recover();
      void
      write_output();

      bool
      has_contact() const
      {
        return with_contact;
      }
      const ContactSummary &
      summary() const
      {
        return summary_;
      }
      bool
      accepts_non_converged() const
      {
        return solver.allow_non_converged;
      }
      const contact::ContactProblem &
      problem() const
      {
        return problem_;
      }
      const contact_surface::ContactSurface<dim> &
      surface(const unsigned int b) const
      {
        return *surfaces[b];
      }
      const condensation::Condenser<dim> &
      condenser(const unsigned int b) const
      {
        return *condensers[b];
      }
      Body<dim> &
      body(const unsigned int b)
      {
        return *bodies[b];
      }
      unsigned int
      n_bodies() const
      {
        return bodies.size();
      }
      // The displacement of body b (recovered from the contact tractions).
      const dealii::Vector<double> &
      displacement(const unsigned int b) const
      {
        return bodies[b]->solution();
      }
      const PhaseLog &
      phases() const
      {
        return phase_log;
      }
      const std::string &
      output_directory() const
      {
        return output_parameters.directory;
      }
      void
      set_output_directory(const std::string &dir)
      {
        output_parameters.directory = dir;
      }
      // A quiet run prints nothing.
      void
      set_quiet(const bool q)
      {
        phase_log.set_output(q ? nullptr : &std::cout);
        quiet = q;
      }
      // Name of the parameter file, quoted in the FCLIB file's info.
      void
      set_scene_file(const std::string &file)
      {
        scene_file = file;
      }
      // Tractions of element j: N, T (force / area).
      double
      normal_traction(const unsigned int j) const
      {
        return summary_.result.r(dim * j);
      }
      double
      tangential_traction(const unsigned int j, const unsigned int k = 0) const
      {
        return summary_.result.r(dim * j + 1 + k);
      }

    private:
      bool                                    with_contact = false;
      std::vector<std::unique_ptr<Body<dim>>> bodies;
      std::vector<std::unique_ptr<contact_surface::ContactSurface<dim>>>
                                                                 surfaces;
      std::vector<std::unique_ptr<condensation::Condenser<dim>>> condensers;

      // Components and their parameters.
      contact_surface::Parameters<dim> surface_parameters;
      condensation::Parameters         condensation_parameters;
      ContactLaw                       law;
      SolverParameters                 solver;
      References<dim>                  references;
      output::Parameters               output_parameters;

      std::string scene_file;
      std::string parameters_prm, parameters_json;
      bool        quiet = false;

      PhaseLog                phase_log;
      contact::ContactProblem problem_;
      ContactSummary          summary_;
      // The warnings of the contact surface and of the output, one line
      // each, for summary.json (the bodies and the references keep theirs).
      std::vector<std::string> warnings_;

      void
      warn(const std::string &text);

      void
      make_surfaces();
      void
      write_output(output::OutputDirectory &directory);
      void
      write_contact_output(const std::string &directory);
      void
      write_summary(const std::string &directory) const;
      void
      print_bodies() const;
      std::unique_ptr<condensation::Condenser<dim>>
      make_condenser(const unsigned int b) const;
      void
      print_factorization(const unsigned int b) const;
      // The bodies assembled, factorised, then condensed, at the same time
      // (concurrent_bodies.cc).
      void
      assemble_concurrently();
      void
      factorize_concurrently();
      void
      condense_concurrently();
      std::string
      body_names() const;
      void
      print_body_results() const;
    };
  } // namespace scene
} // namespace dpana

#endif
