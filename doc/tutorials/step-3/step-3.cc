// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

// @sect3{Include files}
//
// The program uses the driver of a dpana run, dpana::scene::Scene, for
// everything up to the condensed contact problem: the mesh, the stiffness
// matrix, the candidate contact surface and the condensation. It then
// works on the condensed problem itself: the normal linear complementarity
// problem (LCP) of the frictionless case is taken out of it and handed to
// the two normal solvers of the contact layer (normal_lcp.h), and the
// shared residual of the contact layer (residual.h) judges their answers.
#include <dpana/contact/normal_lcp.h>
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
#include <memory>
#include <string>
#include <vector>

namespace Step3
{
  using namespace dealii;
  using namespace dpana;

  // @sect3{Changing the entries of the parameter file}
  //
  // The step reads one parameter file, step-3.prm, with the frictionless
  // receding block of the reference formulation (section 4.2.1), and then
  // changes a few of its entries for each run: the subdivisions of the mesh,
  // the loads and the candidate contact surface. A ParameterHandler can
  // set an entry once its subsection is entered; the little function below
  // enters a path of subsections, sets the entry and leaves them again.
  void
  set_entry(ParameterHandler               &prm,
            const std::vector<std::string> &path,
            const std::string              &entry,
            const std::string              &value)
  {
    for (const auto &subsection : path)
      prm.enter_subsection(subsection);
    prm.set(entry, value);
    for (unsigned int i = 0; i < path.size(); ++i)
      prm.leave_subsection();
  }



  // @sect3{The condensed problem of one run}
  //
  // The first three phases of a dpana run make the condensed problem: the
  // bodies are assembled, the faces of the candidate surface Gamma_c are
  // grouped into contact elements with piecewise constant tractions
  // (N_j, T_j), and the condensation computes the compliance A (the
  // displacements on Gamma_c of unit tractions), the load term D and, since
  // the block floats in y, one equality row G r = e: the reaction of the
  // fictitious support that holds the block's vertical translation must
  // vanish. The scene is kept, since the contact surface and the problem
  // live in it.
  std::unique_ptr<scene::Scene<2>>
  condensed_scene(ParameterHandler &prm)
  {
    auto run = std::make_unique<scene::Scene<2>>();
    run->set_quiet(true);
    run->parse_parameters(prm, 1, true);
    run->assemble();
    run->build_contact_surface();
    run->condense();
    return run;
  }



  // @sect3{The normal LCP}
  //
  // Without friction, T = 0 and the normal tractions N minimise the
  // complementary energy (the reference formulation's N-step with T = 0):
  //   min 1/2 N^T M N + b^T N  over N <= 0 with G_N N = e,
  // with M = A_NN (the normal-normal block of A, symmetric positive
  // definite), b = D_N and G_N the normal columns of G. Its optimality
  // conditions are Signorini's conditions on every element,
  //   w = M N + b + G_N^T alpha <= 0,   N <= 0,   N_j w_j = 0,
  // where w is the normal displacement u_N of the element: a (mixed) linear
  // complementarity problem. The unknowns of the contact layer are
  // interleaved per element, r = (N_0, T_0, N_1, T_1, ...), so the normal
  // block takes every second row and column.
  struct NormalProblem
  {
    Eigen::MatrixXd M, G;
    Eigen::VectorXd b, e;
  };

  NormalProblem
  normal_part(const contact::ContactProblem &problem)
  {
    const unsigned int n = problem.n_elements(), d = problem.dim;
    NormalProblem      normal;
    normal.M.resize(n, n);
    normal.b.resize(n);
    normal.G.resize(problem.n_equalities(), n);
    for (unsigned int i = 0; i < n; ++i)
      {
        normal.b(i)     = problem.D(d * i);
        normal.G.col(i) = problem.G.col(d * i);
        for (unsigned int j = 0; j < n; ++j)
          normal.M(i, j) = problem.A(d * i, d * j);
      }
    normal.e = problem.e;
    return normal;
  }



