// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The surface of the second body of a pair: the contact elements of the
// first body, and on each the part of the second body's surface that
// projects onto it along its normal (a mortar projection), with the gap
// between the two surfaces.

#include <dpana/base/exceptions.h>
#include <dpana/contact_surface/contact_surface.h>
#include <dpana/contact_surface/format_point.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace dpana
{
  namespace contact_surface
  {
    // @sect3{The projection of the second body onto the first}
    //
    // A mortar projection along the normal n of each contact element, in
    // the coordinates c = (x . tau_1, ..., x . tau_{dim-1}) of its tangent
    // plane. The projection of a face f of the first body (or of the piece
    // of f that the element holds) and that of a face g of the second
    // overlap in a convex set: an interval in 2D, a polygon in 3D (the
    // triangle of g clipped by that of f, cut into a fan of triangles). On each
    // piece both faces are flat, so the shape functions of both bodies and the
    // gap (x_2 - x_1) . n are linear in c there, and the centroid rule with the
    // piece's measure as weight integrates them exactly. The pieces of f add up
    // to the projected measure of f, its weight on the first body's side, so
    // the forces on the two sides balance. Each face of the first body must be
    // covered exactly once: otherwise the first body's candidate surface
    // reaches beyond the second body's, or the second body's surface folds over
    // itself along n. Matching meshes are the special case where every
    // face is covered by one partner.
    namespace
    {
      using PlanePoint = std::array<double, 2>;

      // A piece of the overlap of two projected faces: its measure and its
      // centroid.
      using Piece = std::pair<double, PlanePoint>;

      // Twice the signed area of the plane triangle (a, b, c), positive if
      // it is counter-clockwise.
      double
      cross(const PlanePoint &a, const PlanePoint &b, const PlanePoint &c)
      {
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      }



      // A face in the tangent plane of a contact element: its vertices (in
      // 2D the second coordinate is zero) and its bounding box
      // (c_0 min, c_0 max, c_1 min, c_1 max).
      struct ProjectedFace
      {
        std::vector<PlanePoint> vertices;
        std::array<double, 4>   box;
      };

      template <int dim>
      ProjectedFace
      project(const Face<dim>                                   &F,
              const std::array<dealii::Tensor<1, dim>, dim - 1> &tangents)
      {
        ProjectedFace P;
        P.vertices.assign(F.points.size(), PlanePoint{{0, 0}});
        for (unsigned int v = 0; v < F.points.size(); ++v)
          for (unsigned int k = 0; k < dim - 1; ++k)
            P.vertices[v][k] = F.points[v] * tangents[k];
        const auto &c0 = P.vertices[0];
        P.box          = {{c0[0], c0[0], c0[1], c0[1]}};
        for (const auto &c : P.vertices)
          P.box = {{std::min(P.box[0], c[0]),
                    std::max(P.box[1], c[0]),
                    std::min(P.box[2], c[1]),
                    std::max(P.box[3], c[1])}};
        return P;
      }



      // False if the bounding boxes of two projected faces are disjoint (or
      // only touch), so that the faces cannot overlap.
      template <int dim>
      bool
      boxes_overlap(const ProjectedFace &P, const ProjectedFace &Q)
      {
        const auto &a = Q.box, &b = P.box;
        return !(a[0] >= b[1] || a[1] <= b[0] ||
                 (dim == 3 && (a[2] >= b[3] || a[3] <= b[2])));
      }



      // The measure of a projected face: a length in 2D, an area in 3D.
      template <int dim>
      double
      measure(const ProjectedFace &P)
      {
        const auto &c = P.vertices;
        return dim == 2 ? std::abs(c[1][0] - c[0][0]) :
                          0.5 * std::abs(cross(c[0], c[1], c[2]));
      }



      // The barycentric coordinates of the plane point c in the projected
      // face P.
      template <int dim>
      std::array<double, dim>
      barycentric(const ProjectedFace &P, const PlanePoint &c)
      {
        const auto             &Pv = P.vertices;
        std::array<double, dim> lambda;
        if constexpr (dim == 2)
          {
            lambda[1] = (c[0] - Pv[0][0]) / (Pv[1][0] - Pv[0][0]);
            lambda[0] = 1 - lambda[1];
          }
        else
          {
            const double det = cross(Pv[0], Pv[1], Pv[2]);
            lambda[1]        = cross(Pv[0], c, Pv[2]) / det;
            lambda[2]        = cross(Pv[0], Pv[1], c) / det;
            lambda[0]        = 1 - lambda[1] - lambda[2];
          }
        return lambda;
      }



      // The barycentric coordinates of c in the projected face P of F, and
      // the point of F there.
      template <int dim>
      std::pair<std::array<double, dim>, dealii::Point<dim>>
      point_on_face(const Face<dim>     &F,
                    const ProjectedFace &P,
                    const PlanePoint    &c)
      {
        const auto lambda = barycentric<dim>(P, c);
        return std::make_pair(lambda, FacePiece<dim>::point(F, lambda));
      }



      // 2D: the overlap of two intervals of the tangent line, one piece or
      // none.
      std::vector<Piece>
      interval_overlap(const ProjectedFace &P, const ProjectedFace &Q)
      {
        const auto        &p = P.vertices, &q = Q.vertices;
        std::vector<Piece> pieces;
        const double       lo =
          std::max(std::min(p[0][0], p[1][0]), std::min(q[0][0], q[1][0]));
        const double hi =
          std::min(std::max(p[0][0], p[1][0]), std::max(q[0][0], q[1][0]));
        if (hi > lo)
          pieces.push_back({hi - lo, PlanePoint{{0.5 * (lo + hi), 0}}});
        return pieces;
      }



      // Sutherland-Hodgman: the part of the convex polygon @p subject
      // inside the counter-clockwise triangle @p clip.
      std::vector<PlanePoint>
      clip_by_triangle(std::vector<PlanePoint>          subject,
                       const std::array<PlanePoint, 3> &clip)
      {
        for (unsigned int k = 0; k < 3 && !subject.empty(); ++k)
          {
            const auto             &A = clip[k], &B = clip[(k + 1) % 3];
            std::vector<PlanePoint> kept;
            for (unsigned int i = 0; i < subject.size(); ++i)
              {
                const auto  &P  = subject[i];
                const auto  &Q  = subject[(i + 1) % subject.size()];
                const double dP = cross(A, B, P), dQ = cross(A, B, Q);
                if (dP >= 0)
                  kept.push_back(P);
                if ((dP >= 0) != (dQ >= 0))
                  {
                    const double t = dP / (dP - dQ);
                    kept.push_back(
                      {{P[0] + t * (Q[0] - P[0]), P[1] + t * (Q[1] - P[1])}});
                  }
              }
            subject = kept;
          }
        return subject;
      }



      // 3D: the overlap of two triangles of the tangent plane, the triangle
      // of Q clipped by that of P (both turned counter-clockwise), cut into
      // a fan of triangles.
      std::vector<Piece>
      triangle_overlap(const ProjectedFace &P, const ProjectedFace &Q)
      {
        const auto               &p    = P.vertices;
        std::array<PlanePoint, 3> clip = {{p[0], p[1], p[2]}};
        if (cross(p[0], p[1], p[2]) < 0)
          std::swap(clip[1], clip[2]);
        std::vector<PlanePoint> subject(Q.vertices.begin(), Q.vertices.end());
        if (cross(subject[0], subject[1], subject[2]) < 0)
          std::swap(subject[1], subject[2]);
        const auto         poly = clip_by_triangle(subject, clip);
        std::vector<Piece> pieces;
        for (unsigned int i = 1; i + 1 < poly.size(); ++i)
          {
            const double a = 0.5 * cross(poly[0], poly[i], poly[i + 1]);
            if (a > 0)
              pieces.push_back(
                {a,
                 PlanePoint{{(poly[0][0] + poly[i][0] + poly[i + 1][0]) / 3,
                             (poly[0][1] + poly[i][1] + poly[i + 1][1]) / 3}}});
          }
        return pieces;
      }



      // The quadrature points of the second body's side of element @p e
      // on the overlaps of the first body's face F1 (projected P1, measure
      // m1) with the second body's faces (projected Q), and their part of
      // the gap integral (x_2 - x_1) . n. Pieces below 1e-12 m1 (round-off
      // at shared edges) are dropped. Returns the measure of F1 covered.
      template <int dim>
      double
      add_overlaps(const Face<dim>                  &F1,
                   const ProjectedFace              &P1,
                   const double                      m1,
                   const dealii::Tensor<1, dim>     &n,
                   const std::vector<Face<dim>>     &faces,
                   const std::vector<ProjectedFace> &Q,
                   ContactElement<dim>              &e)
      {
        double covered = 0;
        for (unsigned int g = 0; g < faces.size(); ++g)
          {
            if (!boxes_overlap<dim>(P1, Q[g]))
              continue;
            const auto pieces = dim == 2 ? interval_overlap(P1, Q[g]) :
                                           triangle_overlap(P1, Q[g]);
            for (const auto &[w, c] : pieces)
              {
                if (!(w > 1e-12 * m1))
                  continue;
                SurfacePoint<dim> p;
                p.face                       = g;
                std::tie(p.barycentric, p.x) = point_on_face(faces[g], Q[g], c);
                p.weight                     = w;
                e.points.push_back(p);
                if (std::find(e.faces.begin(), e.faces.end(), g) ==
                    e.faces.end())
                  e.faces.push_back(g);
                e.gap_integral +=
                  w * ((p.x - point_on_face(F1, P1, c).second) * n);
                covered += w;
              }
          }
        return covered;
      }



      // Whether the projected face P holds the point c (its interval in 2D,
      // its triangle in 3D, to round-off).
      template <int dim>
      bool
      holds(const ProjectedFace &P, const PlanePoint &c)
      {
        const auto lambda = barycentric<dim>(P, c);
        return *std::min_element(lambda.begin(), lambda.end()) >= -1e-9;
      }



      // An open edge of the first body's candidate surface matters only if
      // the second body's surface goes on beyond it: where the second body's
      // contact boundary ends at that edge (a block on a foundation that is
      // Body 1, whose candidate region the block's width bounds), the contact
      // zone cannot grow past it, and enlarging the first body's region
      // would leave faces without a partner. An open vertex of element e is
      // kept if the point half-way beyond it, on the line from the element's
      // centroid through the vertex in the tangent plane, lies on the
      // projection Q of a face of the second body.
      template <int dim>
      void
      keep_edges_with_surface_beyond(ContactElement<dim>              &e,
                                     const std::vector<ProjectedFace> &Q)
      {
        const auto in_plane = [&](const dealii::Point<dim> &x) {
          PlanePoint c{{0, 0}};
          for (unsigned int k = 0; k < dim - 1; ++k)
            c[k] = x * e.tangents[k];
          return c;
        };
        const PlanePoint                centre = in_plane(e.centroid);
        std::vector<dealii::Point<dim>> kept;
        for (const auto &x : e.open_edge_points)
          {
            const PlanePoint v = in_plane(x);
            const PlanePoint beyond{
              {1.5 * v[0] - 0.5 * centre[0], 1.5 * v[1] - 0.5 * centre[1]}};
            if (std::any_of(Q.begin(), Q.end(), [&](const ProjectedFace &P) {
                  return holds<dim>(P, beyond);
                }))
              kept.push_back(x);
          }
        e.open_edge_points = kept;
      }



      // Keep only the faces that some element uses, renumbered in the order
      // of their first use.
      template <int dim>
      void
      keep_used_faces(std::vector<Face<dim>>           &faces,
                      std::vector<ContactElement<dim>> &elements)
      {
        std::vector<unsigned int> index(faces.size(),
                                        dealii::numbers::invalid_unsigned_int);
        std::vector<Face<dim>>    used;
        for (auto &e : elements)
          {
            for (auto &p : e.points)
              {
                if (index[p.face] == dealii::numbers::invalid_unsigned_int)
                  {
                    index[p.face] = used.size();
                    used.push_back(faces[p.face]);
                  }
                p.face = index[p.face];
              }
            for (auto &f : e.faces)
              f = index[f];
          }
        faces = used;
      }
    } // namespace



    template <int dim>
    void
    ContactSurface<dim>::pair_projected(ContactSurface<dim> &first)
    {
      for (unsigned int j = 0; j < elements.size(); ++j)
        {
          auto       &e  = elements[j];
          const auto &e1 = first.elements[j];

          std::vector<ProjectedFace> Q;
          for (const auto &F : faces)
            Q.push_back(project(F, e1.tangents));
          keep_edges_with_surface_beyond(first.elements[j], Q);

          e.gap_integral = 0;
          for (const auto &piece : e1.pieces)
            {
              const Face<dim>     F1 = piece.as_face(first.faces[piece.face]);
              const ProjectedFace P1 = project(F1, e1.tangents);
              const double        m1 = measure<dim>(P1);
              const double        covered =
                add_overlaps(F1, P1, m1, e1.normal, faces, Q, e);
              if (std::abs(covered - m1) > 1e-9 * m1)
                throw InputError(
                  std::string("Contact: the ") +
                  (piece.fraction() < 1 ? "piece of face" : "face") + " of " +
                  first.opts.body + " at " +
                  internal::format_point(F1.centroid) + " is " +
                  (covered < m1 ? "not covered by" :
                                  "covered more than once by") +
                  " the projection of '" + opts.boundary + "' of " + opts.body +
                  " along the contact direction (enlarge the boundary of " +
                  opts.body + " or reduce Contact / Candidate half width)");
            }
        }
    }



    // @sect3{Two bodies}
    //
    // The traction N n + T tau on the first body is -(N n + T tau) on the
    // second: the second body's elements are the first's groups with the
    // frame negated, and the relative normal displacement (u_1 - u_2) . n is
    // the sum of the normal displacements of both bodies, each along its own
    // normal. Only the faces of the second body that face the first take
    // part (n_F . n < 0): the far side of a cavity projects onto the same
    // tangential positions but is not in contact.
    template <int dim>
    void
    ContactSurface<dim>::pair(const dealii::DoFHandler<dim> &dofs,
                              const Options                 &options,
                              ContactSurface<dim>           &first,
                              const MPI_Comm                 communicator)
    {
      // Every face of the boundary is a candidate (the faces that straddle
      // the edge of the candidate region are needed to cover the first
      // body's faces there); the candidate region acts on the first body.
      opts = options;
      collect_faces(dofs, 0, communicator);
      {
        std::vector<Face<dim>> facing;
        for (const auto &F : faces)
          if (F.normal * first.n_surface < -1e-3)
            facing.push_back(F);
        faces = facing;
      }
      if (faces.empty())
        throw InputError(opts.body + ": no face of the contact boundary '" +
                         opts.boundary + "' faces " + first.opts.body +
                         " along the contact direction (parameters Contact / "
                         "Boundary 2, Contact direction)");
      n_surface   = -first.n_surface;
      tau_surface = first.tau_surface;
      for (auto &t : tau_surface)
        t *= -1.0;

      elements = first.elements;
      for (unsigned int j = 0; j < elements.size(); ++j)
        {
          auto &e  = elements[j];
          e.normal = -first.elements[j].normal;
          for (unsigned int k = 0; k < dim - 1; ++k)
            e.tangents[k] = -first.elements[j].tangents[k];
          e.faces.clear();
          e.pieces.clear();
          e.points.clear();
        }
      pair_projected(first);
      keep_used_faces(faces, elements);

      // Centroids of this side, and the gap of the first body: the integral
      // over the element of the distance along n from its surface to this
      // one, g = (x_2 - x_1) . n (pair_projected() stored it in gap_integral).
      // The open edges are the first body's (its candidate region decides),
      // as pair_projected() kept them.
      for (unsigned int j = 0; j < elements.size(); ++j)
        {
          auto &e            = elements[j];
          e.open_edge_points = first.elements[j].open_edge_points;
          e.centroid         = dealii::Point<dim>();
          double w           = 0;
          for (const auto &p : e.points)
            {
              e.centroid += p.weight * p.x;
              w += p.weight;
            }
          e.centroid /= w;
          first.elements[j].gap_integral = e.gap_integral;
        }
    }



    template void
    ContactSurface<2>::pair(const dealii::DoFHandler<2> &,
                            const Options &,
                            ContactSurface<2> &,
                            const MPI_Comm);
    template void
    ContactSurface<3>::pair(const dealii::DoFHandler<3> &,
                            const Options &,
                            ContactSurface<3> &,
                            const MPI_Comm);
  } // namespace contact_surface
} // namespace dpana
