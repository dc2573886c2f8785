// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_base_simulation_templates_h
#define dpana_base_simulation_templates_h

#include <dpana/base/exceptions.h>
#include <dpana/base/progress.h>
#include <dpana/base/simulation.h>
#include <dpana/output/output.h>

#include <deal.II/base/timer.h>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace dpana
{
  template <int dim>
  Simulation<dim>::Simulation()
    : block_size(64)
  {
  }



  template <int dim>
  void
  Simulation<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Body 1");
    Body<dim>::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output::Parameters::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Linear solver");
    prm.declare_entry("Block size",
                      "64",
                      dealii::Patterns::Integer(1, 4096),
                      "Number of right-hand sides handed at once to the "
                      "sparse Cholesky solver (CHOLMOD) when many are solved "
                      "with one factorisation.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  Simulation<dim>::parse_parameters(dealii::ParameterHandler &prm)
  {
    bodies_.clear();
    prm.enter_subsection("Body 1");
    bodies_.push_back(std::make_unique<Body<dim>>("Body 1"));
    bodies_.back()->parse_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output_parameters.parse_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Linear solver");
    block_size = prm.get_integer("Block size");
    prm.leave_subsection();
    for (auto &body : bodies_)
      body->set_solver_block_size(block_size);
  }



  template <int dim>
  const std::vector<std::unique_ptr<Body<dim>>> &
  Simulation<dim>::bodies() const
  {
    return bodies_;
  }



  template <int dim>
  void
  Simulation<dim>::run(const dealii::ParameterHandler &prm)
  {
    namespace fs = std::filesystem;
    dealii::TimerOutput timer(std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);

    // Phase 1: everything that can go wrong with the input, before any file
    // is written.
    for (auto &body : bodies_)
      {
        {
          Phase phase(timer, "building the mesh of " + body->name());
          body->create_mesh();
        }
        std::cout << "        " << body->name() << ": "
                  << body->geometry_description() << std::endl;
        {
          Phase phase(timer, "setting up " + body->name());
          body->setup();
        }
        body->check_held();
        std::cout << "        " << body->name() << ": "
                  << body->dof_handler().n_dofs() << " unknowns, "
                  << body->constraints().n_constraints() << " constrained; "
                  << body->material().description(dim) << std::endl;
        for (const auto &cf : body->applied_concentrated_forces())
          std::cout << "        " << body->name() << ": concentrated force ("
                    << cf.force << ") requested at (" << cf.requested_point
                    << ") applied at vertex (" << cf.vertex << "), "
                    << cf.vertex.distance(cf.requested_point) << " mm away"
                    << std::endl;
      }

    // Phase 2: the output directory. Remember whether this run created it,
    // so that a failure below removes only what this run made.
    const fs::path directory(output_parameters.directory);
    const bool     existed = fs::exists(directory);
    try
      {
        fs::create_directories(directory);
      }
    catch (const std::exception &e)
      {
        throw InputError("Output / Directory: cannot create '" +
                         directory.string() + "'");
      }

    try
      {
        {
          std::ofstream out(directory / "parameters.prm");
          prm.print_parameters(
            out,
            dealii::ParameterHandler::ShortPRM |
              dealii::ParameterHandler::KeepDeclarationOrder);
          std::ofstream json(directory / "parameters.json");
          prm.print_parameters(json, dealii::ParameterHandler::JSON);
        }

        for (auto &body : bodies_)
          {
            {
              Phase phase(timer, "assembling " + body->name());
              body->assemble();
            }
            {
              Phase phase(timer,
                          "factorising and solving " + body->name() +
                            " (sparse Cholesky)");
              body->solve();
            }
            {
              Phase phase(timer, "postprocessing " + body->name());
              body->postprocess();
            }
            std::cout << "        " << body->name()
                      << ": max |u| = " << body->max_displacement()
                      << " mm; load resultant ("
                      << body->applied_load_resultant() << ")";
            for (const auto &[name, R] : body->reactions())
              std::cout << "; reaction " << name << " (" << R << ")";
            std::cout << std::endl;
          }

        {
          Phase phase(timer, "writing output to " + directory.string());
          if (output_parameters.write_vtu)
            for (const auto &body : bodies_)
              output::write_vtu(*body, directory.string());
          std::ofstream out(directory / "summary.json");
          out << "{\n  \"dimension\": " << dim << ",\n  \"bodies\": [\n";
          for (unsigned int b = 0; b < bodies_.size(); ++b)
            {
              output::write_body_summary(*bodies_[b], out);
              out << (b + 1 < bodies_.size() ? ",\n" : "\n");
            }
          out << "  ]\n}\n";
          AssertThrow(out, dealii::ExcIO());
        }

        const auto timings =
          timer.get_summary_data(dealii::TimerOutput::total_wall_time);
        std::ofstream out(directory / "timings.json");
        output::write_timings(timings, out);
      }
    catch (...)
      {
        if (!existed)
          {
            std::error_code ec;
            fs::remove_all(directory, ec);
          }
        throw;
      }

    timer.print_summary();
  }
} // namespace dpana

#endif
