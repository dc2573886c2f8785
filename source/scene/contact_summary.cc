// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/contact/residual.h>
#include <dpana/scene/contact_summary.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>

namespace dpana
{
  namespace scene
  {
    namespace
    {
      // Half width, maximum pressure and resultant: the contact zone is every
      // element that is not separated; its half width is the outer edge of
      // its farthest element from the centre s0.
      template <int dim>
      void
      measure_contact_zone(const contact_surface::ContactSurface<dim> &surface,
                           const double                                s0,
                           ContactSummary                             &sum)
      {
        const auto &res         = sum.result;
        sum.half_width          = 0;
        sum.half_width_centroid = 0;
        sum.half_width_element  = 0;
        sum.max_pressure = sum.normal_resultant = 0;
        sum.candidate_edge_warning              = false;
        for (unsigned int j = 0; j < surface.n_elements(); ++j)
          {
            const auto &e    = surface.element(j);
            sum.max_pressure = std::max(sum.max_pressure, -res.r(dim * j));
            sum.normal_resultant += -res.r(dim * j) * e.area;
            if (res.status[j] == contact::ContactStatus::separated)
              continue;
            const double edge =
              std::max(std::abs(e.s_max - s0), std::abs(e.s_min - s0));
            if (edge > sum.half_width)
              {
                sum.half_width         = edge;
                sum.half_width_element = e.s_max - e.s_min;
              }
            sum.half_width_centroid =
              std::max(sum.half_width_centroid, std::abs(e.s - s0));
            if (e.at_open_edge())
              sum.candidate_edge_warning = true;
          }
      }



      // 2D: the runs of equal status along s.
      template <int dim>
      std::vector<Zone>
      zones_along_s(const contact_surface::ContactSurface<dim> &surface,
                    const std::vector<contact::ContactStatus>  &status)
      {
        std::vector<Zone> zones;
        for (const unsigned int j : surface.sorted_elements())
          {
            const auto &e = surface.element(j);
            if (zones.empty() || zones.back().status != status[j])
              zones.push_back({status[j], e.s_min, e.s_max});
            zones.back().to = e.s_max;
            ++zones.back().n_elements;
          }
        return zones;
      }



      // 3D: the bounding box in (s, t) of each status.
      template <int dim>
      std::vector<Zone>
      zone_boxes(const contact_surface::ContactSurface<dim> &surface,
                 const std::vector<contact::ContactStatus>  &status)
      {
        using contact::ContactStatus;
        constexpr double  big = std::numeric_limits<double>::max();
        std::vector<Zone> zones;
        for (const ContactStatus st : {ContactStatus::separated,
                                       ContactStatus::stick,
                                       ContactStatus::slip})
          {
            Zone z{st, big, -big, big, -big, 0};
            for (unsigned int j = 0; j < surface.n_elements(); ++j)
              if (status[j] == st)
                {
                  const auto &e = surface.element(j);
                  z.from        = std::min(z.from, e.s_min);
                  z.to          = std::max(z.to, e.s_max);
                  z.t_from      = std::min(z.t_from, e.t_min);
                  z.t_to        = std::max(z.t_to, e.t_max);
                  ++z.n_elements;
                }
            if (z.n_elements > 0)
              zones.push_back(z);
          }
        return zones;
      }



      // The extents along s and the pressures -N of the elements.
      template <int dim>
      std::vector<PressureElement>
      pressure_elements(const contact_surface::ContactSurface<dim> &surface,
                        const Eigen::VectorXd                      &r)
      {
        std::vector<PressureElement> elements;
        for (unsigned int j = 0; j < surface.n_elements(); ++j)
          {
            const auto &e = surface.element(j);
            elements.push_back({e.s_min, e.s_max, -r(dim * j)});
          }
        return elements;
      }



      // 3D: the resultant and the centroid of p = max(-N, 0) over the
      // elements, each element's constant pressure acting at its centroid
      // (exact for the piecewise constant pressure).
      template <int dim>
      PressureEstimates
      pressure_centroid(const contact_surface::ContactSurface<dim> &surface,
                        const Eigen::VectorXd                      &r)
      {
        PressureEstimates      est;
        double                 resultant = 0;
        dealii::Tensor<1, dim> moment;
        for (unsigned int j = 0; j < surface.n_elements(); ++j)
          {
            const auto  &e = surface.element(j);
            const double f = std::max(-r(dim * j), 0.) * e.area;
            resultant += f;
            moment += f * e.centroid;
          }
        if (!(resultant > 0))
          return est;
        est.resultant                = resultant;
        est.point_centroid_available = true;
        for (unsigned int c = 0; c < dim; ++c)
          est.point_centroid[c] = moment[c] / resultant;
        return est;
      }



