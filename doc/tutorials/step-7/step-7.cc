// dpana tutorial step 7: three dimensions.

// @sect3{Include files}
//
// The whole run of a scene (assembly, contact surface, condensation, contact
// solve, recovery, output) is one object, dpana::scene::Scene. Its parameters
// are declared by dpana::scene::declare_parameters() from the outline of the
// run (dimension, number of bodies, contact or not), then read from a
// parameter file (dpana::parameters::parse_file): the scenes of the
// repository's prm/ folder and the .prm files of this step's folder.
#include <dpana/parameters/parameters.h>
#include <dpana/scene/run.h>
#include <dpana/scene/scene.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace step7
{
  using namespace dpana;

  // @sect3{Running a scene}
  //
  // A scene is run in a few lines once its parameters are known. The
  // outline of the file (dimension, number of bodies, contact or not),
  // found by parameters::scan_file(), tells scene::declare_parameters()
  // which subsections exist; parameters::parse_file() then reads the file,
  // and reports any error in it on one line with the file name, the line
  // and the entry. Before the Scene reads its parameters, `change` may set
  // some of them: this is how the program varies a parameter (the
  // friction set, the direction of a drag) without one file per value.
  //
  // Every run here is quiet and writes no VTU and no plot of its own (this
  // program draws its figures); it writes contact.csv and summary.json to
  // `directory` if `write` is true. The plane block must write them: the
  // 3D blocks read its contact.csv as their comparison file.
  template <int dim>
  void
  run_file(scene::Scene<dim>                                     &scene,
           const std::string                                     &file,
           const std::string                                     &directory,
           const bool                                             write,
           const std::function<void(dealii::ParameterHandler &)> &change = {})
  {
    dealii::ParameterHandler prm;
    scene::declare_parameters(prm, parameters::scan_file(file));
    parameters::parse_file(prm, file);
    prm.enter_subsection("Output");
    prm.set("Directory", directory);
    prm.set("Write VTU", false);
    prm.set("Plot", false);
    prm.leave_subsection();
    if (change)
      change(prm);
    scene.parse_parameters(prm, 1, true);
    scene.set_quiet(true);
    scene.run(write);
  }

  // The sum of the wall times of the phases of a run (s).
  template <int dim>
  double
  run_time(const scene::Scene<dim> &scene)
  {
    double seconds = 0;
    for (const auto &phase : scene.phases().timings())
      seconds += phase.second;
    return seconds;
  }

  // Every run must have converged before its numbers mean anything: a run
  // that did not would compare an unfinished iterate with the reference.
  template <int dim>
  void
  check_converged(const scene::Scene<dim> &scene, const std::string &what)
  {
    const auto &result = scene.summary().result;
    AssertThrow(result.converged,
                dealii::ExcMessage(what + ": the contact solver did not " +
                                   "converge: " + result.message));
  }

  // The tangential traction of element j as a vector of space: the
  // components T_k are given in the frame (tau_1, tau_2) of the element.
  // In 2D the frame has the one tangent tau, and the same function gives
  // T tau, so that the plane and the 3D runs are compared in x, y, z.
  template <int dim>
  dealii::Tensor<1, dim>
  tangential_vector(const scene::Scene<dim> &scene, const unsigned int j)
  {
    dealii::Tensor<1, dim> T;
    for (unsigned int k = 0; k + 1 < dim; ++k)
      T += scene.tangential_traction(j, k) *
           scene.surface(0).element(j).tangents[k];
    return T;
  }

  // @sect3{The 3D block against the plane solution}
  //
  // The block of the reference formulation (chapter 4, section 4.2.2) has
  // the cross-section 80 x 40 mm of the plane problem and a length L; by
  // double symmetry a quarter 40 x 40 x L/2 is meshed. With Poisson's ratio
  // nu = 0 and the end face free, the plane stress field of the 2D block is
  // also a solution of the 3D problem: sigma_zz = 0 needs no strain
  // eps_xx, eps_yy to be coupled with eps_zz. The contact tractions of the
  // 3D block must therefore be the 2D ones on every row of contact elements,
  // whatever L. The 2D run is made first; each 3D run is compared with it
  // element by element: every 3D element (s, t) is matched to the 2D
  // element of the same s, and the largest difference of N and of the
  // friction traction along x is divided by the largest 2D pressure.
  struct PlaneSolution
  {
    std::vector<double> s, N, Tx;

    unsigned int
    index_of(const double s_3d) const
    {
      for (unsigned int i = 0; i < s.size(); ++i)
        if (std::abs(s[i] - s_3d) < 1e-6)
          return i;
      AssertThrow(false,
                  dealii::ExcMessage("no 2D element at s = " +
                                     std::to_string(s_3d)));
      return 0;
    }
  };

  PlaneSolution
  plane_solution(const std::string &prm_dir)
  {
    scene::Scene<2> scene;
    run_file(scene,
             prm_dir + "/receding_2d_nu0_mu1.prm",
             "output/receding_2d_nu0_mu1",
             true);
    check_converged(scene, "2D block");
    // The tractions of every element of the plane run, with their abscissa
    // s along the base (from the plane of symmetry x = 0).
    PlaneSolution plane;
    for (unsigned int j = 0; j < scene.surface(0).n_elements(); ++j)
      {
        plane.s.push_back(scene.surface(0).element(j).s);
        plane.N.push_back(scene.normal_traction(j));
        plane.Tx.push_back(tangential_vector(scene, j)[0]);
      }
    return plane;
  }

  // The comparison of one block length with the plane solution: the
  // largest differences of N and T_x over all 3D elements, divided by the
  // largest pressure of the plane run, the spread of N along t, and the
  // size and cost of the run.
  struct BlockError
  {
    double       length = 0, error_N = 0, error_T = 0, spread_N = 0;
    unsigned int n_elements = 0, iterations = 0;
    double       seconds = 0;
  };

  // The spread of N along t (between rows of the same s) tells how far the
  // 3D solution is from being independent of z, apart from its difference
  // with the 2D mesh.
  BlockError
  compare_block(const std::string   &prm_dir,
                const unsigned int   L,
                const PlaneSolution &plane,
                std::ofstream       &csv)
  {
    const std::string name = "receding_3d_L" + std::to_string(L);
    scene::Scene<3>   scene;
    run_file(scene, prm_dir + "/" + name + ".prm", "output/" + name, true);
    check_converged(scene, name);

    double p_max = 0;
    for (const double N : plane.N)
      p_max = std::max(p_max, -N);
    BlockError          e;
    std::vector<double> row_min(plane.s.size(), 1e300);
    std::vector<double> row_max(plane.s.size(), -1e300);
    e.length     = L;
    e.n_elements = scene.surface(0).n_elements();
    e.iterations = scene.summary().result.iterations;
    // Each 3D element is compared with the 2D element of the same s (the
    // two meshes share the lattice of contact elements along s), and the
    // extremes of N are collected per s over the rows t.
    for (unsigned int j = 0; j < e.n_elements; ++j)
      {
        const auto        &element = scene.surface(0).element(j);
        const unsigned int i       = plane.index_of(element.s);
        const double       N       = scene.normal_traction(j);
        const double       Tx      = tangential_vector(scene, j)[0];
        e.error_N  = std::max(e.error_N, std::abs(N - plane.N[i]) / p_max);
        e.error_T  = std::max(e.error_T, std::abs(Tx - plane.Tx[i]) / p_max);
        row_min[i] = std::min(row_min[i], N);
        row_max[i] = std::max(row_max[i], N);
        csv << L << ',' << element.s << ',' << element.t << ',' << N << ','
            << Tx << '\n';
      }
    for (unsigned int i = 0; i < plane.s.size(); ++i)
      e.spread_N = std::max(e.spread_N, (row_max[i] - row_min[i]) / p_max);
    e.seconds = run_time(scene);
    return e;
  }

  // @sect3{The friction polygon against the exact disc}
  //
  // In 3D the Coulomb set of an element is the disc ||T|| <= -mu N. The
  // reference formulation replaces it by the regular polygon with s sides
  // circumscribed about the disc (chapter 2), which turns the friction
  // problem into a quadratic programme with linear constraints. The polygon
  // touches the disc at the s midpoints of its sides (the facet normals
  // a_i = 2 (i - 1) pi / s) and reaches out to the radius 1 / cos(pi / s) at
  // its vertices: in the direction of a vertex, the friction that the
  // polygon lets an element carry exceeds Coulomb's by
  // $$
  //   \epsilon_s = \frac{1}{\cos(\pi / s)} - 1 .
  // $$
  // The error only shows when the contact slips, and only when it slips in
  // the direction of a vertex. The problem made here forces exactly that: a
  // cube of side 20 mm (nu = 0) is pressed onto the rigid plane by a
  // prescribed displacement of 0.01 mm of its top face, which is at the
  // same time dragged tangentially by 0.1 mm, ten times what the cube can
  // take in stick. The whole base slips. Where the slip direction lies
  // within pi / s of a vertex direction, the traction sits on that vertex,
  // so the friction resultant divided by mu times the normal resultant
  // is 1 + epsilon_s exactly, while the disc gives 1 (or a hair less, where
  // the slip directions fan out). Dragging along a facet normal gives 1 for
  // every polygon.
  //
  // The cube is the parameter file dragged_cube.prm of this folder. The
  // frame of the elements is (n, tau_1, tau_2) = (-y, x, z) (see
  // ContactSurface::tangential_frame), so the angle phi of the drag is
  // measured from x towards z, and the drag of 0.1 mm becomes the
  // prescribed displacement (0.1 cos phi, -0.01, 0.1 sin phi) of the top
  // face. Friction opposes the slip: its direction is phi + pi, a vertex of
  // the polygon when phi = pi / s (s even), the midpoint of a side when
  // phi = 0.
  std::function<void(dealii::ParameterHandler &)>
  drag(const std::string &cone, const unsigned int sides, const double phi)
  {
    return [=](dealii::ParameterHandler &prm) {
      std::ostringstream value;
      value << std::setprecision(17) << "top: x = " << 0.1 * std::cos(phi)
            << ", y = -0.01, z = " << 0.1 * std::sin(phi);
      prm.enter_subsection("Body 1");
      prm.enter_subsection("Boundary conditions");
      prm.set("Prescribed displacement", value.str());
      prm.leave_subsection();
      prm.leave_subsection();
      prm.enter_subsection("Contact");
      prm.set("Cone model", cone);
      prm.set("Polygon sides", std::to_string(std::max(sides, 3u)));
      prm.leave_subsection();
    };
  }

  // The friction capacity actually used: |sum_j T_j |Gamma_j|| divided by mu
  // sum_j (-N_j) |Gamma_j|, and the angle of the friction resultant in the
  // plane (x, z).
  struct Capacity
  {
    double ratio = 0, angle = 0;
  };

  Capacity
  friction_capacity(const scene::Scene<3> &scene, const double mu)
  {
    // F is the friction resultant in space, P the normal resultant; both
    // are sums of element tractions times element areas (the tractions
    // are constant on each element). Separated elements add nothing.
    dealii::Tensor<1, 3> F;
    double               P = 0;
    for (unsigned int j = 0; j < scene.surface(0).n_elements(); ++j)
      {
        const double area = scene.surface(0).element(j).area;
        F += area * tangential_vector(scene, j);
        P -= area * scene.normal_traction(j);
      }
    return {F.norm() / (mu * P), std::atan2(F[2], F[0])};
  }

  // One run of the cube: the friction set, the drag angle, the excess
  // measured and the excess predicted, 1 / cos(pi / s) - 1 towards a
  // vertex of a polygon and 0 otherwise. The check that the friction
  // resultant opposes the drag (to 1e-3 rad) makes sure that the frame of
  // the elements is the one assumed above: were tau_1 and tau_2 swapped, a
  // drag towards a vertex would be measured along another direction.
  struct PolygonRun
  {
    unsigned int sides;
    double       phi, measured, predicted, seconds;
  };

  PolygonRun
  run_polygon(const std::string &cone, const unsigned int sides, double phi)
  {
    scene::Scene<3> scene;
    run_file(scene,
             std::string(DPANA_STEP_DIR) + "/dragged_cube.prm",
             "output/dragged_cube",
             false,
             drag(cone, sides, phi));
    check_converged(scene, "dragged cube");
    const Capacity c = friction_capacity(scene, 0.5);
    // The friction resultant must oppose the drag.
    AssertThrow(std::abs(std::remainder(c.angle - phi - M_PI, 2 * M_PI)) < 1e-3,
                dealii::ExcMessage("the friction does not oppose the drag"));
    const bool   on_vertex = (cone == "polygon" && phi > 0);
    const double predicted = on_vertex ? 1 / std::cos(M_PI / sides) - 1 : 0.;
    return {
      cone == "disc" ? 0 : sides, phi, c.ratio - 1, predicted, run_time(scene)};
  }

  // @sect3{An elastic sphere on a rigid plane}
  //
  // The 3D Hertz problem (Hertz 1882; Johnson 1985, chapter 4): a sphere of
  // radius R pressed by a force P onto a rigid plane touches it in a disc
  // of radius a and carries the pressure p0 sqrt(1 - r^2 / a^2), with
  // $$
  //   a = \left(\frac{3 P R}{4 E^*}\right)^{1/3}, \qquad
  //   p_0 = \frac{3 P}{2 \pi a^2}, \qquad E^* = \frac{E}{1 - \nu^2}
  // $$
  // (the plane is rigid). A quarter of the lower half of the sphere, R =
  // 10 mm, is meshed by gmsh from sphere.geo of this folder, with
  // tetrahedra of 0.1 mm near the first contact point; the program runs
  // gmsh itself; the rest is sphere.prm of this folder. The planes x = 0
  // and z = 0 (boundaries x0 and z0) are planes of symmetry, the top
  // y = R carries a pressure of 157.4 MPa, and the sphere is held by
  // contact only (its vertical translation is free, removed by one
  // fictitious support: step 8). The candidate contact surface is the part
  // of the sphere within 2.2 mm of the first contact point, grouped by
  // eight triangles into contact elements. The force P of the Hertz
  // formulas is the one the contact carries, four times the resultant of
  // -N over the quarter, which equilibrium makes equal to the applied load.
  //
  // The measured contact radius is the radius of the quarter disc of the
  // same area as the elements in contact, a_A = sqrt(4 A_c / pi); the
  // measured peak pressure is the largest element mean of -N. Both are
  // written with the profile -N(r), r the distance of an element's
  // centroid from the axis, to output/sphere.csv.
  // What the sphere gives: whether gmsh could mesh it, the load P, Hertz's
  // a and p0 for it, the measured a_A and peak element pressure, the size
  // of the run and its time.
  struct SphereResult
  {
    bool         meshed = false;
    double       P = 0, a = 0, p0 = 0, a_measured = 0, p_max = 0, seconds = 0;
    unsigned int n_elements = 0, n_dofs = 0;
  };

  SphereResult
  hertz_sphere()
  {
    SphereResult      h;
    const std::string geo  = std::string(DPANA_STEP_DIR) + "/sphere.geo";
    const std::string mesh = "output/sphere.msh";
    // The mesh is made at every run from the .geo file, so that the file
    // in the repository is the only description of the geometry: -3 makes
    // the volume mesh, msh22 is the ASCII format 2.2 that dpana reads (as does
    // deal.II's GridIn), and gmsh's own log goes to output/gmsh.log.
    if (std::system(("gmsh -3 " + geo + " -format msh22 -o " + mesh +
                     " > output/gmsh.log 2>&1")
                      .c_str()) != 0)
      {
        std::cerr << "warning: gmsh failed or is missing (see "
                     "output/gmsh.log): the sphere is skipped\n";
        return h;
      }
    h.meshed = true;
    scene::Scene<3> scene;
    run_file(scene,
             std::string(DPANA_STEP_DIR) + "/sphere.prm",
             "output/sphere",
             false);
    check_converged(scene, "sphere");

    // The profile and the resultant: P is four times the force on the
    // quarter.
    std::ofstream csv("output/sphere.csv");
    csv << "r,p\n";
    double contact_area = 0;
    for (unsigned int j = 0; j < scene.surface(0).n_elements(); ++j)
      {
        const auto  &element = scene.surface(0).element(j);
        const double p       = -scene.normal_traction(j);
        h.P += 4 * element.area * p;
        if (p > 0)
          contact_area += element.area;
        h.p_max = std::max(h.p_max, p);
        csv << std::hypot(element.centroid[0], element.centroid[2]) << ',' << p
            << '\n';
      }
    // Hertz's formulas with the material of sphere.prm and R of sphere.geo.
    const double E = 100000, nu = 0.3, R = 10;
    const double E_star = E / (1 - nu * nu);
    h.a                 = std::cbrt(3 * h.P * R / (4 * E_star));
    h.p0                = 3 * h.P / (2 * M_PI * h.a * h.a);
    h.a_measured        = std::sqrt(4 * contact_area / M_PI);
    h.n_elements        = scene.surface(0).n_elements();
    h.n_dofs            = scene.body(0).dof_handler().n_dofs();
    h.seconds           = run_time(scene);
    std::ofstream("output/hertz.csv")
      << "P,a,p0\n"
      << std::setprecision(10) << h.P << ',' << h.a << ',' << h.p0 << '\n';
    return h;
  }
} // namespace step7

