// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The candidate faces of a contact surface: the faces of the contact
// boundary in the candidate region, collected from the cells of this rank
// and, when the cells of the body are split over several ranks, gathered
// on every rank in the order of one process.

#include <dpana/base/exceptions.h>
#include <dpana/contact_surface/contact_surface.h>

#include <deal.II/base/mpi.templates.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>

namespace dpana
{
  namespace contact_surface
  {
    namespace
    {
      // A face of a P1 simplex mesh is flat: its area, centroid and normal
      // follow from its vertices. The normal is turned outwards by comparing
      // with the centre of the cell. The vertices are keyed by their first
      // degree of freedom (the component-wise order of the vector-valued P1
      // element, checked by Body::setup()).
      template <int dim>
      Face<dim>
      make_face(
        const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
        const unsigned int                                            f)
      {
        const auto face = cell->face(f);
        Face<dim>  F;
        F.cell    = cell->id();
        F.face_no = f;
        for (const unsigned int v : face->vertex_indices())
          {
            for (unsigned int c = 0; c < dim; ++c)
              F.dofs.push_back(face->vertex_dof_index(v, c));
            F.vertices.push_back(F.dofs[v * dim]);
            F.points.push_back(face->vertex(v));
            F.centroid += face->vertex(v);
          }
        F.centroid /= static_cast<double>(F.points.size());
        if constexpr (dim == 2)
          {
            const auto t = F.points[1] - F.points[0];
            F.normal[0]  = t[1];
            F.normal[1]  = -t[0];
            F.area       = t.norm();
          }
        else
          {
            F.normal = dealii::cross_product_3d(F.points[1] - F.points[0],
                                                F.points[2] - F.points[0]);
            F.area   = 0.5 * F.normal.norm();
          }
        F.normal /= F.normal.norm();
        if ((F.centroid - cell->center()) * F.normal < 0)
          F.normal *= -1.0;
        return F;
      }



      // A face as numbers for the gathering over ranks (the indices of
      // cells and dofs are exact in a double up to 2^53), with a flag for
      // the candidate region: whether inside, the cell's id (its four
      // numbers), face, vertex count,
      // centroid, normal, area, the vertices' points and dofs.
      template <int dim>
      void
      pack(const Face<dim> &F, const bool inside, std::vector<double> &data)
      {
        data.push_back(inside);
        for (const unsigned int i : F.cell.template to_binary<dim>())
          data.push_back(i);
        data.push_back(F.face_no);
        data.push_back(F.points.size());
        for (unsigned int d = 0; d < dim; ++d)
          data.push_back(F.centroid[d]);
        for (unsigned int d = 0; d < dim; ++d)
          data.push_back(F.normal[d]);
        data.push_back(F.area);
        for (const auto &x : F.points)
          for (unsigned int d = 0; d < dim; ++d)
            data.push_back(x[d]);
        for (const auto i : F.dofs)
          data.push_back(static_cast<double>(i));
      }



      template <int dim>
      std::pair<Face<dim>, bool>
      unpack(const std::vector<double> &data, std::size_t &k)
      {
        Face<dim>                   F;
        const bool                  inside = data[k++] != 0;
        dealii::CellId::binary_type cell;
        for (auto &i : cell)
          i = data[k++];
        F.cell               = dealii::CellId(cell);
        F.face_no            = data[k++];
        const unsigned int n = data[k++];
        for (unsigned int d = 0; d < dim; ++d)
          F.centroid[d] = data[k++];
        for (unsigned int d = 0; d < dim; ++d)
          F.normal[d] = data[k++];
        F.area = data[k++];
        F.points.resize(n);
        for (auto &x : F.points)
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = data[k++];
        F.dofs.resize(n * dim);
        for (auto &i : F.dofs)
          i = static_cast<dealii::types::global_dof_index>(data[k++]);
        for (unsigned int v = 0; v < n; ++v)
          F.vertices.push_back(F.dofs[v * dim]);
        return {F, inside};
      }



      // The faces of all ranks, each with its flag, in the order of the
      // cells and of the faces in a cell: the order in which one process
      // visits them.
      template <int dim>
      std::vector<std::pair<Face<dim>, bool>>
      gather(const std::vector<std::pair<Face<dim>, bool>> &own,
             const MPI_Comm                                 communicator)
      {
        std::vector<double> data;
        for (const auto &[F, inside] : own)
          pack(F, inside, data);
        std::vector<std::pair<Face<dim>, bool>> all;
        for (const auto &part :
             dealii::Utilities::MPI::all_gather(communicator, data))
          for (std::size_t k = 0; k < part.size();)
            all.push_back(unpack<dim>(part, k));
        std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
          return std::tie(a.first.cell, a.first.face_no) <
                 std::tie(b.first.cell, b.first.face_no);
        });
        return all;
      }


