// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_output_output_templates_h
#define dpana_output_output_templates_h

#include <dpana/output/output.h>

#include <deal.II/base/data_out_base.h>

#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <algorithm>
#include <fstream>
#include <iomanip>

namespace dpana
{
  namespace output
  {
    template <int dim>
    void
    write_vtu_file(const Body<dim> &body, const std::string &filename)
    {
      dealii::DataOut<dim> data_out;
      data_out.attach_dof_handler(body.dof_handler());
      data_out.add_data_vector(
        body.solution(),
        std::vector<std::string>(dim, "displacement"),
        dealii::DataOut<dim>::type_dof_data,
        std::vector<
          dealii::DataComponentInterpretation::DataComponentInterpretation>(
          dim,
          dealii::DataComponentInterpretation::component_is_part_of_vector));

      // Stress components as cell data: the strain of a P1 field is constant
      // in each cell.
      const unsigned int n_cells = body.triangulation().n_active_cells();
      const auto        &stress  = body.cell_stress();
      std::vector<std::pair<std::string, std::pair<unsigned, unsigned>>>
        components;
      if (dim == 2)
        components = {{"stress_xx", {0, 0}},
                      {"stress_yy", {1, 1}},
                      {"stress_xy", {0, 1}}};
      else
        components = {{"stress_xx", {0, 0}},
                      {"stress_yy", {1, 1}},
                      {"stress_zz", {2, 2}},
                      {"stress_xy", {0, 1}},
                      {"stress_yz", {1, 2}},
                      {"stress_xz", {0, 2}}};
      std::vector<dealii::Vector<double>> cell_data;
      for (const auto &[name, ij] : components)
        {
          dealii::Vector<double> v(n_cells);
          for (unsigned int c = 0; c < n_cells; ++c)
            v[c] = stress[c][ij.first][ij.second];
          cell_data.push_back(v);
        }
      if (dim == 2)
        {
          cell_data.emplace_back(body.cell_out_of_plane_stress().begin(),
                                 body.cell_out_of_plane_stress().end());
          components.push_back({"stress_zz", {2, 2}});
        }
      cell_data.emplace_back(body.cell_von_mises().begin(),
                             body.cell_von_mises().end());
      components.push_back({"von_mises", {0, 0}});
      for (unsigned int k = 0; k < cell_data.size(); ++k)
        data_out.add_data_vector(cell_data[k],
                                 components[k].first,
                                 dealii::DataOut<dim>::type_cell_data);

      data_out.build_patches(body.mapping());

      std::ofstream out(filename);
      data_out.write_vtu(out);
      AssertThrow(out, dealii::ExcIO());
    }



    template <int dim>
    std::vector<std::string>
    write_vtu(const Body<dim> &body, const std::string &directory)
    {
      const std::string stem = file_stem(body.name());
      write_vtu_file(body, directory + "/" + stem + ".vtu");
      {
        std::ofstream out(directory + "/" + stem + ".pvd");
        dealii::DataOutBase::write_pvd_record(out, {{0.0, stem + ".vtu"}});
        AssertThrow(out, dealii::ExcIO());
      }
      return {stem + ".vtu", stem + ".pvd"};
    }



    namespace internal
    {
      template <int dim>
      void
      write_vector(std::ostream &out, const dealii::Tensor<1, dim> &v)
      {
        out << "[";
        for (unsigned int d = 0; d < dim; ++d)
          out << (d ? ", " : "") << v[d];
        out << "]";
      }

      inline std::string
      escape(const std::string &s)
      {
        std::string e;
        for (const char c : s)
          {
            if (c == '"' || c == '\\')
              e += '\\';
            e += c;
          }
        return e;
      }
    } // namespace internal



    template <int dim>
    void
    write_body_summary(const Body<dim> &body, std::ostream &out)
    {
      using internal::escape;
      using internal::write_vector;
      out << std::setprecision(10);
      out << "    {\n";
      out << "      \"name\": \"" << escape(body.name()) << "\",\n";
      out << "      \"material\": \""
          << escape(body.material().description(dim)) << "\",\n";
      out << "      \"cells\": " << body.triangulation().n_active_cells()
          << ",\n";
      out << "      \"vertices\": " << body.triangulation().n_used_vertices()
          << ",\n";
      out << "      \"dofs\": " << body.dof_handler().n_dofs() << ",\n";
      out << "      \"constrained_dofs\": "
          << body.constraints().n_constraints() << ",\n";
      out << "      \"max_displacement\": " << body.max_displacement() << ",\n";
      const auto &vm = body.cell_von_mises();
      out << "      \"max_von_mises\": "
          << (vm.empty() ? 0.0 : *std::max_element(vm.begin(), vm.end()))
          << ",\n";
      out << "      \"applied_load_resultant\": ";
      write_vector(out, body.applied_load_resultant());
      out << ",\n      \"reactions\": {";
      bool first = true;
      for (const auto &[name, R] : body.reactions())
        {
          out << (first ? "\n" : ",\n") << "        \"" << escape(name)
              << "\": ";
          write_vector(out, R);
          first = false;
        }
      out << (first ? "" : "\n      ") << "},\n";
      out << "      \"concentrated_forces\": [";
      first = true;
      for (const auto &cf : body.applied_concentrated_forces())
        {
          out << (first ? "\n" : ",\n") << "        {\"point\": ";
          write_vector(out, dealii::Tensor<1, dim>(cf.requested_point));
          out << ", \"vertex\": ";
          write_vector(out, dealii::Tensor<1, dim>(cf.vertex));
          out << ", \"force\": ";
          write_vector(out, cf.force);
          out << "}";
          first = false;
        }
      out << (first ? "" : "\n      ") << "]\n";
      out << "    }";
    }
  } // namespace output
} // namespace dpana

#endif
