// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/base/machine.h>
#include <dpana/base/warnings.h>
#include <dpana/condensation/contact_problem.h>
#include <dpana/contact_surface/format_point.h>
#include <dpana/io/fclib.h>
#include <dpana/output/contact_output.h>
#include <dpana/output/output_directory.h>
#include <dpana/output/summary.h>
#include <dpana/parallel/route.h>
#include <dpana/parameters/list_syntax.h>
#include <dpana/scene/input_checks.h>
#include <dpana/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <sstream>

namespace dpana
{
  namespace scene
  {
    namespace
    {
      // The table of the contact elements in an output directory, which
      // write_contact_output() writes and the plot reads.
      const std::string contact_csv = "/contact.csv";



      // Whether the VTU output of the bodies is written in per-rank pieces.
      bool
      writes_in_pieces(const parallel::Route route)
      {
        return route == parallel::Route::mpi && parallel::n_world_ranks() > 1;
      }



      // The MPI route with several ranks: every rank holds its cells of
      // each body (or the whole mesh) and the whole solution, and writes
      // its share of each body's cells into rank 0's staging directory
      // (output::write_bodies()). Rank 0 commits the
      // directory only after the barrier, when all pieces are written.
      template <int dim>
      void
      write_bodies_on_all_ranks(
        const std::vector<std::unique_ptr<Body<dim>>> &bodies,
        const std::string                             &root_staging)
      {
        const MPI_Comm    comm = MPI_COMM_WORLD;
        const std::string staging =
          dealii::Utilities::MPI::broadcast(comm, root_staging, 0);
        output::write_bodies(bodies,
                             staging,
                             dealii::Utilities::MPI::this_mpi_process(comm),
                             dealii::Utilities::MPI::n_mpi_processes(comm));
        MPI_Barrier(comm);
      }
    } // namespace



    template <int dim>
    Scene<dim>::Scene()
      : phase_log(&std::cout)
    {
    }

    template <int dim>
    Scene<dim>::~Scene() = default;



    // @sect3{Parameters}
    //
    // Every component declares and reads its own entries: the bodies their
    // subsections, the contact surface, the contact law, the solver, the
    // condensation and the references theirs inside `subsection Contact`,
    // the output its `subsection Output`.
    template <int dim>
    void
    Scene<dim>::declare_parameters(dealii::ParameterHandler &prm,
                                   const unsigned int        n_bodies,
                                   const bool                with_contact)
    {
      for (unsigned int b = 0; b < n_bodies; ++b)
        {
          prm.enter_subsection("Body " + std::to_string(b + 1));
          Body<dim>::declare_parameters(prm);
          prm.leave_subsection();
        }
      if (with_contact)
        {
          prm.enter_subsection("Contact");
          contact_surface::Parameters<dim>::declare_parameters(prm);
          condensation::Parameters::declare_parameters(prm);
          ContactLaw::declare_parameters(prm);
          SolverParameters::declare_parameters(prm);
          References<dim>::declare_parameters(prm);
          prm.leave_subsection();
        }
      prm.enter_subsection("Output");
      output::Parameters::declare_parameters(prm);
      prm.leave_subsection();
    }



    template <int dim>
    void
    Scene<dim>::parse_parameters(dealii::ParameterHandler &prm,
                                 const unsigned int        n_bodies,
                                 const bool                contact)
    {
      with_contact = contact;
      bodies.clear();
      for (unsigned int b = 0; b < n_bodies; ++b)
        {
          const std::string name = "Body " + std::to_string(b + 1);
          bodies.push_back(std::make_unique<Body<dim>>(name));
          prm.enter_subsection(name);
          bodies.back()->parse_parameters(prm);
          prm.leave_subsection();
        }
      if (with_contact)
        {
          prm.enter_subsection("Contact");
          surface_parameters.parse_parameters(prm);
          condensation_parameters.parse_parameters(prm);
          law.parse_parameters(prm, dim);
          solver.parse_parameters(prm);
          references.parse_parameters(prm);
          prm.leave_subsection();
          check_contact_boundaries_free(bodies, surface_parameters.boundary);
        }
      prm.enter_subsection("Output");
      output_parameters.parse_parameters(prm);
      prm.leave_subsection();
      if (output_parameters.write_mesh && with_contact &&
          condensation_parameters.distributed_mesh)
        throw InputError("Output / Write mesh: not with a distributed mesh "
                         "(Contact / Parallel mesh = distributed), where no "
                         "rank holds the whole mesh");

      std::ostringstream text, json;
      prm.print_parameters(text,
                           dealii::ParameterHandler::ShortPRM |
                             dealii::ParameterHandler::KeepDeclarationOrder);
      prm.print_parameters(json, dealii::ParameterHandler::JSON);
      parameters_prm  = text.str();
      parameters_json = json.str();
    }



