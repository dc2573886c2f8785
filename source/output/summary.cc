// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/output/summary.h>

#include <algorithm>
#include <fstream>

namespace dpana
{
  namespace output
  {
    namespace
    {
      template <int dim>
      std::vector<double>
      to_vector(const dealii::Tensor<1, dim> &v)
      {
        return std::vector<double>(v.begin_raw(), v.end_raw());
      }



      // The pressure estimates finer than an element (2D), the resultant
      // and centroid of the pressure (3D) and the measured approach (3D
      // Hertz scenes), see scene/pressure_estimators.h.
      nlohmann::json
      estimates_to_json(const scene::PressureEstimates &est)
      {
        nlohmann::json j = nlohmann::json::object();
        if (est.approach_measured)
          j["approach"] = est.approach;
        if (est.point_centroid_available)
          {
            j["pressure_resultant"]      = est.resultant;
            j["pressure_centroid_point"] = est.point_centroid;
          }
        if (!est.available)
          return j;
        j["mirrored_half_model"] = est.mirrored;
        j["pressure_resultant"]  = est.resultant;
        j["pressure_centroid"]   = est.centroid;
        j["moment_half_width"]   = est.moment_half_width;
        if (est.fit_available)
          {
            j["fit_half_width"]   = est.fit_half_width;
            j["fit_max_pressure"] = est.fit_max_pressure;
            j["fit_centre"]       = est.fit_centre;
          }
        return j;
      }
    } // namespace



    template <int dim>
    nlohmann::json
    to_json(const Body<dim> &body)
    {
      nlohmann::json j = {
        {"name", body.name()},
        {"material", body.material().description(dim)},
        {"cells", body.n_cells()},
        {"vertices", body.n_vertices()},
        {"dofs", body.dof_handler().n_dofs()},
        {"constrained_dofs", body.constraints().n_constraints()},
        {"max_displacement", body.max_displacement()},
        {"max_von_mises", body.max_von_mises()},
        {"applied_load_resultant", to_vector(body.applied_load_resultant())}};
      j["reactions"] = nlohmann::json::object();
      for (const auto &[name, R] : body.reactions())
        j["reactions"][name] = to_vector(R);
      j["concentrated_forces"] = nlohmann::json::array();
      for (const auto &cf : body.applied_concentrated_forces())
        j["concentrated_forces"].push_back(
          {{"point", to_vector(dealii::Tensor<1, dim>(cf.requested_point))},
           {"vertex", to_vector(dealii::Tensor<1, dim>(cf.vertex))},
           {"force", to_vector(cf.force)}});
      return j;
    }



    nlohmann::json
    to_json(const scene::ContactSummary &summary, const unsigned int dim)
    {
      const auto    &res = summary.result;
      nlohmann::json j   = {
          {"contact_elements", summary.n_elements},
          {"converged", res.converged},
          {"iterations", res.iterations},
          {"residual", res.residual},
          {"residual_figures",
           {{"natural_map", res.figures.natural_map},
            {"penetration", res.figures.penetration},
            {"cone_violation", res.figures.cone_violation},
            {"complementarity", res.figures.complementarity},
            {"equilibrium", res.figures.equilibrium}}},
          {"message", res.message},
          {"solved_by", contact::to_string(res.solver)},
          {"fallbacks", res.fallbacks},
          {"asymmetry_of_A", summary.asymmetry},
          {"contact_half_width", summary.half_width},
          {"contact_half_width_element", summary.half_width_element},
          {"contact_half_width_centroid", summary.half_width_centroid},
          {"max_normal_traction", summary.max_pressure},
          {"normal_resultant", summary.normal_resultant},
          {"candidate_edge_warning", summary.candidate_edge_warning},
          {"rigid_displacements",
           std::vector<double>(res.alpha.begin(), res.alpha.end())}};
      if (summary.estimates.available || summary.estimates.approach_measured ||
          summary.estimates.point_centroid_available)
        j["estimates"] = estimates_to_json(summary.estimates);
      j["zones"] = nlohmann::json::array();
      for (const auto &z : summary.zones)
        {
          nlohmann::json zone = {{"status", contact::to_string(z.status)},
                                 {"s_from", z.from},
                                 {"s_to", z.to}};
          if (dim == 3)
            {
              zone["t_from"] = z.t_from;
              zone["t_to"]   = z.t_to;
            }
          zone["elements"] = z.n_elements;
          j["zones"].push_back(zone);
        }
      j["references"] = nlohmann::json::array();
      for (const auto &c : summary.comparisons)
        {
          nlohmann::json r = {{"type", c.type}};
          if (!c.file.empty())
            r["file"] = c.file;
          for (const auto &[name, value] : c.values)
            r[name] = value;
          j["references"].push_back(r);
        }
      return j;
    }



    nlohmann::json
    to_json(const PhaseLog &phases)
    {
      return {{"timings", phases.timings()},
              {"peak_memory_mb", phases.peak_memory()}};
    }



    nlohmann::json
    to_json(const Machine &machine, const unsigned int mpi_processes)
    {
      nlohmann::json j = {{"processor", nullptr},
                          {"cores", machine.cores},
                          {"blas_kernels", nullptr},
                          {"blas_threads", nullptr},
                          {"mpi_processes", mpi_processes}};
      if (!machine.processor.empty())
        j["processor"] = machine.processor;
      if (!machine.blas_kernels.empty())
        j["blas_kernels"] = machine.blas_kernels;
      if (machine.blas_threads > 0)
        j["blas_threads"] = machine.blas_threads;
      return j;
    }



    void
    write_json(const nlohmann::json &summary, const std::string &filename)
    {
      std::ofstream out(filename);
      out << summary.dump(2) << '\n';
      AssertThrow(out, dealii::ExcIO());
    }



    template nlohmann::json
    to_json(const Body<2> &);
    template nlohmann::json
    to_json(const Body<3> &);
  } // namespace output
} // namespace dpana
