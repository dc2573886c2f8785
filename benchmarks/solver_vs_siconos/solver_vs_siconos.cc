// Benchmark: dpana's contact solvers against Siconos numerics, in one
// process, on the same problems, to the same accuracy measured by dpana's
// ONE shared residual (residual.h, natural_map).
//
// Problems (see README.md):
//   - random:   random SPD compliance with a planted solution that mixes
//               separated, sticking and slipping elements
//               (tests/unit/contact/siconos_problems.h);
//   - indenter: the compliance of an elastic half-plane / half-space
//               (half_space.h) under a rigid parabolic punch pushed in and
//               sideways: FE-like matrices, ill-conditioned as real ones;
//   - FE scenes: FCLIB local problems (--fclib), e.g. the condensed problems
//               that dpana's contact scenes write with `Write FCLIB = true`
//               (run.sh makes three). A body held by contact alone has an
//               equality row G r = e (its free rigid translation), which a
//               Siconos FrictionContactProblem cannot express: such a
//               problem is benchmarked with the rigid mode fixed at its
//               equilibrium amplitude alpha* (a support at the converged
//               position), u = A r + (D + G^T alpha*). Its solution r is
//               the solution of the floating problem, and G r = e holds
//               there; alpha* comes from one accurate dpana solve
//               (tolerance 1e-12) that is not timed.
// Solvers:
//   - dpana: every SolverType that solve() accepts, with tolerance = target;
//   - Siconos: 2D NSGS and Lemke; 3D NSGS, PFP (Panagiotopoulos fixed
//     point), nonsmooth Newton on Alart-Curnier's function (NSN_AC) and on
//     the natural map (NSN_NM). Siconos stops on its own error measure, so
//     its tolerance is calibrated: 1e-8, 1e-10, ... until dpana's residual
//     of its answer reaches the target; the time reported is that of the
//     last (successful) run alone, started from zero like every other run.
// Output: a table on stdout and a CSV file (--csv, default results.csv).
//
// Usage: solver_vs_siconos [--quick | --full] [--target 1e-8] [--csv FILE]
//                          [--fclib FILE [FILE...]] [--fclib-only]
//                          [--solvers NAME,NAME,...] [--cpu]
// --fclib-only leaves out the built-in problems; --solvers runs only the
// named solvers (the names of the table, e.g. siconos_fc3d_nsn_ac,
// dpana_splitting_active_set): on problems of 10^3-10^4 unknowns the slow
// solvers (PFP, NSGS, the PGS splitting) would take hours. --cpu times by
// the processor time of the process (with it, Siconos' time includes the
// adapter's copies of A, which are small beside its factorisations).
#include <dpana/base/exceptions.h>
#include <dpana/contact/residual.h>
#include <dpana/contact/solver.h>
#include <dpana/io/fclib.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "half_space.h"
#include "siconos_adapter.h"
#include "siconos_problems.h"

namespace
{
  using namespace dpana::contact;
  namespace sa = dpana::contact::siconos_adapter;

  struct Case
  {
    std::string    name; // e.g. "indenter2d"
    ContactProblem problem;
  };

  struct Row
  {
    std::string   problem;
    unsigned int  dim = 0, n = 0;
    double        mu = 0;
    std::string   solver;
    bool          peer             = false;
    double        seconds          = 0;
    unsigned int  iterations       = 0;
    unsigned long inner_iterations = 0;
    double        residual         = 0;
    bool          reached          = false; // residual <= target
    double        difference       = std::numeric_limits<double>::quiet_NaN();
    double        ratio            = std::numeric_limits<double>::quiet_NaN();
    std::string   note;
  };

  double
  seconds_since(const std::chrono::steady_clock::time_point &start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
      .count();
  }

  // With --cpu every solver is timed by the processor time of the process
  // (all its threads) instead of the wall clock: on a machine with more
  // runnable jobs than cores the wall time is mostly the wait for a core.
  bool use_cpu_time = false;