  // @sect3{Projected Gauss-Seidel and the active set on the LCP}
  //
  // The contact layer offers two solvers of this LCP (normal_lcp.h). The
  // projected Gauss-Seidel method (Cryer 1971) sweeps over the elements
  // and sets each N_j to the minimiser of the energy in N_j alone, projected
  // onto N_j <= 0; the equality row enters by the method of multipliers.
  // Its cost is a sweep of n^2 operations, and the number of sweeps grows
  // with the condition number of M. The primal-dual active set method
  // (Hintermueller, Ito and Kunisch 2002) guesses the set of elements in
  // contact, solves the equality-constrained problem on that set exactly by
  // a Cholesky factorisation, and updates the set until it repeats; the
  // answer is then exact to round-off. One run below solves the LCP by one
  // method from N = 0 and records the number of sweeps or active-set steps,
  // the time (the mean over as many repetitions as fill 20 ms, for a time
  // that is not dominated by the clock), the shared residual of the full
  // contact problem (residual.h) and the error against the exact solution.
  struct LcpRun
  {
    std::string     method;
    unsigned int    n_elements = 0;
    unsigned int    iterations = 0;
    double          seconds    = 0;
    double          residual   = 0;
    double          error      = 0; // max_j |N_j - N_ref,j| / max_j |N_ref,j|
    Eigen::VectorXd N;
  };

  LcpRun
  solve_lcp(const contact::ContactProblem &problem,
            const std::string             &method,
            const Eigen::VectorXd         &reference_N)
  {
    // The solver object keeps references to M and G and precomputes the
    // inverse diagonal of M (and, for PGS, the augmented matrix of the
    // equality row); its default options stop at a relative change of
    // 1e-12 and allow 10000 sweeps or steps.
    const NormalProblem           normal = normal_part(problem);
    contact::InnerOptions         options;
    contact::NormalLcp            lcp(normal.M, normal.G, options);
    const unsigned int            n = problem.n_elements();
    contact::InnerResult          inner;
    Eigen::VectorXd               N, alpha;
    unsigned int                  repetitions = 0;
    const auto                    start = std::chrono::steady_clock::now();
    std::chrono::duration<double> elapsed{};
    // Every repetition starts cold, from N = 0 and alpha = 0, so that all
    // of them do the same work; a warm start from the previous answer would
    // make the later repetitions trivial.
    do
      {
        N     = Eigen::VectorXd::Zero(n);
        alpha = Eigen::VectorXd::Zero(problem.n_equalities());
        inner = (method == "pgs") ?
                  lcp.solve_pgs(normal.b, normal.e, N, alpha) :
                  lcp.solve_active_set(normal.b, normal.e, N, alpha);
        ++repetitions;
        elapsed = std::chrono::steady_clock::now() - start;
      }
    while (elapsed.count() < 0.02);
    AssertThrow(inner.converged,
                ExcMessage("The " + method +
                           " solver of the normal LCP did not converge: " +
                           inner.message));

    // The tractions of the full problem are (N, T = 0); the shared
    // residual checks Signorini's condition, frictionless sliding and the
    // equality row at once, in the same measure every solver of dpana
    // stops on.
    Eigen::VectorXd r = Eigen::VectorXd::Zero(problem.dim * n);
    for (unsigned int j = 0; j < n; ++j)
      r(problem.dim * j) = N(j);

    LcpRun run;
    run.method     = method;
    run.n_elements = n;
    run.iterations = inner.iterations;
    run.seconds    = elapsed.count() / repetitions;
    run.residual   = contact::compute_residual(problem, r, alpha).natural_map;
    run.error      = (N - reference_N).lpNorm<Eigen::Infinity>() /
                reference_N.lpNorm<Eigen::Infinity>();
    run.N = N;
    return run;
  }



  // @sect3{The Step3 class}
  //
  // The program has two parts. The first solves the uniform receding block
  // on four meshes by both methods and checks the exact answer N = -50 MPa,
  // T = 0; the second presses the same block by a line load, so that only
  // part of its base stays in contact, and shows that the tractions do not
  // depend on the candidate surface as long as it covers the contact zone.
  class Step3
  {
  public:
    explicit Step3(const std::string &parameter_file);

    void
    run();

  private:
    void
    solve_uniform_block();
    void
    vary_candidate_surface();
    std::vector<LcpRun>
    solve_partial_contact(const scene::Scene<2> &layer) const;
    void
    plot() const;

    ParameterHandler    prm;
    std::string         output_directory = "output";
    std::vector<LcpRun> lcp_runs, partial_runs;
  };



