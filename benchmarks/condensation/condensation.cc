// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Benchmark: the two routes of the condensation of a body on its candidate
// contact surface, A = V_r^T K_r^{-1} V_r (condensation::Method), and the
// two back ends of the Schur route (condensation::Backend), side by side on
// the same assembled scene:
//
//   - blocked solves: one sparse Cholesky factorisation with CHOLMOD's
//     fill-reducing ordering, then Z = K_r^{-1} V_r by blocked forward and
//     backward solves (n_dofs x columns per pass) and A = V^T Z;
//   - schur: one factorisation with the surface dofs ordered last, then
//     A = W^T W, W = L_22^{-1} V_Gamma (L_22 the factor of the Schur
//     complement on Gamma_c): a dense triangular solve and a rank update of
//     size n_Gamma x n_c;
//   - mumps: the Schur route with MUMPS through PETSc: MUMPS eliminates the
//     interior unknowns and returns the dense Schur complement S on the
//     surface, factored by LAPACK (S = L_S L_S^T), then W = L_S^{-1}
//     V_Gamma and A = W^T W as above.
//
// For each scene (a .prm file of prm/ with entries overridden, e.g. a finer
// mesh) the bodies are assembled and the contact surface built once; then,
// for each body and each route, a child process (fork) runs the Condenser
// exactly as a contact run does: factorize() (timed: "factor"),
// assemble_coupling() + condense() (timed: "condense"). The child reports its
// times and its peak resident memory (getrusage; it includes the assembled
// scene it inherited, so it is the peak a run with that route would reach up
// to the end of the condensation), and writes its A to a temporary file, so
// that the A of the routes are compared with that of the blocked solves
// (|dA|, relative to max |A_ij|).
//
// Times are the minimum over --repeats runs of the factorisation and the
// condensation in the same child (default 1).
//
// With --orderings, the Schur route alone under each ordering of its
// factorisation (linear_algebra::LastBlockOrdering): CHOLMOD's nnz(L) and
// flop count, the times and the peak memory, one child each.
//
// --analysis-only stops each child after the symbolic analysis (the counts
// without the factorisation). --box "M, H, M" replaces the scenes by the
// scale scene prm/scale/receding_3d_1M.prm at these subdivisions.
//
// Usage: condensation_benchmark [--quick | --full]
//                               [--orderings | --analysis-only]
//                               [--box "M, H, M" ...] [--prm-dir DIR]
//                               [--csv FILE] [--repeats N]