      // The log line of the pressure estimates.
      void
      print_estimates(const PressureEstimates &est, std::ostream &out)
      {
        out << "Estimates finer than an element"
            << (est.mirrored ?
                  " (half model mirrored about the candidate centre)" :
                  "")
            << ": moment half width a_m = " << est.moment_half_width << " mm";
        if (est.fit_available)
          out << ", elliptic fit a_f = " << est.fit_half_width
              << " mm (p0 = " << est.fit_max_pressure
              << " MPa, centre s = " << est.fit_centre << ")";
        else
          out << ", no elliptic fit";
        out << "; pressure resultant " << est.resultant
            << " N/mm, centroid s = " << est.centroid << std::endl;
      }
    } // namespace



    template <int dim>
    void
    summarise(const contact_surface::ContactSurface<dim> &surface,
              const contact::ContactProblem              &problem,
              const dealii::Point<dim>                   &centre,
              ContactSummary                             &summary,
              const bool symmetric_about_centre)
    {
      const auto &res    = summary.result;
      summary.n_elements = surface.n_elements();

      // Per-element natural-map residual ||F_j||, F_j = r_j - Pi_K(r_j - rho
      // u~_j), the same measure as the solvers' (residual.h), in MPa.
      const Eigen::VectorXd element_residual =
        contact::element_residuals(problem, res.r, res.u);
      summary.element_residual.assign(element_residual.begin(),
                                      element_residual.end());

      measure_contact_zone(surface,
                           centre * surface.surface_tangents()[0],
                           summary);
      summary.zones = dim == 2 ? zones_along_s(surface, res.status) :
                                 zone_boxes(surface, res.status);
      // With no element in contact the pressures are round-off: no
      // estimates of a zone that is not there.
      const bool in_contact =
        std::any_of(res.status.begin(), res.status.end(), [](const auto s) {
          return s != contact::ContactStatus::separated;
        });
      if (dim == 2 && in_contact)
        summary.estimates =
          estimate_pressure_profile(pressure_elements(surface, res.r),
                                    centre * surface.surface_tangents()[0],
                                    symmetric_about_centre);
      if (dim == 3 && in_contact)
        summary.estimates = pressure_centroid(surface, res.r);
    }



    std::string
    candidate_edge_warning()
    {
      return "the contact zone reaches an edge of the candidate surface "
             "beyond which the body's surface goes on towards the obstacle; "
             "enlarge the candidate region (Contact / Candidate half width) "
             "or, if it holds the whole contact boundary, that boundary in "
             "the mesh";
    }



    void
    print(const ContactSummary &summary,
          const unsigned int    dim,
          std::ostream         &out)
    {
      out << std::setprecision(6);
      out << "Results: contact half width a = " << summary.half_width
          << " mm (outer edge of the last element in contact, known to its "
             "size "
          << summary.half_width_element
          << " mm; its centroid: " << summary.half_width_centroid
          << " mm), max normal traction -N_max = " << summary.max_pressure
          << " MPa, resultant of -N = " << summary.normal_resultant
          << (dim == 2 ? " N/mm" : " N") << std::endl;
      for (const auto &z : summary.zones)
        {
          out << "  zone " << std::setw(9) << contact::to_string(z.status)
              << ": s in [" << z.from << ", " << z.to << "]";
          if (dim == 3)
            out << ", t in [" << z.t_from << ", " << z.t_to << "]";
          out << " (" << z.n_elements << " elements)" << std::endl;
        }
      if (summary.estimates.available)
        print_estimates(summary.estimates, out);
      if (summary.estimates.point_centroid_available)
        out << "Pressure resultant " << summary.estimates.resultant
            << " N, centroid (" << summary.estimates.point_centroid[0] << ", "
            << summary.estimates.point_centroid[1] << ", "
            << summary.estimates.point_centroid[2]
            << ") mm (of the modelled surface)" << std::endl;
      if (summary.estimates.approach_measured)
        out << "Approach of the bodies (far points relative to the contact "
               "point, along the contact normal): "
            << summary.estimates.approach << " mm" << std::endl;
      if (summary.candidate_edge_warning)
        out << "WARNING: " << candidate_edge_warning() << std::endl;
      for (const auto &c : summary.comparisons)
        out << c.text << std::endl;
    }



    template void
    summarise(const contact_surface::ContactSurface<2> &,
              const contact::ContactProblem &,
              const dealii::Point<2> &,
              ContactSummary &,
              const bool);
    template void
    summarise(const contact_surface::ContactSurface<3> &,
              const contact::ContactProblem &,
              const dealii::Point<3> &,
              ContactSummary &,
              const bool);
  } // namespace scene
} // namespace dpana
