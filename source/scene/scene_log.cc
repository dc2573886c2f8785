// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
// The lines of the log that describe the bodies of a scene: what was built
// (after the assembly) and what they carry (after an elastic solve).

#include <dpana/scene/scene.h>

#include <iostream>

namespace dpana
{
  namespace scene
  {
    template <int dim>
    void
    Scene<dim>::print_bodies() const
    {
      for (const auto &body : bodies)
        {
          std::cout << "        " << body->name() << ": "
                    << body->geometry_description() << "; "
                    << body->dof_handler().n_dofs() << " dofs, "
                    << body->constraints().n_constraints() << " constrained; "
                    << body->material().description(dim);
          if (!body->free_rigid_modes().empty())
            {
              std::cout << "; free rigid motions:";
              for (const auto &m : body->free_rigid_modes())
                std::cout << " " << m.description;
            }
          std::cout << std::endl;
          for (const auto &w : body->warnings())
            std::cout << "        warning: " << w << std::endl;
          for (const auto &cf : body->applied_concentrated_forces())
            std::cout << "        " << body->name() << ": concentrated force ("
                      << cf.force << ") requested at (" << cf.requested_point
                      << ") applied at vertex (" << cf.vertex << "), "
                      << cf.vertex.distance(cf.requested_point) << " mm away"
                      << std::endl;
        }
    }



    template <int dim>
    void
    Scene<dim>::print_body_results() const
    {
      for (const auto &body : bodies)
        {
          std::cout << "        " << body->name()
                    << ": max |u| = " << body->max_displacement()
                    << " mm; load resultant (" << body->applied_load_resultant()
                    << ")";
          for (const auto &[name, R] : body->reactions())
            std::cout << "; reaction " << name << " (" << R << ")";
          std::cout << std::endl;
        }
    }



    template void
    Scene<2>::print_bodies() const;
    template void
    Scene<3>::print_bodies() const;
    template void
    Scene<2>::print_body_results() const;
    template void
    Scene<3>::print_body_results() const;
  } // namespace scene
} // namespace dpana