  // The constructor declares every entry of a contact run of one
  // two-dimensional body (what the dpana executable does after reading the
  // outline of a file) and reads the step's parameter file.
  Step3::Step3(const std::string &parameter_file)
  {
    parameters::FileOutline outline;
    outline.dimension   = 2;
    outline.n_bodies    = 1;
    outline.has_contact = true;
    scene::declare_parameters(prm, outline);
    parameters::parse_file(prm, parameter_file);
  }



  // @sect3{The uniform receding block}
  //
  // For mu = 0 the uniform stress sigma_xx = -100 MPa, sigma_yy = -50 MPa,
  // sigma_xy = 0 is the exact solution of the block (the reference
  // formulation, section 4.2.1): its displacement is linear, hence in the
  // P1 space, and its tractions on the base, N = sigma_yy = -50 MPa and
  // T = 0, are constant, hence in the piecewise constant traction space.
  // The discrete solution is therefore the exact one on every mesh, and
  // both methods must find N = -50 MPa on every element to round-off. The
  // mesh study makes the problem larger (n = 16 to 128 contact elements) to
  // show how the cost of each method grows with it. The active-set answer is
  // also compared with the driver of the contact layer,
  // contact::solve() with the D-PANA splitting, which for mu = 0 is one
  // N-step: the two must be the same numbers.
  void
  Step3::solve_uniform_block()
  {
    std::cout << "Uniform receding block, mu = 0 (exact: N = -50 MPa, T = 0)\n"
              << std::setw(6) << "n" << std::setw(14) << "method"
              << std::setw(12) << "iterations" << std::setw(14) << "time (ms)"
              << std::setw(14) << "residual" << std::setw(16)
              << "max|N/N_ref-1|" << '\n';
    // The meshes have k x k cells, hence k/2 contact elements of two edges
    // each on the base.
    for (const unsigned int k : {32u, 64u, 128u, 256u})
      {
        set_entry(prm,
                  {"Body 1", "Geometry", "Rectangle"},
                  "Subdivisions",
                  std::to_string(k) + ", " + std::to_string(k));
        const auto  block   = condensed_scene(prm);
        const auto &problem = block->problem();
        // The condensed problem must be the one described above: no
        // friction, and one equality row for the free vertical translation.
        AssertThrow(problem.mu.isZero(0) && problem.n_equalities() == 1,
                    ExcMessage("The block must be frictionless and held in y "
                               "by one equality row."));

        for (const std::string method : {"pgs", "active set"})
          {
            const LcpRun run =
              solve_lcp(problem,
                        method,
                        Eigen::VectorXd::Constant(problem.n_elements(), -50.));
            std::cout << std::setw(6) << run.n_elements << std::setw(14)
                      << method << std::setw(12) << run.iterations
                      << std::setw(14) << std::setprecision(4)
                      << 1e3 * run.seconds << std::setw(14)
                      << std::setprecision(3) << run.residual << std::setw(16)
                      << run.error << '\n';
            // The bound: the exact state is reproduced up to the round-off
            // of the condensation itself (A and D come from solves with the
            // stiffness matrix, whose condition number grows like the
            // square of the number of cells along a side), which is why the
            // error grows with the mesh for both methods alike.
            AssertThrow(run.error < 1e-8 && run.residual < 1e-10,
                        ExcMessage("The exact uniform state N = -50 MPa is "
                                   "not reproduced by " +
                                   method + "."));
            lcp_runs.push_back(run);
          }

        // The same problem through the driver of the contact layer, as a
        // scene solves it: its tractions must be those of the active set
        // method on the normal LCP, with T = 0 on every element.
        contact::SolverOptions options;
        options.type = contact::SolverType::splitting_active_set;
        const contact::SolverResult full = contact::solve(problem, options);
        double                      difference = 0;
        for (unsigned int j = 0; j < problem.n_elements(); ++j)
          difference = std::max(difference,
                                std::abs(full.r(2 * j) - lcp_runs.back().N(j)) +
                                  std::abs(full.r(2 * j + 1)));
        AssertThrow(full.converged && difference < 1e-9,
                    ExcMessage("contact::solve() and the normal LCP differ."));
      }

    // One row per mesh and method, for the figure.
    std::ofstream csv(output_directory + "/lcp_solvers.csv");
    csv << "n,method,iterations,seconds,residual,error\n";
    for (const auto &run : lcp_runs)
      csv << run.n_elements << ',' << run.method << ',' << run.iterations << ','
          << run.seconds << ',' << run.residual << ',' << run.error << '\n';
  }



