// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/parallel/route.h>
#include <dpana/scene/run.h>
#include <dpana/scene/scene.h>

#include <deal.II/base/patterns.h>

#include <iostream>

namespace dpana
{
  namespace scene
  {
    void
    declare_parameters(dealii::ParameterHandler      &prm,
                       const parameters::FileOutline &outline)
    {
      parameters::declare_dimension(prm);
      prm.declare_entry("Number of bodies",
                        "1",
                        dealii::Patterns::Integer(1, 2),
                        "1: Body 1 alone (elastic run) or against a rigid "
                        "plane obstacle (Signorini); 2: Body 1 against "
                        "Body 2.");
      if (outline.dimension == 2)
        Scene<2>::declare_parameters(prm,
                                     outline.n_bodies,
                                     outline.has_contact);
      else
        Scene<3>::declare_parameters(prm,
                                     outline.n_bodies,
                                     outline.has_contact);
    }



    void
    print_parameters(const std::string &prm_file, std::ostream &out)
    {
      const parameters::FileOutline outline = prm_file.empty() ?
                                                parameters::FileOutline() :
                                                parameters::scan_file(prm_file);
      dealii::ParameterHandler      prm;
      declare_parameters(prm, outline);
      if (!prm_file.empty())
        parameters::parse_file(prm, prm_file);
      out << "# dpana parameter file (Dimension = " << outline.dimension
          << (outline.has_contact ? ", contact run" : ", elastic run")
          << "); units: mm, N, MPa\n";
      prm.print_parameters(out,
                           dealii::ParameterHandler::PRM |
                             dealii::ParameterHandler::KeepDeclarationOrder);
    }



    namespace
    {
      template <int dim>
      int
      run(const std::string &prm_file, const parameters::FileOutline &outline)
      {
        dealii::ParameterHandler prm;
        declare_parameters(prm, outline);
        parameters::parse_file(prm, prm_file);
        // On several MPI ranks every rank runs the scene (doc/parallel.md);
        // rank 0 alone prints and writes.
        const unsigned int n_ranks = parallel::n_world_ranks();
        if (n_ranks > 1 && !outline.has_contact)
          throw InputError("an elastic run (no subsection Contact) runs on "
                           "one process, not on " +
                           std::to_string(n_ranks) +
                           " MPI ranks; the MPI route (Contact / Parallel "
                           "route) needs a contact scene");
        const bool root = parallel::is_root();
        Scene<dim> scene;
        scene.set_quiet(!root);
        scene.parse_parameters(prm, outline.n_bodies, outline.has_contact);
        scene.set_scene_file(prm_file);
        scene.run(root);

        // A run that did not converge has written its output, marked as
        // such, but must not pass for a result: it exits non-zero unless
        // the user accepted it explicitly.
        const auto &result = scene.summary().result;
        if (scene.has_contact() && !result.converged &&
            !scene.accepts_non_converged())
          {
            if (root)
              std::cerr << "dpana: error: the contact solver did not converge "
                        << "(residual " << result.residual << " after "
                        << result.iterations
                        << " iterations: " << result.message
                        << "); set Contact / Allow non-converged = true to "
                        << "accept it" << std::endl;
            return exit_not_converged;
          }
        return 0;
      }
    } // namespace



    int
    run(const std::string &prm_file)
    {
      const parameters::FileOutline outline = parameters::scan_file(prm_file);
      return outline.dimension == 2 ? run<2>(prm_file, outline) :
                                      run<3>(prm_file, outline);
    }
  } // namespace scene
} // namespace dpana