#include <dpana/base/exceptions.h>
#include <dpana/condensation/condenser.h>
#include <dpana/parameters/parameters.h>
#include <dpana/scene/run.h>
#include <dpana/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
  using namespace dpana;

  double
  seconds_since(const std::chrono::steady_clock::time_point &start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
      .count();
  }

  double
  peak_memory_mb()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0;
  }

  // A scene of prm/ and the entries that change it: "Body 1/Geometry/Box/
  // Subdivisions=32, 16, 32" (path of subsections, entry, value).
  struct Case
  {
    std::string              label;
    std::string              file;
    std::vector<std::string> entries;
  };

  // What a child reports of one route.
  struct Measurement
  {
    double       t_factor = 0, t_condense = 0, peak_mb = 0;
    unsigned int n_gamma = 0;
    // CHOLMOD's analysis: nnz(L), stored numbers and row indices, flops.
    double lnz = 0, entries = 0, indices = 0, flops = 0;
  };

  struct Row
  {
    std::string  label;
    unsigned int body = 0, n_dofs = 0, n_contact = 0;
    double       setup_mb = 0;
    Measurement  blocked, schur, mumps;
    double       difference = 0, difference_mumps = 0;
  };



  // @sect3{The scene}
  //
  // The entries as parameter text: "a/b/c=v" becomes subsection a,
  // subsection b, set c = v, end, end.
  std::string
  entry_text(const std::string &entry)
  {
    const auto  equal = entry.find('=');
    std::string path  = entry.substr(0, equal);
    std::string text, ends;
    for (auto slash = path.find('/'); slash != std::string::npos;
         slash      = path.find('/'))
      {
             text += "subsection " + path.substr(0, slash) + "\n";
             ends += "end\n";
             path = path.substr(slash + 1);
      }
    return text + "set " + path + " = " + entry.substr(equal + 1) + "\n" + ends;
  }

  template <int dim>
  std::unique_ptr<scene::Scene<dim>>
  make_scene(const std::string              &file,
             const parameters::FileOutline  &outline,
             const std::vector<std::string> &entries)
  {
    dealii::ParameterHandler prm;
    scene::declare_parameters(prm, outline);
    prm.parse_input(file);
    for (const auto &entry : entries)
      prm.parse_input_from_string(entry_text(entry));
    auto s = std::make_unique<scene::Scene<dim>>();
    s->parse_parameters(prm, outline.n_bodies, outline.has_contact);
    s->set_quiet(true);
    return s;
  }



  // @sect3{One route in a child process}
  //
  // The child condenses body b by the given parameters, writes its Measurement
  // to the pipe and its A (rows, then the column-major values) to
  // @p a_file, and exits.
  template <int dim>
  Measurement
  measure(scene::Scene<dim>              &s,
          const unsigned int              b,
          const condensation::Parameters &parameters,
          unsigned int                    repeats,
          const std::string              &a_file)
  {
    int channel[2];
    AssertThrow(pipe(channel) == 0, dealii::ExcMessage("pipe() failed"));
    std::fflush(stdout);
    const pid_t pid = fork();
    AssertThrow(pid >= 0, dealii::ExcMessage("fork() failed"));
    if (pid == 0)
      {
        close(channel[0]);
        Measurement m;
        if (parameters.memory_limit_gb > 0)
          {
            // The analysis only: the memory check refuses the tiny limit
            // after CHOLMOD's symbolic analysis, whose counts stay.
            condensation::Condenser<dim> c(s.body(b), s.surface(b), parameters);
            const auto start = std::chrono::steady_clock::now();
            try
              {
                c.factorize();
              }
            catch (const InputError &)
              {
              }
            m.t_factor = seconds_since(start);
            m.n_gamma  = c.factorization().analysis().n_last;
            m.lnz      = c.factorization().analysis().factor_nonzeros;
            m.entries  = c.factorization().analysis().factor_entries;
            m.flops    = c.factorization().analysis().factor_flops;
            std::ofstream(a_file, std::ios::binary);
            repeats = 0;
          }
        for (unsigned int k = 0; k < repeats; ++k)
          {
            condensation::Condenser<dim> c(s.body(b), s.surface(b), parameters);
            auto start = std::chrono::steady_clock::now();
            c.factorize();
            const double t_factor = seconds_since(start);
            start                 = std::chrono::steady_clock::now();
            c.assemble_coupling();
            c.condense(parameters.columns_per_solve);
            const double t_condense = seconds_since(start);
            if (k == 0 || t_factor + t_condense < m.t_factor + m.t_condense)
              {
                m.t_factor   = t_factor;
                m.t_condense = t_condense;
              }
            m.n_gamma = c.schur_factorization().schur_dofs().size();
            m.lnz     = c.factorization().analysis().factor_nonzeros;
            m.entries = c.factorization().analysis().factor_entries;
            m.indices = c.factorization().analysis().factor_indices;
            m.flops   = c.factorization().analysis().factor_flops;
            if (k + 1 == repeats)
              {
                const Eigen::MatrixXd &A = c.compliance();
                std::ofstream          out(a_file, std::ios::binary);
                const Eigen::Index     n = A.rows();
                out.write(reinterpret_cast<const char *>(&n), sizeof(n));
                out.write(reinterpret_cast<const char *>(A.data()),
                          sizeof(double) * n * n);
              }
          }
        m.peak_mb = peak_memory_mb();
        const bool ok =
          write(channel[1], &m, sizeof(m)) == static_cast<long>(sizeof(m));
        close(channel[1]);
        _exit(ok ? 0 : 1);
      }
    close(channel[1]);
    Measurement m;
    const long  got    = read(channel[0], &m, sizeof(m));
    int         status = 0;
    waitpid(pid, &status, 0);
    close(channel[0]);
    AssertThrow(got == static_cast<long>(sizeof(m)) && WIFEXITED(status) &&
                  WEXITSTATUS(status) == 0,
                dealii::ExcMessage("the condensation of body " +
                                   std::to_string(b + 1) + " failed"));
    return m;
  }

  Eigen::MatrixXd
  read_matrix(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary);
    Eigen::Index  n = 0;
    in.read(reinterpret_cast<char *>(&n), sizeof(n));
    Eigen::MatrixXd A(n, n);
    in.read(reinterpret_cast<char *>(A.data()), sizeof(double) * n * n);
    std::remove(file.c_str());
    return A;
  }



  // @sect3{One scene}
  template <int dim>
  std::vector<Row>
  run_case(const Case                    &c,
           const parameters::FileOutline &outline,
           const unsigned int             repeats,
           const bool                     schur_only)
  {
    auto s = make_scene<dim>(c.file, outline, c.entries);
    s->assemble();
    s->build_contact_surface();
    std::vector<Row> rows;
    for (unsigned int b = 0; b < s->n_bodies(); ++b)
      {
        Row row;
        row.label    = c.label;
        row.body     = b + 1;
        row.n_dofs   = s->body(b).dof_handler().n_dofs();
        row.setup_mb = peak_memory_mb();
        const std::string file =
          "/tmp/condensation_benchmark_" + std::to_string(getpid());
        condensation::Parameters blocked, schur;
        blocked.method = condensation::Method::blocked_solves;
        row.schur      = measure(*s, b, schur, repeats, file + "_schur");
        if (schur_only)
          {
            // --schur-only: the other routes are not run (their columns 0).
            row.n_contact  = read_matrix(file + "_schur").rows();
            row.difference = row.difference_mumps = std::nan("");
            rows.push_back(row);
            continue;
          }
        row.blocked = measure(*s, b, blocked, repeats, file + "_blocked");
        condensation::Parameters mumps = schur;
        mumps.backend                  = condensation::Backend::mumps;
        row.mumps = measure(*s, b, mumps, repeats, file + "_mumps");
        const Eigen::MatrixXd A_blocked = read_matrix(file + "_blocked");
        const Eigen::MatrixXd A_schur   = read_matrix(file + "_schur");
        const Eigen::MatrixXd A_mumps   = read_matrix(file + "_mumps");
        const double scale = std::max(A_blocked.cwiseAbs().maxCoeff(), 1e-300);
        row.n_contact      = A_schur.rows();
        row.difference = (A_schur - A_blocked).cwiseAbs().maxCoeff() / scale;
        row.difference_mumps =
          (A_mumps - A_blocked).cwiseAbs().maxCoeff() / scale;
        rows.push_back(row);
      }
    return rows;
  }



  // @sect3{The orderings of the Schur route}
  //
  // The factorisation with the surface last under each LastBlockOrdering,
  // each in its own child: nnz(L), flops, times, and A against the first.
  template <int dim>
  void
  compare_orderings(const Case                    &c,
                    const parameters::FileOutline &outline,
                    const unsigned int             repeats,
                    const bool                     analysis_only)
  {
    using linear_algebra::LastBlockOrdering;
    auto s = make_scene<dim>(c.file, outline, c.entries);
    s->assemble();
    s->build_contact_surface();
    const std::string file =
      "/tmp/condensation_benchmark_" + std::to_string(getpid());
    for (unsigned int b = 0; b < s->n_bodies(); ++b)
      {
        Eigen::MatrixXd A0;
        for (const auto o : {LastBlockOrdering::moved_last,
                             LastBlockOrdering::constrained_amd,
                             LastBlockOrdering::interior_nested_dissection,
                             LastBlockOrdering::automatic})
          {
            condensation::Parameters p;
            p.ordering              = o;
            p.memory_limit_gb       = analysis_only ? 1e-9 : 0.0;
            const Measurement     m = measure(*s, b, p, repeats, file);
            const Eigen::MatrixXd A = read_matrix(file);
            if (A0.size() == 0)
              A0 = A;
            const double d = A.size() == 0 ?
                               0.0 :
                               (A - A0).cwiseAbs().maxCoeff() /
                                 std::max(A0.cwiseAbs().maxCoeff(), 1e-300);
            std::printf("%-26s %4u %8u %6u %-26s %9.3e %9.3e %9.3e %8.3g "
                        "%8.3g %7.0f %7.1e\n",
                        c.label.c_str(),
                        b + 1,
                        s->body(b).dof_handler().n_dofs(),
                        m.n_gamma,
                        linear_algebra::to_string(o).c_str(),
                        m.lnz,
                        m.entries,
                        m.flops,
                        m.t_factor,
                        m.t_condense,
                        m.peak_mb,
                        d);
            std::fflush(stdout);
          }
      }
  }



  // @sect3{Output}
  void
  print_header()
  {
    const char *route = "%8s %8s %6s %7s | ";
    std::printf("%-26s %4s %8s %5s %6s %7s | ",
                "scene",
                "body",
                "n_dofs",
                "n_c",
                "n_G",
                "setupMB");
    for (unsigned int k = 0; k < 3; ++k)
      std::printf(route, "factor", "condense", "ratio", "peakMB");
    std::printf("%7s %7s\n", "|dA|", "|dA|m");
    std::printf("%-26s %4s %8s %5s %6s %7s | %-33s | %-33s | %-33s |\n",
                "",
                "",
                "",
                "",
                "",
                "",
                "blocked solves [s]",
                "schur, cholmod [s]",
                "schur, mumps [s]");
  }

  void
  print_row(const Row &r)
  {
    std::printf("%-26s %4u %8u %5u %6u %7.0f | ",
                r.label.c_str(),
                r.body,
                r.n_dofs,
                r.n_contact,
                r.schur.n_gamma,
                r.setup_mb);
    for (const Measurement *m : {&r.blocked, &r.schur, &r.mumps})
      std::printf("%8.3g %8.3g %6.2f %7.0f | ",
                  m->t_factor,
                  m->t_condense,
                  m->t_condense / m->t_factor,
                  m->peak_mb);
    std::printf("%7.1e %7.1e\n", r.difference, r.difference_mumps);
    std::fflush(stdout);
  }

  void
  write_csv(const std::string &file, const std::vector<Row> &rows)
  {
    std::ofstream out(file);
    if (!out)
      {
        std::cerr << "condensation_benchmark: error: cannot write --csv file "
                  << file << std::endl;
        std::exit(1);
      }
    out << "scene,body,n_dofs,n_contact,n_gamma,setup_mb,"
           "blocked_factor,blocked_condense,blocked_peak_mb,"
           "schur_factor,schur_condense,schur_peak_mb,difference,"
           "mumps_factor,mumps_condense,mumps_peak_mb,mumps_difference,"
           "schur_factor_mb\n";
    out.precision(6);
    for (const Row &r : rows)
      out << r.label << ',' << r.body << ',' << r.n_dofs << ',' << r.n_contact
          << ',' << r.schur.n_gamma << ',' << r.setup_mb << ','
          << r.blocked.t_factor << ',' << r.blocked.t_condense << ','
          << r.blocked.peak_mb << ',' << r.schur.t_factor << ','
          << r.schur.t_condense << ',' << r.schur.peak_mb << ',' << r.difference
          << ',' << r.mumps.t_factor << ',' << r.mumps.t_condense << ','
          << r.mumps.peak_mb << ',' << r.difference_mumps << ','
          << 8e-6 * (r.schur.entries + r.schur.indices) << '\n';
  }



  // @sect3{The cases}
  //
  // The 3D receding block (receding_3d_L80.prm) at Subdivisions 2m, m, 2m
  // and the 2D Hertz cylinder on a rigid plane (hertz_rigid_mu0.prm) with k
  // contact refinements.
  std::vector<Case>
  cases(const std::string              &mode,
        const std::string              &prm_dir,
        const std::vector<std::string> &boxes_given)
  {
    if (!boxes_given.empty())
      {
        // The scale scene (prm/scale/receding_3d_1M.prm) at the given
        // Subdivisions "m, h, m".
        std::vector<Case> result;
        for (const std::string &sub : boxes_given)
          result.push_back({"scale " + sub,
                            prm_dir + "/scale/receding_3d_1M.prm",
                            {"Body 1/Geometry/Box/Subdivisions=" + sub}});
        return result;
      }
    std::vector<unsigned int> boxes = {16, 24}, hertz = {6, 7};
    if (mode == "quick")
      boxes = {8}, hertz = {5};
    else if (mode == "full")
      boxes = {16, 24}, hertz = {6, 7, 8};
    std::vector<Case> result;
    for (const unsigned int m : boxes)
      {
        const std::string sub = std::to_string(2 * m) + ", " +
                                std::to_string(m) + ", " +
                                std::to_string(2 * m);
        result.push_back({"receding_3d_L80 " + std::to_string(2 * m) + "x" +
                            std::to_string(m) + "x" + std::to_string(2 * m),
                          prm_dir + "/receding_3d_L80.prm",
                          {"Body 1/Geometry/Box/Subdivisions=" + sub}});
      }
    for (const unsigned int k : hertz)
      result.push_back(
        {"hertz_rigid_mu0 ref " + std::to_string(k),
         prm_dir + "/hertz_rigid_mu0.prm",
         {"Body 1/Geometry/Right half disc/Contact refinements=" +
          std::to_string(k)}});
    return result;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  std::string  mode      = "default";
  std::string  csv       = "results.csv";
  std::string  prm_dir   = "prm";
  unsigned int repeats   = 1;
  bool         orderings = false, analysis_only = false, schur_only = false;
  std::vector<std::string> boxes, only;
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--quick" || arg == "--full")
        mode = arg.substr(2);
      else if (arg == "--orderings")
        orderings = true;
      else if (arg == "--analysis-only")
        analysis_only = orderings = true;
      else if (arg == "--box" && i + 1 < argc)
        boxes.push_back(argv[++i]);
      else if (arg == "--schur-only")
        schur_only = true;
      else if (arg == "--only" && i + 1 < argc)
        only.push_back(argv[++i]);
      else if (arg == "--csv" && i + 1 < argc)
        csv = argv[++i];
      else if (arg == "--prm-dir" && i + 1 < argc)
        prm_dir = argv[++i];
      else if (arg == "--repeats" && i + 1 < argc && std::atoi(argv[i + 1]) > 0)
        repeats = std::atoi(argv[++i]);
      else
        {
          std::cerr << "condensation_benchmark: error: bad argument '" << arg
                    << "' (usage: condensation_benchmark [--quick | --full] "
                       "[--orderings | --analysis-only] [--box 'M, H, M' ...] "
                       "[--only TEXT ...] [--schur-only] "
                       "[--prm-dir DIR] [--csv FILE] [--repeats N])"
                    << std::endl;
          return 1;
        }
    }

  try
    {
      std::vector<Row> rows;
      const auto       start = std::chrono::steady_clock::now();
      if (orderings)
        {
          std::printf("Orderings of the Schur route (surface last): nnz(L), "
                      "numbers stored by the supernodal factor, flops of the "
                      "factorisation; times in s, peak memory in MB; |dA| "
                      "against the first ordering\n%-26s %4s %8s %6s %-26s "
                      "%9s %9s %9s %8s %8s %7s %7s\n",
                      "scene",
                      "body",
                      "n_dofs",
                      "n_G",
                      "ordering",
                      "nnz(L)",
                      "stored",
                      "flops",
                      "factor",
                      "condense",
                      "peakMB",
                      "|dA|");
          for (const Case &c : cases(mode, prm_dir, boxes))
            {
              const auto outline = parameters::scan_file(c.file);
              if (outline.dimension == 2)
                compare_orderings<2>(c, outline, repeats, analysis_only);
              else
                compare_orderings<3>(c, outline, repeats, analysis_only);
            }
          std::printf("total wall time %.1f s\n", seconds_since(start));
          return 0;
        }
      std::printf("Condensation by blocked solves and through the Schur "
                  "complement (CHOLMOD, MUMPS), side by side (times in s, "
                  "memory in MB)\n");
      print_header();
      for (const Case &c : cases(mode, prm_dir, boxes))
        {
          // --only: the cases whose label contains one of the texts.
          if (!only.empty() &&
              std::none_of(only.begin(), only.end(), [&](const auto &text) {
                return c.label.find(text) != std::string::npos;
              }))
            continue;
          const auto outline = parameters::scan_file(c.file);
          const auto part    = outline.dimension == 2 ?
                                 run_case<2>(c, outline, repeats, schur_only) :
                                 run_case<3>(c, outline, repeats, schur_only);
          for (const Row &r : part)
            {
              print_row(r);
              rows.push_back(r);
            }
        }
      write_csv(csv, rows);
      std::printf("ratio = condense / factor of the same route; peakMB = peak "
                  "resident memory of the process that assembled the scene "
                  "and ran the route (setupMB: before the routes); |dA| = max "
                  "|A_schur - A_blocked| / max |A_ij|, |dA|m the same for "
                  "A_mumps\n"
                  "total wall time %.1f s; csv: %s\n",
                  seconds_since(start),
                  csv.c_str());
    }
  catch (const std::exception &e)
    {
      std::cerr << "condensation_benchmark: error: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
