// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_output_output_h
#define dpana_output_output_h

#include <dpana/body/body.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  namespace output
  {
    /**
     * The "Output" subsection: where a run writes its files, and which.
     * Every run writes, into Directory: the parameters it used
     * (parameters.prm, parameters.json), one VTU per body with a PVD record
     * (body_1.vtu, body_2.vtu, bodies.pvd) and summary.json; a contact run
     * adds contact_surface.vtu, contact.csv, contact.png and, if asked,
     * problem.hdf5; if asked, every run writes the bodies' meshes
     * (body_1.msh, ...).
     */
    struct Parameters
    {
      std::string directory   = "output";
      bool        write_vtu   = true;
      bool        plot        = true;
      bool        write_fclib = false;
      bool        write_mesh  = false;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * Writes the VTU file @p filename of a solved body whose stresses have
     * been computed (Body::compute_stresses() or Body::postprocess()):
     * - point data "displacement" (mm), a vector (ParaView: Warp By Vector);
     * - cell data "stress_xx", "stress_yy", "stress_xy" (, "stress_zz",
     *   "stress_yz", "stress_xz") in MPa, constant in each P1 cell, with
     *   "stress_zz" the out-of-plane stress in 2D, and "von_mises" (MPa).
     */
    template <int dim>
    void
    write_vtu_file(const Body<dim> &body, const std::string &filename);

    /**
     * Writes DIRECTORY/body_N.vtu for every body and the record
     * DIRECTORY/bodies.pvd that opens them together.
     *
     * With @p n_ranks > 1 (the MPI route, every rank holding the whole
     * mesh) rank @p rank writes only its share of each body's cells, a
     * contiguous range of the active cell indices, as body_N_RANK.vtu;
     * rank 0 adds the record body_N.pvtu naming all pieces, and bodies.pvd
     * opens the .pvtu records. Every rank calls it.
     */
    template <int dim>
    void
    write_bodies(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
                 const std::string                             &directory,
                 const unsigned int                             rank    = 0,
                 const unsigned int                             n_ranks = 1);

    /**
     * Writes DIRECTORY/body_N.msh, the mesh of every body in gmsh format 1
     * (deal.II's GridOut::write_msh): the vertices to full precision, the
     * cells, and the boundary faces of nonzero boundary id with that id as
     * their physical tag. Each body must hold its whole mesh (not a distributed
     * one).
     */
    template <int dim>
    void
    write_meshes(const std::vector<std::unique_ptr<Body<dim>>> &bodies,
                 const std::string                             &directory);
  } // namespace output
} // namespace dpana

#endif
