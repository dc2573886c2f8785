// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

// @sect3{Include files}
//
// The first step of the tutorial builds one elastic body and nothing else:
// no contact yet. Everything a body needs lives in dpana::Body (its mesh,
// its P1 displacement space, its stiffness matrix with the kinematic
// conditions eliminated, its sparse Cholesky factorisation and its
// stresses). The parameter reader of dpana turns deal.II's errors into one
// line messages, and dpana::output writes the body as a VTU file for
// ParaView.
#include <dpana/body/body.h>
#include <dpana/output/output.h>
#include <dpana/parameters/parameters.h>

// From deal.II we need the exact solution as a Function, the error
// integration of VectorTools, the cell diameter of GridTools and the
// quadrature rules on simplices.
#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <vector>

namespace Step1
{
  using namespace dealii;
  using namespace dpana;

  // @sect3{The exact solution of Lamé}
  //
  // A long cylinder of inner radius a and outer radius b carries the
  // pressure p on its bore. In plane strain (eps_zz = 0) the displacement
  // is radial,
  //
  //   u_r(r) = (1 + nu) p a^2 / (E (b^2 - a^2)) ((1 - 2 nu) r + b^2 / r),
  //
  // and the stresses are sigma_rr = A - B / r^2, sigma_tt = A + B / r^2 with
  // A = p a^2 / (b^2 - a^2) and B = p a^2 b^2 / (b^2 - a^2) (Timoshenko and
  // Goodier, Theory of Elasticity, section 33). The hoop stress is largest
  // at the bore, sigma_tt(a) = p (b^2 + a^2) / (b^2 - a^2). The class holds
  // the four data of the problem and evaluates both fields in Cartesian
  // components, since the finite element solution is stored that way.
  struct LameSolution
  {
    double a, b, p, E, nu;

    double
    radial_displacement(const double r) const
    {
      return (1. + nu) * p * a * a / (E * (b * b - a * a)) *
             ((1. - 2. * nu) * r + b * b / r);
    }

    Tensor<1, 2>
    displacement(const Point<2> &x) const
    {
      return radial_displacement(x.norm()) / x.norm() * Tensor<1, 2>(x);
    }

    // sigma = sigma_rr e_r (x) e_r + sigma_tt e_t (x) e_t.
    SymmetricTensor<2, 2>
    stress(const Point<2> &x) const
    {
      const double          r2   = x.norm_square();
      const double          A    = p * a * a / (b * b - a * a);
      const double          B    = A * b * b;
      const Tensor<1, 2>    e_r  = Tensor<1, 2>(x) / std::sqrt(r2);
      const Tensor<1, 2>    e_t  = -cross_product_2d(e_r);
      const double          s_rr = A - B / r2;
      const double          s_tt = A + B / r2;
      SymmetricTensor<2, 2> s;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          s[i][j] = s_rr * e_r[i] * e_r[j] + s_tt * e_t[i] * e_t[j];
      return s;
    }
  };

  // deal.II's VectorTools::integrate_difference() wants the exact
  // displacement as a vector-valued Function with two components.
  class ExactDisplacement : public Function<2>
  {
  public:
    explicit ExactDisplacement(const LameSolution &exact)
      : Function<2>(2)
      , exact(exact)
    {
    }

    void
    vector_value(const Point<2> &x, Vector<double> &values) const override
    {
      const Tensor<1, 2> u = exact.displacement(x);
      values[0]            = u[0];
      values[1]            = u[1];
    }

  private:
    const LameSolution exact;
  };

  // @sect3{The errors of one mesh}
  //
  // For every mesh we record its size h (the largest cell diameter), the
  // number of cells and unknowns, four errors and the wall time. All errors
  // are relative: the displacement errors to the exact displacement, the
  // stress errors to the pressure p.
  //
  // - e_u: the L2 norm of u_h - u over the mesh, over the L2 norm of u;
  // - e_u,max: the largest error of u_h at the vertices, over u_r(a);
  // - e_sigma: the L2 norm of sigma_h - sigma, over p times the square root
  //   of the area (a root-mean-square error of the in-plane stress);
  // - e_sigma,max: the largest error of sigma_h at the cell centroids, over p.
  struct CycleResult
  {
    unsigned int refinements, n_cells, n_dofs;
    double       h;
    double       e_u, e_u_max, e_sigma, e_sigma_max;
    double       seconds_assembly, seconds_solve;

