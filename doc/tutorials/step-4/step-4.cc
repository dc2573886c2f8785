// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

// @sect3{Include files}
//
// A whole dpana run is one object, dpana::scene::Scene: it assembles the
// block, builds the candidate contact surface, condenses the problem onto
// it, solves it, recovers the displacements and stresses and writes the
// output. This step runs it once on the receding block with friction, then
// takes the condensed problem out of the scene and hands it to each of the
// four solvers of the contact layer (contact/solver.h), to compare their
// histories, their cost and their answers in the one measure they share
// (contact/residual.h).
#include <dpana/contact/residual.h>
#include <dpana/contact/solver.h>
#include <dpana/parameters/parameters.h>
#include <dpana/scene/run.h>
#include <dpana/scene/scene.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace Step4
{
  using namespace dealii;
  using namespace dpana;

  // @sect3{One solver on the condensed problem}
  //
  // The condensed problem holds the compliance A (32 x 32 here: 16 contact
  // elements with a normal and a tangential traction each), the load term
  // D, the friction coefficients mu_j and the equality row G r = e of the
  // floating block. contact::solve() solves it by the solver named in the
  // options and returns the tractions r, the displacements u = A r + D +
  // G^T alpha, the status of every element, and the shared residual of
  // every outer iteration (residual_history). The time is the mean over as
  // many repetitions as fill 50 ms, so that the clock's resolution does not
  // dominate the small problems.
  struct SolverRun
  {
    contact::SolverType   type;
    contact::SolverResult result;
    double                seconds    = 0;
    double                difference = 0; // from the reference tractions
  };

  SolverRun
  run_solver(const contact::ContactProblem &problem,
             const contact::SolverType      type)
  {
    contact::SolverOptions options;
    options.type = type;
    SolverRun                     run;
    unsigned int                  repetitions = 0;
    const auto                    start = std::chrono::steady_clock::now();
    std::chrono::duration<double> elapsed{};
    do
      {
        run.result = contact::solve(problem, options);
        ++repetitions;
        elapsed = std::chrono::steady_clock::now() - start;
      }
    while (elapsed.count() < 0.05);
    run.type    = type;
    run.seconds = elapsed.count() / repetitions;
    return run;
  }



  // @sect3{The Step4 class}
  //
  // The program solves the receding block of the reference formulation
  // with mu = 1 (its section 4.2.1, the benchmark of Raous, Chabrand and
  // Lebon), reports and checks its contact zones, compares the four solvers
  // and, to see how much of the answer is the mesh, repeats the run on two
  // finer meshes.
  class Step4
  {
  public:
    explicit Step4(const std::string &parameter_file);

    void
    run();

  private:
    void
    solve_block();
    void
    check_zones() const;
    void
    compare_solvers();
    void
    refine_mesh();
    void
    plot() const;

    ParameterHandler       prm;
    scene::Scene<2>        block;
    std::string            output_directory = "output";
    std::vector<SolverRun> runs;
  };



  // The constructor declares every entry of a contact run of one
  // two-dimensional body and reads the step's parameter file, a copy of
  // the scene of the receding block with mu = 1 that writes its output into
  // output/receding.
  Step4::Step4(const std::string &parameter_file)
  {
    parameters::FileOutline outline;
    outline.dimension   = 2;
    outline.n_bodies    = 1;
    outline.has_contact = true;
    scene::declare_parameters(prm, outline);
    parameters::parse_file(prm, parameter_file);
  }



  // @sect3{The receding block with friction}
  //
  // Scene::run() makes every phase of a dpana run and prints its log: the
  // mesh, the candidate surface (16 contact elements of two edges each on
  // the base), the condensation with its one equality row, the solver's
  // outcome, the contact half width, the zones and the timings. The solver
  // is the scene's default, the D-PANA splitting with active-set inner
  // solvers. Its output (the VTU files of the block and of the contact
  // surface, contact.csv, summary.json) goes to output/receding.
  //
  // The first check is an exact one: the block is held in y by the contact
  // alone, so the normal tractions must carry the whole vertical load, the
  // 50 MPa on the top face of width 40 mm, 2000 N/mm. This is the equality
  // row G r = e of the condensed problem, and the solver keeps it to
  // round-off.
  void
  Step4::solve_block()
  {
    block.parse_parameters(prm, 1, true);
    block.run(true);
    const auto &summary = block.summary();
    AssertThrow(summary.result.converged,
                ExcMessage("The contact solver did not converge."));

    // The resultant of the normal tractions: each element carries the
    // force -N_j times its area (its length, per mm of thickness).
    double resultant = 0;
    for (unsigned int j = 0; j < block.surface(0).n_elements(); ++j)
      resultant -= block.normal_traction(j) * block.surface(0).element(j).area;
    const double load = 50. * 40.;
    std::cout << "\nVertical equilibrium: resultant of -N = " << resultant
              << " N/mm, load 2000 N/mm, relative error "
              << std::abs(resultant - load) / load << '\n';
    AssertThrow(std::abs(resultant - load) < 1e-9 * load,
                ExcMessage("The normal tractions do not carry the load."));
  }



  // @sect3{Stick, slip and separation}
  //
  // Without friction the base would slide towards the plane of symmetry,
  // squeezed by the side pressures, and stay in contact with N = -50 MPa
  // (step 3). Friction resists this contraction (T > 0 here, along +x on
  // the block), the normal traction concentrates towards the middle, and
  // the base separates near its outer edge: the contact recedes. Along the base
  // three zones appear: near the plane of symmetry the base sticks (|T| < -mu
  // N, u_T = 0), further out it slips
  // (|T| = -mu N, u_T opposite to T), and at the edge it has left the
  // foundation (N = 0). The scene classifies every element and groups them
  // into zones; the program prints them, writes the tractions and the
  // friction bound along the base for the figure, and checks the order of
  // the zones and Coulomb's inequality |T_j| <= -mu N_j on every element.
  void
  Step4::check_zones() const
  {
    const auto &summary = block.summary();
    std::cout << "\nZones along the base (s from the plane of symmetry):\n";
    for (const auto &zone : summary.zones)
      std::cout << std::setw(12) << contact::to_string(zone.status)
                << ": s in [" << zone.from << ", " << zone.to << "] mm, "
                << zone.n_elements << " elements\n";
    AssertThrow(summary.zones.size() == 3 &&
                  summary.zones[0].status == contact::ContactStatus::stick &&
                  summary.zones[1].status == contact::ContactStatus::slip &&
                  summary.zones[2].status == contact::ContactStatus::separated,
                ExcMessage("Expected stick, slip and separation, in this "
                           "order from the plane of symmetry."));

    const auto   &surface = block.surface(0);
    const double  mu      = block.problem().mu(0);
    std::ofstream csv(output_directory + "/tractions.csv");
    csv << "s,N,T,status\n";
    // The elements in order of their distance s from the plane of symmetry,
    // with the status the solver gave them; the slack of 5e-7 MPa in the
    // inequality allows for the round-off of the slip elements, which lie
    // on the bound.
    for (const unsigned int j : surface.sorted_elements())
      {
        const double N = block.normal_traction(j);
        const double T = block.tangential_traction(j);
        AssertThrow(N <= 0 && std::abs(T) <= -mu * N + 1e-8 * 50,
                    ExcMessage("Coulomb's inequality is violated."));
        csv << surface.element(j).s << ',' << N << ',' << T << ','
            << contact::to_string(summary.result.status[j]) << '\n';
      }
  }



  // @sect3{Four solvers side by side}
  //
  // The four solvers of dpana attack the same problem in different ways:
  // - splitting_active_set and splitting_pgs: the D-PANA splitting of the
  //   reference formulation (Bisegna, Lebon and Maceri 2001; the dual of
  //   Panagiotopoulos' method). A T-step solves the friction problem at the
  //   normal tractions of the last iterate (a Tresca problem with the
  //   radii -mu N), an N-step the Signorini problem at the new tangential
  //   tractions, and the two alternate until a fixed point, which solves
  //   the Coulomb problem. The inner steps are solved by active sets or by
  //   projected Gauss-Seidel;
  // - nsgs: nonsmooth Gauss-Seidel (Jean and Moreau), which sweeps over the
  //   elements and solves each element's Signorini-Coulomb problem exactly;
  // - alart_curnier: semismooth Newton on the equations of Alart and
  //   Curnier (1991), locally superlinear.
  // All stop when the shared residual (the natural map with the modified
  // displacement of De Saxce and Feng, normalised to be free of units)
  // falls below 1e-10, so that their iterations and times compare. An outer
  // iteration is a T-step and an N-step of the splitting, a sweep of NSGS
  // and a Newton step of Alart-Curnier; they do not cost the same, which is
  // why the time is shown too. The answers are compared with the scene's
  // (splitting_active_set) by the largest difference of a traction relative
  // to the largest traction.
  void
  Step4::compare_solvers()
  {
    const auto           &problem   = block.problem();
    const Eigen::VectorXd reference = block.summary().result.r;
    const double          scale     = reference.lpNorm<Eigen::Infinity>();
    std::ofstream         history(output_directory + "/history.csv");
    history << "solver,iteration,residual\n";
    std::cout << "\nThe four solvers on the condensed problem (tolerance "
                 "1e-10 on the shared residual):\n"
              << std::setw(22) << "solver" << std::setw(12) << "iterations"
              << std::setw(10) << "inner" << std::setw(13) << "residual"
              << std::setw(12) << "time (ms)" << std::setw(16)
              << "max|r - r_ref|" << '\n';
    // The solvers share the problem and the default options (tolerance
    // 1e-10, at most 1000 outer iterations); only the type changes. Each
    // starts from scratch, without the scene's answer as a start.
    for (const auto type : {contact::SolverType::splitting_active_set,
                            contact::SolverType::splitting_pgs,
                            contact::SolverType::nsgs,
                            contact::SolverType::alart_curnier})
      {
        SolverRun run = run_solver(problem, type);
        run.difference =
          (run.result.r - reference).lpNorm<Eigen::Infinity>() / scale;
        const auto &result = run.result;
        std::cout << std::setw(22) << contact::to_string(type) << std::setw(12)
                  << result.iterations << std::setw(10)
                  << result.inner_iterations << std::setw(13)
                  << std::setprecision(3) << result.residual << std::setw(12)
                  << std::setprecision(4) << 1e3 * run.seconds << std::setw(16)
                  << std::setprecision(3) << run.difference
                  << std::setprecision(6) << '\n';
        // The history holds the shared residual after every outer
        // iteration (Alart-Curnier also that of its starting point), the
        // curve of the figure.
        for (unsigned int k = 0; k < result.residual_history.size(); ++k)
          history << contact::to_string(type) << ',' << k + 1 << ','
                  << result.residual_history[k] << '\n';

        // The check of the step: every solver converges to the shared
        // tolerance, and all find the same tractions. A residual of 1e-10
        // bounds the violation of the contact laws, not the distance to the
        // solution; that distance is the residual times a condition number
        // of the problem, so the bound on the differences is set at 1e-6,
        // four orders above the tolerance. Four methods that share no step
        // and agree this closely have found the same solution.
        AssertThrow(result.converged && result.residual <= 1e-10,
                    ExcMessage(contact::to_string(type) +
                               " did not converge: " + result.message));
        AssertThrow(run.difference < 1e-6,
                    ExcMessage(contact::to_string(type) +
                               " finds other tractions."));
        runs.push_back(run);
      }
  }



  // @sect3{How much of the answer is the mesh}
  //
  // The contact half width of a run is known to one contact element (2.5 mm
  // on the mesh of the reference formulation's example), since the
  // tractions are constant per element. Two finer meshes (64 x 64 and
  // 128 x 128 cells, 32 and 64 contact elements) show where the zone
  // boundaries move to. The scenes are quiet, and only solved and summarised,
  // not written.
  void
  Step4::refine_mesh()
  {
    std::cout << "\nMesh study (splitting_active_set):\n"
              << std::setw(10) << "elements" << std::setw(16) << "stick ends at"
              << std::setw(16) << "contact a" << std::setw(10) << "-N_max"
              << '\n';
    std::ofstream csv(output_directory + "/mesh.csv");
    csv << "elements,stick_end,half_width,max_pressure\n";
    for (const unsigned int k : {32u, 64u, 128u})
      {
        prm.enter_subsection("Body 1");
        prm.enter_subsection("Geometry");
        prm.enter_subsection("Rectangle");
        prm.set("Subdivisions", std::to_string(k) + ", " + std::to_string(k));
        prm.leave_subsection();
        prm.leave_subsection();
        prm.leave_subsection();
        // A new scene for every mesh: a scene is set up once from its
        // parameters and then runs its phases.
        scene::Scene<2> fine;
        fine.set_quiet(true);
        fine.parse_parameters(prm, 1, true);
        fine.run(false);
        const auto &summary = fine.summary();
        AssertThrow(summary.result.converged && !summary.zones.empty() &&
                      summary.zones[0].status == contact::ContactStatus::stick,
                    ExcMessage("The refined block did not converge, or its "
                               "base does not stick at the middle."));
        std::cout << std::setw(10) << summary.n_elements << std::setw(16)
                  << summary.zones[0].to << std::setw(16) << summary.half_width
                  << std::setw(10) << summary.max_pressure << '\n';
        csv << summary.n_elements << ',' << summary.zones[0].to << ','
            << summary.half_width << ',' << summary.max_pressure << '\n';
      }
  }



  // @sect3{The figures}
  //
  // The plot script of this step's folder draws the tractions with the
  // friction bound and the zones, and the residual of every outer
  // iteration of the four solvers, from the CSV files in output/.
  void
  Step4::plot() const
  {
    const std::string command = std::string("/usr/bin/python3 ") +
                                DPANA_STEP_DIR + "/plot.py " +
                                output_directory + " > /dev/null 2>&1";
    if (std::system(command.c_str()) != 0)
      std::cout << "warning: no figures (python3 with matplotlib needed)\n";
  }



  // @sect3{Step4::run}
  void
  Step4::run()
  {
    std::filesystem::create_directories(output_directory);
    std::cout << std::setprecision(6);
    solve_block();
    check_zones();
    compare_solvers();
    refine_mesh();
    plot();
    std::cout << "\nAll checks passed.\n";
  }
} // namespace Step4



// @sect3{The main function}
//
// Exceptions, among them every failed check, end the program with a message
// and a non-zero exit status, which fails the test of this step.
int
main()
{
  try
    {
      Step4::Step4 step(std::string(DPANA_STEP_DIR) + "/step-4.prm");
      step.run();
    }
  catch (const std::exception &exc)
    {
      std::cerr << "\n----------------------------------------------------\n"
                << "Exception: " << exc.what() << '\n'
                << "----------------------------------------------------\n";
      return 1;
    }
  return 0;
}
