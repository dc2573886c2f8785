// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The candidate contact surface of one body: its faces, the frames of its
// contact elements and their quadrature points, and the gap to a rigid
// plane. The collection of the candidate faces is in candidate_faces.cc,
// the grouping of the faces in face_grouping.cc, the pairing with a second
// body in mortar_pairing.cc.

#include <dpana/base/exceptions.h>
#include <dpana/contact_surface/contact_surface.h>
#include <dpana/contact_surface/format_point.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <sstream>

namespace dpana
{
  namespace contact_surface
  {
    // @sect3{The tangential frame}
    //
    // In 2D tau is n turned by +90 degrees, so that (n, tau) is right-handed:
    // for the downward normal n = (0, -1) of a base, tau = (1, 0). In 3D tau_1
    // is the projection of e_x on the tangent plane (of e_y if n is nearly
    // parallel to e_x) and tau_2 = n x tau_1.
    template <int dim>
    std::array<dealii::Tensor<1, dim>, dim - 1>
    ContactSurface<dim>::tangential_frame(const dealii::Tensor<1, dim> &n)
    {
      std::array<dealii::Tensor<1, dim>, dim - 1> tau;
      if constexpr (dim == 2)
        {
          tau[0][0] = -n[1];
          tau[0][1] = n[0];
        }
      else
        {
          dealii::Tensor<1, dim> e;
          e[std::abs(n[0]) > 0.9 ? 1 : 0] = 1.0;
          tau[0]                          = e - (e * n) * n;
          tau[0] /= tau[0].norm();
          tau[1] = dealii::cross_product_3d(n, tau[0]);
        }
      return tau;
    }