      // The number of ranks of @p communicator and this one's; a program
      // without MPI (the tutorials) works on one process.
      std::pair<unsigned int, unsigned int>
      ranks(const MPI_Comm communicator)
      {
        if (!dealii::Utilities::MPI::job_supports_mpi())
          return {1, 0};
        return {dealii::Utilities::MPI::n_mpi_processes(communicator),
                dealii::Utilities::MPI::this_mpi_process(communicator)};
      }
    } // namespace



    // The faces of the contact boundary whose centroid lies in the box
    // |x_d - x0_d| <= w of the candidate region (w <= 0: the whole
    // boundary). On several ranks each rank visits the cells of its
    // subdomain.
    template <int dim>
    void
    ContactSurface<dim>::collect_faces(const dealii::DoFHandler<dim> &dofs,
                                       const double                   w,
                                       const MPI_Comm communicator)
    {
      const auto [n_ranks, rank] = ranks(communicator);
      std::vector<std::pair<Face<dim>, bool>> candidates;
      for (const auto &cell : dofs.active_cell_iterators())
        if (n_ranks == 1 || cell->subdomain_id() == rank)
          for (const unsigned int f : cell->face_indices())
            {
              const auto face = cell->face(f);
              if (!face->at_boundary() ||
                  face->boundary_id() != opts.boundary_id)
                continue;
              const Face<dim> F      = make_face<dim>(cell, f);
              bool            inside = true;
              if (w > 0)
                for (unsigned int d = 0; d < dim; ++d)
                  if (std::abs(F.centroid[d] - opts.region_centre[d]) >
                      w * (1 + 1e-12))
                    inside = false;
              candidates.emplace_back(F, inside);
            }
      if (n_ranks > 1)
        candidates = gather(candidates, communicator);

      faces.clear();
      for (const auto &[F, inside] : candidates)
        if (inside)
          faces.push_back(F);
      if (faces.empty())
        throw InputError(opts.body + ": no face of the contact boundary '" +
                         opts.boundary +
                         "' lies in the candidate region (parameters "
                         "Contact / Boundary, Candidate centre, Candidate "
                         "half width)");
    }



    // @sect3{Open edges of the candidate surface}
    //
    // Contact that reaches the edge of the candidate surface may have been
    // cut short by it, but only where the surface of the body goes on
    // towards the obstacle. So a vertex of the candidate surface lies at an
    // open edge if it is a vertex of a boundary face outside the candidate
    // surface (of any boundary: the same one cut by the candidate region,
    // or the next one of the mesh, as the rest of a sphere beyond its
    // contact cap) whose outward normal faces the obstacle, n_F . n >
    // cos 87 deg. A face at a right angle to n ends the body's surface
    // towards the obstacle: the side of a block, a symmetry plane (on which
    // a half model's mean normal leans away, n_F . n < 0). Contact may
    // reach those. Each rank visits the faces of its subdomain; the
    // vertices found are gathered on every rank.
    template <int dim>
    void
    ContactSurface<dim>::find_open_edges(const dealii::DoFHandler<dim> &dofs,
                                         const MPI_Comm communicator)
    {
      const double facing        = std::cos(87.0 / 180.0 * M_PI);
      const auto [n_ranks, rank] = ranks(communicator);

      std::set<std::pair<dealii::CellId, unsigned int>> candidate;
      std::set<dealii::types::global_dof_index>         surface_vertices;
      for (const auto &F : faces)
        {
          candidate.emplace(F.cell, F.face_no);
          surface_vertices.insert(F.vertices.begin(), F.vertices.end());
        }
      std::vector<dealii::types::global_dof_index> open;
      for (const auto &cell : dofs.active_cell_iterators())
        if (n_ranks == 1 || cell->subdomain_id() == rank)
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                candidate.count({cell->id(), f}) == 0)
              {
                const Face<dim> F = make_face<dim>(cell, f);
                if (F.normal * n_surface > facing)
                  for (const auto v : F.vertices)
                    if (surface_vertices.count(v))
                      open.push_back(v);
              }
      open_edge_vertices.clear();
      if (n_ranks > 1)
        for (const auto &part :
             dealii::Utilities::MPI::all_gather(communicator, open))
          open_edge_vertices.insert(part.begin(), part.end());
      else
        open_edge_vertices.insert(open.begin(), open.end());
    }



    template void
    ContactSurface<2>::find_open_edges(const dealii::DoFHandler<2> &,
                                       const MPI_Comm);
    template void
    ContactSurface<3>::find_open_edges(const dealii::DoFHandler<3> &,
                                       const MPI_Comm);
    template void
    ContactSurface<2>::collect_faces(const dealii::DoFHandler<2> &,
                                     const double,
                                     const MPI_Comm);
    template void
    ContactSurface<3>::collect_faces(const dealii::DoFHandler<3> &,
                                     const double,
                                     const MPI_Comm);
  } // namespace contact_surface
} // namespace dpana
