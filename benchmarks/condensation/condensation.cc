// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Benchmark: the cost of the condensation of one elastic body on its
// candidate contact surface,
//
//   Z = K_r^{-1} V (in the full-length form M K_r^{-1} M^T V),  A = V^T Z,
//
// with V the n_dofs x dim n_elements coupling matrix of the piecewise
// constant contact tractions. The condensation needs one sparse Cholesky
// factorisation and one solve per contact unknown; it is cheap only if
// those solves are done in blocks of right-hand sides (dense BLAS 3 kernels
// in the supernodal factor) rather than one at a time. Measured, for each
// body and mesh:
//
//   1. t_factor:  SparseCholesky::factorize(K, constraints) alone (the
//                 extraction of the reduced matrix K_r and CHOLMOD's
//                 analysis and numerical factorisation);
//   2. t_blocked: SparseCholesky::solve(MatrixXd) on all columns of V, in
//                 passes of 256 columns as the Condenser does (each pass is
//                 handed to CHOLMOD in blocks of block_size() = 64);
//   3. t_single:  SparseCholesky::solve(VectorXd) on each column of V
//                 separately (the one-column-at-a-time baseline; on large
//                 surfaces an evenly spaced sample of columns is solved and
//                 the time scaled to all columns, flagged in the output);
//   4. t_condense: the whole condensation through the Condenser's own
//                 API: assemble_coupling() + factorize() (fictitious
//                 supports, factorisation, load solve u_o) + condense()
//                 (blocked solves, A = V^T Z, symmetrisation, G).
//
// and reported: ratio = t_condense / (t_factor + t_blocked), the overhead of
// the Condenser over the bare linear algebra (target <= ~1.5), and
// speedup = t_single / t_blocked. The A computed here from the blocked
// solves and from the one-column solves is compared with the Condenser's,
// so that the three computations are known to be the same one.
//
// Bodies: a 2D receding-block-like rectangle 40 x 40 mm, n x n cells
// (symmetry on the left, pressures on the top and right, Gamma_c = bottom,
// 2 edges per contact element), and a 3D box 40 x 20 x 40 mm with
// 2m x m x 2m cells (symmetry on the left and front, pressure on the top,
// Gamma_c = bottom y = 0, 8 triangles per contact element). Both are held
// in all directions but the vertical one, which the Condenser supports by a
// fictitious support, as in a real contact run.
//
// Times of steps 1, 2 and 4 are the minimum over --repeats runs (default
// 2); step 3 runs once, on at most --single-columns columns (default 128).
//
// Usage: condensation_benchmark [--quick | --full] [--csv FILE]
//                               [--single-columns N] [--repeats N]

