// dpana, tutorial step 5: increasing contact, the Hertz cylinder on a
// rigid plane.

// @sect3{Include files}
//
// The whole run of a contact problem is one object, dpana::scene::Scene,
// which owns the body, its contact surface, the condensation and the contact
// solver. This program only reads its parameter file, changes one entry (the
// number of refinements around the contact point) and asks the scene for the
// numbers it wants to show: the initial gaps, the load term of the condensed
// problem, the tractions and the timings of every phase.
#include <dpana/parameters/parameters.h>
#include <dpana/scene/run.h>
#include <dpana/scene/scene.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace Step5
{
  using namespace dealii;
  using namespace dpana;

  // @sect3{The plane strain Hertz solution}
  //
  // A cylinder of radius $R$ pressed by a load $P$ per unit length onto a
  // rigid plane touches it on a strip of half width $a$ carrying the
  // elliptic pressure $p(x) = N_{\max}\sqrt{1 - x^2/a^2}$, with (Hertz
  // 1882; Johnson 1985, section 4.2; the reference formulation, eqs.
  // 4.17-4.18, with $k^{(2)} = 0$ for the rigid plane)
  // $$ a = \sqrt{4 P k R}, \qquad k = \frac{1-\nu^2}{\pi E}, \qquad
  //    N_{\max} = \frac{2P}{\pi a}. $$
  // The formula treats the cylinder as an elastic half-plane whose surface
  // is the parabola $x^2/(2R)$: it holds when $a \ll R$.
  // The library computes this formula for the references of a run
  // (scene::hertz_line_contact(), with $k$ the sum of the compliances of
  // the two bodies and the radius of the plane 0); the program calls it.
  scene::HertzLineContact
  hertz_on_rigid_plane(const double P,
                       const double R,
                       const double E,
                       const double nu)
  {
    AssertThrow(P > 0 && R > 0 && E > 0 && nu >= 0 && nu < 0.5,
                ExcMessage("Hertz: P, R, E must be positive, 0 <= nu < 1/2"));
    const double k = (1 - nu * nu) / (numbers::PI * E);
    return scene::hertz_line_contact(P, k, R, 0);
  }

  // @sect3{What one mesh gives}
  //
  // For every mesh the program keeps the size of the contact elements, the
  // number of unknowns, the half width and the maximum pressure, and the
  // wall time of the whole run. The half width is measured as the outer edge
  // of the last element in contact: with tractions constant per element it
  // is known only to one element size $h$. A second estimate, `a_fit`, fits
  // the ellipse of Hertz through the element tractions:
  // $N_j^2 = N_{\max}^2 (1 - s_j^2/a^2)$ is linear in $s_j^2$, so a least
  // squares line through the points $(s_j^2, N_j^2)$ of the elements in
  // contact gives $a^2$ as the ratio of its intercept to its slope.
  struct MeshResult
  {
    unsigned int                       contact_refinements;
    unsigned int                       n_elements;
    unsigned int                       n_dofs;
    double                             h;
    double                             a;
    double                             a_fit;
    double                             max_pressure;
    double                             seconds;
    std::map<std::string, double>      phases;  // wall time of each phase
    std::vector<std::array<double, 2>> profile; // (s, -N) per element
  };

  double
  elliptic_fit_half_width(const std::vector<std::array<double, 2>> &profile)
  {
    double       sx = 0, sy = 0, sxx = 0, sxy = 0;
    unsigned int n = 0;
    for (const auto &[s, p] : profile)
      if (p > 0)
        {
          const double x = s * s, y = p * p;
          sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
        }
    AssertThrow(n >= 3, ExcMessage("fewer than 3 elements in contact"));
    const double slope     = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    const double intercept = (sy - slope * sx) / n;
    AssertThrow(slope < 0 && intercept > 0,
                ExcMessage("the tractions are not elliptic"));
    return std::sqrt(-intercept / slope);
  }

  // @sect3{The HertzConvergence class}
  //
  // The class reads the scene of the reference formulation's section 4.3
  // (the file hertz_rigid.prm next to this program), solves it on a
  // sequence of meshes refined towards the contact point, and compares
  // every mesh with Hertz.
  class HertzConvergence
  {
  public:
    explicit HertzConvergence(const std::string &prm_file);
    void
    run();

  private:
    // The parameters of the scene, read once and changed between the
    // meshes; the Hertz solution and the two numbers of the file that the
    // checks need: the radius of the cylinder and the load of the half
    // model.
    ParameterHandler        prm;
    scene::HertzLineContact hertz;
    double                  radius, half_load;

    MeshResult
    solve_on(const unsigned int contact_refinements, const bool explain);
    void
    show_initial_gaps(const scene::Scene<2> &scene) const;
    void
    print_table(const std::vector<MeshResult> &results) const;
    void
    write_and_plot(const std::vector<MeshResult> &results) const;
  };

  // The constructor declares every entry a scene of one body with contact
  // has (scene::declare_parameters() does so for any outline of dimension,
  // number of bodies and contact), reads the file, and computes the Hertz
  // values from the same file: the load of the full cylinder, its radius
  // and its elastic constants.
  HertzConvergence::HertzConvergence(const std::string &prm_file)
  {
    scene::declare_parameters(prm, {2, 1, true});
    parameters::parse_file(prm, prm_file);

    // The material of the cylinder. The reference formulation's scenes are
    // in plane strain, the material's default, which is why Hertz's
    // compliance carries the factor 1 - nu^2.
    prm.enter_subsection("Body 1");
    prm.enter_subsection("Material");
    const double E  = prm.get_double("Young's modulus");
    const double nu = prm.get_double("Poisson's ratio");
    prm.leave_subsection();
    prm.leave_subsection();

    // The load and the radius of the Hertz comparison. The file gives the
    // load of the whole cylinder, 200 kN/mm; the half model carries half of
    // it, the check of the resultant below uses that half.
    prm.enter_subsection("Contact");
    prm.enter_subsection("Reference");
    const double P = prm.get_double("Hertz load");
    radius         = prm.get_double("Radius 1");
    prm.leave_subsection();
    prm.leave_subsection();

    half_load = P / 2;
    hertz     = hertz_on_rigid_plane(P, radius, E, nu);
  }

  // @sect3{Initial gaps}
  //
  // In an "increasing" contact problem the bodies first touch at one point
  // and the zone grows with the load, so the initial gap $g_o(x)$ between
  // the surfaces is part of the data. Every contact element uses the same
  // normal $\mathbf n = (0,-1)$, the normal of the tangent plane at the
  // first contact point, and the gap is measured along it: on the rigid
  // plane $y = 0$ it is the height of the cylinder's surface. The surface
  // is meshed by flat faces (chords of the circle), so the gap is linear on
  // each face, and it enters the condensed problem integrated over the
  // element (the reference formulation, section 4.1 after eq. 4.9):
  // $$ D_N = \hat D_N - \mathbf g, \qquad
  //    g_j = \int_{\Gamma_j} g_o \, d\Gamma , $$
  // the integral taken over the projection of the element on the plane.
  // The function recomputes $g_j$ from the vertices of the faces (the
  // trapezoidal rule, exact for a linear gap), checks it against the
  // surface's value and checks that the load term of the problem is the
  // condenser's $\hat D_N$ minus it. Then it prints the mean gap of the
  // first elements next to the mean height of the circle and of the
  // parabola $x^2/(2R)$ that Hertz's theory assumes.
  void
  HertzConvergence::show_initial_gaps(const scene::Scene<2> &scene) const
  {
    const auto &surface = scene.surface(0);
    const auto &D       = scene.problem().D;
    const auto &D_hat   = scene.condenser(0).load_term();
    // The primitive of the circle's height above the plane,
    // $\int_0^x \left(R - \sqrt{R^2 - \xi^2}\right) d\xi$, for the exact mean
    // gap of the circle over an element; the parabola's mean over
    // $[x_0, x_1]$ is $(x_1^3 - x_0^3) / (6 R (x_1 - x_0))$.
    const auto circle = [this](const double x) {
      return radius * x - 0.5 * (x * std::sqrt(radius * radius - x * x) +
                                 radius * radius * std::asin(x / radius));
    };
    std::cout << "Initial gaps (mean over each element, mm):\n"
              << "    j   s_min   s_max     chords     circle   parabola"
              << "      D_N\n";
    for (unsigned int j = 0; j < surface.n_elements(); ++j)
      {
        // The plane passes through the first contact point, the origin, so
        // the gap at a vertex is its y coordinate; the projected length of a
        // face along n = (0,-1) is its extent in x.
        const auto &e = surface.element(j);
        double      g = 0;
        for (const unsigned int f : e.faces)
          {
            const auto &p = surface.get_faces()[f].points;
            g += std::abs(p[1][0] - p[0][0]) * 0.5 * (p[0][1] + p[1][1]);
          }
        AssertThrow(std::abs(g - e.gap_integral) <= 1e-12 * (1 + g),
                    ExcMessage("gap integral of element " + std::to_string(j)));
        AssertThrow(std::abs(D(2 * j) - (D_hat(2 * j) - g)) <=
                      1e-9 * (1 + std::abs(D(2 * j))),
                    ExcMessage("D_N is not s_o - g"));
        // Print the first six elements and every fifth after them; the
        // checks above ran on every element.
        if (j >= 6 && j % 5 != 0)
          continue;
        const double x0 = e.s_min, x1 = e.s_max;
        std::cout << std::setw(5) << j << std::fixed << std::setprecision(3)
                  << std::setw(8) << x0 << std::setw(8) << x1
                  << std::setprecision(6) << std::setw(11) << e.mean_gap()
                  << std::setw(11) << (circle(x1) - circle(x0)) / (x1 - x0)
                  << std::setw(11)
                  << (x1 * x1 * x1 - x0 * x0 * x0) / (6 * radius * (x1 - x0))
                  << std::setprecision(1) << std::setw(10) << D(2 * j)
                  << std::defaultfloat << "\n";
      }
  }

  // @sect3{One mesh}
  //
  // The quarter disc is refined `Contact refinements` times within the
  // `Contact refinement radius` of the contact point; each refinement halves
  // the faces there, and so the contact elements (two faces each). The
  // program sets this one entry and lets the scene do the rest. The run is
  // quiet and writes no files: this program writes its own. The scene's
  // phases are the same as in the earlier steps: assemble K and f, build the
  // contact surface with its gaps, condense onto it (one Cholesky
  // factorisation, then $A = V^T K^{-1} V$), solve the contact problem,
  // recover the displacements.
  MeshResult
  HertzConvergence::solve_on(const unsigned int contact_refinements,
                             const bool         explain)
  {
    // The entry lives in the subsection named after the shape of the
    // geometry, as every shape declares and reads its own entries. The
    // other entries, among them the Contact refinement radius of 14 mm
    // (larger than the contact zone on every mesh), stay as in the file.
    prm.enter_subsection("Body 1");
    prm.enter_subsection("Geometry");
    prm.enter_subsection("Quarter disc");
    prm.set("Contact refinements", std::to_string(contact_refinements));
    prm.leave_subsection();
    prm.leave_subsection();
    prm.leave_subsection();

    // A new scene for every mesh: the parameters are read into its
    // components, then all phases run. The wall time is measured around the
    // whole of it; the phase log of the scene splits it up.
    const auto      start = std::chrono::steady_clock::now();
    scene::Scene<2> scene;
    scene.parse_parameters(prm, 1, true);
    scene.set_quiet(true);
    scene.run(false);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();

    // Every answer is checked before it is used: the solver converged, and
    // the normal tractions carry exactly the load of the half model (the
    // equality row of the floating cylinder says so).
    const auto &summary = scene.summary();
    AssertThrow(summary.result.converged,
                ExcMessage("the contact solver did not converge"));
    AssertThrow(std::abs(summary.normal_resultant - half_load) <=
                  1e-8 * half_load,
                ExcMessage("the tractions do not carry the load"));
    AssertThrow(!summary.candidate_edge_warning,
                ExcMessage("the contact zone reaches the candidate edge"));
    // The gaps are shown for one mesh only, the first: its few, long
    // elements show the difference between chords and circle best.
    if (explain)
      show_initial_gaps(scene);

    // What the study keeps of this mesh. The summary holds the half width,
    // the size of the element that ends the contact zone and the maximum
    // pressure; the tractions of every element are read from the scene, and
    // the degrees of freedom from the body's DoFHandler.
    MeshResult r;
    r.contact_refinements = contact_refinements;
    r.n_elements          = scene.surface(0).n_elements();
    r.n_dofs              = scene.body(0).dof_handler().n_dofs();
    r.h                   = summary.half_width_element;
    r.a                   = summary.half_width;
    r.max_pressure        = summary.max_pressure;
    r.seconds             = seconds;
    r.phases              = scene.phases().timings();
    for (unsigned int j = 0; j < r.n_elements; ++j)
      r.profile.push_back(
        {{scene.surface(0).element(j).s, -scene.normal_traction(j)}});
    r.a_fit = elliptic_fit_half_width(r.profile);
    return r;
  }

  // @sect3{The convergence table}
  //
  // Relative errors against Hertz, $e_a = a_h/a - 1$ and
  // $e_N = N_{\max,h}/N_{\max} - 1$, for every mesh, and the change of
  // $N_{\max}$ from the previous mesh, $\delta_N$: the first says how far
  // the discrete answer is from Hertz's, the second how far it still is
  // from the answer of the same model on an infinitely fine mesh.
  void
  HertzConvergence::print_table(const std::vector<MeshResult> &results) const
  {
    std::cout << std::setprecision(6)
              << "\nHertz (plane strain, rigid plane): a = " << hertz.half_width
              << " mm, N_max = " << hertz.max_pressure << " MPa\n"
              << " ref elements   dofs   h (mm)   a (mm)     e_a    a_fit"
              << "    e_fit    N_max      e_N  delta_N time (s)\n";
    for (unsigned int i = 0; i < results.size(); ++i)
      {
        const MeshResult &r = results[i];
        const double      delta =
          i == 0 ? 0 : r.max_pressure / results[i - 1].max_pressure - 1;
        std::cout << std::setw(4) << r.contact_refinements << std::setw(9)
                  << r.n_elements << std::setw(7) << r.n_dofs << std::fixed
                  << std::setprecision(4) << std::setw(9) << r.h << std::setw(9)
                  << r.a << std::showpos << std::setw(8)
                  << r.a / hertz.half_width - 1 << std::noshowpos
                  << std::setw(9) << r.a_fit << std::showpos << std::setw(9)
                  << r.a_fit / hertz.half_width - 1 << std::noshowpos
                  << std::setprecision(1) << std::setw(9) << r.max_pressure
                  << std::showpos << std::setprecision(4) << std::setw(9)
                  << r.max_pressure / hertz.max_pressure - 1 << std::setw(9)
                  << delta << std::noshowpos << std::setprecision(2)
                  << std::setw(9) << r.seconds << std::defaultfloat << "\n";
      }
  }

  // @sect3{Output and plot}
  //
  // Two CSV files in output/: the convergence table and the traction
  // profile of every mesh; then the plot script of this step's folder
  // draws them with the Python of the system (/usr/bin/python3, where
  // the setup script installs matplotlib). A missing matplotlib is a
  // warning only.
  void
  HertzConvergence::write_and_plot(const std::vector<MeshResult> &results) const
  {
    // One row per mesh, with the Hertz values repeated so that the plot
    // script needs no other input.
    std::filesystem::create_directories("output");
    std::ofstream table("output/convergence.csv");
    table << "contact_refinements,n_elements,n_dofs,h,a,a_fit,max_pressure,"
          << "seconds,hertz_a,hertz_max_pressure\n";
    // One row per contact element and mesh: the centroid s of the element
    // and its pressure -N.
    std::ofstream profile("output/profiles.csv");
    profile << "contact_refinements,s,pressure\n";
    for (const auto &r : results)
      {
        table << r.contact_refinements << ',' << r.n_elements << ',' << r.n_dofs
              << ',' << r.h << ',' << r.a << ',' << r.a_fit << ','
              << r.max_pressure << ',' << r.seconds << ',' << hertz.half_width
              << ',' << hertz.max_pressure << '\n';
        for (const auto &[s, p] : r.profile)
          profile << r.contact_refinements << ',' << s << ',' << p << '\n';
      }
    table.close();
    profile.close();

    // The files are closed before the script reads them. The plot is a
    // convenience: without matplotlib the program warns and goes on.
    const std::string python = "/usr/bin/python3";
    const std::string command =
      python + " " + std::string(DPANA_STEP_DIR) + "/plot.py output";
    if (std::system((python + " -c 'import matplotlib' 2>/dev/null").c_str()))
      std::cerr << "warning: no plot (" << python << " has no matplotlib)\n";
    else if (std::system(command.c_str()) != 0)
      std::cerr << "warning: no plot (" << command << " failed)\n";
  }

  // @sect3{HertzConvergence::run}
  //
  // The meshes of the study: 3 to 6 refinements around the contact point,
  // contact elements from about 2 mm down to 0.24 mm (a seventh refinement,
  // 0.12 mm, takes four times as long as the sixth and changes N_max by
  // less than 0.01 %). The first mesh also shows its initial gaps, the
  // finest the time of each of its phases.
  //
  // The headline check: on the finest mesh the maximum pressure lies
  // within 4 % of Hertz, and the half width within one element size plus
  // 5 % of Hertz's. These are the accuracies that the half model and the
  // piecewise constant tractions allow (see the results): the bounds guard
  // the numbers this page discusses, they do not claim that dpana
  // reproduces Hertz to them.
  void
  HertzConvergence::run()
  {
    std::vector<MeshResult> results;
    for (unsigned int n = 3; n <= 6; ++n)
      results.push_back(solve_on(n, n == 3));
    print_table(results);
    write_and_plot(results);

    const MeshResult &finest = results.back();
    const double      e_N    = finest.max_pressure / hertz.max_pressure - 1;
    const double      e_a    = finest.a / hertz.half_width - 1;
    std::cout << std::setprecision(3) << "\nFinest mesh: N_max " << std::showpos
              << 100 * e_N << " %, a " << 100 * e_a << std::noshowpos
              << " % from Hertz (element size " << finest.h << " mm)\n"
              << "Its phases (s):";
    for (const auto &[phase, t] : finest.phases)
      std::cout << " " << phase << " " << std::setprecision(3) << t << ";";
    std::cout << std::endl;
    AssertThrow(std::abs(e_N) < 0.04,
                ExcMessage("N_max more than 4 % from Hertz"));
    AssertThrow(std::abs(finest.a - hertz.half_width) <
                  finest.h + 0.05 * hertz.half_width,
                ExcMessage("a more than one element and 5 % from Hertz"));
  }
} // namespace Step5

// @sect3{The main function}
//
// As in deal.II's tutorials, main() only catches and reports exceptions.
int
main()
{
  try
    {
      Step5::HertzConvergence study(std::string(DPANA_STEP_DIR) +
                                    "/hertz_rigid.prm");
      study.run();
    }
  catch (const std::exception &exc)
    {
      std::cerr << "\nException: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