// @sect3{The main program}
//
// run() of deal.II's tutorials is here main() itself: the plane solution,
// the three block lengths against it, the polygons against the disc, then
// the sphere, each as a table on the screen and as CSV data in output/ for
// the plot script of this folder, plot.py, which draws the figures of the
// results (run_step.sh copies them to figures/). The headline numbers are
// checked at the end, so that the test tutorial/step-7 fails if any of
// them drifts:
//
// - every 3D element of every length within 3% of max |N| of the plane
//   solution. The bound is not a tolerance on round-off: the tetrahedra of
//   the 3D block and the triangles of the plane block do not carry the
//   same discretisation error, and it is this difference (2.5%), not the
//   length of the block, that the comparison measures;
// - the excess of friction capacity of every polygon dragged towards a
//   vertex equal to 1 / cos(pi / s) - 1, and that of the disc and of the
//   polygon dragged along a facet normal equal to 0, both within 1e-5 (of
//   the Coulomb capacity mu P): the geometry of the friction sets is exact,
//   only the solver's tolerance and the fanning out of the slip directions
//   under the disc remain;
// - the sphere's contact radius within 5% and its peak pressure within 10%
//   of Hertz's (if gmsh could mesh it): the contact elements of the
//   unstructured surface, eight triangles each, are about 0.3 mm wide, a
//   fifth of the contact radius.
int
main()
{
  using namespace step7;
  try
    {
      const std::string prm_dir = std::string(DPANA_STEP_DIR) + "/../../../prm";
      std::filesystem::create_directories("output");

      // The plane solution and the three lengths. The repository's scenes
      // are found from the step's folder, which CMake passes to the
      // compiler as DPANA_STEP_DIR; the runs write into output/ of the
      // current directory, the build folder of the step.
      const PlaneSolution plane = plane_solution(prm_dir);
      {
        std::ofstream csv("output/plane.csv");
        csv << "s,N,Tx\n";
        for (unsigned int i = 0; i < plane.s.size(); ++i)
          csv << plane.s[i] << ',' << plane.N[i] << ',' << plane.Tx[i] << '\n';
      }
      std::ofstream csv("output/block_3d.csv");
      csv << "L,s,t,N,Tx\n";
      std::vector<BlockError> blocks;
      for (const unsigned int L : {80u, 160u, 320u})
        blocks.push_back(compare_block(prm_dir, L, plane, csv));
      csv.close();

      std::cout << "3D receding block (nu = 0, mu = 1) against the plane "
                   "solution\n"
                << "    L  elements  iterations  max|N-N2D|/p  max|Tx-Tx2D|/p"
                   "  spread of N along t   time (s)\n";
      for (const BlockError &e : blocks)
        std::cout << std::setw(5) << e.length << std::setw(10) << e.n_elements
                  << std::setw(12) << e.iterations << std::setw(14)
                  << std::setprecision(4) << e.error_N << std::setw(16)
                  << e.error_T << std::setw(21) << e.spread_N << std::setw(11)
                  << std::setprecision(3) << e.seconds << '\n';

      // The polygons against the disc: the disc dragged along x and at 45
      // degrees (no vertex anywhere), then each polygon dragged along a
      // facet normal and towards a vertex.
      std::vector<PolygonRun> polygons;
      polygons.push_back(run_polygon("disc", 0, 0));
      polygons.push_back(run_polygon("disc", 0, M_PI / 4));
      for (const unsigned int s : {4u, 8u, 16u, 32u})
        {
          polygons.push_back(run_polygon("polygon", s, 0));
          polygons.push_back(run_polygon("polygon", s, M_PI / s));
        }
      std::ofstream pcsv("output/polygon.csv");
      pcsv << "sides,phi,measured,predicted\n";
      std::cout << "\nFriction capacity of the dragged cube (mu = 0.5), "
                   "excess over Coulomb's\n"
                << "  set    drag angle  measured excess  1/cos(pi/s) - 1"
                   "   time (s)\n";
      for (const PolygonRun &p : polygons)
        {
          pcsv << std::setprecision(17) << p.sides << ',' << p.phi << ','
               << p.measured << ',' << p.predicted << '\n';
          std::cout << std::setw(5)
                    << (p.sides == 0 ? std::string("disc") :
                                       std::to_string(p.sides) + "-gon")
                    << std::setw(10) << std::setprecision(4)
                    << p.phi * 180 / M_PI << " deg" << std::setw(17)
                    << std::setprecision(9) << p.measured << std::setw(17)
                    << p.predicted << std::setw(11) << std::setprecision(3)
                    << p.seconds << '\n';
        }
      pcsv.close();

      // The sphere. Without gmsh there is no mesh; the program then says
      // so and skips the sphere, as it skips the figures without
      // matplotlib.
      const SphereResult h = hertz_sphere();
      if (h.meshed)
        std::cout << std::setprecision(6)
                  << "\nElastic sphere R = 10 on a rigid plane (quarter, "
                  << h.n_dofs << " dofs, " << h.n_elements
                  << " contact elements), P = " << h.P << " N\n"
                  << "  contact radius: Hertz a = " << h.a
                  << " mm, measured (area) " << h.a_measured << " mm, error "
                  << (h.a_measured - h.a) / h.a
                  << "\n  peak pressure:  Hertz p0 = " << h.p0
                  << " MPa, largest element mean " << h.p_max << " MPa, error "
                  << (h.p_max - h.p0) / h.p0 << "\n  time " << h.seconds
                  << " s\n";

      // The figures: plot.py reads the CSV files written above. The
      // system Python is used (it has matplotlib from Debian's package);
      // without it the run goes on, with a warning.
      if (std::system(("/usr/bin/python3 " + std::string(DPANA_STEP_DIR) +
                       "/plot.py output")
                        .c_str()) != 0)
        std::cerr << "warning: no plot (python3 with matplotlib needed)\n";

      // The headline numbers (see above).
      for (const BlockError &e : blocks)
        AssertThrow(e.error_N < 0.03 && e.error_T < 0.03,
                    dealii::ExcMessage("3D block too far from the plane "
                                       "solution"));
      for (const PolygonRun &p : polygons)
        AssertThrow(std::abs(p.measured - p.predicted) < 1e-5,
                    dealii::ExcMessage("friction capacity off: measured " +
                                       std::to_string(p.measured) +
                                       ", predicted " +
                                       std::to_string(p.predicted)));
      if (h.meshed)
        AssertThrow(std::abs(h.a_measured - h.a) < 0.05 * h.a &&
                      std::abs(h.p_max - h.p0) < 0.10 * h.p0,
                    dealii::ExcMessage("sphere too far from Hertz"));
      std::cout << "\nAll checks passed." << std::endl;
    }
  // Errors of input (a parameter file that does not parse, a mesh file
  // that cannot be read) and failed checks end the program with one line
  // and exit status 1, which fails the test.
  catch (const std::exception &e)
    {
      std::cerr << "step-7: " << dpana::parameters::one_line_message(e)
                << std::endl;
      return 1;
    }
  return 0;
}
