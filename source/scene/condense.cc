// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Phase 3 of a scene (scene.h): every body factored once and condensed on
// its candidate contact surface, then the contact problem of the bodies.
#include <dpana/condensation/contact_problem.h>
#include <dpana/linear_algebra/mumps_schur.h>
#include <dpana/scene/input_checks.h>
#include <dpana/scene/scene.h>

#include <iostream>

namespace dpana
{
  namespace scene
  {
    // @sect3{Phase 3: condensation}
    //
    // Each body is factored once and condensed on its candidate surface:
    // A_b = V_b^T K_b^-1 V_b and the load term. The contact problem then
    // adds the relative quantities of the two sides.
    template <int dim>
    void
    Scene<dim>::condense()
    {
      condensers.clear();
      for (unsigned int b = 0; b < bodies.size(); ++b)
        condensers.push_back(make_condenser(b));
      if (condensation_parameters.concurrent_bodies && bodies.size() > 1)
        {
          factorize_concurrently();
          for (unsigned int b = 0; b < bodies.size(); ++b)
            print_factorization(b);
          condense_concurrently();
        }
      else
        for (unsigned int b = 0; b < bodies.size(); ++b)
          {
            {
              const auto phase =
                phase_log.phase("factorization",
                                "factorising " + bodies[b]->name());
              condensers[b]->factorize();
            }
            print_factorization(b);
            const auto phase =
              phase_log.phase("condensation",
                              "condensing " + bodies[b]->name());
            condensers[b]->condense(condensation_parameters.columns_per_solve);
          }
      std::vector<const condensation::Condenser<dim> *> parts;
      for (const auto &c : condensers)
        parts.push_back(c.get());
      problem_ = condensation::assemble_contact_problem(
        parts, *surfaces[0], law.friction, law.cone, law.polygon_sides);
      // Patches around vertices on a symmetry line or plane carry no
      // tangential traction across it (tangentially_held_unknowns()).
      condensation::hold_tangential_tractions(
        problem_,
        condensation::tangentially_held_unknowns(*bodies[0], *surfaces[0]));
      warn(condensation::polygon_symmetry_warning(
        *bodies[0], *surfaces[0], law.cone, law.polygon_sides));
      summary_.asymmetry = condensation::largest_asymmetry(parts);
      check_held_by_contact(bodies, problem_);
      if (quiet)
        return;
      std::cout << "        Condensation: " << problem_.n_elements()
                << " contact elements, " << problem_.A.rows() << " unknowns, "
                << problem_.G.rows() << " equality rows (fictitious supports:";
      for (const auto &c : condensers)
        std::cout << " " << c->fictitious_supports().size();
      std::cout << "), relative asymmetry of A before symmetrisation "
                << summary_.asymmetry << std::endl;
    }



    // The memory estimate of body b's factorisation and, for MUMPS, its
    // statistics.
    template <int dim>
    void
    Scene<dim>::print_factorization(const unsigned int b) const
    {
      if (quiet)
        return;
      std::cout << "        Memory estimate of " << bodies[b]->name() << ": "
                << condensers[b]->memory_estimate().describe() << std::endl;
      const auto *mumps =
        dynamic_cast<const linear_algebra::MumpsSchurFactorization *>(
          &condensers[b]->schur_factorization());
      if (mumps != nullptr)
        std::cout << "        MUMPS on " << mumps->n_ranks()
                  << " rank(s): " << mumps->statistics().describe()
                  << std::endl;
    }



    // The condensation of body b with the parameters of the run.
    template <int dim>
    std::unique_ptr<condensation::Condenser<dim>>
    Scene<dim>::make_condenser(const unsigned int b) const
    {
      return std::make_unique<condensation::Condenser<dim>>(
        *bodies[b], *surfaces[b], condensation_parameters);
    }



    template void
    Scene<2>::condense();
    template std::unique_ptr<condensation::Condenser<2>>
    Scene<2>::make_condenser(const unsigned int) const;
    template void
    Scene<2>::print_factorization(const unsigned int) const;
    template void
    Scene<3>::condense();
    template std::unique_ptr<condensation::Condenser<3>>
    Scene<3>::make_condenser(const unsigned int) const;
    template void
    Scene<3>::print_factorization(const unsigned int) const;
  } // namespace scene
} // namespace dpana