#include <dpana/body/body.h>
#include <dpana/condensation/condenser.h>
#include <dpana/contact_surface/contact_surface.h>
#include <dpana/linear_algebra/sparse_cholesky.h>

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

  // One line of the results.
  struct Row
  {
    std::string  problem;
    unsigned int dim = 0;
    std::string  mesh;
    unsigned int n_dofs = 0, n_free = 0, n_contact = 0;
    double       t_setup  = 0; // mesh, dofs, assembly (not compared)
    double       t_factor = 0, t_blocked = 0, t_single = 0;
    unsigned int single_columns = 0; // columns actually solved one by one
    double t_coupling = 0, t_condenser_factorize = 0, t_condenser_condense = 0;
    double t_condense = 0;
    double ratio = 0, speedup = 0;
    // Largest difference between the A of the Condenser and that of the
    // blocked (resp. one-column) solves, relative to max |A_ij|.
    double difference_blocked = 0, difference_single = 0;
  };



  // @sect3{The bodies}
  //
  // The parameter text of the body, in the syntax of a dpana scene file.
  template <int dim>
  std::string
  body_parameters(const unsigned int n)
  {
    std::ostringstream text;
    text << "subsection Body 1\n"
         << "  subsection Geometry\n";
    if (dim == 2)
      text << "    set Type = rectangle\n"
           << "    subsection Rectangle\n"
           << "      set Lower corner = 0, 0\n"
           << "      set Upper corner = 40, 40\n"
           << "      set Subdivisions = " << n << ", " << n << "\n";
    else
      text << "    set Type = box\n"
           << "    subsection Box\n"
           << "      set Lower corner = 0, 0, 0\n"
           << "      set Upper corner = 40, 20, 40\n"
           << "      set Subdivisions = " << 2 * n << ", " << n << ", " << 2 * n
           << "\n";
    text << "    end\n"
         << "  end\n"
         << "  subsection Material\n"
         << "    set Young's modulus = 130000\n"
         << "    set Poisson's ratio = 0.2\n"
         << "  end\n"
         << "  subsection Boundary conditions\n"
         << (dim == 2 ? "    set Symmetry = left\n" :
                        "    set Symmetry = left, front\n")
         << "  end\n"
         << "  subsection Loads\n"
         << "    set Pressure = top: 50; right: 100\n"
         << "  end\n"
         << "end\n";
    return text.str();
  }



  // @sect3{One measurement}
  template <int dim>
  Row
  run_case(const unsigned int n,
           const unsigned int max_single_columns,
           const unsigned int repeats)
  {
    Row row;
    row.dim     = dim;
    row.problem = dim == 2 ? "block2d" : "box3d";
    row.mesh    = dim == 2 ? std::to_string(n) + "x" + std::to_string(n) :
                             std::to_string(2 * n) + "x" + std::to_string(n) +
                            "x" + std::to_string(2 * n);

    // The body: mesh, degrees of freedom, constraints and assembly.
    auto      start = std::chrono::steady_clock::now();
    Body<dim> body("Body 1");
    {
      dealii::ParameterHandler prm;
      prm.enter_subsection("Body 1");
      Body<dim>::declare_parameters(prm);
      prm.leave_subsection();
      prm.parse_input_from_string(body_parameters<dim>(n));
      prm.enter_subsection("Body 1");
      body.parse_parameters(prm);
      prm.leave_subsection();
    }
    body.create_mesh();
    body.setup();
    body.assemble();

    // The candidate contact surface: the whole bottom, normal -y.
    contact_surface::ContactSurface<dim>                   surface;
    typename contact_surface::ContactSurface<dim>::Options options;
    options.boundary     = "bottom";
    options.boundary_id  = body.boundary_names().at("bottom");
    options.body         = body.name();
    options.direction[1] = -1;
    surface.build(body.triangulation(), options);
    surface.set_plane_gap(surface.first_contact_point());
    row.t_setup = seconds_since(start);

    // 4. The condensation through the Condenser, call by call. Every
    // timing in this function is the minimum over `repeats` runs: the
    // machine may be shared, and the minimum is the least disturbed run.
    condensation::Condenser<dim> condenser(body, surface);
    for (unsigned int k = 0; k < repeats; ++k)
      {
        start = std::chrono::steady_clock::now();
        condenser.assemble_coupling();
        const double t_coupling = seconds_since(start);
        start                   = std::chrono::steady_clock::now();
        condenser.factorize();
        const double t_factorize = seconds_since(start);
        start                    = std::chrono::steady_clock::now();
        condenser.condense();
        const double t_condense = seconds_since(start);
        if (k == 0 || t_coupling + t_factorize + t_condense < row.t_condense)
          {
            row.t_coupling            = t_coupling;
            row.t_condenser_factorize = t_factorize;
            row.t_condenser_condense  = t_condense;
            row.t_condense            = t_coupling + t_factorize + t_condense;
          }
      }

    const Eigen::SparseMatrix<double> &V  = condenser.coupling();
    const Eigen::MatrixXd             &A  = condenser.compliance();
    const unsigned int                 nc = V.cols();
    row.n_dofs                            = body.dof_handler().n_dofs();
    row.n_contact                         = nc;

    // 1. The bare factorisation, of the same reduced matrix: the body's
    // constraints plus the Condenser's fictitious supports.
    dealii::AffineConstraints<double> constraints;
    for (const auto &line : body.constraints().get_lines())
      {
        constraints.add_line(line.index);
        constraints.add_entries(line.index, line.entries);
        constraints.set_inhomogeneity(line.index, line.inhomogeneity);
      }
    for (const unsigned int s : condenser.fictitious_supports())
      constraints.add_line(s);
    constraints.close();

    linear_algebra::SparseCholesky cholesky;
    for (unsigned int k = 0; k < repeats; ++k)
      {
        start = std::chrono::steady_clock::now();
        cholesky.factorize(body.system_matrix(), constraints);
        const double t = seconds_since(start);
        row.t_factor   = k == 0 ? t : std::min(row.t_factor, t);
      }
    row.n_free = cholesky.n_unknowns();

    // 2. Blocked solves, in passes of 256 columns of V (the Condenser's
    // default). Only the solve is timed; A = V^T Z is formed untimed for
    // the comparison.
    const double       A_scale = std::max(A.cwiseAbs().maxCoeff(), 1e-300);
    Eigen::MatrixXd    A_blocked(nc, nc);
    const unsigned int pass = 256;
    for (unsigned int c0 = 0; c0 < nc; c0 += pass)
      {
        const unsigned int    nb = std::min(pass, nc - c0);
        const Eigen::MatrixXd Vb = Eigen::MatrixXd(V.middleCols(c0, nb));
        Eigen::MatrixXd       Zb;
        double                t_pass = 0;
        for (unsigned int k = 0; k < repeats; ++k)
          {
            start          = std::chrono::steady_clock::now();
            Zb             = cholesky.solve(Vb);
            const double t = seconds_since(start);
            t_pass         = k == 0 ? t : std::min(t_pass, t);
          }
        row.t_blocked += t_pass;
        A_blocked.middleCols(c0, nb) = V.transpose() * Zb;
      }
    row.difference_blocked = (A_blocked - A).cwiseAbs().maxCoeff() / A_scale;

    // 3. One column at a time: all columns, or an evenly spaced sample of
    // max_single_columns of them, the time then scaled by nc / sample
    // (every column costs the same two triangular sweeps). Run once: this
    // is the slow baseline, and its noise is small against the speed-up.
    std::vector<unsigned int> columns;
    if (nc <= max_single_columns)
      for (unsigned int j = 0; j < nc; ++j)
        columns.push_back(j);
    else
      for (unsigned int k = 0; k < max_single_columns; ++k)
        columns.push_back(static_cast<unsigned int>(
          (static_cast<unsigned long>(k) * nc) / max_single_columns));
    double t_sample = 0;
    for (const unsigned int j : columns)
      {
        const Eigen::VectorXd b = Eigen::VectorXd(V.col(j));
        start                   = std::chrono::steady_clock::now();
        const Eigen::VectorXd z = cholesky.solve(b);
        t_sample += seconds_since(start);
        const Eigen::VectorXd a = V.transpose() * z;
        row.difference_single =
          std::max(row.difference_single,
                   (a - A.col(j)).cwiseAbs().maxCoeff() / A_scale);
      }
    row.single_columns = columns.size();
    row.t_single       = t_sample * nc / columns.size();

    row.ratio   = row.t_condense / (row.t_factor + row.t_blocked);
    row.speedup = row.t_single / row.t_blocked;
    return row;
  }



  // @sect3{Output}
  void
  print_header()
  {
    std::printf("%-8s %-10s %8s %6s %9s %9s %9s %9s %9s %6s %7s %8s\n",
                "problem",
                "mesh",
                "n_dofs",
                "n_c",
                "setup[s]",
                "factor[s]",
                "blocked",
                "single",
                "condense",
                "ratio",
                "speedup",
                "|dA|");
  }

  void
  print_row(const Row &r)
  {
    char single[32];
    std::snprintf(single,
                  sizeof(single),
                  "%.3g%s",
                  r.t_single,
                  r.single_columns < r.n_contact ? "*" : "");
    std::printf(
      "%-8s %-10s %8u %6u %9.3g %9.3g %9.3g %9s %9.3g %6.2f %7.1f %8.1e\n",
      r.problem.c_str(),
      r.mesh.c_str(),
      r.n_dofs,
      r.n_contact,
      r.t_setup,
      r.t_factor,
      r.t_blocked,
      single,
      r.t_condense,
      r.ratio,
      r.speedup,
      std::max(r.difference_blocked, r.difference_single));
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
    out << "problem,dim,mesh,n_dofs,n_free,n_contact,t_setup,t_factor,"
           "t_blocked,t_single,single_columns,t_coupling,"
           "t_condenser_factorize,t_condenser_condense,t_condense,ratio,"
           "speedup,difference_blocked,difference_single\n";
    out.precision(6);
    for (const Row &r : rows)
      out << r.problem << ',' << r.dim << ',' << r.mesh << ',' << r.n_dofs
          << ',' << r.n_free << ',' << r.n_contact << ',' << r.t_setup << ','
          << r.t_factor << ',' << r.t_blocked << ',' << r.t_single << ','
          << r.single_columns << ',' << r.t_coupling << ','
          << r.t_condenser_factorize << ',' << r.t_condenser_condense << ','
          << r.t_condense << ',' << r.ratio << ',' << r.speedup << ','
          << r.difference_blocked << ',' << r.difference_single << '\n';
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  std::string  mode               = "default";
  std::string  csv                = "results.csv";
  unsigned int max_single_columns = 128;
  unsigned int repeats            = 2;
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--quick" || arg == "--full")
        mode = arg.substr(2);
      else if (arg == "--csv" && i + 1 < argc)
        csv = argv[++i];
      else if ((arg == "--single-columns" || arg == "--repeats") &&
               i + 1 < argc)
        {
          const int value = std::atoi(argv[++i]);
          if (value <= 0)
            {
              std::cerr << "condensation_benchmark: error: " << arg
                        << " must be a positive integer" << std::endl;
              return 1;
            }
          (arg == "--repeats" ? repeats : max_single_columns) = value;
        }
      else
        {
          std::cerr << "condensation_benchmark: error: unknown argument '"
                    << arg
                    << "' (usage: condensation_benchmark [--quick | --full] "
                       "[--csv FILE] [--single-columns N] [--repeats N])"
                    << std::endl;
          return 1;
        }
    }

  // Sizes: n x n cells in 2D, 2m x m x 2m in 3D.
  std::vector<unsigned int> sizes_2d = {32, 64, 128, 256};
  std::vector<unsigned int> sizes_3d = {4, 8, 12, 16};
  if (mode == "quick")
    {
      sizes_2d = {16, 32};
      sizes_3d = {2, 4};
    }
  else if (mode == "full")
    {
      sizes_2d = {64, 128, 256, 512};
      sizes_3d = {8, 12, 16, 20};
    }

  try
    {
      // Warm-up (untimed): the first CHOLMOD and BLAS calls of a process
      // pay for their initialisation.
      run_case<2>(16, 4, 1);

      std::vector<Row> rows;
      const auto       start = std::chrono::steady_clock::now();
      std::printf("Condensation of one body (times in seconds; single* = "
                  "sampled columns, scaled to all)\n");
      print_header();
      for (const unsigned int n : sizes_2d)
        {
          rows.push_back(run_case<2>(n, max_single_columns, repeats));
          print_row(rows.back());
        }
      for (const unsigned int n : sizes_3d)
        {
          rows.push_back(run_case<3>(n, max_single_columns, repeats));
          print_row(rows.back());
        }
      write_csv(csv, rows);
      std::printf("ratio = condense / (factor + blocked), speedup = single / "
                  "blocked; |dA| = max difference of A (blocked and single "
                  "solves vs the Condenser), relative to max |A_ij|\n"
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