    // @sect3{Phase 1: the bodies}
    //
    // Mesh, constraints, stiffness matrix and load vector of every body.
    // Without contact every body must be held by its supports; with contact
    // a body may float, and the condensation holds it by fictitious
    // supports whose reactions the contact problem drives to zero.
    template <int dim>
    void
    Scene<dim>::assemble()
    {
      const bool distributed =
        with_contact && condensation_parameters.distributed_assembly;
      if (with_contact && condensation_parameters.concurrent_bodies &&
          bodies.size() > 1 && !distributed)
        assemble_concurrently();
      else
        for (auto &body : bodies)
          {
            // The distributed assembly of the MPI route: the cells split over
            // the ranks (a body needs at least one cell per rank); with a
            // distributed mesh only rank 0 builds the whole mesh.
            if (distributed)
              body->partition(MPI_COMM_WORLD,
                              condensation_parameters.distributed_mesh);
            {
              const auto phase =
                phase_log.phase("mesh", "meshing " + body->name());
              phase_log.add("mesh", body->mesh_reading_time());
              body->create_mesh();
            }
            const auto phase =
              phase_log.phase("assembly", "assembling " + body->name());
            if (distributed)
              parallel::check_ranks(body->name(),
                                    body->n_cells(),
                                    parallel::n_world_ranks());
            body->setup();
            if (!with_contact)
              body->check_held();
            body->assemble();
          }
      if (!quiet)
        print_bodies();
      // On several ranks, the peak memory of every rank so far and the
      // memory it holds now (the mesh, K, f): what the distributed assembly
      // and the distributed mesh save (doc/parallel.md).
      if (with_contact && condensation_parameters.route == parallel::Route::mpi)
        {
          const auto peaks =
            dealii::Utilities::MPI::gather(MPI_COMM_WORLD, peak_memory_mb(), 0);
          // In MB of 2^20 bytes, as the peak.
          const auto resident = dealii::Utilities::MPI::gather(
            MPI_COMM_WORLD, condensation::resident_memory() / 1048576.0, 0);
          if (!quiet && parallel::is_root())
            {
              const std::string how =
                condensation_parameters.distributed_mesh ? "distributed mesh" :
                condensation_parameters.distributed_assembly ? "distributed" :
                                                               "replicated";
              std::cout << "        Peak memory after the assembly (" << how
                        << "), per rank (MB):";
              for (const double m : peaks)
                std::cout << " " << m;
              std::cout << "\n        Resident memory after the assembly ("
                        << how << "), per rank (MB):";
              for (const double m : resident)
                std::cout << " " << m;
              std::cout << std::endl;
            }
        }
    }



    // print_bodies() and print_body_results(): scene_log.cc.



    // @sect3{Phase 2: the contact surface}
    template <int dim>
    void
    Scene<dim>::build_contact_surface()
    {
      Assert(with_contact, dealii::ExcMessage("A run without contact."));
      {
        const auto phase = phase_log.phase("contact surface");
        make_surfaces();
      }
      // The warnings are rank 0's, which writes the summary.
      if (!parallel::is_root())
        return;
      for (const auto &s : surfaces)
        {
          if (!quiet)
            std::cout << "        Candidate contact surface: "
                      << s->description() << std::endl;
          warn(surface_resolution(*s, s == surfaces[0]));
        }
      warn(leaning_direction(*bodies[0], *surfaces[0], bodies.size() == 1));
      warn(far_gap(*surfaces[0]));
    }



    // A warning of the scene (empty: none) in the log, indented under the
    // phase that found it, and in summary.json.
    template <int dim>
    void
    Scene<dim>::warn(const std::string &text)
    {
      if (add_warning(warnings_, text) && !quiet)
        std::cout << "        warning: " << text << std::endl;
    }



    template <int dim>
    void
    Scene<dim>::make_surfaces()
    {
      surfaces.clear();
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          auto options =
            surface_parameters.surface_options(b,
                                               bodies[b]->name(),
                                               bodies[b]->boundary_names());
          options.rigid_plane = bodies.size() == 1;
          surfaces.push_back(
            std::make_unique<contact_surface::ContactSurface<dim>>());
          if (b == 0)
            surfaces[0]->build(bodies[0]->dof_handler(),
                               options,
                               bodies[0]->communicator());
          else
            surfaces[1]->pair(bodies[1]->dof_handler(),
                              options,
                              *surfaces[0],
                              bodies[1]->communicator());
        }
      if (bodies.size() == 1)
        {
          // The rigid obstacle: the plane through the obstacle point (by
          // default the first contact point of the candidate surface) normal
          // to the contact direction.
          surfaces[0]->set_plane_gap(surface_parameters.obstacle_point_given ?
                                       surface_parameters.obstacle_point :
                                       surfaces[0]->first_contact_point());
        }
    }