    // @sect3{Pieces of faces}
    //
    // The rows of the corner matrix sum to one, so its determinant is the
    // ratio of the piece's area to the face's.
    template <int dim>
    double
    FacePiece<dim>::fraction() const
    {
      const auto &c = corners;
      if constexpr (dim == 2)
        return std::abs(c[0][0] * c[1][1] - c[0][1] * c[1][0]);
      else
        return std::abs(c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) -
                        c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0]) +
                        c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0]));
    }



    template <int dim>
    dealii::Point<dim>
    FacePiece<dim>::point(const Face<dim>               &F,
                          const std::array<double, dim> &lambda)
    {
      dealii::Point<dim> x;
      for (unsigned int v = 0; v < dim; ++v)
        x += lambda[v] * F.points[v];
      return x;
    }



    template <int dim>
    std::array<dealii::Point<dim>, dim>
    FacePiece<dim>::corner_points(const Face<dim> &F) const
    {
      std::array<dealii::Point<dim>, dim> x;
      for (unsigned int k = 0; k < dim; ++k)
        x[k] = point(F, corners[k]);
      return x;
    }



    template <int dim>
    std::array<double, dim>
    FacePiece<dim>::centroid() const
    {
      std::array<double, dim> lambda{};
      for (unsigned int k = 0; k < dim; ++k)
        for (unsigned int v = 0; v < dim; ++v)
          lambda[v] += corners[k][v] / dim;
      return lambda;
    }



    template <int dim>
    Face<dim>
    FacePiece<dim>::as_face(const Face<dim> &F) const
    {
      Face<dim>  P       = F;
      const auto corners = corner_points(F);
      P.points.assign(corners.begin(), corners.end());
      P.centroid = point(F, centroid());
      P.area     = fraction() * F.area;
      return P;
    }



    template <int dim>
    void
    ContactSurface<dim>::build(const dealii::DoFHandler<dim> &dofs,
                               const Options                 &options,
                               const MPI_Comm                 communicator)
    {
      opts = options;
      collect_faces(dofs, opts.region_half_width, communicator);

      // The surface normal: the given contact direction, or the
      // area-weighted mean of the outward normals of the faces.
      if (opts.direction.norm() > 0)
        n_surface = opts.direction / opts.direction.norm();
      else
        {
          n_surface = 0;
          for (const auto &F : faces)
            n_surface += F.area * F.normal;
          if (!(n_surface.norm() > 0))
            throw InputError(opts.body + ": the candidate faces of '" +
                             opts.boundary +
                             "' have no mean normal; give the parameter "
                             "Contact / Contact direction");
          n_surface /= n_surface.norm();
        }
      // A direction that looks away from the candidate faces as a whole,
      // none of them facing it, is the direction's fault; if some face it,
      // the candidate region's (the whole half circle of a half disc has
      // the mean normal e_x, at a right angle to the direction 0, -1).
      dealii::Tensor<1, dim> mean_normal;
      bool                   some_facing = false;
      for (const auto &F : faces)
        {
          mean_normal += F.area * F.normal;
          some_facing = some_facing || F.normal * n_surface > 1e-3;
        }
      if (opts.direction.norm() > 0 && mean_normal.norm() > 0 &&
          mean_normal * n_surface <= 0 && !some_facing)
        throw InputError(
          "Contact / Contact direction " +
          internal::format_point(dealii::Point<dim>(opts.direction)) +
          " points away from the boundary '" + opts.boundary + "' of " +
          opts.body + " (its mean outward normal is " +
          internal::format_point(
            dealii::Point<dim>(mean_normal / mean_normal.norm())) +
          "): it must point from " + opts.body + " towards the obstacle");
      for (const auto &F : faces)
        if (F.normal * n_surface <= 1e-3)
          throw InputError(
            opts.body + ": the candidate face at " +
            internal::format_point(F.centroid) + " of '" + opts.boundary +
            "' faces away from the contact direction; reduce the candidate "
            "region (parameter Contact / Candidate half width)");
      tau_surface = tangential_frame(n_surface);
      find_open_edges(dofs, communicator);
      if (opts.shape == ElementShape::vertex_patches)
        group_around_vertices();
      else
        group_faces();
      finish_elements();
    }



    // Frame, projected area, quadrature points, centroid and tangential
    // extents of every element. The frame comes first: the weight of a piece
    // of face is its area projected on the plane normal to n,
    // |piece| (n_F . n). Groups of faces get one piece per face; patches
    // around vertices made their pieces already.
    template <int dim>
    void
    ContactSurface<dim>::finish_elements()
    {
      for (auto &e : elements)
        {
          if (e.pieces.empty())
            for (const unsigned int f : e.faces)
              {
                FacePiece<dim> whole{f, {}};
                for (unsigned int v = 0; v < dim; ++v)
                  whole.corners[v][v] = 1;
                e.pieces.push_back(whole);
              }
          dealii::Tensor<1, dim> n;
          for (const auto &piece : e.pieces)
            n += piece.fraction() * faces[piece.face].area *
                 faces[piece.face].normal;
          e.normal   = (opts.direction.norm() > 0 || opts.rigid_plane) ?
                         n_surface :
                         n / n.norm();
          e.tangents = tangential_frame(e.normal);

          e.area     = 0;
          e.centroid = dealii::Point<dim>();
          e.points.clear();
          e.s_min = e.t_min = std::numeric_limits<double>::max();
          e.s_max = e.t_max = -std::numeric_limits<double>::max();
          e.open_edge_points.clear();
          for (const auto &piece : e.pieces)
            {
              const auto  &F = faces[piece.face];
              const double c = F.normal * e.normal;
              if (!(c > 1e-3))
                throw InputError(
                  opts.body + ": the candidate face at " +
                  internal::format_point(F.centroid) + " of '" + opts.boundary +
                  "' is nearly parallel to the normal of its contact "
                  "element; use " +
                  (opts.shape == ElementShape::vertex_patches ?
                     std::string() :
                     "smaller contact elements (parameter Contact / Faces per "
                     "contact element) or ") +
                  "a smaller candidate region");
              SurfacePoint<dim> p;
              p.face        = piece.face;
              p.barycentric = piece.centroid();
              p.x           = FacePiece<dim>::point(F, p.barycentric);
              p.weight      = piece.fraction() * F.area * c;
              e.points.push_back(p);
              e.area += p.weight;
              e.centroid += p.weight * p.x;
              for (const auto &x : piece.corner_points(F))
                {
                  e.s_min = std::min(e.s_min, x * tau_surface[0]);
                  e.s_max = std::max(e.s_max, x * tau_surface[0]);
                  e.t_min = std::min(e.t_min, x * tau_surface[dim - 2]);
                  e.t_max = std::max(e.t_max, x * tau_surface[dim - 2]);
                }
              // The corners at vertices of the face: is one of them at an
              // open edge of the candidate surface?
              for (const auto &lambda : piece.corners)
                for (unsigned int v = 0; v < dim; ++v)
                  if (lambda[v] == 1 &&
                      open_edge_vertices.count(F.vertices[v]) &&
                      std::find(e.open_edge_points.begin(),
                                e.open_edge_points.end(),
                                F.points[v]) == e.open_edge_points.end())
                    e.open_edge_points.push_back(F.points[v]);
            }
          e.centroid /= e.area;
          e.s = e.centroid * tau_surface[0];
          e.t = dim == 3 ? e.centroid * tau_surface[dim - 2] : 0.0;
          if (dim == 2)
            e.t_min = e.t_max = 0;
          e.gap_integral = 0;
        }
    }



    // @sect3{The gap to a rigid plane}
    //
    // The obstacle is the plane through @p point normal to the surface
    // normal: every element of a surface on the rigid plane has that normal
    // (the contact direction, or without one the mean outward normal of the
    // candidate faces, Options::rigid_plane). With each element's own
    // normal the "plane" would be the one through the point normal to that
    // element, a different one per element: on a full disc without a
    // direction every gap but the lowest came out negative. The gap is
    // linear on each face, so the rule of the element (one point at the
    // centroid of each piece of face) integrates it exactly.
    template <int dim>
    void
    ContactSurface<dim>::set_plane_gap(const dealii::Point<dim> &point)
    {
      for (auto &e : elements)
        {
          AssertThrow((e.normal - n_surface).norm() < 1e-12,
                      dealii::ExcMessage("An element of a surface on the "
                                         "rigid plane without the plane's "
                                         "normal (Options::rigid_plane)."));
          e.gap_integral = 0;
          for (const auto &p : e.points)
            e.gap_integral += p.weight * ((point - p.x) * e.normal);
        }
    }



    template <int dim>
    dealii::Point<dim>
    ContactSurface<dim>::first_contact_point() const
    {
      dealii::Point<dim> best = faces[0].points[0];
      for (const auto &F : faces)
        for (const auto &x : F.points)
          if (x * n_surface > best * n_surface)
            best = x;
      return best;
    }



    template <int dim>
    std::vector<unsigned int>
    ContactSurface<dim>::sorted_elements() const
    {
      std::vector<unsigned int> order(elements.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(),
                order.end(),
                [&](const unsigned int a, const unsigned int b) {
                  if (std::abs(elements[a].s - elements[b].s) >
                      1e-10 * (std::abs(elements[a].s) + 1))
                    return elements[a].s < elements[b].s;
                  return elements[a].t < elements[b].t;
                });
      return order;
    }



    template <int dim>
    std::string
    ContactSurface<dim>::description() const
    {
      std::ostringstream s;
      double smin = std::numeric_limits<double>::max(), smax = -smin;
      for (const auto &e : elements)
        {
          smin = std::min(smin, e.s_min);
          smax = std::max(smax, e.s_max);
        }
      s << faces.size() << " faces of '" << opts.boundary << "' of "
        << opts.body << " in " << elements.size() << " contact elements, s in ["
        << smin << ", " << smax << "]";
      return s.str();
    }



    template <int dim>
    unsigned int
    ContactSurface<dim>::n_vertices() const
    {
      std::set<unsigned int> vertices;
      for (const auto &f : faces)
        vertices.insert(f.vertices.begin(), f.vertices.end());
      return vertices.size();
    }



    template struct FacePiece<2>;
    template struct FacePiece<3>;
    template class ContactSurface<2>;
    template class ContactSurface<3>;
  } // namespace contact_surface
} // namespace dpana