    // The four errors in the order of the table.
    std::array<double, 4>
    errors() const
    {
      return {{e_u, e_u_max, e_sigma, e_sigma_max}};
    }
  };

  // @sect3{The LameProblem class}
  //
  // The class follows the pattern of deal.II's tutorial programs: a
  // constructor that reads the parameters, a run() that does the study, and
  // one function per task. The body itself is a dpana::Body<2>; a new one
  // is built on every cycle from the same parameters with a different
  // number of global refinements.
  class LameProblem
  {
  public:
    explicit LameProblem(const std::string &parameter_file);

    void
    run();

  private:
    // One mesh: build the body with the given number of global
    // refinements, solve it, and measure its errors.
    CycleResult
    solve_on_mesh(const unsigned int refinements);
    // The error measures of a solved body (see CycleResult).
    double
    l2_displacement_error(const Body<2> &body) const;
    double
    max_nodal_displacement_error(const Body<2> &body) const;
    std::pair<double, double>
    stress_errors(const Body<2> &body) const;
    // Throws unless the mesh is the ring of the exact solution.
    void
    check_geometry(const Body<2> &body) const;

    // The output: the table on the screen and in errors.csv, the stresses
    // along the radius, the figures, and the check of the headline number.
    void
    print_and_write_table() const;
    void
    write_stress_profile(const Body<2> &body) const;
    void
    plot() const;
    void
    check_convergence() const;

    // The parameters of the whole file (all subsections), the range of the
    // study, where the output goes, the exact solution, and one
    // CycleResult per mesh.
    ParameterHandler         prm;
    unsigned int             first_refinement, last_refinement;
    std::string              output_directory;
    LameSolution             exact;
    std::vector<CycleResult> results;
  };

  // @sect3{Parameters}
  //
  // The parameters of a body are declared by the body itself: Body<2>
  // declares the subsections Geometry, Material, Boundary conditions and
  // Loads, each component its own entries (see doc/parameters.md, or run
  // `dpana --print-parameters step-1.prm`). We put them in `subsection
  // Body 1`, as in every dpana scene, and add two subsections of our own:
  // the range of the convergence study and the output directory, which
  // dpana::output::Parameters declares. The file, step-1.prm in the folder
  // of this program, reads (apart from its opening comments):
  //
  //     subsection Body 1
  //       subsection Geometry
  //         set Type = quarter annulus
  //         # Overwritten by the program on every cycle of the study.
  //         set Global refinements = 1
  //         subsection Quarter annulus
  //           set Inner radius = 10
  //           set Outer radius = 20
  //         end
  //       end
  //       subsection Material
  //         set Young's modulus = 200000
  //         set Poisson's ratio = 0.3
  //         set Plane state     = plane strain
  //       end
  //       subsection Boundary conditions
  //         set Symmetry = x_axis, y_axis
  //       end
  //       subsection Loads
  //         set Pressure = inner: 100
  //       end
  //     end
  //     subsection Convergence study
  //       set First refinement = 1
  //       set Last refinement  = 6
  //     end
  //     subsection Output
  //       set Directory = output
  //     end
  //
  // The quarter annulus is one of the geometries of dpana's Geometry
  // component (doc/geometry.md): the part x >= 0, y >= 0 of the ring
  // between the two radii, meshed with triangles, its boundaries named
  // `inner`, `outer`, `x_axis` (y = 0) and `y_axis` (x = 0). Symmetry makes
  // u . n = 0 on the two straight edges: u_y = 0 on y = 0 and u_x = 0 on
  // x = 0. The pressure is positive when it pushes on the surface, so the
  // traction on the bore is -p n with n the outward normal of the body
  // (pointing to the axis).
  //
  // The data of the exact solution are read back from the same file, so
  // that changing the radii, the material or the pressure in step-1.prm
  // changes both sides of the comparison: the radii from the quarter
  // annulus subsection, E and nu from the body's Material, p from its Loads.
  // The exact solution holds only for this one load case, so the program
  // asserts it: plane strain and a single pressure on the bore.
  LameProblem::LameProblem(const std::string &parameter_file)
  {
    prm.enter_subsection("Body 1");
    Body<2>::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Convergence study");
    prm.declare_entry("First refinement", "1", Patterns::Integer(0, 10));
    prm.declare_entry("Last refinement", "6", Patterns::Integer(0, 10));
    prm.leave_subsection();
    prm.enter_subsection("Output");
    output::Parameters::declare_parameters(prm);
    prm.leave_subsection();

    // parse_file() reads the file with every entry declared; a misspelt
    // entry, a value that does not match its pattern or a missing `end`
    // becomes a dpana::InputError that names the file and the line.
    dpana::parameters::parse_file(prm, parameter_file);

    prm.enter_subsection("Convergence study");
    first_refinement = prm.get_integer("First refinement");
    last_refinement  = prm.get_integer("Last refinement");
    prm.leave_subsection();
    AssertThrow(first_refinement + 1 < last_refinement,
                ExcMessage("A convergence rate needs three meshes or more."));
    prm.enter_subsection("Output");
    output::Parameters output_parameters;
    output_parameters.parse_parameters(prm);
    output_directory = output_parameters.directory;
    prm.leave_subsection();

    prm.enter_subsection("Body 1");
    Body<2> body;
    body.parse_parameters(prm);
    prm.enter_subsection("Geometry");
    AssertThrow(prm.get("Type") == "quarter annulus",
                ExcMessage("Lamé's solution is for the quarter annulus."));
    prm.enter_subsection("Quarter annulus");
    exact.a = prm.get_double("Inner radius");
    exact.b = prm.get_double("Outer radius");
    prm.leave_subsection();
    prm.leave_subsection();
    prm.leave_subsection();

    exact.E  = body.material().youngs_modulus();
    exact.nu = body.material().poissons_ratio();
    AssertThrow(body.material().plane_state() ==
                  Material::PlaneState::plane_strain,
                ExcMessage("The exact solution here is the plane strain one."));
    const auto &pressures = body.loads().pressure;
    AssertThrow(pressures.size() == 1 && pressures[0].boundary == "inner",
                ExcMessage("Lamé's problem: one pressure, on 'inner'."));
    exact.p = pressures[0].pressure;
  }