  // @sect3{Independence of the candidate surface}
  //
  // The candidate surface Gamma_c is where contact may occur; the user
  // chooses it before the contact zone is known (`Candidate centre` and
  // `Candidate half width`). If the true contact zone lies inside Gamma_c,
  // the answer must not depend on the choice: the tractions on a larger
  // Gamma_c are those on the smaller one, extended by N = 0 (separation) on
  // the extra elements. This holds exactly for the discrete problem as well,
  // because the LCP has a unique solution: if the solution on the smaller
  // surface does not penetrate the foundation outside it, its extension by
  // zeros satisfies every condition of the larger problem.
  //
  // To see this the problem needs a contact zone smaller than the base: the
  // block is made half as tall (80 x 20 mm, the half model 40 x 20 mm on 64
  // x 32 cells, so 32 contact elements of 1.25 mm) and the pressures are
  // replaced by a line load of 4000 N/mm at the middle of its top (2000
  // N/mm on the half model, at the vertex (0, 20)). The layer then bends,
  // and its base lifts off the foundation away from the load: a receding
  // contact, whose zone is fixed by the geometry and the load, not by the
  // candidate surface. The runs use the whole base and candidate half
  // widths of 30, 25 and 20 mm, and one that is too small (10 mm). The
  // tractions are compared on the common elements.
  void
  Step3::vary_candidate_surface()
  {
    set_entry(prm,
              {"Body 1", "Geometry", "Rectangle"},
              "Upper corner",
              "40, 20");
    set_entry(prm,
              {"Body 1", "Geometry", "Rectangle"},
              "Subdivisions",
              "64, 32");
    set_entry(prm, {"Body 1", "Loads"}, "Pressure", "");
    set_entry(prm,
              {"Body 1", "Loads"},
              "Concentrated forces",
              "0, 20: 0, -2000");
    // A half width of 0 means the whole boundary named in `Boundary 1`,
    // here the base from s = 0 to 40 mm; the candidate centre is the origin,
    // on the plane of symmetry.
    const std::vector<double> half_widths = {0, 30, 25, 20, 10};

    std::ofstream csv(output_directory + "/candidates.csv");
    csv << "half_width,s,N,T\n";
    std::vector<double> full_N; // the whole base, sorted by s
    std::cout
      << "\nLine load 2000 N/mm on the half layer 40 x 20 mm: candidate "
         "surfaces\n"
      << std::setw(12) << "half width" << std::setw(10) << "elements"
      << std::setw(14) << "contact a" << std::setw(20) << "max|N - N_full|"
      << std::setw(10) << "warning" << '\n';
    for (const double w : half_widths)
      {
        set_entry(prm, {"Contact"}, "Candidate half width", std::to_string(w));
        // This time the scene also solves the problem (by its default
        // solver, the D-PANA splitting with active sets) and recovers the
        // displacements, which gives the summary of the contact zone: the
        // half width and the warning for a candidate surface that is too
        // small.
        auto block = condensed_scene(prm);
        block->solve();
        block->recover();
        const auto &surface = block->surface(0);
        const auto &summary = block->summary();
        AssertThrow(summary.result.converged,
                    ExcMessage("The contact solver did not converge."));

        // The elements in order of s, their normal tractions, and the
        // largest difference from the run on the whole base on the elements
        // both runs share (the grouping of faces into elements starts at
        // s = 0 in every run, so the j-th element in order of s is the same
        // element).
        std::vector<double> N;
        for (const unsigned int j : surface.sorted_elements())
          {
            N.push_back(block->normal_traction(j));
            csv << (w == 0 ? 40. : w) << ',' << surface.element(j).s << ','
                << block->normal_traction(j) << ','
                << block->tangential_traction(j) << '\n';
          }
        if (w == 0)
          {
            full_N       = N;
            partial_runs = solve_partial_contact(*block);
          }
        double difference = 0;
        for (unsigned int j = 0; j < N.size(); ++j)
          difference = std::max(difference, std::abs(N[j] - full_N[j]));
        const double max_pressure = summary.max_pressure;
        std::cout << std::setw(12) << (w == 0 ? 40. : w) << std::setw(10)
                  << surface.n_elements() << std::setw(14) << summary.half_width
                  << std::setw(20) << std::setprecision(3)
                  << difference / max_pressure << std::setw(10)
                  << (summary.candidate_edge_warning ? "yes" : "no") << '\n'
                  << std::setprecision(6);

        // A candidate surface that covers the contact zone gives the same
        // tractions to round-off (relative to the largest pressure); one
        // that cuts into it is noticed by the scene, which warns that an
        // element in contact touches a face left out of Gamma_c.
        if (w == 0 || w > 15)
          {
            AssertThrow(difference / max_pressure < 1e-9 &&
                          !summary.candidate_edge_warning,
                        ExcMessage("The tractions depend on a candidate "
                                   "surface that covers the contact zone."));
          }
        else
          {
            AssertThrow(summary.candidate_edge_warning,
                        ExcMessage("A candidate surface smaller than the "
                                   "contact zone must be reported."));
          }
      }

    std::cout << "\nThe normal LCP of the layer on the whole base:\n";
    for (const auto &run : partial_runs)
      std::cout << std::setw(14) << run.method << ": " << run.iterations
                << (run.method == "pgs" ? " sweeps, " : " active-set steps, ")
                << std::setprecision(4) << 1e3 * run.seconds << " ms, residual "
                << std::setprecision(3) << run.residual
                << ", max|N - N_scene| / max|N_scene| = " << run.error << '\n'
                << std::setprecision(6);
  }