  double
  cpu_seconds()
  {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
  }

  // Time of a call: the minimum over a few repetitions for fast calls
  // (below 50 ms), one call otherwise.
  template <typename F>
  double
  timed(F &&call)
  {
    double best = std::numeric_limits<double>::infinity(), total = 0;
    for (unsigned int k = 0; k < 5; ++k)
      {
        const auto   start     = std::chrono::steady_clock::now();
        const double cpu_start = cpu_seconds();
        call();
        const double t =
          use_cpu_time ? cpu_seconds() - cpu_start : seconds_since(start);
        best = std::min(best, t);
        total += t;
        if (total > 0.05)
          break;
      }
    return best;
  }

  // The cap on the iterations of every iterative solver, dpana's and
  // Siconos' alike (sweeps of NSGS, outer iterations of the splittings and
  // of PFP).
  constexpr unsigned int max_sweeps = 10000;

  double
  residual_of(const ContactProblem &p, const Eigen::VectorXd &r)
  {
    return compute_residual(p, r, Eigen::VectorXd()).natural_map;
  }

  std::vector<sa::PeerSolver>
  peer_solvers(const unsigned int dim)
  {
    if (dim == 2)
      return {sa::PeerSolver::fc2d_nsgs, sa::PeerSolver::fc2d_lemke};
    return {sa::PeerSolver::fc3d_nsgs,
            sa::PeerSolver::fc3d_pfp,
            sa::PeerSolver::fc3d_nsn_ac,
            sa::PeerSolver::fc3d_nsn_nm};
  }

  // Run one Siconos solver with the tolerance calibration described above.
  Row
  run_peer(const Case          &c,
           const sa::PeerSolver solver,
           const double         target,
           Eigen::VectorXd     &r_out)
  {
    Row row;
    row.solver        = sa::to_string(solver);
    row.peer          = true;
    const bool newton = (solver == sa::PeerSolver::fc3d_nsn_ac ||
                         solver == sa::PeerSolver::fc3d_nsn_nm);
    for (double tolerance = target; tolerance >= 1e-16; tolerance *= 1e-2)
      {
        sa::PeerOptions options;
        options.solver         = solver;
        options.tolerance      = tolerance;
        options.max_iterations = newton ? 500 : max_sweeps;
        // The time is that of Siconos' driver call alone (the adapter's
        // copies of A in and of r out are not counted), the minimum over a
        // few repetitions for fast calls, as in timed().
        sa::PeerResult result;
        double         t = std::numeric_limits<double>::infinity(), total = 0;
        for (unsigned int k = 0; k < 5 && total <= 0.05; ++k)
          {
            const double cpu_start = cpu_seconds();
            result                 = sa::solve(c.problem, options);
            const double seconds =
              use_cpu_time ? cpu_seconds() - cpu_start : result.seconds;
            t = std::min(t, seconds);
            total += seconds;
          }
        row.seconds    = t;
        row.iterations = result.iterations;
        row.residual   = residual_of(c.problem, result.r);
        r_out          = result.r;
        std::ostringstream note;
        note << "tol " << tolerance << (result.info != 0 ? " info!=0" : "");
        row.note = note.str();
        if (row.residual <= target)
          {
            row.reached = true;
            break;
          }
        if (result.info != 0)
          break; // the solver failed; a smaller tolerance will not help
      }
    return row;
  }

  Row
  run_dpana(const Case      &c,
            const SolverType type,
            const double     target,
            Eigen::VectorXd &r_out,
            bool            &implemented)
  {
    Row row;
    row.solver = "dpana_" + to_string(type);
    dpana::contact::SolverOptions options;
    options.type           = type;
    options.tolerance      = target;
    options.max_iterations = max_sweeps;
    SolverResult result;
    implemented = true;
    try
      {
        row.seconds = timed([&]() { result = solve(c.problem, options); });
      }
    catch (const std::invalid_argument &e)
      {
        implemented = false;
        return row;
      }
    row.iterations       = result.iterations;
    row.inner_iterations = result.inner_iterations;
    // The residual is recomputed here, by the same function as for Siconos.
    row.residual = residual_of(c.problem, result.r);
    row.reached  = row.residual <= target;
    row.note     = result.converged ? "" : "not converged: " + result.message;
    r_out        = result.r;
    return row;
  }