  // @sect3{One cycle: build, assemble, factor, solve}
  //
  // This is the whole life of an elastic body in dpana, in the order of its
  // member functions:
  //
  // - parse_parameters() reads the four subsections;
  // - create_mesh() lets the Geometry component build the triangulation
  //   (here a quarter annulus of triangles, refined `refinements` times,
  //   with the new vertices on the two circles) and names its boundaries
  //   `inner`, `outer`, `x_axis`, `y_axis`;
  // - setup() distributes the degrees of freedom of FESystem(FE_SimplexP(1),
  //   2), turns the two symmetry conditions into constraints u . n = 0 and
  //   finds the rigid motions they leave free; check_held() throws if there
  //   are any (here the two symmetry planes hold the body: they stop both
  //   translations and the rotation);
  // - assemble() builds K and f with the constraints eliminated;
  // - solve() factors the reduced K by CHOLMOD's sparse Cholesky
  //   (dpana::linear_algebra::SparseCholesky) and solves K u = f;
  // - compute_stresses() evaluates sigma = C : eps(u_h) in every cell, a
  //   constant for P1 elements.
  //
  // The timings separate the assembly (mesh and matrix) from the
  // factorisation and solution.
  CycleResult
  LameProblem::solve_on_mesh(const unsigned int refinements)
  {
    using Clock      = std::chrono::steady_clock;
    const auto start = Clock::now();

    // A Body owns its triangulation and everything built on it, so every
    // cycle makes a new one. Its number of global refinements is changed
    // in the ParameterHandler, exactly as a user would change it in the
    // file; the body then parses the same subsections as before.
    prm.enter_subsection("Body 1");
    prm.enter_subsection("Geometry");
    prm.set("Global refinements", std::to_string(refinements));
    prm.leave_subsection();
    Body<2> body("Lamé cylinder");
    body.parse_parameters(prm);
    prm.leave_subsection();

    body.create_mesh();
    check_geometry(body);
    body.setup();
    body.check_held();
    body.assemble();
    const auto assembled = Clock::now();
    body.solve();
    body.compute_stresses();
    const auto solved = Clock::now();

    CycleResult result;
    result.refinements = refinements;
    result.n_cells     = body.triangulation().n_active_cells();
    result.n_dofs      = body.dof_handler().n_dofs();
    result.h =
      GridTools::maximal_cell_diameter(body.triangulation(), body.mapping());
    result.e_u     = l2_displacement_error(body);
    result.e_u_max = max_nodal_displacement_error(body);
    std::tie(result.e_sigma, result.e_sigma_max) = stress_errors(body);
    result.seconds_assembly =
      std::chrono::duration<double>(assembled - start).count();
    result.seconds_solve =
      std::chrono::duration<double>(solved - assembled).count();

    // Two bodies are kept for the pictures. The finest is written as a VTU
    // file (open it in ParaView, Warp By Vector on "displacement", colour
    // by "von_mises"). On the third mesh, coarse enough for single cells to
    // show, the stresses along the radius are written for the plot.
    if (refinements == last_refinement)
      output::write_vtu_file(body, output_directory + "/lame.vtu");
    if (refinements == first_refinement + 2)
      write_stress_profile(body);
    return result;
  }