    // @sect3{Phase 4: the solve}
    template <int dim>
    void
    Scene<dim>::solve()
    {
      if (!with_contact)
        {
          for (auto &body : bodies)
            {
              const auto phase =
                phase_log.phase("solve",
                                "factorising and solving " + body->name() +
                                  " (sparse Cholesky)");
              body->solve();
            }
          return;
        }
      {
        const auto phase =
          phase_log.phase("contact solve",
                          "solving the contact problem (" +
                            contact::to_string(solver.options.type) + ")");
        // On the MPI route rank 0 alone solves; the others receive its
        // result.
        const bool mpi = condensation_parameters.route == parallel::Route::mpi;
        try
          {
            if (!mpi || parallel::is_root())
              summary_.result = contact::solve(problem_, solver.options);
          }
        catch (const std::invalid_argument &e)
          {
            throw InputError(std::string("Contact: ") + e.what());
          }
        if (mpi)
          parallel::broadcast(summary_.result, MPI_COMM_WORLD);
      }
      const auto &r = summary_.result;
      if (!quiet)
        std::cout << "        Contact solver "
                  << contact::to_string(solver.options.type)
                  << (r.fallbacks.empty() ?
                        std::string() :
                        " (answer by " + contact::to_string(r.solver) + ")")
                  << ": " << (r.converged ? "converged" : "NOT converged")
                  << " in " << r.iterations << " iterations, residual "
                  << r.residual << " (" << r.message << ")" << std::endl;
    }