  // The problem sizes: --quick (a few seconds), default (up to 300 elements
  // in 2D and 200 in 3D; well under two minutes on two cores) and --full
  // (up to 512 in 2D and 324 in 3D; several minutes).
  enum class Level
  {
    quick,
    standard,
    full
  };

  std::vector<Case>
  make_cases(const Level level)
  {
    using V = std::vector<unsigned int>;
    V random2d, random3d, plane, space;
    switch (level)
      {
        case Level::quick:
          random2d = {50}, random3d = {30}, plane = {64}, space = {6};
          break;
        case Level::standard:
          random2d = {50, 300}, random3d = {50, 200}, plane = {64, 256},
          space = {8, 14};
          break;
        case Level::full:
          random2d = {50, 200, 500}, random3d = {50, 200, 300},
          plane = {64, 256, 512}, space = {8, 14, 18};
          break;
      }
    std::vector<Case> cases;
    for (const double mu : {0.3, 1.0})
      {
        for (const unsigned int n : random2d)
          cases.push_back(
            {"random2d",
             dpana::contact::test_problems::planted_problem(2, n, mu, 100 + n)
               .problem});
        for (const unsigned int n : plane)
          cases.push_back(
            {"indenter2d", dpana::benchmarks::indenter_problem(2, n, mu)});
        for (const unsigned int n : random3d)
          cases.push_back(
            {"random3d",
             dpana::contact::test_problems::planted_problem(3, n, mu, 200 + n)
               .problem});
        for (const unsigned int m : space)
          cases.push_back(
            {"indenter3d", dpana::benchmarks::indenter_problem(3, m, mu)});
      }
    return cases;
  }

  // The label of an FCLIB file: its name without extension, or the name of
  // its directory if the file is a scene's `problem.hdf5`.
  std::string
  fclib_label(const std::string &file)
  {
    const std::filesystem::path path(file);
    std::string                 label = path.stem().string();
    if (label == "problem" && path.has_parent_path())
      label = path.parent_path().filename().string();
    return label;
  }

  // A case from an FCLIB file. A problem with equality rows G r = e (a body
  // held by contact alone) is turned into the supported problem with the
  // rigid mode fixed at its equilibrium amplitude (see the head of this
  // file).
  Case
  fclib_case(const std::string &file)
  {
    Case c{fclib_label(file), dpana::io::read_fclib_local(file)};
    if (c.problem.n_equalities() != 0)
      {
        dpana::contact::SolverOptions options;
        options.tolerance         = 1e-12;
        options.max_iterations    = 10000;
        const SolverResult result = solve(c.problem, options);
        if (!result.converged)
          throw dpana::InputError(file +
                                  ": the rigid mode amplitude could "
                                  "not be found (dpana's solver did "
                                  "not converge: " +
                                  result.message + ")");
        c.problem.D += c.problem.G.transpose() * result.alpha;
        c.problem.G.resize(0, c.problem.A.cols());
        c.problem.e.resize(0);
        c.name += "*";
      }
    return c;
  }