  // The exact solution is centred at the origin. A mistaken Centre in the
  // parameter file would make every error large for no visible reason, so
  // we check that every vertex lies in the ring a <= r <= b.
  void
  LameProblem::check_geometry(const Body<2> &body) const
  {
    for (const auto &x : body.triangulation().get_vertices())
      AssertThrow(x.norm() > exact.a * (1 - 1e-10) &&
                    x.norm() < exact.b * (1 + 1e-10),
                  ExcMessage("The quarter annulus must be centred at 0."));
  }

  // @sect3{The displacement errors}
  //
  // The L2 error is integrated cell by cell with a quadrature rule of
  // degree 4 (P1 error terms are smooth in each cell), through the body's
  // MappingFE: simplex cells need it, deal.II's default mapping is for
  // quadrilaterals. Note that the mesh covers the polygon inscribed in the
  // ring, not the ring: the integral runs over the discrete domain, and the
  // exact solution is simply evaluated there (it is smooth across r = a).
  double
  LameProblem::l2_displacement_error(const Body<2> &body) const
  {
    const ExactDisplacement u_exact(exact);
    const QGaussSimplex<2>  quadrature(3);
    Vector<double>          cellwise(body.triangulation().n_active_cells());
    VectorTools::integrate_difference(body.mapping(),
                                      body.dof_handler(),
                                      body.solution(),
                                      u_exact,
                                      cellwise,
                                      quadrature,
                                      VectorTools::L2_norm);
    const double error =
      VectorTools::compute_global_error(body.triangulation(),
                                        cellwise,
                                        VectorTools::L2_norm);

    // The norm of u itself, the same integral with u_h = 0.
    const Vector<double> zero(body.dof_handler().n_dofs());
    VectorTools::integrate_difference(body.mapping(),
                                      body.dof_handler(),
                                      zero,
                                      u_exact,
                                      cellwise,
                                      quadrature,
                                      VectorTools::L2_norm);
    return error / VectorTools::compute_global_error(body.triangulation(),
                                                     cellwise,
                                                     VectorTools::L2_norm);
  }

  // The nodal values are read through Body::vertex_dofs(), the map from a
  // mesh vertex to its two degrees of freedom. For P1 elements the nodal
  // values are the whole discrete solution: u_h is their linear
  // interpolant in each triangle. Vertices that the triangulation no
  // longer uses (there are none after global refinement, but the vertex
  // list of a deal.II triangulation may hold some) are skipped.
  double
  LameProblem::max_nodal_displacement_error(const Body<2> &body) const
  {
    const auto &vertices = body.triangulation().get_vertices();
    double      error    = 0;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (body.triangulation().vertex_used(v))
        {
          Tensor<1, 2> u_h;
          for (unsigned int c = 0; c < 2; ++c)
            u_h[c] = body.solution()[body.vertex_dofs()[v][c]];
          error =
            std::max(error, (u_h - exact.displacement(vertices[v])).norm());
        }
    return error / exact.radial_displacement(exact.a);
  }

