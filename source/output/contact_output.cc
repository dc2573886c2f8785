// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/output/contact_output.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/vector.h>

#include <deal.II/numerics/data_out.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>

#include <sys/wait.h>

namespace dpana
{
  namespace output
  {
    template <int dim>
    void
    write_contact_csv(const contact_surface::ContactSurface<dim> &surface,
                      const scene::ContactSummary                &summary,
                      const std::string                          &filename)
    {
      const auto   &res = summary.result;
      std::ofstream out(filename);
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
          out << ',' << contact::to_string(res.status[j]) << ','
              << summary.element_residual[j] << '\n';
        }
      AssertThrow(out, dealii::ExcIO());
    }



    namespace
    {
      // The pieces of faces of the contact elements (whole faces, or the
      // pieces of the patches around vertices) as a mesh of their own: each
      // piece keeps its own vertices, so that values constant per element show
      // as such, and the index of its element as the material id of its cell.
      template <int dim>
      void
      make_piece_mesh(const contact_surface::ContactSurface<dim> &surface,
                      dealii::Triangulation<dim - 1, dim>        &tria)
      {
        std::vector<dealii::Point<dim>>        vertices;
        std::vector<dealii::CellData<dim - 1>> cells;
        for (unsigned int j = 0; j < surface.n_elements(); ++j)
          for (const auto &piece : surface.element(j).pieces)
            {
              dealii::CellData<dim - 1> cell(dim);
              cell.material_id = j;
              const auto corners =
                piece.corner_points(surface.get_faces()[piece.face]);
              for (unsigned int v = 0; v < dim; ++v)
                {
                  cell.vertices[v] = vertices.size();
                  vertices.push_back(corners[v]);
                }
              cells.push_back(cell);
            }
        tria.create_triangulation(vertices, cells, dealii::SubCellData());
      }



      // Piecewise constant elements on the faces: lines in 2D, triangles in
      // 3D.
      template <int dim>
      std::unique_ptr<dealii::FiniteElement<dim - 1, dim>>
      constant_element()
      {
        if constexpr (dim == 2)
          return std::make_unique<dealii::FE_DGQ<1, 2>>(0);
        else
          return std::make_unique<dealii::FE_SimplexDGP<2, 3>>(0);
      }
    } // namespace



    template <int dim>
    void
    write_contact_surface_vtu(
      const contact_surface::ContactSurface<dim> &surface,
      const scene::ContactSummary                &summary,
      const std::string                          &filename)
    {
      using DCI =
        dealii::DataComponentInterpretation::DataComponentInterpretation;
      const auto &res = summary.result;

      // The fields, one value (or one vector) per contact element.
      std::vector<std::string>                         names;
      std::vector<DCI>                                 kinds;
      std::vector<std::function<double(unsigned int)>> value;
      const auto scalar = [&](const std::string                  &name,
                              std::function<double(unsigned int)> f) {
        names.push_back(name);
        kinds.push_back(
          dealii::DataComponentInterpretation::component_is_scalar);
        value.push_back(std::move(f));
      };
      const auto suffix = [](const unsigned int k) {
        return dim == 2 ? std::string() : std::to_string(k);
      };
      scalar("element", [](unsigned int j) { return j; });
      scalar("N", [&](unsigned int j) { return res.r(dim * j); });
      for (unsigned int k = 1; k < dim; ++k)
        scalar("T" + suffix(k),
               [&, k](unsigned int j) { return res.r(dim * j + k); });
      scalar("u_N", [&](unsigned int j) {
        return res.u(dim * j) / surface.element(j).area;
      });
      for (unsigned int k = 1; k < dim; ++k)
        scalar("u_T" + suffix(k), [&, k](unsigned int j) {
          return res.u(dim * j + k) / surface.element(j).area;
        });
      scalar("gap",
             [&](unsigned int j) { return surface.element(j).mean_gap(); });
      scalar("status",
             [&](unsigned int j) { return static_cast<int>(res.status[j]); });
      scalar("residual",
             [&](unsigned int j) { return summary.element_residual[j]; });
      // The traction vector N n + sum T_k tau_k in global coordinates.
      for (unsigned int d = 0; d < dim; ++d)
        {
          names.push_back("traction");
          kinds.push_back(
            dealii::DataComponentInterpretation::component_is_part_of_vector);
          value.push_back([&, d](unsigned int j) {
            const auto &e = surface.element(j);
            double      t = res.r(dim * j) * e.normal[d];
            for (unsigned int k = 1; k < dim; ++k)
              t += res.r(dim * j + k) * e.tangents[k - 1][d];
            return t;
          });
        }

      dealii::Triangulation<dim - 1, dim> tria;
      make_piece_mesh(surface, tria);
      const dealii::FESystem<dim - 1, dim> fe(*constant_element<dim>(),
                                              names.size());
      dealii::DoFHandler<dim - 1, dim>     dof_handler(tria);
      dof_handler.distribute_dofs(fe);
      dealii::Vector<double>                       data(dof_handler.n_dofs());
      std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const unsigned int j = cell->material_id();
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            data[dofs[i]] = value[fe.system_to_component_index(i).first](j);
        }

      dealii::DataOut<dim - 1, dim> data_out;
      data_out.attach_dof_handler(dof_handler);
      data_out.add_data_vector(data,
                               names,
                               dealii::DataOut<dim - 1, dim>::type_dof_data,
                               kinds);
      if constexpr (dim == 2)
        data_out.build_patches();
      else
        data_out.build_patches(
          dealii::MappingFE<2, 3>(dealii::FE_SimplexP<2, 3>(1)));
      std::ofstream out(filename);
      data_out.write_vtu(out);
      AssertThrow(out, dealii::ExcIO());
    }



    std::string
    plot_contact(const std::string &csv, const std::string &png)
    {
      const std::string script = DPANA_PLOT_SCRIPT;
      const std::string python = "/usr/bin/python3";
      if (!std::filesystem::exists(script))
        return "no plot: " + script + " not found";
      // The script's exit status without matplotlib (NO_MATPLOTLIB there).
      constexpr int no_matplotlib = 3;
      const int     status =
        std::system((python + " " + script + " " + csv + " " + png).c_str());
      if (status != -1 && WIFEXITED(status) &&
          WEXITSTATUS(status) == no_matplotlib)
        return "no plot: " + python + " has no matplotlib";
      if (status != 0)
        return "the plot script failed";
      return "";
    }



    template void
    write_contact_csv(const contact_surface::ContactSurface<2> &,
                      const scene::ContactSummary &,
                      const std::string &);
    template void
    write_contact_csv(const contact_surface::ContactSurface<3> &,
                      const scene::ContactSummary &,
                      const std::string &);
    template void
    write_contact_surface_vtu(const contact_surface::ContactSurface<2> &,
                              const scene::ContactSummary &,
                              const std::string &);
    template void
    write_contact_surface_vtu(const contact_surface::ContactSurface<3> &,
                              const scene::ContactSummary &,
                              const std::string &);
  } // namespace output
} // namespace dpana
