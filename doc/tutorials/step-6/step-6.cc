// dpana, tutorial step 6: two bodies and non-matching meshes.

// @sect3{Include files}
//
// As in step-5, one dpana::scene::Scene does the whole run; this program
// reads two parameter files, changes the elastic moduli of the bodies, and
// looks inside the contact surfaces to show how two meshes that do not
// match are coupled. The scene's headers bring in those of its components:
// the bodies (dpana::Body), the contact surfaces
// (dpana::contact_surface::ContactSurface, whose elements and quadrature
// points this program reads), the condensers and the contact problem.
#include <dpana/parameters/parameters.h>
#include <dpana/scene/run.h>
#include <dpana/scene/scene.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace Step6
{
  using namespace dealii;
  using namespace dpana;

  // @sect3{Hertz for two elastic cylinders}
  //
  // Two cylinders of radii $R^{(1)}$, $R^{(2)}$ pressed together by a load
  // $P$ per unit length touch on a strip of half width $a$ (Hertz 1882;
  // Johnson 1985, section 4.2; the reference formulation, eqs. 4.17-4.18):
  // $$ a = \sqrt{4 P \left(k^{(1)} + k^{(2)}\right) R}, \qquad
  //    k^{(i)} = \frac{1 - \nu^{(i)2}}{\pi E^{(i)}}, \qquad
  //    \frac 1R = \frac 1{R^{(1)}} + \frac 1{R^{(2)}}, \qquad
  //    N_{\max} = \frac{2P}{\pi a}. $$
  // A flat foundation has $1/R^{(2)} = 0$ (written $R^{(2)} = 0$ in the
  // parameter files) and a cavity a negative radius: a cylinder of radius
  // 40 mm in a cavity of radius 120 mm behaves like one of radius 60 mm on
  // a plane. The compliances $k^{(i)}$ add, so the stiffer body matters less
  // and less: $E^{(1)}/E^{(2)} \to \infty$ is the rigid punch, $\to 0$ the
  // rigid foundation, and both give the same $a$ when the soft bodies are
  // of the same material.
  // The library computes this formula for the references of a run
  // (scene::hertz_line_contact(), with the cavity's negative radius and
  // $k = k^{(1)} + k^{(2)}$); the program calls it.
  scene::HertzLineContact
  hertz(const double P,
        const double R1,
        const double R2,
        const double k1,
        const double k2)
  {
    return scene::hertz_line_contact(P, k1 + k2, R1, R2);
  }

  double
  plane_strain_compliance(const double E, const double nu)
  {
    return (1 - nu * nu) / (numbers::PI * E);
  }

  // @sect3{Reading and changing a parameter file}
  //
  // The two small functions below declare a scene of two bodies with contact,
  // read a file of this step's folder, and get or set one entry of a nested
  // subsection such as "Body 2 / Material / Young's modulus".
  void
  read_scene(ParameterHandler &prm, const std::string &file)
  {
    scene::declare_parameters(prm, {2, 2, true});
    parameters::parse_file(prm, std::string(DPANA_STEP_DIR) + "/" + file);
  }

  std::string
  entry(ParameterHandler               &prm,
        const std::vector<std::string> &path,
        const std::string              &name,
        const std::string              &value = "")
  {
    // A ParameterHandler addresses an entry by the subsections entered
    // before it, so the path is entered, the entry set (if a value is given)
    // and read, and the path left again: the handler is back at the top
    // level for the next call.
    for (const auto &s : path)
      prm.enter_subsection(s);
    if (!value.empty())
      prm.set(name, value);
    const std::string v = prm.get(name);
    for (unsigned int i = 0; i < path.size(); ++i)
      prm.leave_subsection();
    return v;
  }

  // @sect3{One run}
  //
  // The scene runs quietly, without writing files. The checks: the solver
  // converged, and the normal tractions carry the load of the half model,
  // 100 kN/mm (the cylinder floats: its vertical translation is fixed only
  // by the equality row $G\mathbf r = \mathbf e$ of the contact problem).
  struct RunResult
  {
    double                             a, h, max_pressure, seconds;
    std::vector<std::array<double, 2>> profile; // (s, -N) per element
  };

  RunResult
  solve(ParameterHandler &prm, scene::Scene<2> &scene)
  {
    // The wall time covers the whole run: reading the parameters into the
    // components, meshing, assembly, contact surface, condensation, solve
    // and recovery.
    const auto start = std::chrono::steady_clock::now();
    scene.parse_parameters(prm, 2, true);
    scene.set_quiet(true);
    scene.run(false);
    // A contact zone that reached the edge of the candidate surface would
    // mean that the surface was chosen too small and the answer depends on
    // it; the summary flags it, and the program refuses such a run.
    const auto &summary = scene.summary();
    AssertThrow(summary.result.converged,
                ExcMessage("the contact solver did not converge"));
    AssertThrow(std::abs(summary.normal_resultant - 1e5) <= 1e-3,
                ExcMessage("the tractions do not carry the load"));
    AssertThrow(!summary.candidate_edge_warning,
                ExcMessage("the contact zone reaches the candidate edge"));
    RunResult r{summary.half_width,
                summary.half_width_element,
                summary.max_pressure,
                std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                              start)
                  .count(),
                {}};
    // The pressure profile: the tangential coordinate s of each element's
    // centroid (measured from the first contact point) and its pressure -N.
    for (unsigned int j = 0; j < scene.surface(0).n_elements(); ++j)
      r.profile.push_back(
        {{scene.surface(0).element(j).s, -scene.normal_traction(j)}});
    return r;
  }

  // @sect3{The mortar projection}
  //
  // The contact elements are those of Body 1, the cylinder: two adjacent
  // chords of its arc each, carrying one constant traction $(N, T)$. Body
  // 2's side of element $j$ is the part of its surface that projects onto
  // element $j$ along $\mathbf n$. In 2D the projections are intervals of
  // the tangent line: every face of Body 2 is cut at the projections of
  // Body 1's vertices, and each piece gets one quadrature point at its
  // midpoint, weighted by its projected length. The coupling operator of
  // Body 2, $V^{(2)}_{i,2j+k} = \int \varphi_i\cdot\mathbf e_k$, is then
  // integrated exactly (the integrand is linear on each piece), whatever
  // the two meshes are. Where Body 2's faces are smaller than Body 1's a
  // piece is a whole face of Body 2; where they are larger, a face of Body
  // 2 is shared by several elements.
  //
  // The function lists the pieces of the first elements, checks that on
  // every element the pieces of both sides cover the same projected length
  // (the element's area: the forces on the two sides balance exactly), and
  // writes the vertices of both surfaces and the cuts for the figure.
  void
  show_mortar_projection(const scene::Scene<2> &scene)
  {
    const auto &s1 = scene.surface(0);
    const auto &s2 = scene.surface(1);
    std::filesystem::create_directories("output");
    std::ofstream csv("output/mortar.csv");
    // First the faces of Body 2 that face Body 1, whole, as the mesh made
    // them.
    csv << "kind,element,x_from,x_to,y_from,y_to\n";
    for (const auto &face : s2.get_faces())
      csv << "face2,-1," << face.points[0][0] << ',' << face.points[1][0] << ','
          << face.points[0][1] << ',' << face.points[1][1] << '\n';
    unsigned int n_pieces = 0;
    std::cout << "Mortar projection (x of the pieces, mm):\n";
    for (unsigned int j = 0; j < s1.n_elements(); ++j)
      {
        // The quadrature weights of each side add up to the projected
        // length of the side. Both must be the element's area: Body 1's
        // because its points are its own faces, Body 2's because its
        // pieces cover the projection of element j exactly once, without
        // gaps or overlaps. This is what makes the forces of the two sides
        // balance.
        double w1 = 0, w2 = 0;
        for (const auto &p : s1.element(j).points)
          w1 += p.weight;
        for (const auto &p : s2.element(j).points)
          w2 += p.weight;
        const double area = s1.element(j).area;
        AssertThrow(std::abs(w1 - area) < 1e-12 * area &&
                      std::abs(w2 - area) < 1e-12 * area,
                    ExcMessage("the two sides of element " + std::to_string(j) +
                               " do not match"));
        // Then the faces of Body 1 grouped by element, and the pieces of
        // Body 2: a piece is stored only as its quadrature point (the
        // midpoint) and its weight (the projected length), so its ends are
        // the midpoint plus and minus half the weight along x, the tangent
        // direction of this scene.
        n_pieces += s2.element(j).points.size();
        for (const unsigned int f : s1.element(j).faces)
          {
            const auto &q = s1.get_faces()[f].points;
            csv << "face1," << j << ',' << q[0][0] << ',' << q[1][0] << ','
                << q[0][1] << ',' << q[1][1] << '\n';
          }
        if (j < 3)
          std::cout << "  element " << j << ": Body 1 [" << s1.element(j).s_min
                    << ", " << s1.element(j).s_max << "], Body 2 pieces";
        for (const auto &p : s2.element(j).points)
          {
            const double x0 = p.x[0] - p.weight / 2, x1 = p.x[0] + p.weight / 2;
            csv << "piece2," << j << ',' << x0 << ',' << x1 << ",0,0\n";
            if (j < 3)
              std::cout << " [" << x0 << ", " << x1 << "]";
          }
        if (j < 3)
          std::cout << "\n";
      }
    // More pieces than faces of either body: every vertex of either surface
    // inside the candidate zone ends a piece.
    std::cout << "  " << s1.get_faces().size() << " faces of Body 1, "
              << s2.get_faces().size() << " faces of Body 2 facing it, "
              << s1.n_elements() << " contact elements, " << n_pieces
              << " pieces of Body 2\n";
  }

  // @sect3{Part 1: the cylinder in a cavity}
  //
  // The scene of the reference formulation's table 4.4: a cylinder of
  // radius 40 mm in a cavity of radius 120 mm, both bodies of the same
  // material. The cylinder's arc is refined 5 times and the cavity's 6
  // times around the contact point, so their vertices do not match.
  // Returns the relative difference of the maximum pressure from the
  // reference formulation's table.
  double
  cylinder_in_cavity()
  {
    ParameterHandler prm;
    read_scene(prm, "hertz_cavity.prm");
    // The data of the Hertz formula and of the table come from the same
    // file as the scene, so that the comparison cannot drift from it. The
    // two bodies have the same elastic constants, hence one compliance k.
    const std::vector<std::string> material  = {"Body 1", "Material"};
    const std::vector<std::string> reference = {"Contact", "Reference"};
    const double E   = std::stod(entry(prm, material, "Young's modulus"));
    const double nu  = std::stod(entry(prm, material, "Poisson's ratio"));
    const double R1  = std::stod(entry(prm, reference, "Radius 1"));
    const double R2  = std::stod(entry(prm, reference, "Radius 2"));
    const double a_t = std::stod(entry(prm, reference, "Table half width"));
    const double N_t =
      std::stod(entry(prm, reference, "Table maximum pressure"));
    const double                  k = plane_strain_compliance(E, nu);
    const scene::HertzLineContact h = hertz(2e5, R1, R2, k, k);

    // The scene is kept after the run: its contact surfaces hold the
    // mortar projection that the next function shows.
    scene::Scene<2> scene;
    const RunResult r = solve(prm, scene);
    show_mortar_projection(scene);

    // The comparison: the relative differences of a and N_max from Hertz
    // and from the reference formulation's table 4.4. The half width is an
    // element edge, so it is printed with the element size that bounds its
    // error.

    std::cout << std::fixed << std::setprecision(4) << "Cylinder in a cavity ("
              << r.seconds << " s):\n"
              << "              a (mm)    N_max (MPa)\n"
              << "  dpana      " << std::setw(8) << r.a << std::setw(12)
              << r.max_pressure << "   (a known to h = " << r.h << " mm)\n"
              << "  Hertz      " << std::setw(8) << h.half_width
              << std::setw(12) << h.max_pressure << std::showpos
              << "   dpana: a " << r.a / h.half_width - 1 << ", N_max "
              << r.max_pressure / h.max_pressure - 1 << std::noshowpos
              << "\n  table 4.4  " << std::setw(8) << a_t << std::setw(12)
              << N_t << std::showpos << "   dpana: a " << r.a / a_t - 1
              << ", N_max " << r.max_pressure / N_t - 1 << std::noshowpos
              << std::defaultfloat << "\n";

    // The traction profile for the figure: one row per contact element,
    // with the Hertz values that the plot script turns into the ellipse.
    std::ofstream csv("output/cavity.csv");
    csv << "s,pressure,hertz_a,hertz_max_pressure\n";
    for (const auto &[s, p] : r.profile)
      csv << s << ',' << p << ',' << h.half_width << ',' << h.max_pressure
          << '\n';
    return r.max_pressure / N_t - 1;
  }

  // @sect3{Part 2: from equal moduli to the rigid punch}
  //
  // The scene of table 4.1: the cylinder on a flat foundation (a graded
  // grid, not matching the arc). Its moduli are both 130 GPa; the program
  // makes one body stiffer by the factor $E^{(1)}/E^{(2)}$ (or
  // $E^{(2)}/E^{(1)}$), keeping the softer one at 130 GPa. The ratio
  // $10^{-3}$ is the rigid foundation of table 4.2, $10^3$ the rigid punch
  // of table 4.3. The reference formulation's values of the three tables
  // are kept here for comparison. Returns the largest relative difference
  // of the maximum pressure from those tables.
  double
  stiffness_ratios()
  {
    struct Table
    {
      double ratio, a, max_pressure;
    };
    const std::vector<Table> tables = {{1e-3, 7.98, 14892},
                                       {1, 11.97, 10576},
                                       {1e3, 7.98, 14904}};
    std::ofstream            csv("output/ratios.csv");
    csv << "ratio,a,h,max_pressure,hertz_a,hertz_max_pressure,table_a,"
        << "table_max_pressure,seconds\n";
    std::cout << "\nStiffness ratios (cylinder on a foundation):\n"
              << "   E1/E2   a (mm)    Hertz    table    N_max    Hertz"
              << "    table e_N(Hertz) e_N(table) time (s)\n";
    double worst = 0;
    for (const double ratio : {1e-3, 1.0, 1e1, 1e2, 1e3})
      {
        // The softer body keeps E = 130 GPa, the other is made stiffer by
        // the ratio; both keep nu = 0.2, which the file must have.
        ParameterHandler prm;
        read_scene(prm, "hertz_ratio.prm");
        const double                   E = 130000, nu = 0.2;
        const double                   E1     = E * std::max(1.0, ratio);
        const double                   E2     = E * std::max(1.0, 1 / ratio);
        const std::vector<std::string> body_1 = {"Body 1", "Material"};
        const std::vector<std::string> body_2 = {"Body 2", "Material"};
        entry(prm, body_1, "Young's modulus", std::to_string(E1));
        entry(prm, body_2, "Young's modulus", std::to_string(E2));
        AssertThrow(std::stod(entry(prm, body_1, "Poisson's ratio")) == nu &&
                      std::stod(entry(prm, body_2, "Poisson's ratio")) == nu,
                    ExcMessage("hertz_ratio.prm: nu must be 0.2"));

        // Hertz for a flat foundation (R2 = 0 stands for 1/R2 = 0) with the
        // compliances of both bodies, and the run.
        const double                  k1 = plane_strain_compliance(E1, nu);
        const double                  k2 = plane_strain_compliance(E2, nu);
        const scene::HertzLineContact h  = hertz(2e5, 40, 0, k1, k2);
        scene::Scene<2>               scene;
        const RunResult               r = solve(prm, scene);

        // The reference formulation's table of this ratio, if it has one.
        double a_t = 0, N_t = 0;
        for (const auto &t : tables)
          if (std::abs(t.ratio / ratio - 1) < 1e-9)
            a_t = t.a, N_t = t.max_pressure;

        // One row of the table; a ratio without a table gets dashes.
        const auto cell = [](const double x, const char *format) {
          char text[32];
          std::snprintf(text, sizeof(text), format, x);
          return std::string(text);
        };
        const auto tabled = [&cell, N_t](const double x, const char *format) {
          return N_t > 0 ? cell(x, format) : std::string("-");
        };
        std::cout << cell(ratio, "%8g") << cell(r.a, " %8.3f")
                  << cell(h.half_width, " %8.3f") << std::setw(9)
                  << tabled(a_t, "%.2f") << cell(r.max_pressure, " %8.0f")
                  << cell(h.max_pressure, " %8.0f") << std::setw(9)
                  << tabled(N_t, "%.0f")
                  << cell(r.max_pressure / h.max_pressure - 1, " %+9.4f")
                  << std::setw(10) << tabled(r.max_pressure / N_t - 1, "%+.4f")
                  << cell(r.seconds, " %7.2f") << "\n";

        // The largest difference from a table is the number the headline
        // check bounds; all rows go to the CSV file of the figure.
        if (N_t > 0)
          worst = std::max(worst, std::abs(r.max_pressure / N_t - 1));
        csv << ratio << ',' << r.a << ',' << r.h << ',' << r.max_pressure << ','
            << h.half_width << ',' << h.max_pressure << ',' << a_t << ',' << N_t
            << ',' << r.seconds << '\n';
      }
    return worst;
  }

  // @sect3{The figures}
  //
  // The plot script of this step's folder reads the three CSV files of
  // output/ and draws the mortar projection, the pressure in the cavity and
  // the stiffness ratios, with the Python of the system (/usr/bin/python3,
  // where the setup script installs matplotlib). A missing matplotlib is a
  // warning only: the numbers, and the checks, do not depend on it.
  void
  plot()
  {
    const std::string python = "/usr/bin/python3";
    const std::string command =
      python + " " + std::string(DPANA_STEP_DIR) + "/plot.py output";
    if (std::system((python + " -c 'import matplotlib' 2>/dev/null").c_str()))
      std::cerr << "warning: no plot (" << python << " has no matplotlib)\n";
    else if (std::system(command.c_str()) != 0)
      std::cerr << "warning: no plot (" << command << " failed)\n";
  }
} // namespace Step6

