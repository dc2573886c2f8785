// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

// @sect3{Include files}
//
// Step 1 built an elastic body. This step adds the three objects that turn
// a body into the operator of a contact problem: the candidate contact
// surface, cut into contact elements (dpana::contact_surface), the coupling
// operator V and the compliance A = V^T K^{-1} V (dpana::condensation), and
// the parameters of both. Eigen gives us the eigenvalues of the dense A.
#include <dpana/body/body.h>
#include <dpana/condensation/condenser.h>
#include <dpana/condensation/parameters.h>
#include <dpana/contact_surface/contact_surface.h>
#include <dpana/contact_surface/parameters.h>
#include <dpana/output/output.h>
#include <dpana/parameters/parameters.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <vector>

namespace Step2
{
  using namespace dealii;
  using namespace dpana;

  // @sect3{The elastic half-plane}
  //
  // Far from its edges, a large block loaded on a small part of its base
  // responds like an elastic half-plane. A line load P (force per unit
  // thickness) pulling the surface of a half-plane outwards, along its
  // outward normal, moves the surface point at distance x from it by
  //
  //   u_n(x) = -k P ln|x| + C,  k = 2 (1 - nu^2) / (pi E),
  //   u_t(x) = c P sgn(x) + C_t,  c = (1 - 2 nu)(1 + nu) / (2 E),
  //
  // in plane strain, u_t pointing away from the load (Flamant's solution;
  // Johnson, Contact Mechanics, 1985, section 2.2, there for a compressive
  // load). The constants C and C_t are not determined: the logarithm grows
  // without bound at infinity, so a half-plane has no point that stays
  // fixed, and any rigid translation can be added. A finite body fixes them
  // through its supports. We remove them by comparing differences of
  // displacements, which do not contain them.
  //
  // The contact unknowns of dpana are constant tractions on contact
  // elements, and the conjugate displacements are integrals over elements
  // (the reference formulation, section 4.1): A_ij is the integral over
  // element i of the displacement due to a unit traction on element j. For
  // elements i = [x1, x2] and j = [y1, y2] on a straight surface the exact
  // half-plane value needs the double integral of ln|x - y|, which has a
  // closed form: with F(t) = t ln|t| - t, an antiderivative of ln|t|, and
  // G(t) = t^2 ln|t| / 2 - 3 t^2 / 4, one of F,
  //
  //   I(i, j) = G(x2 - y1) - G(x1 - y1) - G(x2 - y2) + G(x1 - y2),
  //
  // and the mean normal displacement of element i is
  // -k I(i, j) / |x2 - x1| + C |y2 - y1|.
  struct HalfPlane
  {
    double E, nu;

    static double
    G(const double t)
    {
      return t == 0. ? 0. : t * t * (0.5 * std::log(std::abs(t)) - 0.75);
    }

    double
    mean_normal_displacement(const std::array<double, 2> &i,
                             const std::array<double, 2> &j) const
    {
      const double k = 2. * (1. - nu * nu) / (numbers::PI * E);
      const double I =
        G(i[1] - j[0]) - G(i[0] - j[0]) - G(i[1] - j[1]) + G(i[0] - j[1]);
      return -k * I / (i[1] - i[0]);
    }

    // The jump of the tangential displacement across the load, for the
    // force P: from -c P on one side to +c P on the other.
    double
    tangential_jump(const double P) const
    {
      return (1. - 2. * nu) * (1. + nu) / E * P;
    }
  };

  // @sect3{One condensation}
  //
  // A Condenser keeps references to its body and to its contact surface,
  // so the three live together in one object that is never moved. The
  // timings are those of the two costly parts: the sparse Cholesky
  // factorisation of the body's reduced stiffness K_r, and the
  // condensation proper, the n = 2 x (number of contact elements) solves
  // with the columns of V and the products with V^T.
  struct Condensation
  {
    std::unique_ptr<contact_surface::ContactSurface<2>> surface;
    std::unique_ptr<condensation::Condenser<2>>         condenser;
    double seconds_factorization = 0, seconds_condensation = 0;
  };

  // One row of the cost table.
  struct Cost
  {
    unsigned int refinements, n_dofs, n_unknowns;
    double       half_width, seconds_factorization, seconds_condensation;
  };

  // @sect3{The BlockCompliance class}
  //
  // The program has three parts, each a member function called by run():
  // the properties of A (how it is made, and why it is dense, symmetric and
  // positive definite), its comparison with the half-plane, and its cost.
  class BlockCompliance
  {
  public:
    explicit BlockCompliance(const std::string &parameter_file);

