// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/condensation/contact_problem.h>
#include <dpana/contact/feasibility.h>
#include <dpana/contact_surface/format_point.h>
#include <dpana/parameters/parameters.h>
#include <dpana/scene/input_checks.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace dpana
{
  namespace scene
  {
    namespace
    {
      // The motions along which a body's unbalanced load acts: its
      // components of at least 0.3 times the largest, each with the sign
      // of the load ("+x", "-rotation"). The closest balanced load within
      // the friction cones may overshoot the body's own load along a
      // motion (a block pushed sideways on the plane: the fit presses it
      // harder than its loads do, for more friction, and leaves an
      // unbalanced part against the load, -e, along y); such a component
      // is not a part of the loads that cannot be balanced, and is named
      // only if no other one is.
      std::string
      directions(const std::vector<RigidMode> &modes,
                 const Eigen::VectorXd        &unbalanced,
                 const Eigen::VectorXd        &rhs)
      {
        const double largest = unbalanced.lpNorm<Eigen::Infinity>();
        std::string  short_of_load, all;
        for (unsigned int k = 0; k < modes.size(); ++k)
          if (std::abs(unbalanced(k)) >= 0.3 * largest)
            {
              const std::string d = std::string(unbalanced(k) > 0 ? "+" : "-") +
                                    modes[k].description;
              all += (all.empty() ? "" : ", ") + d;
              // G r = e: the load on the motion is -e.
              if (unbalanced(k) * rhs(k) < 0)
                short_of_load += (short_of_load.empty() ? "" : ", ") + d;
            }
        return short_of_load.empty() ? all : short_of_load;
      }
    } // namespace



    template <int dim>
    void
    check_held_by_contact(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
                          const contact::ContactProblem &problem)
    {
      const double tolerance = 1e-8;
      if (problem.n_equalities() == 0)
        return;
      double scale = 0;
      for (const auto &body : bodies)
        scale = std::max(scale, body->system_rhs().l1_norm());
      if (!(scale > 0))
        return;
      const auto f = contact::check_feasibility(
        problem,
        Eigen::VectorXd::Constant(problem.n_equalities(), scale),
        tolerance);
      if (f.feasible)
        return;

      std::vector<std::pair<std::string, std::string>> unheld;
      unsigned int                                     row = 0;
      for (const auto &body : bodies)
        {
          const auto           &modes = body->free_rigid_modes();
          const Eigen::VectorXd u     = f.unbalanced.segment(row, modes.size());
          const Eigen::VectorXd e     = problem.e.segment(row, modes.size());
          row += modes.size();
          if (!modes.empty() && u.lpNorm<Eigen::Infinity>() > tolerance)
            unheld.emplace_back(body->name(), directions(modes, u, e));
        }
      std::string names, where;
      for (const auto &[name, along] : unheld)
        {
          names += (names.empty() ? "" : " and ") + name;
          where += (where.empty() ? "" : ", ") + along +
                   (unheld.size() > 1 ? " (" + name + ")" : "");
        }
      std::ostringstream details;
      details << "Contact / Friction coefficient = "
              << (problem.n_elements() > 0 ? problem.mu(0) : 0.)
              << "; unbalanced: " << f.residual << " of the largest load sum";
      throw InputError(names + " cannot be held by the contact: the part of " +
                       (unheld.size() > 1 ? "the" : "its") + " loads along " +
                       where +
                       " cannot be balanced by compressive tractions within "
                       "the friction cones (" +
                       details.str() + "); hold " +
                       (unheld.size() > 1 ? "the bodies" : "the body") +
                       " by Dirichlet or symmetry conditions or change the "
                       "loads");
    }



    template <int dim>
    void
    check_contact_boundaries_free(
      const std::vector<std::unique_ptr<Body<dim>>> &bodies,
      const std::array<std::string, 2>              &contact_boundaries)
    {
      for (unsigned int b = 0; b < bodies.size() && b < 2; ++b)
        for (const auto &[boundary, parameter] :
             bodies[b]->boundary_conditions().used_boundaries())
          if (boundary == contact_boundaries[b])
            throw InputError(parameter + ": " + parameters::quote(boundary) +
                             " is the contact boundary of " +
                             bodies[b]->name() + " (Contact / Boundary " +
                             std::to_string(b + 1) +
                             "); a kinematic condition there holds what the "
                             "contact is to carry");
    }



    // The mean normal against the held axes (input_checks.h), vertex by
    // vertex of the candidate faces.
    template <int dim>
    std::string
    leaning_axes(const Body<dim>                            &body,
                 const contact_surface::ContactSurface<dim> &surface)
    {
      std::string  axes;
      const auto   n        = surface.surface_normal();
      unsigned int dominant = 0;
      for (unsigned int c = 1; c < dim; ++c)
        if (std::abs(n[c]) > std::abs(n[dominant]))
          dominant = c;
      // The axis of n itself is no lean (a support along the normal at the
      // edge of the surface is not a symmetry plane).
      for (unsigned int c = 0; c < dim; ++c)
        if (c != dominant)
          {
            bool held = false;
            for (const auto &F : surface.get_faces())
              for (unsigned int v = 0; v < dim; ++v)
                held =
                  held || condensation::held_to_zero(body, F.dofs[dim * v + c]);
            if (held && std::abs(n[c]) > 1e-3)
              axes += (axes.empty() ? "" : " and ") + std::string(1, "xyz"[c]);
          }
      return axes;
    }



    template <int dim>
    std::string
    far_gap(const contact_surface::ContactSurface<dim> &surface)
    {
      if (surface.n_elements() == 0)
        return "";
      double gap   = std::numeric_limits<double>::max();
      double s_min = gap, t_min = gap, s_max = -gap, t_max = -gap;
      for (unsigned int j = 0; j < surface.n_elements(); ++j)
        {
          const auto &e = surface.element(j);
          gap           = std::min(gap, e.mean_gap());
          s_min         = std::min(s_min, e.s_min);
          s_max         = std::max(s_max, e.s_max);
          t_min         = std::min(t_min, e.t_min);
          t_max         = std::max(t_max, e.t_max);
        }
      const double extent = std::max(s_max - s_min, t_max - t_min);
      if (!(std::abs(gap) > 0.1 * extent))
        return "";
      std::ostringstream text;
      text << std::setprecision(4) << "the closest initial gap of "
           << surface.options().body << " is " << gap << " mm ("
           << (gap < 0 ? "an overlap" : "apart") << "), "
           << std::abs(gap) / extent << " times the extent " << extent
           << " mm of its candidate surface: a body, Contact / Obstacle point "
              "or Contact direction possibly misplaced (contact is linearised "
              "about the initial configuration: a floating body closes a "
              "uniform gap by a rigid motion, but its displacements are then "
              "far from small)";
      return text.str();
    }



    template <int dim>
    std::string
    leaning_direction(const Body<dim>                            &body,
                      const contact_surface::ContactSurface<dim> &surface,
                      const bool                                  rigid_plane)
    {
      const bool given = surface.options().direction.norm() > 0;
      if (!given && !rigid_plane)
        return "";
      const std::string axes = leaning_axes(body, surface);
      if (axes.empty())
        return "";
      const std::string n = contact_surface::internal::format_point(
        dealii::Point<dim>(surface.surface_normal()));
      const std::string held = ", along which vertices of the candidate "
                               "surface of " +
                               body.name() + " are held (symmetry planes?): ";
      return given ? "Contact / Contact direction " + n + " leans along " +
                       axes + held +
                       "the obstacle of a half or quarter model is then not "
                       "symmetric; give a direction within the symmetry "
                       "planes" :
                     "Contact / Contact direction is empty, and the mean "
                     "outward normal " +
                       n + " of the candidate surface of " + body.name() +
                       " leans along " + axes + held +
                       "a half or quarter model on the rigid plane needs "
                       "the contact direction";
    }



    template <int dim>
    std::string
    surface_resolution(const contact_surface::ContactSurface<dim> &surface,
                       const bool                                  first)
    {
      using contact_surface::ElementShape;
      const auto        &opts    = surface.options();
      const bool         patches = opts.shape == ElementShape::vertex_patches;
      const unsigned int n_e = surface.n_elements(), n_v = surface.n_vertices();
      std::ostringstream text;
      const std::string counts = std::to_string(n_e) + " contact elements on " +
                                 std::to_string(n_v) + " surface vertices of " +
                                 opts.body;
      if (n_e > n_v)
        text << counts
             << ": more normal tractions than the surface can resist; A may "
                "be singular and the tractions may oscillate ("
             << (patches ? "refine the surface of " + opts.body +
                             " or use Contact / Contact elements = faces" :
                           std::string("raise Contact / Faces per contact "
                                       "element"))
             << ")";
      else if (first && !patches && 4 * n_e > 3 * n_v)
        text << counts
             << ": a constant traction on each face or two is not a stable "
                "pair with linear displacements, and the tractions may "
                "oscillate from element to element (raise Contact / Faces "
                "per contact element: the default groups "
             << (dim == 2 ? "2 edges" : "8 triangles")
             << "; or use Contact / Contact elements = vertices)";
      return text.str();
    }



    template <int dim>
    std::string
    off_axis_centre(const contact_surface::ContactSurface<dim> &surface)
    {
      // Without a contact direction the axis is the mean normal, which a
      // quarter model's cap tilts (leaning_axes()): no vertex is nearest
      // along it that could stand for the axis.
      if (surface.options().direction.norm() == 0)
        return "";
      const dealii::Tensor<1, dim> n       = surface.surface_normal();
      const auto                  &faces   = surface.get_faces();
      dealii::Point<dim>           nearest = faces.at(0).points.at(0);
      for (const auto &F : faces)
        for (const auto &x : F.points)
          if (x * n > nearest * n)
            nearest = x;
      double edge = 0;
      for (const auto &F : faces)
        if (std::find(F.points.begin(), F.points.end(), nearest) !=
            F.points.end())
          for (unsigned int v = 0; v < F.points.size(); ++v)
            edge = std::max(
              edge, F.points[v].distance(F.points[(v + 1) % F.points.size()]));
      const dealii::Point<dim>     x0 = surface.options().region_centre;
      const dealii::Tensor<1, dim> d =
        (nearest - x0) - ((nearest - x0) * n) * n;
      if (!(d.norm() > edge))
        return "";
      std::ostringstream text;
      text << std::setprecision(4) << "Contact / Candidate centre "
           << contact_surface::internal::format_point(x0) << " lies "
           << d.norm() << " mm off the axis through the point of "
           << surface.options().body
           << "'s candidate surface nearest the obstacle, "
           << contact_surface::internal::format_point(nearest)
           << " (more than the " << edge
           << " mm of the faces there): the Hertz reference measures a, a_m "
              "and the approach about the candidate centre; put it on the "
              "axis of the sphere";
      return text.str();
    }



    template <int dim>
    bool
    held_across_centre(const Body<dim>                            &body,
                       const contact_surface::ContactSurface<dim> &surface,
                       const dealii::Point<dim>                   &centre)
    {
      const auto   tau = surface.surface_tangents()[0];
      const double s0  = centre * tau;
      unsigned int c   = 0;
      for (unsigned int d = 1; d < dim; ++d)
        if (std::abs(tau[d]) > std::abs(tau[c]))
          c = d;
      if (!(tau[c] * tau[c] > 0.5))
        return false;
      double extent = 0;
      for (const auto &F : surface.get_faces())
        for (const auto &x : F.points)
          extent = std::max(extent, std::abs(x * tau - s0));
      for (const auto &F : surface.get_faces())
        for (unsigned int v = 0; v < F.points.size(); ++v)
          if (std::abs(F.points[v] * tau - s0) <= 1e-9 * extent &&
              condensation::held_to_zero(body, F.dofs[dim * v + c]))
            return true;
      return false;
    }



    template void
    check_held_by_contact(const std::vector<std::unique_ptr<Body<2>>> &,
                          const contact::ContactProblem &);
    template void
    check_held_by_contact(const std::vector<std::unique_ptr<Body<3>>> &,
                          const contact::ContactProblem &);
    template void
    check_contact_boundaries_free(const std::vector<std::unique_ptr<Body<2>>> &,
                                  const std::array<std::string, 2> &);
    template void
    check_contact_boundaries_free(const std::vector<std::unique_ptr<Body<3>>> &,
                                  const std::array<std::string, 2> &);
    template std::string
    leaning_axes(const Body<2> &, const contact_surface::ContactSurface<2> &);
    template std::string
    leaning_axes(const Body<3> &, const contact_surface::ContactSurface<3> &);
    template std::string
    far_gap(const contact_surface::ContactSurface<2> &);
    template std::string
    far_gap(const contact_surface::ContactSurface<3> &);
    template std::string
    leaning_direction(const Body<2> &,
                      const contact_surface::ContactSurface<2> &,
                      const bool);
    template std::string
    leaning_direction(const Body<3> &,
                      const contact_surface::ContactSurface<3> &,
                      const bool);
    template std::string
    surface_resolution(const contact_surface::ContactSurface<2> &, const bool);
    template std::string
    surface_resolution(const contact_surface::ContactSurface<3> &, const bool);
    template std::string
    off_axis_centre(const contact_surface::ContactSurface<2> &);
    template std::string
    off_axis_centre(const contact_surface::ContactSurface<3> &);
    template bool
    held_across_centre(const Body<2> &,
                       const contact_surface::ContactSurface<2> &,
                       const dealii::Point<2> &);
    template bool
    held_across_centre(const Body<3> &,
                       const contact_surface::ContactSurface<3> &,
                       const dealii::Point<3> &);
  } // namespace scene
} // namespace dpana