  void
  print_usage()
  {
    std::cout
      << "usage: solver_vs_siconos [--quick | --full] [--target TOL] [--csv "
         "FILE] [--fclib FILE [FILE...]]\n"
      << "  --fclib: add the FCLIB local problems of the files (repeatable);\n"
      << "           a name with * had its rigid mode fixed at equilibrium\n"
      << "  --fclib-only: leave out the built-in problems\n"
      << "  --cpu: time by processor time instead of wall time\n"
      << "  --solvers NAME,...: run only these solvers (names of the table)\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  // dpana_fe (the FCLIB reader) is a deal.II library: MPI is initialised
  // once for the whole run, serial.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<std::string>                 fclib_files;
  Level                                    level   = Level::standard;
  double                                   target  = 1e-8;
  std::string                              csv     = "results.csv";
  bool                                     builtin = true;
  std::vector<std::string>                 only; // empty: every solver
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--quick")
        level = Level::quick;
      else if (arg == "--full")
        level = Level::full;
      else if (arg == "--target" && i + 1 < argc)
        {
          char *end = nullptr;
          target    = std::strtod(argv[++i], &end);
          if (*end != '\0' || !(target > 0))
            {
              std::cerr << "solver_vs_siconos: error: --target must be a "
                           "positive number, got '"
                        << argv[i] << "'\n";
              return 1;
            }
        }
      else if (arg == "--csv" && i + 1 < argc)
        csv = argv[++i];
      else if (arg == "--fclib-only")
        builtin = false;
      else if (arg == "--cpu")
        use_cpu_time = true;
      else if (arg == "--solvers" && i + 1 < argc)
        {
          std::stringstream list(argv[++i]);
          for (std::string name; std::getline(list, name, ',');)
            only.push_back(name);
        }
      else if (arg == "--fclib")
        {
          const int first = i + 1;
          while (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0)
            fclib_files.emplace_back(argv[++i]);
          if (i + 1 == first)
            {
              std::cerr << "solver_vs_siconos: error: --fclib needs at least "
                           "one FILE\n";
              return 1;
            }
        }
      else if (arg == "--help" || arg == "-h")
        {
          print_usage();
          return 0;
        }
      else
        {
          std::cerr << "solver_vs_siconos: error: unknown argument '" << arg
                    << "' (see --help)\n";
          return 1;
        }
    }
  std::ofstream out(csv);
  if (!out)
    {
      std::cerr << "solver_vs_siconos: error: cannot write CSV file '" << csv
                << "'\n";
      return 1;
    }

  // Siconos prints a line on some failed factorisations; keep stdout for
  // the table.
  std::cout << "# dpana vs Siconos, target residual " << target
            << " (dpana's natural_map, residual.h), "
            << (use_cpu_time ? "processor" : "wall") << " times\n";
  const auto               start_all = std::chrono::steady_clock::now();
  std::vector<Row>         rows;
  std::vector<std::string> states;
  std::vector<Case> cases  = builtin ? make_cases(level) : std::vector<Case>();
  const auto        chosen = [&](const std::string &name) {
    return only.empty() ||
           std::find(only.begin(), only.end(), name) != only.end();
  };
  for (const std::string &file : fclib_files)
    {
      try
        {
          cases.push_back(fclib_case(file));
        }
      catch (const std::exception &e)
        {
          std::cerr << "solver_vs_siconos: error: " << e.what() << "\n";
          return 1;
        }
    }
  for (const Case &c : cases)
    {
      const unsigned int dim = c.problem.dim, n = c.problem.n_elements();
      const double       mu = c.problem.mu[0];
      std::vector<Row>   case_rows;
      std::vector<Eigen::VectorXd> solutions;

      for (const sa::PeerSolver s : peer_solvers(dim))
        {
          if (!chosen(sa::to_string(s)))
            continue;
          Eigen::VectorXd r;
          case_rows.push_back(run_peer(c, s, target, r));
          solutions.push_back(r);
        }
      for (const SolverType t : {SolverType::splitting_pgs,
                                 SolverType::splitting_active_set,
                                 SolverType::nsgs,
                                 SolverType::alart_curnier})
        {
          if (!chosen("dpana_" + to_string(t)))
            continue;
          Eigen::VectorXd r;
          bool            implemented = false;
          Row             row         = run_dpana(c, t, target, r, implemented);
          if (!implemented)
            continue;
          case_rows.push_back(row);
          solutions.push_back(r);
        }

      // Siconos' best: the fastest Siconos solver that reached the target;
      // its solution is the reference for the difference column.
      int best = -1;
      for (std::size_t k = 0; k < case_rows.size(); ++k)
        if (case_rows[k].peer && case_rows[k].reached &&
            (best < 0 || case_rows[k].seconds < case_rows[best].seconds))
          best = static_cast<int>(k);
      // The contact states of the reference solution, to show the mixture.
      if (best >= 0)
        {
          const Eigen::VectorXd           &r = solutions[best];
          const std::vector<ContactStatus> status =
            classify(c.problem, r, c.problem.A * r + c.problem.D, 1e-6);
          unsigned int count[3] = {0, 0, 0};
          for (const ContactStatus s : status)
            ++count[static_cast<int>(s)];
          std::ostringstream line;
          line << "# " << c.name << " n=" << n << " mu=" << mu << ": "
               << count[0] << " separated, " << count[1] << " stick, "
               << count[2] << " slip (reference " << case_rows[best].solver
               << ")";
          states.push_back(line.str());
        }
      for (std::size_t k = 0; k < case_rows.size(); ++k)
        {
          Row &row    = case_rows[k];
          row.problem = c.name;
          row.dim     = dim;
          row.n       = n;
          row.mu      = mu;
          if (best >= 0)
            {
              row.ratio = row.seconds / case_rows[best].seconds;
              const Eigen::VectorXd &ref = solutions[best];
              row.difference = (solutions[k] - ref).cwiseAbs().maxCoeff() /
                               std::max(ref.cwiseAbs().maxCoeff(), 1e-300);
            }
          rows.push_back(row);
        }
      std::cerr << "done " << c.name << " n=" << n << " mu=" << mu << " ("
                << seconds_since(start_all) << " s)\n";
    }

