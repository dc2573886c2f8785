// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The bodies of a two-body scene assembled, factorised and condensed at the
// same time (Contact / Concurrent bodies = true). Up to the contact problem
// the bodies share nothing but the memory of the machine: each has its own
// mesh, matrix, factor and dense blocks, so each runs on a thread of its
// own, and the BLAS on the thread that calls it.
#include <dpana/linear_algebra/blas_threads.h>
#include <dpana/scene/scene.h>

#include <exception>
#include <future>
#include <vector>

namespace dpana
{
  namespace scene
  {
    namespace
    {
      // work(b) for b = 0 ... n - 1 at the same time, b = 0 on this thread
      // and each other on a thread of its own. Once all are done, the
      // exception of the first b that threw one is thrown again.
      template <typename Work>
      void
      for_each_at_once(const unsigned int n, const Work &work)
      {
        std::vector<std::future<void>> others;
        for (unsigned int b = 1; b < n; ++b)
          others.push_back(std::async(std::launch::async, work, b));
        std::exception_ptr first;
        try
          {
            work(0);
          }
        catch (...)
          {
            first = std::current_exception();
          }
        for (auto &f : others)
          try
            {
              f.get();
            }
          catch (...)
            {
              if (!first)
                first = std::current_exception();
            }
        if (first)
          std::rethrow_exception(first);
      }
    } // namespace



    template <int dim>
    std::string
    Scene<dim>::body_names() const
    {
      std::string names;
      for (unsigned int b = 0; b < bodies.size(); ++b)
        names += (b == 0                 ? "" :
                  b + 1 == bodies.size() ? " and " :
                                           ", ") +
                 bodies[b]->name();
      return names;
    }



    // Mesh, constraints, K and f of every body on the serial route (the
    // distributed assembly of the MPI route is Scene::assemble()'s).
    template <int dim>
    void
    Scene<dim>::assemble_concurrently()
    {
      {
        const auto phase =
          phase_log.phase("mesh", "meshing " + body_names() + " concurrently");
        for (const auto &body : bodies)
          phase_log.add("mesh", body->mesh_reading_time());
        for_each_at_once(bodies.size(), [this](const unsigned int b) {
          bodies[b]->create_mesh();
        });
      }
      const auto phase =
        phase_log.phase("assembly",
                        "assembling " + body_names() + " concurrently");
      for_each_at_once(bodies.size(), [this](const unsigned int b) {
        bodies[b]->setup();
        bodies[b]->assemble();
      });
    }



    // Each body's memory check adds the memory granted to the others
    // (condensation::MemoryReservations). A body deferred by it is
    // factorised again once the others are done, alone, by a new
    // Condenser, with the check of a run one body after the other.
    template <int dim>
    void
    Scene<dim>::factorize_concurrently()
    {
      condensation::MemoryReservations grants;
      std::vector<char>                deferred(bodies.size(), 0);
      {
        const auto phase =
          phase_log.phase("factorization",
                          "factorising " + body_names() + " concurrently");
        const linear_algebra::SingleThreadedBlas one_thread_per_body;
        for_each_at_once(bodies.size(), [&](const unsigned int b) {
          condensers[b]->set_memory_reservations(&grants);
          try
            {
              condensers[b]->factorize();
            }
          catch (const condensation::Deferred &)
            {
              deferred[b] = 1;
            }
          catch (...)
            {
              condensers[b]->set_memory_reservations(nullptr);
              throw;
            }
          condensers[b]->set_memory_reservations(nullptr);
        });
      }
      for (unsigned int b = 0; b < bodies.size(); ++b)
        if (deferred[b])
          {
            const auto phase =
              phase_log.phase("factorization",
                              "factorising " + bodies[b]->name() +
                                " after the others (its memory check)");
            condensers[b] = make_condenser(b);
            condensers[b]->factorize();
          }
    }



    template <int dim>
    void
    Scene<dim>::condense_concurrently()
    {
      const auto phase =
        phase_log.phase("condensation",
                        "condensing " + body_names() + " concurrently");
      const linear_algebra::SingleThreadedBlas one_thread_per_body;
      for_each_at_once(bodies.size(), [this](const unsigned int b) {
        condensers[b]->condense(condensation_parameters.columns_per_solve);
      });
    }



    template std::string
    Scene<2>::body_names() const;
    template std::string
    Scene<3>::body_names() const;
    template void
    Scene<2>::assemble_concurrently();
    template void
    Scene<3>::assemble_concurrently();
    template void
    Scene<2>::factorize_concurrently();
    template void
    Scene<3>::factorize_concurrently();
    template void
    Scene<2>::condense_concurrently();
    template void
    Scene<3>::condense_concurrently();
  } // namespace scene
} // namespace dpana