  // @sect3{The two methods on a partial contact}
  //
  // On the uniform block the whole base is in contact, and the active set
  // method, which starts from the guess "every element that the loads alone
  // push into the foundation is in contact", is right at its first step.
  // Under the line load only part of the base stays in contact, and the
  // method has to find that part. The normal LCP of the layer on the whole
  // base is solved by both methods and compared with the scene's answer
  // (the D-PANA splitting of the contact layer, which without friction is
  // one active-set N-step).
  std::vector<LcpRun>
  Step3::solve_partial_contact(const scene::Scene<2> &layer) const
  {
    const auto     &problem = layer.problem();
    Eigen::VectorXd reference(problem.n_elements());
    for (unsigned int j = 0; j < problem.n_elements(); ++j)
      reference(j) = layer.normal_traction(j);
    std::vector<LcpRun> runs;
    for (const std::string method : {"pgs", "active set"})
      {
        runs.push_back(solve_lcp(problem, method, reference));
        AssertThrow(runs.back().error < 1e-8 && runs.back().residual < 1e-10,
                    ExcMessage("The " + method +
                               " solver misses the partial contact."));
      }
    return runs;
  }



  // @sect3{The figure}
  //
  // The numbers go to output/*.csv, and the plot script of this step's
  // folder draws them (iterations and time of both methods against the
  // number of contact elements; the normal tractions of the candidate
  // surfaces). A machine without matplotlib gets a warning, not an error.
  void
  Step3::plot() const
  {
    const std::string command = std::string("/usr/bin/python3 ") +
                                DPANA_STEP_DIR + "/plot.py " +
                                output_directory + " > /dev/null 2>&1";
    if (std::system(command.c_str()) != 0)
      std::cout << "warning: no figures (python3 with matplotlib needed)\n";
  }



  // @sect3{Step3::run}
  //
  // The two studies, then the figures. The program returns normally only
  // if every check above has passed.
  void
  Step3::run()
  {
    std::filesystem::create_directories(output_directory);
    std::cout << std::setprecision(6);
    solve_uniform_block();
    vary_candidate_surface();
    plot();
    std::cout << "\nAll checks passed.\n";
  }
} // namespace Step3



// @sect3{The main function}
//
// As in every deal.II tutorial, exceptions are caught and reported, so that
// a failed check ends the program (and its test) with a message and a
// non-zero exit status.
int
main()
{
  try
    {
      Step3::Step3 step(std::string(DPANA_STEP_DIR) + "/step-3.prm");
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