  // The table.
  std::cout << std::left << std::setw(18) << "problem" << std::right
            << std::setw(3) << "d" << std::setw(5) << "n" << std::setw(5)
            << "mu"
            << "  " << std::left << std::setw(29) << "solver" << std::right
            << std::setw(10) << "time[s]" << std::setw(8) << "iter"
            << std::setw(10) << "inner" << std::setw(11) << "residual"
            << std::setw(10) << "|dr|/|r|" << std::setw(9) << "ratio"
            << "  note\n";
  for (const Row &r : rows)
    {
      std::cout << std::left << std::setw(18) << r.problem << std::right
                << std::setw(3) << r.dim << std::setw(5) << r.n << std::setw(5)
                << std::setprecision(2) << r.mu << "  " << std::left
                << std::setw(29) << r.solver << std::right << std::setw(10)
                << std::setprecision(3) << std::scientific << r.seconds
                << std::defaultfloat << std::setw(8) << r.iterations
                << std::setw(10) << r.inner_iterations << std::setw(11)
                << std::setprecision(2) << std::scientific << r.residual
                << std::setw(10) << r.difference << std::defaultfloat
                << std::setw(9) << std::setprecision(3) << r.ratio << "  "
                << (r.reached ? "" : "MISSED ") << r.note << "\n";
    }
  for (const std::string &line : states)
    std::cout << line << "\n";
  std::cout << "# total wall time " << seconds_since(start_all) << " s\n";

  out << "problem,dim,n,mu,solver,peer,seconds,iterations,inner_iterations,"
         "residual,reached,difference,ratio,note\n";
  out << std::setprecision(10);
  for (const Row &r : rows)
    out << r.problem << ',' << r.dim << ',' << r.n << ',' << r.mu << ','
        << r.solver << ',' << (r.peer ? "siconos" : "dpana") << ',' << r.seconds
        << ',' << r.iterations << ',' << r.inner_iterations << ',' << r.residual
        << ',' << (r.reached ? 1 : 0) << ',' << r.difference << ',' << r.ratio
        << ",\"" << r.note << "\"\n";
  return 0;
}
