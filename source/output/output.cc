// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/output/output.h>

#include <deal.II/grid/grid_out.h>

#include <deal.II/numerics/data_out.h>

#include <filesystem>
#include <fstream>
#include <limits>

namespace dpana
{
  namespace output
  {
    void
    Parameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry(
        "Directory",
        "output",
        Anything(),
        "Directory of the results, relative to the working directory. The "
        "run checks first that it can write there; its files are written "
        "into a staging directory that replaces this one at the end, so "
        "that it holds exactly this run's files; a run that fails leaves "
        "the previous results intact. A directory holding files dpana did "
        "not write is refused.");
      prm.declare_entry("Write VTU",
                        "true",
                        Bool(),
                        "Write the VTU/PVD files of the bodies (displacement "
                        "in mm, stresses in MPa).");
      prm.declare_entry("Plot",
                        "true",
                        Bool(),
                        "Contact runs: write contact.png, the tractions along "
                        "the contact surface (python3 with matplotlib).");
      prm.declare_entry("Write FCLIB",
                        "false",
                        Bool(),
                        "Contact runs: write the condensed contact problem to "
                        "problem.hdf5, an FCLIB local problem (HDF5) for "
                        "other contact solvers.");
      prm.declare_entry(
        "Write mesh",
        "false",
        Bool(),
        "Write the mesh each body was solved on as "
        "body_N.msh (gmsh format 1, as deal.II's GridOut "
        "writes it: the vertices to full precision, the "
        "cells, and the boundary faces of nonzero boundary "
        "id with that id as their physical tag), e.g. to solve the same "
        "discretisation with another code. Not with a "
        "distributed mesh (Contact / Parallel mesh = "
        "distributed), where no rank holds the whole mesh.");
    }



    void
    Parameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      directory   = prm.get("Directory");
      write_vtu   = prm.get_bool("Write VTU");
      plot        = prm.get_bool("Plot");
      write_fclib = prm.get_bool("Write FCLIB");
      write_mesh  = prm.get_bool("Write mesh");
      if (directory.empty())
        throw InputError("Output / Directory: must not be empty");
    }



    // Writes the cells of piece @p piece of @p n_pieces to @p filename and,
    // unless @p record is empty, the .pvtu record of all pieces.
    template <int dim>
    void
    write_vtu_piece(const Body<dim>   &body,
                    const std::string &filename,
                    const unsigned int piece,
                    const unsigned int n_pieces,
                    const std::string &record)
    {
      dealii::DataOut<dim> data_out;
      // A body partitioned into as many parts as there are pieces: piece p
      // holds the cells of subdomain p, those rank p assembled.
      // Otherwise piece p of P holds the active cells of the contiguous
      // index range [p N / P, (p + 1) N / P): the split changes neither the
      // mesh nor the numbering of the degrees of freedom, only which cells
      // are written.
      if (n_pieces > 1 && body.n_parts() == n_pieces)
        data_out.set_cell_selection(
          [piece](
            const typename dealii::Triangulation<dim>::cell_iterator &cell) {
            return cell->is_active() && cell->subdomain_id() == piece;
          });
      else if (n_pieces > 1)
        {
          const std::size_t n     = body.triangulation().n_active_cells();
          const std::size_t first = n * piece / n_pieces;
          const std::size_t end   = n * (piece + 1) / n_pieces;
          data_out.set_cell_selection(
            [first, end](
              const typename dealii::Triangulation<dim>::cell_iterator &cell) {
              return cell->is_active() && cell->active_cell_index() >= first &&
                     cell->active_cell_index() < end;
            });
        }
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

      // Binary, zlib-compressed VTU at the fastest compression level:
      // deal.II's default, the best compression, took 6.9 times as long for
      // a file 7 % smaller (1.04 M dofs, 2D: 82.9 s against 12.0 s for the
      // whole output phase, 24.3 MB against 26.2 MB).
      dealii::DataOutBase::VtkFlags flags;
      flags.compression_level =
        dealii::DataOutBase::VtkFlags::ZlibCompressionLevel::best_speed;
      data_out.set_flags(flags);

      std::ofstream out(filename);
      data_out.write_vtu(out);
      AssertThrow(out, dealii::ExcIO());
      if (record.empty())
        return;
      // The .pvtu record names the pieces, relative to its own directory.
      const std::filesystem::path path(record);
      const std::string           base = path.stem().string();
      std::vector<std::string>    pieces;
      for (unsigned int p = 0; p < n_pieces; ++p)
        pieces.push_back(base + "_" + std::to_string(p) + ".vtu");
      std::ofstream pvtu(record);
      data_out.write_pvtu_record(pvtu, pieces);
      AssertThrow(pvtu, dealii::ExcIO());
    }



    template <int dim>
    void
    write_vtu_file(const Body<dim> &body, const std::string &filename)
    {
      write_vtu_piece(body, filename, 0, 1, "");
    }



    template <int dim>
    void
    write_bodies(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
                 const std::string                             &directory,
                 const unsigned int                             rank,
                 const unsigned int                             n_ranks)
    {
      std::vector<std::pair<double, std::string>> records;
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const std::string base = "body_" + std::to_string(b + 1);
          if (n_ranks == 1)
            {
              write_vtu_file(*bodies[b], directory + "/" + base + ".vtu");
              records.emplace_back(0.0, base + ".vtu");
              continue;
            }
          const std::string piece = base + "_" + std::to_string(rank) + ".vtu";
          const std::string record =
            rank == 0 ? directory + "/" + base + ".pvtu" : std::string();
          write_vtu_piece(
            *bodies[b], directory + "/" + piece, rank, n_ranks, record);
          records.emplace_back(0.0, base + ".pvtu");
        }
      if (rank != 0)
        return;
      std::ofstream pvd(directory + "/bodies.pvd");
      dealii::DataOutBase::write_pvd_record(pvd, records);
      AssertThrow(pvd, dealii::ExcIO());
    }



    template void
    write_vtu_file(const Body<2> &, const std::string &);
    template void
    write_vtu_file(const Body<3> &, const std::string &);



    template <int dim>
    void
    write_meshes(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
                 const std::string                             &directory)
    {
      dealii::GridOut out;
      // The boundary faces (in 3D also edges) of nonzero boundary id, with
      // that id as their physical tag; GridOut leaves out those of id 0.
      out.set_flags(dealii::GridOutFlags::Msh(true, true));
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          Assert(!bodies[b]->mesh_is_distributed(),
                 dealii::ExcMessage("a distributed mesh is not whole here"));
          const std::string name =
            directory + "/body_" + std::to_string(b + 1) + ".msh";
          std::ofstream file(name);
          // Round trip of the coordinates: 17 significant digits.
          file.precision(std::numeric_limits<double>::max_digits10);
          out.write_msh(bodies[b]->triangulation(), file);
          AssertThrow(file, dealii::ExcIO());
        }
    }



    template void
    write_meshes(const std::vector<std::unique_ptr<Body<2>>> &,
                 const std::string &);
    template void
    write_meshes(const std::vector<std::unique_ptr<Body<3>>> &,
                 const std::string &);
    template void
    write_bodies(const std::vector<std::unique_ptr<Body<2>>> &,
                 const std::string &,
                 unsigned int,
                 unsigned int);
    template void
    write_bodies(const std::vector<std::unique_ptr<Body<3>>> &,
                 const std::string &,
                 unsigned int,
                 unsigned int);
  } // namespace output
} // namespace dpana