// @sect3{The main function}
//
// As in deal.II's tutorials, main() runs the parts and catches and reports
// exceptions. The headline checks: the maximum pressure in the cavity lies
// within 2 % of the reference formulation's table 4.4, and that of every
// tabled stiffness ratio within 3 % of its table. The bounds are those of
// the comparison, not of the method: the tables come from coarse meshes of
// their own, and Hertz's formula does not describe the half models exactly
// (see the results). What the checks guard is that the library keeps giving
// the numbers this page discusses.
int
main()
{
  try
    {
      // The cavity first: it also writes the mortar projection. Then the
      // five stiffness ratios, each a new scene read from its file.
      const double cavity = Step6::cylinder_in_cavity();
      const double ratios = Step6::stiffness_ratios();
      Step6::plot();

      // The headline numbers, and the checks that make the ctest fail if a
      // change of the library moves them.
      std::cout << "\nN_max against the reference formulation: cavity "
                << 100 * cavity << " %, largest over tables 4.1-4.3 "
                << 100 * ratios << " %\n";
      AssertThrow(std::abs(cavity) < 0.02,
                  dealii::ExcMessage(
                    "cavity: N_max more than 2 % from table 4.4"));
      AssertThrow(ratios < 0.03,
                  dealii::ExcMessage(
                    "N_max more than 3 % from tables 4.1-4.3"));
    }
  catch (const std::exception &exc)
    {
      std::cerr << "\nException: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