    // @sect3{Phase 5: recovery}
    //
    // With contact, u_b = K_b^-1 (f_b + V_b r) plus the rigid displacements
    // of the floating bodies; without, the solution is already there. Then
    // the stresses, and the measures of the contact zone.
    template <int dim>
    void
    Scene<dim>::recover()
    {
      const auto phase = phase_log.phase("recovery");
      if (!with_contact)
        {
          for (auto &body : bodies)
            body->postprocess();
          return;
        }
      unsigned int offset = 0;
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const unsigned int    mb = condensers[b]->n_free_modes();
          const Eigen::VectorXd alpha =
            summary_.result.alpha.segment(offset, mb);
          offset += mb;
          bodies[b]->set_solution(
            condensers[b]->recover(summary_.result.r, alpha));
          bodies[b]->compute_stresses();
        }
      // The approach is measured on every rank (with a distributed mesh,
      // the ranks that hold the points evaluate the displacement there).
      // The summary needs A, which on the MPI route rank 0 alone holds and
      // which rank 0 alone prints and writes.
      references.measure_approach(bodies, *surfaces[0], summary_);
      const auto approach = summary_.estimates;
      if (condensation_parameters.route == parallel::Route::mpi &&
          !parallel::is_root())
        return;
      summarise(*surfaces[0],
                problem_,
                surface_parameters.region_centre,
                summary_,
                held_across_centre(*bodies[0],
                                   *surfaces[0],
                                   surface_parameters.region_centre));
      summary_.estimates.approach_measured = approach.approach_measured;
      summary_.estimates.approach          = approach.approach;
      references.check_radii(surfaces);
      summary_.comparisons = references.compare(bodies, *surfaces[0], summary_);
    }



    // @sect3{Phase 6: output}
    //
    // The results are written into a staging directory that replaces the
    // output directory only when everything is written
    // (output::OutputDirectory): afterwards the directory holds exactly this
    // run's files, and a run that fails leaves nothing behind and the
    // previous results intact.
    template <int dim>
    void
    Scene<dim>::write_output()
    {
      output::OutputDirectory directory(output_parameters.directory);
      write_output(directory);
    }



    template <int dim>
    void
    Scene<dim>::write_output(output::OutputDirectory &directory)
    {
      const std::string staging = directory.staging();
      {
        const auto phase =
          phase_log.phase("output",
                          "writing output to " + output_parameters.directory);
        std::ofstream(staging + "/parameters.prm") << parameters_prm;
        std::ofstream(staging + "/parameters.json") << parameters_json;
        // The contact files first, so that the plot of contact.csv (a python
        // process of about a second) is drawn while the bodies are written.
        std::future<std::string> plot;
        if (with_contact)
          {
            write_contact_output(staging);
            if (output_parameters.plot)
              plot = std::async(std::launch::async,
                                output::plot_contact,
                                staging + contact_csv,
                                staging + "/contact.png");
          }
        if (output_parameters.write_vtu &&
            writes_in_pieces(condensation_parameters.route))
          write_bodies_on_all_ranks(bodies, staging);
        else if (output_parameters.write_vtu)
          output::write_bodies(bodies, staging);
        if (output_parameters.write_mesh)
          output::write_meshes(bodies, staging);
        if (plot.valid())
          warn(plot.get());
      }
      write_summary(staging);
      directory.commit();
    }



    template <int dim>
    void
    Scene<dim>::write_contact_output(const std::string &directory)
    {
      output::write_contact_surface_vtu(*surfaces[0],
                                        summary_,
                                        directory + "/contact_surface.vtu");
      output::write_contact_csv(*surfaces[0],
                                summary_,
                                directory + contact_csv);
      if (output_parameters.write_fclib)
        {
          // The condensed problem, for other contact solvers.
          const std::string scene =
            scene_file.empty() ? std::string("(unnamed)") : scene_file;
          io::FclibInfo info;
          info.title       = "dpana contact scene " + scene;
          info.description = "Condensed frictional contact problem of the "
                             "dpana scene " +
                             scene + ", dimension " + std::to_string(dim) +
                             ", " + std::to_string(problem_.n_elements()) +
                             " contact elements";
          io::write_fclib_local(directory + "/problem.hdf5", problem_, info);
        }
    }



    // One summary for every run: the bodies, the contact answer if there is
    // one, the time and peak memory of every phase.
    template <int dim>
    void
    Scene<dim>::write_summary(const std::string &directory) const
    {
      nlohmann::json summary = output::to_json(phase_log);
      summary["machine"] =
        output::to_json(this_machine(), parallel::n_world_ranks());
      summary["dimension"] = dim;
      summary["bodies"]    = nlohmann::json::array();
      for (const auto &body : bodies)
        summary["bodies"].push_back(output::to_json(*body));
      for (const auto &body : bodies)
        for (const auto &w : body->warnings())
          summary["warnings"].push_back(w);
      for (const auto &w : references.warnings())
        summary["warnings"].push_back(w);
      if (with_contact && summary_.candidate_edge_warning)
        summary["warnings"].push_back(candidate_edge_warning());
      for (const auto &w : warnings_)
        summary["warnings"].push_back(w);
      if (with_contact)
        {
          summary["contact"] = output::to_json(summary_, dim);
          summary["contact"]["friction_coefficient"] = law.friction;
          summary["contact"]["solver"] =
            contact::to_string(solver.options.type);
          summary["memory_estimate_mb"] = nlohmann::json::array();
          for (const auto &c : condensers)
            {
              const auto &m = c->memory_estimate();
              if (!m.made)
                {
                  summary["memory_estimate_mb"].push_back(nullptr);
                  continue;
                }
              summary["memory_estimate_mb"].push_back(
                {{"n_dofs", m.n_dofs},
                 {"n_gamma", m.n_gamma},
                 {"n_c", m.n_c},
                 {"before", m.current / 1e6},
                 {"factor", m.factor / 1e6},
                 {"dense", m.dense / 1e6},
                 {"total", m.total() / 1e6}});
            }
        }
      output::write_json(summary, directory + "/summary.json");
    }



    // A run checks first that it can write its output directory, so that a
    // mistyped or unwritable path does not throw away a long computation.
    template <int dim>
    void
    Scene<dim>::run(const bool output)
    {
      std::unique_ptr<output::OutputDirectory> directory;
      if (output)
        directory = std::make_unique<output::OutputDirectory>(
          output_parameters.directory);
      assemble();
      if (with_contact)
        {
          build_contact_surface();
          condense();
        }
      solve();
      recover();
      if (output)
        write_output(*directory);
      else if (writes_in_pieces(condensation_parameters.route) &&
               output_parameters.write_vtu)
        write_bodies_on_all_ranks(bodies, std::string());
      if (quiet)
        return;
      if (with_contact)
        print(summary_, dim, std::cout);
      else
        print_body_results();
      phase_log.print(std::cout);
      std::cout << describe(this_machine()) << std::endl;
      if (output)
        std::cout << "Output written to " << output_parameters.directory << "/"
                  << std::endl;
    }



    template class Scene<2>;
    template class Scene<3>;
  } // namespace scene
} // namespace dpana
