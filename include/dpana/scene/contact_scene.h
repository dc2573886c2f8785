// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_scene_contact_scene_h
#define dpana_scene_contact_scene_h

#include <dpana/body/body.h>
#include <dpana/condensation/condenser.h>
#include <dpana/contact/solver.h>
#include <dpana/contact_surface/contact_surface.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <Eigen/Dense>

#include <array>
#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  namespace scene
  {
    /**
     * Declare every parameter of a contact run: the top-level entries
     * `Dimension` and `Number of bodies`, the subsections `Body 1` (and
     * `Body 2`) of Body<dim>, and the subsection `Contact` (candidate
     * surface, friction, solver, reference values, output).
     */
    void
    declare_parameters(dealii::ParameterHandler &prm,
                       const unsigned int        dim,
                       const unsigned int        n_bodies);

    /**
     * Run the contact scene of @p prm_file, whose dimension and number of
     * bodies the pre-scan parameters::scan_file() has read into
     * @p outline: build the bodies, condense them on the candidate contact
     * surface, solve the contact problem, recover the displacements and
     * stresses and write the output. Errors in the input are printed as one
     * line "dpana: error: ..." on std::cerr. Returns the exit status: 0 on
     * success, 1 on an input error, exit_not_converged if the contact
     * solver did not converge (the output is written and marked as such)
     * and `Contact / Allow non-converged` is false.
     */
    int
    run_contact(const std::string             &prm_file,
                const parameters::FileOutline &outline);

    /**
     * Exit status of a run whose contact solver did not converge (and
     * `Contact / Allow non-converged` is false).
     */
    constexpr int exit_not_converged = 2;

    /**
     * The values a run produces, for the log, the JSON summary and tests.
     */
    struct Zone
    {
      contact::ContactStatus status;
      double                 from, to; // along s (2D) or bounding box in s
      double                 t_from = 0, t_to = 0; // 3D: bounding box in t
      unsigned int           n_elements = 0;
    };

    /**
     * The comparison of a run with one of its references: the kind
     * ("uniform", "hertz", "seed table", "table"), the log line, and the
     * named numbers (reference values and relative errors) that the JSON
     * summary lists.
     */
    struct Comparison
    {
      std::string                                 type;
      std::string                                 text;
      std::vector<std::pair<std::string, double>> values;
    };

    struct Summary
    {
      std::vector<unsigned int> dofs; // per body
      unsigned int              n_elements = 0;
      double half_width          = 0; // outer edge of the contact zone
      double half_width_centroid = 0;
      // Tangential size of the element that ends the contact zone: with
      // piecewise constant tractions, a is known to this size.
      double                        half_width_element     = 0;
      double                        max_pressure           = 0; // max(-N)
      double                        normal_resultant       = 0; // sum(-N area)
      bool                          candidate_edge_warning = false;
      std::vector<Zone>             zones;
      std::map<std::string, double> timings;
      contact::SolverResult         result;
      double                        asymmetry = 0;
      std::vector<double>           element_residual;
      std::vector<Comparison>       comparisons;
    };

    /**
     * A contact run of dimension dim, usable by programs and tests: parse,
     * then run() (or the phases one by one).
     */
    template <int dim>
    class ContactScene
    {
    public:
      ContactScene();
      ~ContactScene();

      /**
       * Read all parameters (the handler has been declared by
       * declare_parameters() and filled).
       */
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const unsigned int        n_bodies);

      /**
       * All phases; writes the output unless @p write_output is false.
       */
      void
      run(const bool write_output = true);

      void
      setup_bodies();
      void
      setup_surfaces();
      void
      condense();
      void
      solve();
      void
      recover();
      void
      write_output();
      void
      print_comparison(std::ostream &out) const;

      const Summary &
      summary() const
      {
        return summary_;
      }

      // True if `Contact / Allow non-converged` is set.
      bool
      accepts_non_converged() const
      {
        return allow_non_converged;
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
      // The displacement of body b recovered from the contact tractions.
      const dealii::Vector<double> &
      displacement(const unsigned int b) const
      {
        return bodies[b]->solution();
      }
      void
      set_output_directory(const std::string &dir)
      {
        output_directory = dir;
      }
      void
      set_quiet(const bool q)
      {
        quiet = q;
      }
      // Name of the parameter file, quoted in the FCLIB file's info.
      void
      set_scene_file(const std::string &file)
      {
        scene_file = file;
      }
      // Tractions of element j: N, T (force / area, seeds' signs).
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
      std::vector<std::unique_ptr<Body<dim>>> bodies;
      std::vector<std::unique_ptr<contact_surface::ContactSurface<dim>>>
                                                                 surfaces;
      std::vector<std::unique_ptr<condensation::Condenser<dim>>> condensers;

      // Contact parameters.
      std::vector<std::string> boundary;
      dealii::Point<dim>       region_centre;
      double                   region_half_width = 0;
      unsigned int             faces_per_element = 0;
      dealii::Tensor<1, dim>   direction;
      bool                     obstacle_point_given = false;
      dealii::Point<dim>       obstacle_point;
      double                   friction      = 0;
      contact::ConeModel       cone          = contact::ConeModel::disc;
      unsigned int             polygon_sides = 16;
      contact::SolverOptions   solver_options;
      unsigned int             columns_per_pass    = 256;
      bool                     allow_non_converged = false;

      // Reference values.
      std::string reference_type          = "none";
      double      uniform_normal_traction = 0;
      double      hertz_load = 0, radius_1 = 0, radius_2 = 0;
      double      seed_half_width = 0, seed_max_pressure = 0;
      std::string reference_csv;
      // Rows (s, N, T) of the comparison file, sorted by s; empty if none.
      std::vector<std::array<double, 3>> reference_table;

      // Output.
      std::string output_directory = "output";
      bool        plot             = true;
      bool        write_fclib      = false;
      std::string scene_file;
      bool        quiet = false;
      std::string parameters_text;

      contact::ContactProblem problem_;
      Summary                 summary_;

      void
      compute_summary();
      void
      compare_with_references();
      void
      write_surface_vtu() const;
      void
      write_csv(const std::string &file) const;
      void
      write_json() const;
      void
      load_reference_table();
    };
  } // namespace scene
} // namespace dpana

#endif
