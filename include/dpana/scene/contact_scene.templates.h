// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_scene_contact_scene_templates_h
#define dpana_scene_contact_scene_templates_h

#include <dpana/base/exceptions.h>
#include <dpana/contact/residual.h>
#include <dpana/io/fclib.h>
#include <dpana/output/output.templates.h>
#include <dpana/scene/contact_scene.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace dpana
{
  namespace scene
  {
    namespace internal
    {
      template <int dim>
      dealii::Tensor<1, dim>
      parse_vector(const std::string &text, const std::string &parameter)
      {
        dealii::Tensor<1, dim> x;
        if (dealii::Utilities::trim(text).empty())
          return x;
        std::vector<double> v;
        try
          {
            v = dealii::Utilities::string_to_double(
              dealii::Utilities::split_string_list(text));
          }
        catch (...)
          {
            v.clear();
          }
        if (v.size() != dim)
          throw InputError("Contact / " + parameter + ": expected " +
                           std::to_string(dim) +
                           " comma separated numbers, got '" + text + "'");
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = v[d];
        return x;
      }

      inline double
      seconds_since(const std::chrono::steady_clock::time_point &start)
      {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             start)
          .count();
      }

      inline std::string
      status_name(const contact::ContactStatus s)
      {
        return contact::to_string(s);
      }
    } // namespace internal



    template <int dim>
    ContactScene<dim>::ContactScene() = default;

    template <int dim>
    ContactScene<dim>::~ContactScene() = default;



    // @sect3{Parameters}
    template <int dim>
    void
    ContactScene<dim>::parse_parameters(dealii::ParameterHandler &prm,
                                        const unsigned int        n_bodies)
    {
      bodies.clear();
      for (unsigned int b = 0; b < n_bodies; ++b)
        {
          const std::string name = "Body " + std::to_string(b + 1);
          bodies.push_back(std::make_unique<Body<dim>>(name));
          prm.enter_subsection(name);
          bodies.back()->parse_parameters(prm);
          prm.leave_subsection();
        }

      prm.enter_subsection("Contact");
      boundary      = {prm.get("Boundary 1"), prm.get("Boundary 2")};
      region_centre = dealii::Point<dim>(
        internal::parse_vector<dim>(prm.get("Candidate centre"),
                                    "Candidate centre"));
      region_half_width = prm.get_double("Candidate half width");
      faces_per_element = prm.get_integer("Faces per contact element");
      direction = internal::parse_vector<dim>(prm.get("Contact direction"),
                                              "Contact direction");
      const bool direction_given =
        !dealii::Utilities::trim(prm.get("Contact direction")).empty();
      obstacle_point_given =
        !dealii::Utilities::trim(prm.get("Obstacle point")).empty();
      obstacle_point = dealii::Point<dim>(
        internal::parse_vector<dim>(prm.get("Obstacle point"),
                                    "Obstacle point"));
      friction = prm.get_double("Friction coefficient");
      if (dim == 2)
        cone = contact::ConeModel::interval;
      else
        cone = prm.get("Cone model") == "polygon" ?
                 contact::ConeModel::polygon :
                 contact::ConeModel::disc;
      polygon_sides       = prm.get_integer("Polygon sides");
      solver_options.type = contact::solver_type_from_string(prm.get("Solver"));
      solver_options.tolerance      = prm.get_double("Tolerance");
      solver_options.max_iterations = prm.get_integer("Maximum iterations");
      columns_per_pass              = prm.get_integer("Columns per solve");
      allow_non_converged           = prm.get_bool("Allow non-converged");

      prm.enter_subsection("Reference");
      reference_type          = prm.get("Type");
      uniform_normal_traction = prm.get_double("Uniform normal traction");
      hertz_load              = prm.get_double("Hertz load");
      radius_1                = prm.get_double("Radius 1");
      radius_2                = prm.get_double("Radius 2");
      seed_half_width         = prm.get_double("Seed half width");
      seed_max_pressure       = prm.get_double("Seed maximum pressure");
      reference_csv           = prm.get("Comparison file");
      prm.leave_subsection();

      prm.enter_subsection("Output");
      output_directory = prm.get("Directory");
      plot             = prm.get_bool("Plot");
      write_fclib      = prm.get_bool("Write FCLIB");
      prm.leave_subsection();
      prm.leave_subsection();

      if (reference_type == "hertz" && !(hertz_load > 0 && radius_1 > 0))
        throw InputError("Contact / Reference: Hertz load and Radius 1 must "
                         "be positive for Type = hertz");
      if (reference_type == "hertz" && radius_2 < 0 && -radius_2 <= radius_1)
        throw InputError("Contact / Reference / Radius 2: a cavity radius "
                         "must exceed Radius 1");
      if (solver_options.tolerance <= 0)
        throw InputError("Contact / Tolerance: must be positive");
      if (direction_given && direction.norm() == 0)
        throw InputError("Contact / Contact direction: must not be the zero "
                         "vector (leave it empty for the element normals)");
      load_reference_table();

      std::ostringstream text;
      prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
      parameters_text = text.str();
    }



    // The comparison file (a contact.csv of another run, e.g. the 2D plane
    // solution of the 3D block) is read and checked before anything is
    // computed, so that a bad file stops the run before any output exists.
    // A file that does not exist yet (its scene has not been run) only
    // disables the comparison, with a warning that says which file.
    template <int dim>
    void
    ContactScene<dim>::load_reference_table()
    {
      reference_table.clear();
      if (reference_csv.empty())
        return;
      const std::string what =
        "Contact / Reference / Comparison file '" + reference_csv + "'";
      std::ifstream in(reference_csv);
      if (!in)
        {
          std::cerr << "dpana: warning: " << what
                    << " not found (run the scene that writes it first); "
                       "no comparison is printed"
                    << std::endl;
          return;
        }
      std::string line;
      std::getline(in, line);
      const auto header = dealii::Utilities::split_string_list(line);
      int        cs = -1, cN = -1, cT = -1;
      for (unsigned int c = 0; c < header.size(); ++c)
        {
          if (header[c] == "s")
            cs = c;
          if (header[c] == "N")
            cN = c;
          if (header[c] == "T" || header[c] == "T1")
            cT = c;
        }
      if (cs < 0 || cN < 0 || cT < 0)
        throw InputError(what + " has no columns s, N, T");
      unsigned int line_number = 1;
      while (std::getline(in, line))
        {
          ++line_number;
          const auto v = dealii::Utilities::split_string_list(line);
          if (v.size() < header.size())
            continue;
          try
            {
              reference_table.push_back(
                {{std::stod(v[cs]), std::stod(v[cN]), std::stod(v[cT])}});
            }
          catch (const std::exception &)
            {
              throw InputError(what + ": line " + std::to_string(line_number) +
                               " is not numeric");
            }
        }
      if (reference_table.size() < 2)
        throw InputError(what + " has fewer than two rows");
      std::sort(reference_table.begin(), reference_table.end());
    }



    // @sect3{The phases of a run}
    template <int dim>
    void
    ContactScene<dim>::setup_bodies()
    {
      const auto start = std::chrono::steady_clock::now();
      for (auto &body : bodies)
        {
          body->create_mesh();
          body->setup();
          body->assemble();
          if (!quiet)
            {
              std::cout << body->name() << ": " << body->geometry_description()
                        << ", " << body->dof_handler().n_dofs() << " dofs";
              if (!body->free_rigid_modes().empty())
                {
                  std::cout << "; free rigid motions:";
                  for (const auto &m : body->free_rigid_modes())
                    std::cout << " " << m.description;
                }
              std::cout << std::endl;
            }
        }
      summary_.timings["assembly"] = internal::seconds_since(start);
    }



    template <int dim>
    void
    ContactScene<dim>::setup_surfaces()
    {
      surfaces.clear();
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const auto &names = bodies[b]->boundary_names();
          const auto  it    = names.find(boundary[b]);
          if (it == names.end())
            {
              std::string list;
              for (const auto &n : names)
                list += (list.empty() ? "" : ", ") + n.first;
              throw InputError("Contact / Boundary " + std::to_string(b + 1) +
                               ": " + bodies[b]->name() +
                               " has no boundary named '" + boundary[b] +
                               "' (it has: " + list + ")");
            }
          typename contact_surface::ContactSurface<dim>::Options options;
          options.boundary          = boundary[b];
          options.boundary_id       = it->second;
          options.body              = bodies[b]->name();
          options.region_centre     = region_centre;
          options.region_half_width = region_half_width;
          options.faces_per_element = faces_per_element;
          options.direction         = b == 0 ? direction : -direction;
          surfaces.push_back(
            std::make_unique<contact_surface::ContactSurface<dim>>());
          if (b == 0)
            surfaces[0]->build(bodies[0]->triangulation(), options);
          else
            surfaces[1]->pair(bodies[1]->triangulation(),
                              options,
                              *surfaces[0]);
        }
      if (bodies.size() == 1)
        {
          // The rigid obstacle: the plane through the obstacle point (by
          // default the first contact point of the candidate surface) normal
          // to the contact direction.
          if (!obstacle_point_given)
            obstacle_point = surfaces[0]->first_contact_point();
          surfaces[0]->set_plane_gap(obstacle_point);
        }
      if (!quiet)
        for (const auto &s : surfaces)
          std::cout << "Candidate contact surface: " << s->description()
                    << std::endl;
    }



    template <int dim>
    void
    ContactScene<dim>::condense()
    {
      condensers.clear();
      double t_factor = 0, t_condense = 0;
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          condensers.push_back(
            std::make_unique<condensation::Condenser<dim>>(*bodies[b],
                                                           *surfaces[b]));
          auto start = std::chrono::steady_clock::now();
          condensers[b]->factorize();
          t_factor += internal::seconds_since(start);
          start = std::chrono::steady_clock::now();
          condensers[b]->assemble_coupling();
          condensers[b]->condense(columns_per_pass);
          t_condense += internal::seconds_since(start);
        }
      summary_.timings["factorization"] = t_factor;
      summary_.timings["condensation"]  = t_condense;

      // The contact problem: relative quantities add (A = A1 + A2,
      // D = D1 + D2), the initial gap enters the normal rows, the equality
      // rows of the floating bodies are stacked.
      const auto        &surface = *surfaces[0];
      const unsigned int n       = surface.n_elements();
      problem_                   = contact::ContactProblem();
      problem_.dim               = dim;
      problem_.A                 = Eigen::MatrixXd::Zero(dim * n, dim * n);
      problem_.D                 = Eigen::VectorXd::Zero(dim * n);
      problem_.mu                = Eigen::VectorXd::Constant(n, friction);
      problem_.cone              = cone;
      problem_.polygon_sides     = polygon_sides;
      unsigned int m             = 0;
      summary_.asymmetry         = 0;
      for (const auto &c : condensers)
        {
          problem_.A += c->compliance();
          problem_.D += c->load_term();
          m += c->n_free_modes();
          summary_.asymmetry = std::max(summary_.asymmetry, c->asymmetry());
        }
      for (unsigned int j = 0; j < n; ++j)
        problem_.D(dim * j) -= surface.element(j).gap_integral;
      problem_.G.resize(m, dim * n);
      problem_.e.resize(m);
      unsigned int row = 0;
      for (const auto &c : condensers)
        {
          const unsigned int mb = c->n_free_modes();
          if (mb == 0)
            continue;
          problem_.G.middleRows(row, mb) = c->equilibrium_matrix();
          problem_.e.segment(row, mb)    = c->equilibrium_rhs();
          row += mb;
        }
      if (!quiet)
        {
          std::cout << "Condensation: " << n << " contact elements, " << dim * n
                    << " unknowns, " << m
                    << " equality rows (fictitious supports:";
          for (const auto &c : condensers)
            std::cout << " " << c->fictitious_supports().size();
          std::cout << "), relative asymmetry of A before symmetrisation "
                    << summary_.asymmetry << std::endl;
        }
    }



    template <int dim>
    void
    ContactScene<dim>::solve()
    {
      const auto start = std::chrono::steady_clock::now();
      try
        {
          summary_.result = contact::solve(problem_, solver_options);
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError(std::string("Contact: ") + e.what());
        }
      summary_.timings["contact solve"] = internal::seconds_since(start);
      const auto &r                     = summary_.result;
      if (!quiet)
        std::cout << "Contact solver "
                  << contact::to_string(solver_options.type) << ": "
                  << (r.converged ? "converged" : "NOT converged") << " in "
                  << r.iterations << " iterations, residual " << r.residual
                  << " (" << r.message << ")" << std::endl;
    }



    template <int dim>
    void
    ContactScene<dim>::recover()
    {
      const auto   start  = std::chrono::steady_clock::now();
      unsigned int offset = 0;
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const unsigned int mb = condensers[b]->n_free_modes();
          Eigen::VectorXd    alpha =
            mb > 0 ?
                 Eigen::VectorXd(summary_.result.alpha.segment(offset, mb)) :
                 Eigen::VectorXd();
          offset += mb;
          bodies[b]->set_solution(
            condensers[b]->recover(summary_.result.r, alpha));
          bodies[b]->compute_stresses();
        }
      compute_summary();
      summary_.timings["recovery"] = internal::seconds_since(start);
    }



    // @sect3{Zones, half width, maximum pressure}
    template <int dim>
    void
    ContactScene<dim>::compute_summary()
    {
      using contact::ContactStatus;
      const auto        &surface = *surfaces[0];
      const auto        &res     = summary_.result;
      const unsigned int n       = surface.n_elements();
      summary_.n_elements        = n;
      summary_.dofs.clear();
      for (const auto &b : bodies)
        summary_.dofs.push_back(b->dof_handler().n_dofs());

      // Per-element natural-map residual ||F_j||, F_j = r_j - Pi_K(r_j - rho
      // u~_j), the same measure as the solvers' (residual.h), in MPa.
      const Eigen::VectorXd element_residual =
        contact::element_residuals(problem_, res.r, res.u);
      summary_.element_residual.assign(element_residual.begin(),
                                       element_residual.end());

      const double s0     = region_centre * surface.surface_tangents()[0];
      summary_.half_width = summary_.half_width_centroid = 0;
      summary_.half_width_element                        = 0;
      summary_.max_pressure = summary_.normal_resultant = 0;
      summary_.candidate_edge_warning                   = false;
      for (unsigned int j = 0; j < n; ++j)
        {
          const auto &e = surface.element(j);
          summary_.max_pressure =
            std::max(summary_.max_pressure, -res.r(dim * j));
          summary_.normal_resultant += -res.r(dim * j) * e.area;
          if (res.status[j] != ContactStatus::separated)
            {
              const double edge =
                std::max(std::abs(e.s_max - s0), std::abs(e.s_min - s0));
              if (edge > summary_.half_width)
                {
                  summary_.half_width         = edge;
                  summary_.half_width_element = e.s_max - e.s_min;
                }
              summary_.half_width_centroid =
                std::max(summary_.half_width_centroid, std::abs(e.s - s0));
              if (e.at_open_edge)
                summary_.candidate_edge_warning = true;
            }
        }

      // Zones: in 2D the runs of equal status along s; in 3D the bounding
      // box (in s, t) of each status.
      summary_.zones.clear();
      const auto order = surface.sorted_elements();
      if (dim == 2)
        {
          for (const unsigned int j : order)
            {
              const auto &e = surface.element(j);
              if (summary_.zones.empty() ||
                  summary_.zones.back().status != res.status[j])
                summary_.zones.push_back({res.status[j], e.s_min, e.s_max});
              summary_.zones.back().to = e.s_max;
              ++summary_.zones.back().n_elements;
            }
        }
      else
        {
          for (const ContactStatus st : {ContactStatus::separated,
                                         ContactStatus::stick,
                                         ContactStatus::slip})
            {
              Zone z{st,
                     std::numeric_limits<double>::max(),
                     -std::numeric_limits<double>::max(),
                     std::numeric_limits<double>::max(),
                     -std::numeric_limits<double>::max(),
                     0};
              for (unsigned int j = 0; j < n; ++j)
                if (res.status[j] == st)
                  {
                    const auto &e = surface.element(j);
                    z.from        = std::min(z.from, e.s_min);
                    z.to          = std::max(z.to, e.s_max);
                    z.t_from      = std::min(z.t_from, e.t_min);
                    z.t_to        = std::max(z.t_to, e.t_max);
                    ++z.n_elements;
                  }
              if (z.n_elements > 0)
                summary_.zones.push_back(z);
            }
        }
      compare_with_references();
    }



    // @sect3{Comparison with the references}
    template <int dim>
    void
    ContactScene<dim>::print_comparison(std::ostream &out) const
    {
      out << std::setprecision(6);
      out << "Results: contact half width a = " << summary_.half_width
          << " mm (outer edge of the last element in contact, known to its "
             "size "
          << summary_.half_width_element
          << " mm; its centroid: " << summary_.half_width_centroid
          << " mm), max normal traction "
          << "-N_max = " << summary_.max_pressure
          << " MPa, resultant of -N = " << summary_.normal_resultant
          << (dim == 2 ? " N/mm" : " N") << std::endl;
      for (const auto &z : summary_.zones)
        {
          out << "  zone " << std::setw(9) << internal::status_name(z.status)
              << ": s in [" << z.from << ", " << z.to << "]";
          if (dim == 3)
            out << ", t in [" << z.t_from << ", " << z.t_to << "]";
          out << " (" << z.n_elements << " elements)" << std::endl;
        }
      if (summary_.candidate_edge_warning)
        out << "WARNING: the contact zone reaches the edge of the candidate "
               "surface; enlarge Contact / Candidate half width"
            << std::endl;

      for (const auto &c : summary_.comparisons)
        out << c.text << std::endl;
    }



    // The references of the run: each comparison keeps its log line and its
    // numbers for the JSON summary.
    template <int dim>
    void
    ContactScene<dim>::compare_with_references()
    {
      const auto &res = summary_.result;
      summary_.comparisons.clear();
      const auto add = [this](const std::string                          &type,
                              const std::ostringstream                   &text,
                              std::vector<std::pair<std::string, double>> v) {
        summary_.comparisons.push_back({type, text.str(), std::move(v)});
      };
      const auto rel = [](const double x, const double ref) {
        return ref != 0 ? (x - ref) / std::abs(ref) : 0.0;
      };
      if (reference_type == "uniform")
        {
          // Every element must carry N = N_ref and T = 0.
          double eN = 0, eT = 0;
          for (unsigned int j = 0; j < summary_.n_elements; ++j)
            {
              eN = std::max(eN,
                            std::abs(res.r(dim * j) - uniform_normal_traction));
              for (unsigned int k = 1; k < dim; ++k)
                eT = std::max(eT, std::abs(res.r(dim * j + k)));
            }
          const double       scale = std::abs(uniform_normal_traction);
          std::ostringstream out;
          out << std::setprecision(6)
              << "Reference (uniform state): N = " << uniform_normal_traction
              << " MPa, T = 0 on every element; max |N - N_ref| / |N_ref| = "
              << eN / scale << ", max |T| / |N_ref| = " << eT / scale;
          add("uniform",
              out,
              {{"N", uniform_normal_traction},
               {"max_N_error", eN / scale},
               {"max_T", eT / scale}});
        }
      if (reference_type == "hertz")
        {
          // Hertz, plane strain, load P per unit length:
          //   a = sqrt(4 P (k1 + k2) R), k_i = (1 - nu_i^2) / (pi E_i),
          //   1/R = 1/R1 + 1/R2 (R2 = 0: flat; R2 < 0: cavity of radius |R2|,
          //   R = R1 |R2| / (|R2| - R1)), N_max = 2 P / (pi a).
          // In plane stress the factor 1 - nu^2 drops: k_i = 1 / (pi E_i).
          const auto k = [](const Material &m) {
            const double nu2 =
              m.plane_state() == Material::PlaneState::plane_stress &&
                  dim == 2 ?
                0. :
                m.poissons_ratio() * m.poissons_ratio();
            return (1 - nu2) / (M_PI * m.youngs_modulus());
          };
          const double k1 = k(bodies[0]->material());
          const double k2 = bodies.size() > 1 ? k(bodies[1]->material()) : 0;
          double       R  = radius_1;
          if (radius_2 > 0)
            R = radius_1 * radius_2 / (radius_1 + radius_2);
          else if (radius_2 < 0)
            R = radius_1 * (-radius_2) / (-radius_2 - radius_1);
          const double       a_H = std::sqrt(4 * hertz_load * (k1 + k2) * R);
          const double       N_H = 2 * hertz_load / (M_PI * a_H);
          std::ostringstream out;
          out << std::setprecision(6) << "Reference (Hertz): a = " << a_H
              << " mm, N_max = " << N_H
              << " MPa; relative errors of this run: a " << std::showpos
              << rel(summary_.half_width, a_H) << " (centroid "
              << rel(summary_.half_width_centroid, a_H) << "), N_max "
              << rel(summary_.max_pressure, N_H);
          add("hertz",
              out,
              {{"a", a_H},
               {"N_max", N_H},
               {"a_error", rel(summary_.half_width, a_H)},
               {"a_centroid_error", rel(summary_.half_width_centroid, a_H)},
               {"N_max_error", rel(summary_.max_pressure, N_H)}});
          if (seed_half_width > 0 || seed_max_pressure > 0)
            {
              std::ostringstream seed;
              seed << std::setprecision(6)
                   << "Reference (seed table): a = " << seed_half_width
                   << " mm, N_max = " << seed_max_pressure
                   << " MPa; relative differences: a " << std::showpos
                   << rel(summary_.half_width, seed_half_width) << ", N_max "
                   << rel(summary_.max_pressure, seed_max_pressure);
              add("seed table",
                  seed,
                  {{"a", seed_half_width},
                   {"N_max", seed_max_pressure},
                   {"a_difference", rel(summary_.half_width, seed_half_width)},
                   {"N_max_difference",
                    rel(summary_.max_pressure, seed_max_pressure)}});
            }
        }
      if (!reference_table.empty())
        {
          // A CSV of another run (e.g. the 2D plane solution): N and T
          // interpolated linearly in s at the centroids of this run's
          // elements (in 3D those of the first row, t minimal: the
          // symmetry plane).
          const auto &ref    = reference_table;
          const auto  interp = [&](const double s, const unsigned int c) {
            if (s <= ref.front()[0])
              return ref.front()[c];
            if (s >= ref.back()[0])
              return ref.back()[c];
            auto it =
              std::lower_bound(ref.begin(),
                               ref.end(),
                               std::array<double, 3>{{s, -1e300, -1e300}});
            const auto &b = *it, &a = *(it - 1);
            return a[c] + (b[c] - a[c]) * (s - a[0]) / (b[0] - a[0]);
          };
          const auto &surface = *surfaces[0];
          double      tmin    = std::numeric_limits<double>::max();
          for (const auto &e : surface.get_elements())
            tmin = std::min(tmin, e.t_min);
          double eN = 0, eT = 0, scale = 0;
          for (const auto &r : ref)
            scale = std::max(scale, std::abs(r[1]));
          for (unsigned int j = 0; j < summary_.n_elements; ++j)
            {
              const auto &e = surface.element(j);
              if (dim == 3 && e.t_min > tmin + 1e-10 * (1 + std::abs(tmin)))
                continue;
              eN = std::max(eN, std::abs(res.r(dim * j) - interp(e.s, 1)));
              eT = std::max(eT, std::abs(res.r(dim * j + 1) - interp(e.s, 2)));
            }
          std::ostringstream out;
          out << std::setprecision(6) << "Reference (" << reference_csv
              << "): max |N - N_ref| / max|N_ref| = " << eN / scale
              << ", max |T - T_ref| / max|N_ref| = " << eT / scale;
          add("table",
              out,
              {{"max_N_difference", eN / scale},
               {"max_T_difference", eT / scale}});
        }
    }



    // @sect3{Output}
    //
    // Each body is written by the writer of the elastic runs,
    // output::write_vtu_file(): the displacement recovered from the contact
    // tractions, the stresses and the von Mises stress that recover() had
    // Body::compute_stresses() evaluate.

    // The contact surface: one VTK cell per face (a line in 2D, a triangle
    // in 3D) with the values of its contact element as cell data.
    template <int dim>
    void
    ContactScene<dim>::write_surface_vtu() const
    {
      const auto               &surface = *surfaces[0];
      const auto               &faces   = surface.get_faces();
      const auto               &res     = summary_.result;
      std::vector<unsigned int> element_of_face(faces.size());
      for (unsigned int j = 0; j < surface.n_elements(); ++j)
        for (const unsigned int f : surface.element(j).faces)
          element_of_face[f] = j;
      unsigned int n_points = 0;
      for (const auto &F : faces)
        n_points += F.points.size();

      std::ofstream out(output_directory + "/contact_surface.vtu");
      out << std::setprecision(10);
      out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
             "version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>"
             "\n<Piece NumberOfPoints=\""
          << n_points << "\" NumberOfCells=\"" << faces.size() << "\">\n";
      out << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
             "format=\"ascii\">\n";
      for (const auto &F : faces)
        for (const auto &x : F.points)
          out << x[0] << ' ' << x[1] << ' ' << (dim == 3 ? x[dim - 1] : 0.0)
              << '\n';
      out << "</DataArray></Points>\n<Cells>\n<DataArray type=\"Int32\" "
             "Name=\"connectivity\" format=\"ascii\">\n";
      unsigned int p = 0;
      for (const auto &F : faces)
        {
          for (unsigned int v = 0; v < F.points.size(); ++v)
            out << p++ << ' ';
          out << '\n';
        }
      out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" "
             "format=\"ascii\">\n";
      p = 0;
      for (const auto &F : faces)
        out << (p += F.points.size()) << '\n';
      out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
             "format=\"ascii\">\n";
      for (unsigned int f = 0; f < faces.size(); ++f)
        out << (dim == 2 ? 3 : 5) << '\n';
      out << "</DataArray>\n</Cells>\n<CellData Scalars=\"N\">\n";

      const auto scalar = [&](const std::string &name, const auto &value) {
        out << "<DataArray type=\"Float64\" Name=\"" << name
            << "\" format=\"ascii\">\n";
        for (unsigned int f = 0; f < faces.size(); ++f)
          out << value(element_of_face[f]) << '\n';
        out << "</DataArray>\n";
      };
      scalar("element", [](unsigned int j) { return j; });
      scalar("N", [&](unsigned int j) { return res.r(dim * j); });
      for (unsigned int k = 1; k < dim; ++k)
        scalar(dim == 2 ? "T" : "T" + std::to_string(k),
               [&](unsigned int j) { return res.r(dim * j + k); });
      scalar("u_N", [&](unsigned int j) {
        return res.u(dim * j) / surface.element(j).area;
      });
      for (unsigned int k = 1; k < dim; ++k)
        scalar(dim == 2 ? "u_T" : "u_T" + std::to_string(k),
               [&](unsigned int j) {
                 return res.u(dim * j + k) / surface.element(j).area;
               });
      scalar("gap",
             [&](unsigned int j) { return surface.element(j).mean_gap(); });
      scalar("status",
             [&](unsigned int j) { return static_cast<int>(res.status[j]); });
      scalar("residual",
             [&](unsigned int j) { return summary_.element_residual[j]; });
      // The traction vector N n + sum T_k tau_k in global coordinates.
      out << "<DataArray type=\"Float64\" Name=\"traction\" "
             "NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (unsigned int f = 0; f < faces.size(); ++f)
        {
          const unsigned int j = element_of_face[f];
          const auto        &e = surface.element(j);
          auto               t = res.r(dim * j) * e.normal;
          for (unsigned int k = 1; k < dim; ++k)
            t += res.r(dim * j + k) * e.tangents[k - 1];
          out << t[0] << ' ' << t[1] << ' ' << (dim == 3 ? t[dim - 1] : 0.0)
              << '\n';
        }
      out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n"
             "</VTKFile>\n";
    }



    template <int dim>
    void
    ContactScene<dim>::write_csv(const std::string &file) const
    {
      const auto   &surface = *surfaces[0];
      const auto   &res     = summary_.result;
      std::ofstream out(file);
      out << std::setprecision(8);
      out << "element,s," << (dim == 3 ? "t," : "") << "x,y,"
          << (dim == 3 ? "z," : "") << "area,gap,N,"
          << (dim == 2 ? "T,u_N,u_T," : "T1,T2,u_N,u_T1,u_T2,")
          << "status,residual\n";
      for (const unsigned int j : surface.sorted_elements())
        {
          const auto &e = surface.element(j);
          out << j << ',' << e.s << ',';
          if (dim == 3)
            out << e.t << ',';
          for (unsigned int d = 0; d < dim; ++d)
            out << e.centroid[d] << ',';
          out << e.area << ',' << e.mean_gap();
          for (unsigned int k = 0; k < dim; ++k)
            out << ',' << res.r(dim * j + k);
          for (unsigned int k = 0; k < dim; ++k)
            out << ',' << res.u(dim * j + k) / e.area;
          out << ',' << internal::status_name(res.status[j]) << ','
              << summary_.element_residual[j] << '\n';
        }
    }



    template <int dim>
    void
    ContactScene<dim>::write_json() const
    {
      const auto   &res = summary_.result;
      std::ofstream out(output_directory + "/summary.json");
      out << std::setprecision(10);
      out << "{\n  \"dimension\": " << dim
          << ",\n  \"bodies\": " << bodies.size() << ",\n  \"dofs\": [";
      for (unsigned int b = 0; b < summary_.dofs.size(); ++b)
        out << (b ? ", " : "") << summary_.dofs[b];
      out << "]"
          << ",\n  \"contact_elements\": " << summary_.n_elements
          << ",\n  \"friction_coefficient\": " << friction
          << ",\n  \"solver\": \"" << contact::to_string(solver_options.type)
          << "\",\n  \"converged\": " << (res.converged ? "true" : "false")
          << ",\n  \"iterations\": " << res.iterations
          << ",\n  \"residual\": " << res.residual
          << ",\n  \"residual_figures\": {\"natural_map\": "
          << res.figures.natural_map
          << ", \"penetration\": " << res.figures.penetration
          << ", \"cone_violation\": " << res.figures.cone_violation
          << ", \"complementarity\": " << res.figures.complementarity
          << ", \"equilibrium\": " << res.figures.equilibrium
          << "},\n  \"message\": \"" << output::internal::escape(res.message)
          << "\",\n  \"asymmetry_of_A\": " << summary_.asymmetry
          << ",\n  \"contact_half_width\": " << summary_.half_width
          << ",\n  \"contact_half_width_element\": "
          << summary_.half_width_element
          << ",\n  \"contact_half_width_centroid\": "
          << summary_.half_width_centroid
          << ",\n  \"max_normal_traction\": " << summary_.max_pressure
          << ",\n  \"normal_resultant\": " << summary_.normal_resultant
          << ",\n  \"candidate_edge_warning\": "
          << (summary_.candidate_edge_warning ? "true" : "false")
          << ",\n  \"zones\": [";
      for (unsigned int z = 0; z < summary_.zones.size(); ++z)
        {
          const auto &Z = summary_.zones[z];
          out << (z ? ", " : "") << "\n    {\"status\": \""
              << internal::status_name(Z.status) << "\", \"s_from\": " << Z.from
              << ", \"s_to\": " << Z.to;
          if (dim == 3)
            out << ", \"t_from\": " << Z.t_from << ", \"t_to\": " << Z.t_to;
          out << ", \"elements\": " << Z.n_elements << "}";
        }
      out << "\n  ],\n  \"rigid_displacements\": [";
      for (int i = 0; i < res.alpha.size(); ++i)
        out << (i ? ", " : "") << res.alpha(i);
      out << "],\n  \"references\": [";
      for (unsigned int c = 0; c < summary_.comparisons.size(); ++c)
        {
          const auto &C = summary_.comparisons[c];
          out << (c ? ", " : "") << "\n    {\"type\": \"" << C.type << "\"";
          if (C.type == "table")
            out << ", \"file\": \"" << output::internal::escape(reference_csv)
                << "\"";
          for (const auto &[name, value] : C.values)
            out << ", \"" << name << "\": " << value;
          out << "}";
        }
      out << (summary_.comparisons.empty() ? "" : "\n  ")
          << "],\n  \"timings\": {";
      bool first = true;
      for (const auto &[name, t] : summary_.timings)
        {
          out << (first ? "" : ", ") << "\"" << name << "\": " << t;
          first = false;
        }
      out << "}\n}\n";
    }



    template <int dim>
    void
    ContactScene<dim>::write_output()
    {
      const auto start = std::chrono::steady_clock::now();
      std::filesystem::create_directories(output_directory);
      {
        std::ofstream prm_out(output_directory + "/parameters.prm");
        prm_out << parameters_text;
      }
      std::vector<std::pair<double, std::string>> records;
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const std::string name = "body_" + std::to_string(b + 1) + ".vtu";
          output::write_vtu_file(*bodies[b], output_directory + "/" + name);
          records.emplace_back(0.0, name);
        }
      {
        std::ofstream pvd(output_directory + "/bodies.pvd");
        dealii::DataOutBase::write_pvd_record(pvd, records);
      }
      write_surface_vtu();
      const std::string csv = output_directory + "/contact.csv";
      write_csv(csv);
      // The condensed problem, for other contact solvers: an FCLIB local
      // problem in the convention of io/fclib.h.
      if (write_fclib)
        {
          io::FclibInfo info;
          info.title = "dpana contact scene" +
                       (scene_file.empty() ? std::string() : " " + scene_file);
          info.description =
            "Condensed frictional contact problem of the dpana scene " +
            (scene_file.empty() ? std::string("(unnamed)") : scene_file) +
            ", dimension " + std::to_string(dim) + ", " +
            std::to_string(problem_.n_elements()) + " contact elements";
          io::write_fclib_local(output_directory + "/problem.hdf5",
                                problem_,
                                info);
        }

      // The plot, by the python3 of the system (the one with matplotlib).
      if (plot)
        {
          const std::filesystem::path script = std::filesystem::path(__FILE__)
                                                 .parent_path()
                                                 .parent_path()
                                                 .parent_path()
                                                 .parent_path() /
                                               "scripts" / "plot_contact.py";
          const std::string python = "/usr/bin/python3";
          if (!std::filesystem::exists(script))
            std::cout << "warning: no plot: " << script << " not found"
                      << std::endl;
          else if (std::system((python + " -c 'import matplotlib' "
                                         ">/dev/null 2>&1")
                                 .c_str()) != 0)
            std::cout << "warning: no plot: " << python << " has no matplotlib"
                      << std::endl;
          else if (std::system((python + " " + script.string() + " " + csv +
                                " " + output_directory + "/contact.png")
                                 .c_str()) != 0)
            std::cout << "warning: the plot script failed" << std::endl;
        }
      summary_.timings["output"] = internal::seconds_since(start);
      write_json();
    }



    template <int dim>
    void
    ContactScene<dim>::run(const bool output)
    {
      setup_bodies();
      setup_surfaces();
      condense();
      solve();
      recover();
      if (output)
        write_output();
      if (!quiet)
        {
          print_comparison(std::cout);
          std::cout << "Timings (s):";
          for (const auto &[name, t] : summary_.timings)
            std::cout << " " << name << " " << t << ";";
          std::cout << std::endl;
          if (output)
            std::cout << "Output written to " << output_directory << "/"
                      << std::endl;
        }
    }
  } // namespace scene
} // namespace dpana

#endif