    void
    run();

  private:
    std::unique_ptr<Body<2>>
    make_body(const unsigned int refinements);
    std::unique_ptr<Condensation>
    condense(const Body<2> &body, const double half_width) const;

    void
    cost_study();
    void
    check_column_from_unit_traction(const Condensation &c) const;
    void
    properties_of_A(const Condensation &c) const;
    void
    compare_with_half_plane(const Condensation &c);
    void
    plot() const;

    ParameterHandler               prm;
    contact_surface::Parameters<2> surface_parameters;
    condensation::Parameters       condensation_parameters;
    std::vector<unsigned int>      refinements;
    std::vector<double>            half_widths;
    std::string                    output_directory;
    HalfPlane                      half_plane;
    std::vector<Cost>              costs;
    std::unique_ptr<Body<2>>       finest_body;
    std::unique_ptr<Condensation>  finest;
    double                         half_plane_error = 0;
  };

  // @sect3{Parameters}
  //
  // Every component declares its own entries: Body<2> the subsections of
  // the body, contact_surface::Parameters the candidate surface (which
  // boundary, which region, how many faces per contact element) and
  // condensation::Parameters the number of columns per blocked solve, both
  // in `subsection Contact` as in every dpana scene. The `Cost study`
  // subsection is this program's own. The file, step-2.prm in the folder of
  // this program, reads (apart from its opening comments):
  //
  //     subsection Body 1
  //       subsection Geometry
  //         set Type = rectangle
  //         # Overwritten by the program on every cycle of the cost study.
  //         set Global refinements = 3
  //         subsection Rectangle
  //           set Lower corner      = -200, 0
  //           set Upper corner      = 200, 200
  //           set Subdivisions      = 40, 20
  //           set Grading centre    = 0, 0
  //           set Grading exponents = 2, 2
  //         end
  //       end
  //       subsection Material
  //         set Young's modulus = 130000
  //         set Poisson's ratio = 0.2
  //         set Plane state     = plane strain
  //       end
  //       subsection Boundary conditions
  //         set Fixed = top: all
  //       end
  //     end
  //     subsection Contact
  //       set Boundary 1                = bottom
  //       set Candidate centre          = 0, 0
  //       set Candidate half width      = 20
  //       set Faces per contact element = 2
  //       set Columns per solve         = 256
  //     end
  //     subsection Cost study
  //       set Refinements  = 0, 1, 2, 3
  //       set Half widths  = 10, 20, 40, 80, 160
  //     end
  //     subsection Output
  //       set Directory = output
  //     end
  //
  // The grading moves the vertices of the 40 x 20 grid of the rectangle
  // towards the centre of the base: a vertex at relative distance t from
  // the planes x = 0 and y = 0 goes to t^2 (doc/geometry.md). With three
  // global refinements the edges of the base are 0.0625 mm long at the
  // centre and about 0.8 mm at |x| = 20 mm, so the contact elements (two
  // edges each) range from 0.125 to 1.625 mm, and the top, 200 mm away,
  // is meshed coarsely. The Contact entries select the faces of `bottom`
  // whose centroids lie within 20 mm of the centre.
  BlockCompliance::BlockCompliance(const std::string &parameter_file)
  {
    prm.enter_subsection("Body 1");
    Body<2>::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Contact");
    contact_surface::Parameters<2>::declare_parameters(prm);
    condensation::Parameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Cost study");
    prm.declare_entry("Refinements", "0, 1, 2", Patterns::Anything());
    prm.declare_entry("Half widths", "10, 20", Patterns::Anything());
    prm.leave_subsection();
    prm.enter_subsection("Output");
    output::Parameters::declare_parameters(prm);
    prm.leave_subsection();

    dpana::parameters::parse_file(prm, parameter_file);

    prm.enter_subsection("Contact");
    surface_parameters.parse_parameters(prm);
    condensation_parameters.parse_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Cost study");
    for (const int r : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("Refinements"))))
      refinements.push_back(r);
    half_widths = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Half widths")));
    prm.leave_subsection();
    AssertThrow(refinements.size() >= 2 && half_widths.size() >= 2,
                ExcMessage("The cost study needs two points at least."));
    prm.enter_subsection("Output");
    output::Parameters output_parameters;
    output_parameters.parse_parameters(prm);
    output_directory = output_parameters.directory;
    prm.leave_subsection();

    // The half-plane solution compared with below is that of a straight
    // base y = 0 with outward normal -e_y, in plane strain.
    AssertThrow(surface_parameters.boundary[0] == "bottom",
                ExcMessage("The comparison is for the base of the block."));
    const auto body = make_body(0);
    AssertThrow(body->material().plane_state() ==
                  Material::PlaneState::plane_strain,
                ExcMessage("The half-plane solution is the plane strain one."));
    half_plane = {body->material().youngs_modulus(),
                  body->material().poissons_ratio()};
  }

  // @sect3{The block and its condensation}
  //
  // The body is built as in step 1: parameters, mesh, degrees of freedom
  // and constraints (here the top face is clamped, so no rigid motion is
  // left and K_r is positive definite), and the assembly of K and f. There
  // are no loads: the compliance does not depend on them.
  std::unique_ptr<Body<2>>
  BlockCompliance::make_body(const unsigned int n_refinements)
  {
    prm.enter_subsection("Body 1");
    prm.enter_subsection("Geometry");
    prm.set("Global refinements", std::to_string(n_refinements));
    prm.leave_subsection();
    auto body = std::make_unique<Body<2>>("Block");
    body->parse_parameters(prm);
    prm.leave_subsection();
    body->create_mesh();
    body->setup();
    body->check_held();
    body->assemble();
    return body;
  }

  // The condensation in its three steps:
  //
  // - ContactSurface::build() collects the faces of the base whose centroid
  //   lies within the candidate half width of the centre, sorts them along
  //   the base and groups pairs of adjacent edges into contact elements: one
  //   constant traction per edge would violate the discrete inf-sup (LBB)
  //   condition with P1 displacements (the reference formulation, section
  //   4.1), so that A would be singular;
  // - Condenser::factorize() factors K_r with CHOLMOD;
  // - assemble_coupling() builds V, whose column 2 j + k holds the nodal
  //   forces of a unit traction along e_k (e_0 = n, e_1 = tau) on element
  //   j, and condense() solves K_r Z = V a block of columns at a time and
  //   forms A = V^T Z. A is symmetric in exact arithmetic; condense()
  //   records its relative asymmetry and then symmetrises it.
  std::unique_ptr<Condensation>
  BlockCompliance::condense(const Body<2> &body, const double half_width) const
  {
    using Clock = std::chrono::steady_clock;
    auto c      = std::make_unique<Condensation>();
    auto options =
      surface_parameters.surface_options(0, body.name(), body.boundary_names());
    options.region_half_width = half_width;
    c->surface = std::make_unique<contact_surface::ContactSurface<2>>();
    c->surface->build(body.dof_handler(), options);
    c->condenser =
      std::make_unique<condensation::Condenser<2>>(body, *c->surface);

    const auto start = Clock::now();
    c->condenser->factorize();
    const auto factored = Clock::now();
    c->condenser->assemble_coupling();
    c->condenser->condense(condensation_parameters.columns_per_solve);
    const auto condensed = Clock::now();
    c->seconds_factorization =
      std::chrono::duration<double>(factored - start).count();
    c->seconds_condensation =
      std::chrono::duration<double>(condensed - factored).count();
    return c;
  }

  // @sect3{The cost of the condensation}
  //
  // The factorisation costs what the sparse Cholesky factorisation of a 2D
  // mesh costs, roughly O(N^{3/2}) for N unknowns with a nested dissection
  // ordering; the condensation is n solves with the factor, each about the
  // number of nonzeros of the factor, O(N log N), plus the products V^T Z.
  // Refining the mesh multiplies N by 4 and n by 2. To see the dependence
  // on n alone, the last mesh is then condensed on wider and wider
  // candidate surfaces: the factorisation stays the same and the
  // condensation grows in proportion to n.
  void
  BlockCompliance::cost_study()
  {
    const double default_width = surface_parameters.region_half_width;
    std::cout << "Cost of the condensation (s)\n"
              << "ref    dofs  half width  unknowns  factorization  "
                 "condensation\n";
    const auto record = [this](const Body<2>      &body,
                               const unsigned int  level,
                               const double        w,
                               const Condensation &c) {
      costs.push_back(
        {level,
         body.dof_handler().n_dofs(),
         static_cast<unsigned int>(c.condenser->compliance().rows()),
         w,
         c.seconds_factorization,
         c.seconds_condensation});
      const Cost &k = costs.back();
      std::cout << std::setw(3) << k.refinements << std::setw(8) << k.n_dofs
                << std::setw(12) << k.half_width << std::setw(10)
                << k.n_unknowns << std::fixed << std::setprecision(4)
                << std::setw(15) << k.seconds_factorization << std::setw(14)
                << k.seconds_condensation << std::defaultfloat << std::endl;
    };
    for (const unsigned int level : refinements)
      {
        auto body = make_body(level);
        auto c    = condense(*body, default_width);
        record(*body, level, default_width, *c);
        finest_body = std::move(body);
        finest      = std::move(c);
      }
    for (const double w : half_widths)
      record(*finest_body, refinements.back(), w, *condense(*finest_body, w));

    std::ofstream csv(output_directory + "/cost.csv");
    csv << "refinements,dofs,half_width,unknowns,seconds_factorization,"
           "seconds_condensation\n";
    for (const Cost &k : costs)
      csv << k.refinements << ',' << k.n_dofs << ',' << k.half_width << ','
          << k.n_unknowns << ',' << k.seconds_factorization << ','
          << k.seconds_condensation << '\n';
  }

  // @sect3{A column of A is the response to a unit traction}
  //
  // The definition of A, without the blocked solves: put the unit normal
  // traction on one contact element j (r = e_{2j}), compute the
  // displacement u = K^{-1} V r of the body (Condenser::recover(); the body
  // carries no load, so u_o = 0), and measure it on the contact surface:
  // V^T u, the integrals of u . n and u . tau over every contact element.
  // This vector must be column 2j of A, computed by the blocked solves
  // (and then symmetrised), to round-off.
  void
  BlockCompliance::check_column_from_unit_traction(const Condensation &c) const
  {
    const Eigen::MatrixXd &A = c.condenser->compliance();
    const unsigned int     j = c.surface->sorted_elements()[A.rows() / 4];
    Eigen::VectorXd        r = Eigen::VectorXd::Zero(A.rows());
    r(2 * j)                 = 1.;
    const Eigen::VectorXd column =
      c.condenser->surface_response(c.condenser->recover(r, Eigen::VectorXd()));
    const double to_column = (column - A.col(2 * j)).norm() / column.norm();
    std::cout << "Unit normal traction on contact element " << j
              << ": |V^T u - A e_" << 2 * j << "| / |V^T u| = " << to_column
              << std::endl;
    AssertThrow(to_column < 1e-10,
                ExcMessage("A column of A is not the unit traction response."));
  }

  // @sect3{Dense, symmetric, positive definite}
  //
  // - Dense: a traction anywhere on the surface displaces every point of
  //   it (in 2D the influence decays only like the logarithm of the
  //   distance), so no entry of the normal block of A vanishes. We print
  //   its smallest |A_ij| relative to the largest, and the share of all
  //   entries of A above a thousandth of the largest.
  // - Symmetric: A = V_r^T K_r^{-1} V_r with K_r symmetric; this is Betti's
  //   reciprocal theorem (the work of traction i on the displacement due to
  //   traction j is that of j on the displacement due to i). The computed A
  //   differs from its transpose by round-off only.
  // - Positive definite: r^T A r = (V_r r)^T K_r^{-1} (V_r r) is the
  //   elastic energy stored by the tractions r (twice the complementary
  //   energy), positive unless V_r r = 0. The grouping of edges in pairs
  //   makes the columns of V_r independent, so the smallest eigenvalue is
  //   positive. We compute all eigenvalues and confirm with a dense
  //   Cholesky factorisation of A.
  void
  BlockCompliance::properties_of_A(const Condensation &c) const
  {
    const Eigen::MatrixXd &A = c.condenser->compliance();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(
      A, Eigen::EigenvaluesOnly);
    const Eigen::VectorXd &lambda = eigen.eigenvalues();
    const bool             cholesky_ok =
      Eigen::LLT<Eigen::MatrixXd>(A).info() == Eigen::Success;

    // Density: the normal-normal block A_NN (even rows and columns) has no
    // small entry at all. In the whole of A the small entries are
    // normal-tangential couplings: that of each element with itself, which
    // vanishes on a half-plane by symmetry, and a few between neighbours.
    const unsigned int n_elements = A.rows() / 2;
    double             nn_min = A(0, 0), nn_max = 0;
    for (unsigned int i = 0; i < n_elements; ++i)
      for (unsigned int j = 0; j < n_elements; ++j)
        {
          nn_min = std::min(nn_min, std::abs(A(2 * i, 2 * j)));
          nn_max = std::max(nn_max, std::abs(A(2 * i, 2 * j)));
        }
    const double largest = A.cwiseAbs().maxCoeff();
    const double fraction =
      (A.cwiseAbs().array() > 1e-3 * largest).cast<double>().mean();

    // The entries of A scale like the product of the widths of the two
    // elements, which differ by a factor of 13 on this graded surface. The
    // spread of the eigenvalues is mostly that scaling: the Jacobi-scaled
    // matrix S A S, S = diag(A)^{-1/2}, has a much smaller condition number.
    const Eigen::VectorXd s = A.diagonal().cwiseSqrt().cwiseInverse();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> scaled(
      s.asDiagonal() * A * s.asDiagonal(), Eigen::EigenvaluesOnly);

    std::cout << "A: " << A.rows() << " x " << A.cols()
              << "; normal block: smallest |A_ij| / largest = "
              << nn_min / nn_max
              << "; entries above 1e-3 of the largest: " << 100. * fraction
              << " %\n"
              << "   relative asymmetry ||A - A^T||_F / ||A||_F before "
                 "symmetrisation: "
              << c.condenser->asymmetry() << "\n   eigenvalues from "
              << lambda.minCoeff() << " to " << lambda.maxCoeff()
              << " mm^2/MPa, condition number "
              << lambda.maxCoeff() / lambda.minCoeff() << " (Jacobi-scaled: "
              << scaled.eigenvalues().maxCoeff() /
                   scaled.eigenvalues().minCoeff()
              << "), dense Cholesky of A: " << (cholesky_ok ? "ok" : "failed")
              << std::endl;
    AssertThrow(c.condenser->asymmetry() < 1e-10,
                ExcMessage("A is not symmetric to round-off."));
    AssertThrow(lambda.minCoeff() > 0 && cholesky_ok,
                ExcMessage("A is not positive definite."));

    std::ofstream csv(output_directory + "/eigenvalues.csv");
    csv << "eigenvalue\n" << std::setprecision(10) << lambda << '\n';
    std::ofstream matrix(output_directory + "/compliance.csv");
    matrix << std::setprecision(10)
           << A.format(Eigen::IOFormat(
                Eigen::FullPrecision, Eigen::DontAlignCols, ",", "\n"))
           << '\n';
  }

  // @sect3{A column of A against the half-plane}
  //
  // The loaded element j is the one nearest to the centre of the base. For
  // every element i we take the mean normal displacement w_i = A_{2i,2j} /
  // |Gamma_i| and subtract that of a reference element, the outermost one
  // on the right, w_ref: the differences w_i - w_ref no longer contain the
  // undetermined constant C of the half-plane. The exact differences follow
  // from HalfPlane::mean_normal_displacement(). The error is the largest
  // difference between the two over the elements at least two elements
  // away from the loaded one (the loaded element and its neighbours are
  // where the piecewise linear displacement resolves the load worst),
  // relative to the largest exact difference.
  //
  // The tangential row of the same column, A_{2i+1,2j} / |Gamma_i|, is the
  // mean tangential displacement; its jump across the load, the mean on
  // the right minus the mean on the left, removes C_t and is compared with
  // (1 - 2 nu)(1 + nu) P / E.
  void
  BlockCompliance::compare_with_half_plane(const Condensation &c)
  {
    const auto            &surface = *c.surface;
    const Eigen::MatrixXd &A       = c.condenser->compliance();
    const auto             order   = surface.sorted_elements();
    const unsigned int     n       = order.size();

    // The extent [x_min, x_max] of every element along the base, from the
    // vertices of its faces.
    std::vector<std::array<double, 2>> extent(n, {{1e300, -1e300}});
    for (unsigned int e = 0; e < n; ++e)
      for (const unsigned int f : surface.element(e).faces)
        for (const auto &x : surface.get_faces()[f].points)
          extent[e] = {
            {std::min(extent[e][0], x[0]), std::max(extent[e][1], x[0])}};
    unsigned int k_load = 0;
    for (unsigned int k = 0; k < n; ++k)
      if (std::abs(surface.element(order[k]).centroid[0]) <
          std::abs(surface.element(order[k_load]).centroid[0]))
        k_load = k;
    const unsigned int j     = order[k_load];
    const double       P     = extent[j][1] - extent[j][0];
    const auto         width = [&](const unsigned int i) {
      return extent[i][1] - extent[i][0];
    };
    const auto mean = [&](const unsigned int row, const unsigned int i) {
      return A(row, 2 * j) / width(i);
    };

    // The reference element: the outermost one on the side of the surface
    // farther from the load.
    const unsigned int i_ref = k_load < n / 2 ? order[n - 1] : order[0];
    const double       w_ref = mean(2 * i_ref, i_ref);
    const double       exact_ref =
      half_plane.mean_normal_displacement(extent[i_ref], extent[j]);

    std::ofstream csv(output_directory + "/column.csv");
    csv << "x,width,w_minus_ref,exact_w_minus_ref,tangential\n";
    double       largest_error = 0, largest_exact = 0;
    double       right_sum = 0, left_sum = 0;
    unsigned int n_right = 0, n_left = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        const unsigned int i = order[k];
        const double       x = 0.5 * (extent[i][0] + extent[i][1]);
        const double       w = mean(2 * i, i) - w_ref;
        const double       exact =
          half_plane.mean_normal_displacement(extent[i], extent[j]) - exact_ref;
        const double tangential = mean(2 * i + 1, i);
        csv << x << ',' << width(i) << ',' << w << ',' << exact << ','
            << tangential << '\n';
        largest_exact = std::max(largest_exact, std::abs(exact));
        if (k + 2 <= k_load || k >= k_load + 2)
          {
            largest_error = std::max(largest_error, std::abs(w - exact));
            // The tangential displacement along e_x: tau is the normal
            // (0, -1) turned by +90 degrees.
            const double u_x = tangential * surface.element(i).tangents[0][0];
            (k > k_load ? right_sum : left_sum) += u_x;
            ++(k > k_load ? n_right : n_left);
          }
      }
    half_plane_error = largest_error / largest_exact;
    AssertThrow(n_right > 0 && n_left > 0,
                ExcMessage("The load must have elements on both sides."));
    const double jump       = right_sum / n_right - left_sum / n_left;
    const double exact_jump = half_plane.tangential_jump(P);
    std::cout << "Column of A for the unit normal traction on element " << j
              << " (x from " << extent[j][0] << " to " << extent[j][1]
              << " mm), reference element at x = "
              << 0.5 * (extent[i_ref][0] + extent[i_ref][1])
              << " mm:\n   max |(w_i - w_ref) - half-plane| / max "
                 "|half-plane| = "
              << half_plane_error
              << " over the elements two or more away from the load\n"
              << "   tangential jump across the load: " << jump
              << " mm, half-plane " << exact_jump << " mm (relative error "
              << std::abs(jump - exact_jump) / exact_jump << ")" << std::endl;
    AssertThrow(std::abs(jump - exact_jump) < 0.1 * exact_jump,
                ExcMessage("The tangential response departs from the "
                           "half-plane by more than 10 %."));
  }

  // @sect3{Figures}
  //
  // The plot script of this step's folder draws the column of A against
  // the half-plane, the spectrum and the matrix of A, and the cost, from the
  // CSV files written above. Without python3 and matplotlib there are no
  // figures, and only a warning.
  void
  BlockCompliance::plot() const
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

  // @sect3{run()}
  //
  // The cost study comes first because it builds the finest mesh and its
  // condensation, which the other parts then examine. The headline check:
  // away from the loaded element, the column of A agrees with the
  // half-plane to within 2 % of the range of the displacement differences.
  void
  BlockCompliance::run()
  {
    std::filesystem::create_directories(output_directory);
    cost_study();
    std::cout << "\nFinest mesh: " << finest_body->dof_handler().n_dofs()
              << " degrees of freedom; candidate surface "
              << finest->surface->description() << std::endl;
    check_column_from_unit_traction(*finest);
    properties_of_A(*finest);
    compare_with_half_plane(*finest);
    plot();
    AssertThrow(half_plane_error < 0.01,
                ExcMessage("The column of A departs from the half-plane by " +
                           std::to_string(100 * half_plane_error) + " %."));
  }
} // namespace Step2

// @sect3{The main function}
//
// As in step 1: the program reads the parameter file of its folder, and a
// failed check or a bad parameter ends it with a non-zero exit status.
int
main()
{
  try
    {
      Step2::BlockCompliance program(std::string(DPANA_STEP_DIR) +
                                     "/step-2.prm");
      program.run();
    }
  catch (const std::exception &exc)
    {
      std::cerr << "\nError: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