  // @sect3{The stress errors}
  //
  // The P1 stress is constant in each cell: Body::cell_stress() holds one
  // tensor per active cell. The L2 error is integrated with the quadrature
  // points of an FEValues object (it gives their positions and weights on
  // the mapped cell), and the largest error is sampled at the centroids,
  // where a constant-strain triangle represents the stress best.
  std::pair<double, double>
  LameProblem::stress_errors(const Body<2> &body) const
  {
    const QGaussSimplex<2> quadrature(3);
    FEValues<2>            fe_values(body.mapping(),
                          body.fe(),
                          quadrature,
                          update_quadrature_points | update_JxW_values);
    const auto            &stress = body.cell_stress();
    AssertThrow(stress.size() == body.triangulation().n_active_cells(),
                ExcMessage("The stresses have not been computed."));
    double integral = 0, area = 0, largest = 0;
    for (const auto &cell : body.dof_handler().active_cell_iterators())
      {
        fe_values.reinit(cell);
        const auto &sigma_h = stress[cell->active_cell_index()];
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const auto difference =
              sigma_h - exact.stress(fe_values.quadrature_point(q));
            integral += (difference * difference) * fe_values.JxW(q);
            area += fe_values.JxW(q);
          }
        const Point<2> centroid = cell->center();
        largest = std::max(largest, (sigma_h - exact.stress(centroid)).norm());
      }
    return {std::sqrt(integral / area) / exact.p, largest / exact.p};
  }

  // @sect3{Output: the table, the profile, the plot}
  //
  // The observed order of convergence between two meshes is
  // log(e_coarse / e_fine) / log(h_coarse / h_fine). For P1 elements and a
  // smooth solution the theory (e.g. Ciarlet, The Finite Element Method for
  // Elliptic Problems, 1978) predicts 2 for the L2 error of the
  // displacement and 1 for the stress, its gradient.
  double
  rate(const double e_coarse,
       const double e_fine,
       const double h_coarse,
       const double h_fine)
  {
    return std::log(e_coarse / e_fine) / std::log(h_coarse / h_fine);
  }

  void
  LameProblem::print_and_write_table() const
  {
    std::ofstream csv(output_directory + "/errors.csv");
    csv << "refinements,cells,dofs,h,e_u,e_u_max,e_sigma,e_sigma_max,"
           "seconds_assembly,seconds_solve\n";
    std::cout << "ref  cells    dofs     h (mm)    e_u       rate  "
                 "e_u,max   rate  e_sigma   rate  e_sig,max rate  time (s)\n";
    for (unsigned int i = 0; i < results.size(); ++i)
      {
        const CycleResult &c = results[i];
        csv << c.refinements << ',' << c.n_cells << ',' << c.n_dofs << ','
            << std::setprecision(6) << c.h << ',' << c.e_u << ',' << c.e_u_max
            << ',' << c.e_sigma << ',' << c.e_sigma_max << ','
            << c.seconds_assembly << ',' << c.seconds_solve << '\n';
        // Each error is followed by its rate against the previous mesh.
        std::printf("%3u%7u%8u  %.4f", c.refinements, c.n_cells, c.n_dofs, c.h);
        for (unsigned int k = 0; k < 4; ++k)
          {
            std::printf("  %.2e", c.errors()[k]);
            if (i == 0)
              std::printf("   -  ");
            else
              std::printf("  %.2f",
                          rate(results[i - 1].errors()[k],
                               c.errors()[k],
                               results[i - 1].h,
                               c.h));
          }
        std::printf("  %.3f\n", c.seconds_assembly + c.seconds_solve);
      }
    std::fflush(stdout);
  }

  // On one mesh: r and the polar stresses sigma_rr, sigma_tt of the
  // finite element solution at every cell centroid, next to the exact ones.
  void
  LameProblem::write_stress_profile(const Body<2> &body) const
  {
    std::ofstream csv(output_directory + "/stress_profile.csv");
    csv << "r,sigma_rr,sigma_tt,exact_sigma_rr,exact_sigma_tt\n";
    for (const auto &cell : body.triangulation().active_cell_iterators())
      {
        const Point<2>     x   = cell->center();
        const Tensor<1, 2> e_r = Tensor<1, 2>(x) / x.norm();
        const Tensor<1, 2> e_t = -cross_product_2d(e_r);
        const auto        &s   = body.cell_stress()[cell->active_cell_index()];
        const auto         exact_s = exact.stress(x);
        csv << x.norm() << ',' << e_r * (s * e_r) << ',' << e_t * (s * e_t)
            << ',' << e_r * (exact_s * e_r) << ',' << e_t * (exact_s * e_t)
            << '\n';
      }
  }

  // The figures are drawn by the plot script of this step's folder (the
  // DPANA_STEP_DIR that CMake gives the program) with matplotlib. A missing
  // python or matplotlib leaves the CSV files and is only a warning.
  void
  LameProblem::plot() const
  {
    const std::string script = std::string(DPANA_STEP_DIR) + "/plot.py";
    const std::string python = "/usr/bin/python3";
    if (std::system(
          (python + " -c 'import matplotlib' > /dev/null 2>&1").c_str()) != 0)
      {
        std::cerr << "Warning: no python3 with matplotlib, no figures."
                  << std::endl;
        return;
      }
    if (std::system((python + " " + script + " " + output_directory).c_str()) !=
        0)
      std::cerr << "Warning: " << script << " failed." << std::endl;
  }

  // @sect3{The headline check}
  //
  // A tutorial that nobody checks rots. The program therefore fails (and
  // with it the ctest tutorial/step-1) unless, on the two finest meshes,
  // the L2 error of the displacement converges at an observed rate of at
  // least 1.9, the L2 error of the stress at a rate of at least 0.9, and the
  // finest displacement error is below 1e-4 (the values of the run are in
  // the results section).
  void
  LameProblem::check_convergence() const
  {
    const CycleResult &c          = results[results.size() - 2];
    const CycleResult &f          = results.back();
    const double       rate_u     = rate(c.e_u, f.e_u, c.h, f.h);
    const double       rate_sigma = rate(c.e_sigma, f.e_sigma, c.h, f.h);
    std::cout << "Observed rates on the two finest meshes: displacement "
              << std::fixed << std::setprecision(3) << rate_u << ", stress "
              << rate_sigma << "; finest displacement error " << std::scientific
              << f.e_u << std::defaultfloat << std::endl;
    AssertThrow(rate_u > 1.9,
                ExcMessage("L2 displacement rate " + std::to_string(rate_u) +
                           " < 1.9"));
    AssertThrow(rate_sigma > 0.9,
                ExcMessage("L2 stress rate " + std::to_string(rate_sigma) +
                           " < 0.9"));
    AssertThrow(f.e_u < 1e-4,
                ExcMessage("finest L2 displacement error " +
                           std::to_string(f.e_u) + " > 1e-4"));
  }

  // @sect3{run()}
  //
  // The study: one cycle per refinement level, then the table, the plot and
  // the check. The first line printed gives the data of the problem and the
  // two values of the exact solution worth remembering: the displacement
  // of the bore u_r(a) and the hoop stress there, sigma_tt(a), the largest
  // stress in the cylinder. At the point (a, 0) the hoop direction is e_y,
  // so sigma_tt(a) is the yy component of the exact stress tensor there.
  void
  LameProblem::run()
  {
    std::filesystem::create_directories(output_directory);
    std::cout << "Lamé's thick cylinder: a = " << exact.a
              << " mm, b = " << exact.b << " mm, p = " << exact.p
              << " MPa, E = " << exact.E << " MPa, nu = " << exact.nu
              << "; u_r(a) = " << exact.radial_displacement(exact.a)
              << " mm, sigma_tt(a) = "
              << exact.stress(Point<2>(exact.a, 0))[1][1] << " MPa\n";
    for (unsigned int level = first_refinement; level <= last_refinement;
         ++level)
      results.push_back(solve_on_mesh(level));
    print_and_write_table();
    plot();
    check_convergence();
  }
} // namespace Step1

// @sect3{The main function}
//
// As in deal.II's tutorials, main() only catches and reports exceptions: a
// failed AssertThrow (the headline check) and dpana's InputError (a bad
// parameter file) both end the program with a non-zero exit status.
int
main()
{
  try
    {
      Step1::LameProblem problem(std::string(DPANA_STEP_DIR) + "/step-1.prm");
      problem.run();
    }
  catch (const std::exception &exc)
    {
      std::cerr << "\nError: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
