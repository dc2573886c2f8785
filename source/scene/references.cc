// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/base/warnings.h>
#include <dpana/parallel/route.h>
#include <dpana/scene/approach.h>
#include <dpana/scene/input_checks.h>
#include <dpana/scene/references.h>

#include <deal.II/base/patterns.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace dpana
{
  namespace scene
  {
    namespace
    {
      // A number as the warnings print it (6 significant digits).
      std::string
      number(const double x)
      {
        std::ostringstream s;
        s << std::setprecision(6) << x;
        return s.str();
      }



      // Relative difference of x from a reference value (0 if there is none).
      double
      relative(const double x, const double ref)
      {
        return ref != 0 ? (x - ref) / std::abs(ref) : 0.0;
      }



      // The radius R of the Hertz formulas, 1/R = 1/R1 + 1/R2, of two
      // curved surfaces pressed together by a positive load: R2 = 0 is a
      // plane (R = R1), R2 < 0 a cavity or seat of radius |R2| > R1.
      double
      effective_radius(const double load,
                       const double compliance,
                       const double radius_1,
                       const double radius_2)
      {
        AssertThrow(load > 0 && compliance > 0 && radius_1 > 0 &&
                      (radius_2 >= 0 || -radius_2 > radius_1),
                    dealii::ExcMessage(
                      "Hertz: the load, the compliance and Radius 1 must be "
                      "positive, and a cavity larger than Radius 1"));
        if (radius_2 > 0)
          return radius_1 * radius_2 / (radius_1 + radius_2);
        if (radius_2 < 0)
          return radius_1 * (-radius_2) / (-radius_2 - radius_1);
        return radius_1;
      }



      // Adds to the Hertz comparison @p c the errors of the estimates finer
      // than an element (pressure_estimators.h) against the Hertz half
      // width a_H and pressure N_H, to its values and its log line.
      void
      add_estimator_errors(Comparison           &c,
                           const double          a_H,
                           const double          N_H,
                           const ContactSummary &summary)
      {
        const PressureEstimates &est = summary.estimates;
        if (!est.available)
          return;
        std::ostringstream out;
        out << std::setprecision(6) << std::showpos << "; a_m "
            << relative(est.moment_half_width, a_H);
        c.values.emplace_back("a_moment_error",
                              relative(est.moment_half_width, a_H));
        if (est.fit_available)
          {
            out << ", a_f " << relative(est.fit_half_width, a_H)
                << ", p0 of the fit " << relative(est.fit_max_pressure, N_H);
            c.values.emplace_back("a_fit_error",
                                  relative(est.fit_half_width, a_H));
            c.values.emplace_back("fit_max_pressure_error",
                                  relative(est.fit_max_pressure, N_H));
          }
        c.text += out.str();
      }
      // Adds the measured approach (if any) to the comparison @p c: against
      // Hertz's delta and against delta less the half-space displacement at
      // the spheres' centres, @p centre_approach.
      void
      add_approach(Comparison              &c,
                   const PressureEstimates &est,
                   const double             delta,
                   const double             centre_approach)
      {
        if (!est.approach_measured)
          return;
        const double       d = est.approach;
        std::ostringstream t;
        t << std::setprecision(6) << "; approach of the centres " << d
          << " mm against Hertz's delta " << std::showpos << relative(d, delta)
          << ", against delta less the half-space "
          << "displacement at the centres (" << std::noshowpos
          << centre_approach << " mm) " << std::showpos
          << relative(d, centre_approach);
        c.text += t.str();
        c.values = {{"approach_measured", d},
                    {"approach_at_centres", centre_approach},
                    {"approach_error", relative(d, delta)},
                    {"approach_at_centres_error",
                     relative(d, centre_approach)}};
      }
    } // namespace



    HertzLineContact
    hertz_line_contact(const double load,
                       const double compliance,
                       const double radius_1,
                       const double radius_2)
    {
      const double R = effective_radius(load, compliance, radius_1, radius_2);
      const double a = std::sqrt(4 * load * compliance * R);
      return {a, 2 * load / (M_PI * a)};
    }



    HertzPointContact
    hertz_point_contact(const double load,
                        const double compliance,
                        const double radius_1,
                        const double radius_2)
    {
      const double R = effective_radius(load, compliance, radius_1, radius_2);
      const double a = std::cbrt(3 * load * R * compliance / 4);
      return {a, 3 * load / (2 * M_PI * a * a), a * a / R};
    }



    template <int dim>
    void
    References<dim>::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.enter_subsection("Reference");
      prm.declare_entry("Type",
                        "none",
                        Selection("none|uniform|hertz|hertz sphere"),
                        "Reference printed with the results: 'uniform' "
                        "(every element N = Uniform normal traction, T = 0), "
                        "'hertz' (plane strain Hertz formulas), 'hertz "
                        "sphere' (3D Hertz formulas of two spheres).");
      prm.declare_entry("Uniform normal traction",
                        "-50",
                        Double(),
                        "Expected uniform N (MPa, compressive < 0).");
      prm.declare_entry("Hertz load",
                        "200000",
                        Double(0.),
                        "Load P per unit length of the whole (not half) "
                        "model (N/mm); for 'hertz sphere' the force on the "
                        "whole sphere (N).");
      prm.declare_entry("Radius 1",
                        "40",
                        Double(0.),
                        "Radius of the cylinder or sphere (Body 1) (mm); "
                        "a run warns if its surface about Candidate centre "
                        "has another.");
      prm.declare_entry("Radius 2",
                        "0",
                        Double(),
                        "Radius of the other surface (mm): 0 flat, > 0 "
                        "convex, < 0 a cavity of radius |Radius 2| (checked "
                        "like Radius 1; the rigid plane is flat).");
      prm.declare_entry("Table half width",
                        "0",
                        Double(0.),
                        "Contact half width a of a published table, e.g. the "
                        "reference formulation's (mm); 0: none.");
      prm.declare_entry("Table maximum pressure",
                        "0",
                        Double(0.),
                        "-N_max of that table (MPa); 0: none.");
      prm.declare_entry("Model fraction",
                        "1",
                        Double(0., 1.),
                        "'hertz sphere': the fraction of the whole body "
                        "that the model holds (0.25 for a quarter model by "
                        "two symmetry planes); the resultant of the run "
                        "divided by it is compared with the Hertz load.");
      prm.declare_entry("Comparison file",
                        "",
                        Anything(),
                        "CSV of another run (columns s, N, T) compared with "
                        "this one, e.g. the 2D plane solution for a 3D run.");
      prm.leave_subsection();
    }



    template <int dim>
    void
    References<dim>::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Reference");
      type                    = prm.get("Type");
      uniform_normal_traction = prm.get_double("Uniform normal traction");
      hertz_load              = prm.get_double("Hertz load");
      radius_1                = prm.get_double("Radius 1");
      radius_2                = prm.get_double("Radius 2");
      table_half_width        = prm.get_double("Table half width");
      table_max_pressure      = prm.get_double("Table maximum pressure");
      comparison_file         = prm.get("Comparison file");
      model_fraction          = prm.get_double("Model fraction");
      prm.leave_subsection();

      if (type == "hertz sphere" && (dim != 3 || !(model_fraction > 0)))
        throw InputError("Contact / Reference / Type: 'hertz sphere' needs "
                         "Dimension = 3 and a positive Model fraction");
      if ((type == "hertz" || type == "hertz sphere") &&
          !(hertz_load > 0 && radius_1 > 0))
        throw InputError("Contact / Reference: Hertz load and Radius 1 must "
                         "be positive for Type = hertz");
      if ((type == "hertz" || type == "hertz sphere") && radius_2 < 0 &&
          -radius_2 <= radius_1)
        throw InputError("Contact / Reference / Radius 2: a cavity radius "
                         "must exceed Radius 1");
      load_comparison_file();
    }



    template <int dim>
    std::vector<Comparison>
    References<dim>::compare(
      const std::vector<std::unique_ptr<Body<dim>>> &bodies,
      const contact_surface::ContactSurface<dim>    &surface,
      const ContactSummary                          &summary) const
    {
      std::vector<Comparison> comparisons;
      if (type == "uniform")
        comparisons.push_back(uniform(summary));
      if (type == "hertz")
        for (auto &c : hertz(bodies, summary))
          comparisons.push_back(std::move(c));
      if (type == "hertz sphere")
        comparisons.push_back(hertz_sphere(bodies, surface, summary));
      if (!comparison_table.empty())
        comparisons.push_back(comparison_run(surface, summary));
      return comparisons;
    }



    template <int dim>
    void
    References<dim>::warn(const std::string &text) const
    {
      if (add_warning(warnings_, text) && parallel::is_root())
        std::cerr << "dpana: warning: " << text << std::endl;
    }



    // The Hertz formulas are those of the load Hertz load: a run whose
    // contact carries another one (a force changed, a half or quarter model
    // given the load of the whole body or the wrong fraction) is compared
    // with another problem, which the relative errors alone do not show.
    // The resultant equals the applied load to round-off, so 1 % is a
    // wrong input, not a discretisation error.
    template <int dim>
    void
    References<dim>::check_hertz_load(const double       P,
                                      const std::string &measured) const
    {
      if (std::abs(relative(P, hertz_load)) <= 1e-2)
        return;
      warn("Contact / Reference / Hertz load = " + number(hertz_load) +
           ", but the contact of this run carries P = " + number(P) + " (" +
           measured +
           "): the Hertz values compared are those of another load; give "
           "the load of the whole body");
    }



    template <int dim>
    void
    References<dim>::measure_approach(
      const std::vector<std::unique_ptr<Body<dim>>> &bodies,
      const contact_surface::ContactSurface<dim>    &surface,
      ContactSummary                                &summary) const
    {
      summary.estimates.approach_measured = false;
      if (type != "hertz sphere" || (bodies.size() > 1 && !(radius_2 > 0)))
        return;
      const dealii::Point<dim>     x0    = surface.options().region_centre;
      const dealii::Tensor<1, dim> n     = surface.surface_normal();
      double                       delta = 0;
      try
        {
          delta = body_approach(*bodies[0], x0, x0 - radius_1 * n, n, 1.);
          if (bodies.size() > 1)
            delta += body_approach(*bodies[1], x0, x0 + radius_2 * n, n, -1.);
        }
      catch (const std::exception &)
        {
          // A mesh of a part of the sphere need not hold its centre.
          warn("Contact / Reference: the centre of a sphere or the "
               "contact point lies outside its mesh; the approach is not "
               "measured");
          return;
        }
      summary.estimates.approach_measured = true;
      summary.estimates.approach          = delta;
    }



    // Every element must carry N = N_ref and T = 0.
    template <int dim>
    Comparison
    References<dim>::uniform(const ContactSummary &summary) const
    {
      const auto &r  = summary.result.r;
      double      eN = 0, eT = 0;
      for (unsigned int j = 0; j < summary.n_elements; ++j)
        {
          eN = std::max(eN, std::abs(r(dim * j) - uniform_normal_traction));
          for (unsigned int k = 1; k < dim; ++k)
            eT = std::max(eT, std::abs(r(dim * j + k)));
        }
      const double       scale = std::abs(uniform_normal_traction);
      std::ostringstream out;
      out << std::setprecision(6)
          << "Reference (uniform state): N = " << uniform_normal_traction
          << " MPa, T = 0 on every element; max |N - N_ref| / |N_ref| = "
          << eN / scale << ", max |T| / |N_ref| = " << eT / scale;
      return {"uniform",
              out.str(),
              {{"N", uniform_normal_traction},
               {"max_N_error", eN / scale},
               {"max_T", eT / scale}},
              ""};
    }



    template <int dim>
    std::vector<Comparison>
    References<dim>::hertz(
      const std::vector<std::unique_ptr<Body<dim>>> &bodies,
      const ContactSummary                          &summary) const
    {
      const auto k = [](const Material &m) {
        const double nu2 =
          m.plane_state() == Material::PlaneState::plane_stress && dim == 2 ?
            0. :
            m.poissons_ratio() * m.poissons_ratio();
        return (1 - nu2) / (M_PI * m.youngs_modulus());
      };
      const double k1 = k(bodies[0]->material());
      const double k2 = bodies.size() > 1 ? k(bodies[1]->material()) : 0;
      const HertzLineContact hertz =
        hertz_line_contact(hertz_load, k1 + k2, radius_1, radius_2);
      const double a_H = hertz.half_width;
      const double N_H = hertz.max_pressure;
      const double a = summary.half_width, N = summary.max_pressure;
      // The load of the whole body: the resultant of a half model twice.
      const double P =
        summary.normal_resultant * (summary.estimates.mirrored ? 2 : 1);
      check_hertz_load(P,
                       summary.estimates.mirrored ?
                         "twice the resultant of -N of this half model" :
                         "the resultant of -N");

      std::ostringstream out;
      out << std::setprecision(6) << "Reference (Hertz): a = " << a_H
          << " mm, N_max = " << N_H << " MPa; relative errors of this run: a "
          << std::showpos << relative(a, a_H) << " (centroid "
          << relative(summary.half_width_centroid, a_H) << "), N_max "
          << relative(N, N_H) << ", P " << relative(P, hertz_load);
      std::vector<Comparison> c{
        {"hertz",
         out.str(),
         {{"a", a_H},
          {"N_max", N_H},
          {"a_error", relative(a, a_H)},
          {"a_centroid_error", relative(summary.half_width_centroid, a_H)},
          {"N_max_error", relative(N, N_H)},
          {"load", hertz_load},
          {"resultant", P},
          {"load_error", relative(P, hertz_load)}},
         ""}};
      add_estimator_errors(c[0], a_H, N_H, summary);
      if (table_half_width > 0 || table_max_pressure > 0)
        {
          std::ostringstream t;
          t << std::setprecision(6)
            << "Reference (published table): a = " << table_half_width
            << " mm, N_max = " << table_max_pressure
            << " MPa; relative differences: a " << std::showpos
            << relative(a, table_half_width) << ", N_max "
            << relative(N, table_max_pressure);
          c.push_back({"published table",
                       t.str(),
                       {{"a", table_half_width},
                        {"N_max", table_max_pressure},
                        {"a_difference", relative(a, table_half_width)},
                        {"N_max_difference", relative(N, table_max_pressure)}},
                       ""});
        }
      return c;
    }



    namespace
    {
      // A flat face seen on the plane normal to n: its projected area, the
      // integral of r^2 over that projection (r: the distance from the axis
      // through x0 along n) and the largest and smallest r of its vertices.
      // r^2 is quadratic on the face, so the rule of the edge midpoints
      // integrates it exactly.
      template <int dim>
      std::array<double, 4>
      radial_moments(const contact_surface::Face<dim> &face,
                     const dealii::Point<dim>         &x0,
                     const dealii::Tensor<1, dim>     &n)
      {
        std::vector<dealii::Tensor<1, dim>> q;
        double r_min = std::numeric_limits<double>::max(), r_max = 0;
        for (const auto &x : face.points)
          {
            const dealii::Tensor<1, dim> d = x - x0;
            q.push_back(d - (d * n) * n);
            r_min = std::min(r_min, q.back().norm());
            r_max = std::max(r_max, q.back().norm());
          }
        const double area = face.area * std::abs(face.normal * n);
        double       r2   = 0;
        for (unsigned int i = 0; i < q.size(); ++i)
          r2 += (0.5 * (q[i] + q[(i + 1) % q.size()])).norm_square();
        return {{area, area * r2 / q.size(), r_min, r_max}};
      }
    } // namespace



    // The 3D Hertz solution of two spheres against the run: the contact
    // radius (outer edge of the elements in contact, and the moment
    // estimate), the maximum pressure and the resultant.
    template <int dim>
    Comparison
    References<dim>::hertz_sphere(
      const std::vector<std::unique_ptr<Body<dim>>> &bodies,
      const contact_surface::ContactSurface<dim>    &surface,
      const ContactSummary                          &summary) const
    {
      double compliance = 0;
      for (const auto &body : bodies)
        {
          const double nu = body->material().poissons_ratio();
          compliance += (1 - nu * nu) / body->material().youngs_modulus();
        }
      const HertzPointContact H =
        hertz_point_contact(hertz_load, compliance, radius_1, radius_2);

      const dealii::Point<dim> x0 = surface.options().region_centre;
      warn(off_axis_centre(surface));
      std::vector<PressurePiece> pieces;
      double                     a_edge = 0, a_element = 0;
      for (unsigned int j = 0; j < summary.n_elements; ++j)
        {
          const auto   &e     = surface.element(j);
          double        r_min = std::numeric_limits<double>::max(), r_max = 0;
          PressurePiece piece{0, 0, -summary.result.r(dim * j)};
          for (const auto &p : e.pieces)
            {
              const auto m =
                radial_moments(p.as_face(surface.get_faces()[p.face]),
                               x0,
                               e.normal);
              piece.area += m[0];
              piece.r2_integral += m[1];
              r_min = std::min(r_min, m[2]);
              r_max = std::max(r_max, m[3]);
            }
          pieces.push_back(piece);
          if (summary.result.status[j] != contact::ContactStatus::separated &&
              r_max > a_edge)
            {
              a_edge    = r_max;
              a_element = r_max - r_min;
            }
        }
      const double      a_m = moment_contact_radius(pieces);
      const EllipticFit fit = elliptic_fit(pieces);
      const double      P   = summary.normal_resultant / model_fraction;
      const double      N   = summary.max_pressure;
      check_hertz_load(P,
                       "the resultant of -N over Model fraction = " +
                         number(model_fraction));
      // Hertz's approach seen from the spheres' centres: less the
      // half-space displacement at their depths.
      double centre_approach = H.approach;
      for (unsigned int b = 0; b < bodies.size(); ++b)
        centre_approach -=
          boussinesq_axial_displacement(hertz_load,
                                        bodies[b]->material().youngs_modulus(),
                                        bodies[b]->material().poissons_ratio(),
                                        b == 0 ? radius_1 : radius_2);

      std::ostringstream out;
      out << std::setprecision(6)
          << "Reference (Hertz, spheres): a = " << H.radius
          << " mm, p0 = " << H.max_pressure << " MPa, approach " << H.approach
          << " mm, P = " << hertz_load << " N; this run: a = " << a_edge
          << " mm (outer edge, known to " << a_element << " mm), a_m = " << a_m
          << " mm, N_max = " << N << " MPa, P = " << P
          << " N; relative errors: a " << std::showpos
          << relative(a_edge, H.radius) << ", a_m " << relative(a_m, H.radius)
          << ", N_max " << relative(N, H.max_pressure) << ", P "
          << relative(P, hertz_load);
      if (fit.available)
        out << std::noshowpos << "; elliptic fit: p0 = " << fit.max_pressure
            << " MPa, a = " << fit.radius << " mm, relative errors: p0 "
            << std::showpos << relative(fit.max_pressure, H.max_pressure)
            << ", a " << relative(fit.radius, H.radius);
      else
        out << "; no elliptic fit";
      Comparison c{"hertz sphere", out.str(), {}, ""};
      add_approach(c, summary.estimates, H.approach, centre_approach);
      c.values.insert(c.values.begin(),
                      {{"a", H.radius},
                       {"N_max", H.max_pressure},
                       {"approach", H.approach},
                       {"load", hertz_load},
                       {"a_edge", a_edge},
                       {"a_edge_element", a_element},
                       {"a_moment", a_m},
                       {"resultant", P},
                       {"a_error", relative(a_edge, H.radius)},
                       {"a_moment_error", relative(a_m, H.radius)},
                       {"N_max_error", relative(N, H.max_pressure)},
                       {"load_error", relative(P, hertz_load)}});
      if (fit.available)
        c.values.insert(c.values.end(),
                        {{"fit_max_pressure", fit.max_pressure},
                         {"a_fit", fit.radius},
                         {"fit_max_pressure_error",
                          relative(fit.max_pressure, H.max_pressure)},
                         {"a_fit_error", relative(fit.radius, H.radius)}});
      return c;
    }



    template class References<2>;
    template class References<3>;
  } // namespace scene
} // namespace dpana
