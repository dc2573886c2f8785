// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_contact_surface_contact_surface_templates_h
#define dpana_contact_surface_contact_surface_templates_h

#include <dpana/base/exceptions.h>
#include <dpana/contact_surface/contact_surface.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <tuple>

namespace dpana
{
  namespace contact_surface
  {
    namespace internal
    {
      inline std::string
      format_point(const double *x, const unsigned int n)
      {
        std::ostringstream s;
        s.precision(6);
        s << "(";
        for (unsigned int d = 0; d < n; ++d)
          s << (d ? ", " : "") << x[d];
        s << ")";
        return s.str();
      }

      template <int dim>
      std::string
      format_point(const dealii::Point<dim> &p)
      {
        double x[dim];
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = p[d];
        return format_point(x, dim);
      }
    } // namespace internal



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



    // @sect3{Candidate faces}
    //
    // A face of a P1 simplex mesh is flat: its area, centroid and normal
    // follow from its vertices. The normal is turned outwards by comparing
    // with the centre of the cell. Faces whose centroid lies outside the
    // candidate region of half width w (w <= 0: no region) are left out.
    template <int dim>
    void
    ContactSurface<dim>::collect_faces(const dealii::Triangulation<dim> &tria,
                                       const double                      w)
    {
      faces.clear();
      excluded_vertices.clear();
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() || face->boundary_id() != opts.boundary_id)
              continue;
            Face<dim> F;
            F.cell    = cell;
            F.face_no = f;
            for (const unsigned int v : face->vertex_indices())
              {
                F.vertices.push_back(face->vertex_index(v));
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

            bool inside = true;
            if (w > 0)
              for (unsigned int d = 0; d < dim; ++d)
                if (std::abs(F.centroid[d] - opts.region_centre[d]) >
                    w * (1 + 1e-12))
                  inside = false;
            if (inside)
              faces.push_back(F);
            else
              excluded_vertices.insert(F.vertices.begin(), F.vertices.end());
          }
      if (faces.empty())
        throw InputError(opts.body + ": no face of the contact boundary '" +
                         opts.boundary +
                         "' lies in the candidate region (parameters "
                         "Contact / Boundary, Candidate centre, Candidate "
                         "half width)");
    }



    template <int dim>
    void
    ContactSurface<dim>::build(const dealii::Triangulation<dim> &tria,
                               const Options                    &options)
    {
      opts = options;
      collect_faces(tria, opts.region_half_width);

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
      for (const auto &F : faces)
        if (F.normal * n_surface <= 1e-3)
          throw InputError(
            opts.body + ": the candidate face at " +
            internal::format_point(F.centroid) + " of '" + opts.boundary +
            "' faces away from the contact direction; reduce the candidate "
            "region (parameter Contact / Candidate half width)");
      tau_surface = tangential_frame(n_surface);
      group_faces();
      finish_elements();
    }



    // @sect3{Grouping faces into contact elements}
    template <int dim>
    void
    ContactSurface<dim>::group_faces()
    {
      unsigned int size = opts.faces_per_element;
      if (size == 0)
        size = (dim == 2 ? 2 : 8);
      elements.clear();

      if constexpr (dim == 2)
        {
          // Sort the edges along tau and cut the chain into runs of `size`
          // adjacent edges. A run also ends where two consecutive edges do
          // not share a vertex (a gap in the candidate surface).
          std::vector<unsigned int> order(faces.size());
          std::iota(order.begin(), order.end(), 0);
          std::sort(order.begin(),
                    order.end(),
                    [&](const unsigned int a, const unsigned int b) {
                      return faces[a].centroid * tau_surface[0] <
                             faces[b].centroid * tau_surface[0];
                    });
          for (unsigned int k = 0; k < order.size(); ++k)
            {
              const auto &F        = faces[order[k]];
              bool        adjacent = false;
              if (!elements.empty())
                {
                  const auto &G = faces[elements.back().faces.back()];
                  for (const unsigned int v : F.vertices)
                    for (const unsigned int u : G.vertices)
                      adjacent = adjacent || (u == v);
                }
              if (elements.empty() || !adjacent ||
                  elements.back().faces.size() == size)
                elements.emplace_back();
              elements.back().faces.push_back(order[k]);
            }
        }
      else
        {
          const unsigned int q =
            static_cast<unsigned int>(std::lround(std::sqrt(size / 2.0)));
          if (!(2 * q * q == size && group_on_lattice(q)))
            group_greedy(size);
        }
    }



    // A structured surface: every vertex lies on one of the lines
    // s = s_i, t = t_j of a tangential lattice, every face lies inside one
    // lattice cell and every cell holds exactly two faces (a quadrilateral
    // split in two triangles). Then q x q cells form one contact element.
    template <int dim>
    bool
    ContactSurface<dim>::group_on_lattice(const unsigned int q)
    {
      double diameter = 0;
      for (const auto &F : faces)
        diameter = std::max(diameter, F.centroid.distance(faces[0].centroid));
      const double        tol = 1e-8 * std::max(diameter, 1e-300);
      std::vector<double> s_lines, t_lines;
      for (const auto &F : faces)
        for (const auto &x : F.points)
          {
            s_lines.push_back(x * tau_surface[0]);
            t_lines.push_back(x * tau_surface[dim - 2]);
          }
      const auto unique = [tol](std::vector<double> &v) {
        std::sort(v.begin(), v.end());
        std::vector<double> u;
        for (const double x : v)
          if (u.empty() || x > u.back() + tol)
            u.push_back(x);
        v = u;
      };
      unique(s_lines);
      unique(t_lines);
      const auto cell_of = [tol](const std::vector<double> &lines,
                                 const double               x) -> int {
        return static_cast<int>(
                 std::upper_bound(lines.begin(), lines.end(), x + tol) -
                 lines.begin()) -
               1;
      };

      std::map<std::pair<int, int>, std::vector<unsigned int>> cells;
      for (unsigned int f = 0; f < faces.size(); ++f)
        {
          const auto &F = faces[f];
          const int   i = cell_of(s_lines, F.centroid * tau_surface[0]);
          const int   j = cell_of(t_lines, F.centroid * tau_surface[dim - 2]);
          if (i < 0 || j < 0 || i + 1 >= static_cast<int>(s_lines.size()) ||
              j + 1 >= static_cast<int>(t_lines.size()))
            return false;
          for (const auto &x : F.points)
            {
              const double s = x * tau_surface[0], t = x * tau_surface[dim - 2];
              if (!(std::abs(s - s_lines[i]) < tol ||
                    std::abs(s - s_lines[i + 1]) < tol) ||
                  !(std::abs(t - t_lines[j]) < tol ||
                    std::abs(t - t_lines[j + 1]) < tol))
                return false;
            }
          cells[{i, j}].push_back(f);
        }
      for (const auto &c : cells)
        if (c.second.size() != 2)
          return false;

      std::map<std::pair<int, int>, unsigned int> group;
      for (const auto &[ij, fs] : cells)
        {
          const std::pair<int, int> key(ij.first / q, ij.second / q);
          if (group.count(key) == 0)
            {
              group[key] = elements.size();
              elements.emplace_back();
            }
          for (const unsigned int f : fs)
            elements[group[key]].faces.push_back(f);
        }
      return true;
    }



    // Unstructured surfaces: each group grows from the first free face in
    // the order of the tangential coordinates, by the free face sharing an
    // edge with the group whose centroid is nearest to the group's centroid.
    template <int dim>
    void
    ContactSurface<dim>::group_greedy(const unsigned int size)
    {
      std::map<unsigned int, std::vector<unsigned int>> faces_of_vertex;
      for (unsigned int f = 0; f < faces.size(); ++f)
        for (const unsigned int v : faces[f].vertices)
          faces_of_vertex[v].push_back(f);
      const auto adjacent = [&](const unsigned int a, const unsigned int b) {
        unsigned int shared = 0;
        for (const unsigned int u : faces[a].vertices)
          for (const unsigned int v : faces[b].vertices)
            shared += (u == v);
        return shared >= dim - 1;
      };

      std::vector<unsigned int> order(faces.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(),
                order.end(),
                [&](const unsigned int a, const unsigned int b) {
                  const double sa = faces[a].centroid * tau_surface[0],
                               sb = faces[b].centroid * tau_surface[0];
                  if (std::abs(sa - sb) > 1e-10 * (std::abs(sa) + 1))
                    return sa < sb;
                  return faces[a].centroid * tau_surface[dim - 2] <
                         faces[b].centroid * tau_surface[dim - 2];
                });
      std::vector<bool> taken(faces.size(), false);
      for (const unsigned int seed : order)
        {
          if (taken[seed])
            continue;
          std::vector<unsigned int> group(1, seed);
          taken[seed] = true;
          while (group.size() < size)
            {
              dealii::Point<dim> c;
              double             area = 0;
              for (const unsigned int f : group)
                {
                  c += faces[f].area * faces[f].centroid;
                  area += faces[f].area;
                }
              c /= area;
              unsigned int best = dealii::numbers::invalid_unsigned_int;
              double       dist = std::numeric_limits<double>::max();
              for (const unsigned int f : group)
                for (const unsigned int v : faces[f].vertices)
                  for (const unsigned int g : faces_of_vertex[v])
                    if (!taken[g] && adjacent(f, g) &&
                        faces[g].centroid.distance(c) < dist)
                      {
                        best = g;
                        dist = faces[g].centroid.distance(c);
                      }
              if (best == dealii::numbers::invalid_unsigned_int)
                break;
              group.push_back(best);
              taken[best] = true;
            }
          elements.emplace_back();
          elements.back().faces = group;
        }
    }



    // Frame, projected area, quadrature points, centroid and tangential
    // extents of every element. The frame comes first: the weight of a face
    // is its area projected on the plane normal to n, |F| (n_F . n).
    template <int dim>
    void
    ContactSurface<dim>::finish_elements()
    {
      for (auto &e : elements)
        {
          dealii::Tensor<1, dim> n;
          for (const unsigned int f : e.faces)
            n += faces[f].area * faces[f].normal;
          e.normal   = opts.direction.norm() > 0 ? n_surface : n / n.norm();
          e.tangents = tangential_frame(e.normal);

          e.area     = 0;
          e.centroid = dealii::Point<dim>();
          e.points.clear();
          e.s_min = e.t_min = std::numeric_limits<double>::max();
          e.s_max = e.t_max = -std::numeric_limits<double>::max();
          e.at_open_edge    = false;
          for (const unsigned int f : e.faces)
            {
              const auto  &F = faces[f];
              const double c = F.normal * e.normal;
              if (!(c > 1e-3))
                throw InputError(
                  opts.body + ": the candidate face at " +
                  internal::format_point(F.centroid) + " of '" + opts.boundary +
                  "' is nearly parallel to the normal of its contact "
                  "element; use smaller contact elements (parameter "
                  "Contact / Faces per contact element) or a smaller candidate "
                  "region");
              SurfacePoint<dim> p;
              p.face = f;
              p.barycentric.fill(1.0 / dim);
              p.x      = F.centroid;
              p.weight = F.area * c;
              e.points.push_back(p);
              e.area += p.weight;
              e.centroid += p.weight * F.centroid;
              for (const auto &x : F.points)
                {
                  e.s_min = std::min(e.s_min, x * tau_surface[0]);
                  e.s_max = std::max(e.s_max, x * tau_surface[0]);
                  e.t_min = std::min(e.t_min, x * tau_surface[dim - 2]);
                  e.t_max = std::max(e.t_max, x * tau_surface[dim - 2]);
                }
              for (const unsigned int v : F.vertices)
                if (excluded_vertices.count(v))
                  e.at_open_edge = true;
            }
          e.centroid /= e.area;
          e.s = e.centroid * tau_surface[0];
          e.t = dim == 3 ? e.centroid * tau_surface[dim - 2] : 0.0;
          if (dim == 2)
            e.t_min = e.t_max = 0;
          e.gap_integral = 0;
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
    ContactSurface<dim>::pair(const dealii::Triangulation<dim> &tria,
                              const Options                    &options,
                              ContactSurface<dim>              &first)
    {
      // Every face of the boundary is a candidate (the faces that straddle
      // the edge of the candidate region are needed to cover the first
      // body's faces there); the candidate region acts on the first body.
      opts = options;
      collect_faces(tria, 0);
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
          e.points.clear();
          e.at_open_edge = first.elements[j].at_open_edge;
        }
      pair_projected(first);

      // Keep only the faces that some element uses, renumbered.
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

      // Centroids of this side, and the gap of the first body: the integral
      // over the element of the distance along n from its surface to this
      // one, g = (x_2 - x_1) . n (pair_projected() stored it in gap_integral).
      // The open-edge flag is the first body's: its candidate region decides.
      for (unsigned int j = 0; j < elements.size(); ++j)
        {
          auto &e    = elements[j];
          e.centroid = dealii::Point<dim>();
          double w   = 0;
          for (const auto &p : e.points)
            {
              e.centroid += p.weight * p.x;
              w += p.weight;
            }
          e.centroid /= w;
          first.elements[j].gap_integral = e.gap_integral;
        }
    }



    // @sect4{The projection of the second body onto the first}
    //
    // A mortar projection along the normal n of each contact element, in
    // the coordinates c = (x . tau_1, ..., x . tau_{dim-1}) of its tangent
    // plane. The projection of a face f of the first body and that of a
    // face g of the second overlap in a convex set: an interval in 2D, a
    // polygon in 3D (the triangle of g clipped by that of f, cut into a fan
    // of triangles). On each piece both faces are flat, so the shape
    // functions of both bodies and the gap (x_2 - x_1) . n are linear in c
    // there, and the centroid rule with the piece's measure as weight
    // integrates them exactly. The pieces of f add up to the projected
    // measure of f, its weight on the first body's side, so the forces on
    // the two sides balance. Each face of the first body must be covered
    // exactly once: otherwise the first body's candidate surface reaches
    // beyond the second body's, or the second body's surface folds over
    // itself along n. Matching meshes are the special case where every
    // face is covered by one partner.
    namespace internal
    {
      using PlanePoint = std::array<double, 2>;

      inline double
      cross(const PlanePoint &a, const PlanePoint &b, const PlanePoint &c)
      {
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      }

      // Sutherland-Hodgman: the part of the convex polygon @p subject
      // inside the counter-clockwise triangle @p clip.
      inline std::vector<PlanePoint>
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
    } // namespace internal



    template <int dim>
    void
    ContactSurface<dim>::pair_projected(ContactSurface<dim> &first)
    {
      using internal::PlanePoint;
      for (unsigned int j = 0; j < elements.size(); ++j)
        {
          auto       &e  = elements[j];
          const auto &e1 = first.elements[j];

          // The vertices of a face in the tangent plane of element j (in
          // 3D ordered counter-clockwise), and its projected measure.
          const auto project = [&](const Face<dim> &F) {
            std::vector<PlanePoint> c(F.points.size(), PlanePoint{{0, 0}});
            for (unsigned int v = 0; v < F.points.size(); ++v)
              for (unsigned int k = 0; k < dim - 1; ++k)
                c[v][k] = F.points[v] * e1.tangents[k];
            return c;
          };
          const auto measure = [](const std::vector<PlanePoint> &c) {
            return dim == 2 ? std::abs(c[1][0] - c[0][0]) :
                              0.5 * std::abs(internal::cross(c[0], c[1], c[2]));
          };
          // Barycentric coordinates of the plane point c in the projected
          // face and the point of the face there.
          const auto at = [](const Face<dim>               &F,
                             const std::vector<PlanePoint> &P,
                             const PlanePoint              &c) {
            std::array<double, dim> lambda;
            if constexpr (dim == 2)
              {
                lambda[1] = (c[0] - P[0][0]) / (P[1][0] - P[0][0]);
                lambda[0] = 1 - lambda[1];
              }
            else
              {
                const double det = internal::cross(P[0], P[1], P[2]);
                lambda[1]        = internal::cross(P[0], c, P[2]) / det;
                lambda[2]        = internal::cross(P[0], P[1], c) / det;
                lambda[0]        = 1 - lambda[1] - lambda[2];
              }
            dealii::Point<dim> x;
            for (unsigned int v = 0; v < dim; ++v)
              x += lambda[v] * F.points[v];
            return std::make_pair(lambda, x);
          };
          // The pieces of the overlap of two projected faces: measure and
          // centroid of each.
          const auto overlap = [](const std::vector<PlanePoint> &P,
                                  const std::vector<PlanePoint> &Q) {
            std::vector<std::pair<double, PlanePoint>> pieces;
            if constexpr (dim == 2)
              {
                const double lo = std::max(std::min(P[0][0], P[1][0]),
                                           std::min(Q[0][0], Q[1][0]));
                const double hi = std::min(std::max(P[0][0], P[1][0]),
                                           std::max(Q[0][0], Q[1][0]));
                if (hi > lo)
                  pieces.push_back({hi - lo, PlanePoint{{0.5 * (lo + hi), 0}}});
              }
            else
              {
                std::array<PlanePoint, 3> clip = {{P[0], P[1], P[2]}};
                if (internal::cross(P[0], P[1], P[2]) < 0)
                  std::swap(clip[1], clip[2]);
                std::vector<PlanePoint> subject(Q.begin(), Q.end());
                if (internal::cross(Q[0], Q[1], Q[2]) < 0)
                  std::swap(subject[1], subject[2]);
                const auto poly = internal::clip_by_triangle(subject, clip);
                for (unsigned int i = 1; i + 1 < poly.size(); ++i)
                  {
                    const double a =
                      0.5 * internal::cross(poly[0], poly[i], poly[i + 1]);
                    if (a > 0)
                      pieces.push_back(
                        {a,
                         PlanePoint{
                           {(poly[0][0] + poly[i][0] + poly[i + 1][0]) / 3,
                            (poly[0][1] + poly[i][1] + poly[i + 1][1]) / 3}}});
                  }
              }
            return pieces;
          };

          std::vector<std::vector<PlanePoint>> Q(faces.size());
          std::vector<std::array<double, 4>>   box(faces.size());
          for (unsigned int g = 0; g < faces.size(); ++g)
            {
              Q[g]   = project(faces[g]);
              box[g] = {{Q[g][0][0], Q[g][0][0], Q[g][0][1], Q[g][0][1]}};
              for (const auto &c : Q[g])
                box[g] = {{std::min(box[g][0], c[0]),
                           std::max(box[g][1], c[0]),
                           std::min(box[g][2], c[1]),
                           std::max(box[g][3], c[1])}};
            }

          e.gap_integral = 0;
          for (const unsigned int f : e1.faces)
            {
              const auto  &F1   = first.faces[f];
              const auto   P    = project(F1);
              const double m1   = measure(P);
              double       b[4] = {P[0][0], P[0][0], P[0][1], P[0][1]};
              for (const auto &c : P)
                {
                  b[0] = std::min(b[0], c[0]);
                  b[1] = std::max(b[1], c[0]);
                  b[2] = std::min(b[2], c[1]);
                  b[3] = std::max(b[3], c[1]);
                }
              double covered = 0;
              for (unsigned int g = 0; g < faces.size(); ++g)
                {
                  if (box[g][0] >= b[1] || box[g][1] <= b[0] ||
                      (dim == 3 && (box[g][2] >= b[3] || box[g][3] <= b[2])))
                    continue;
                  for (const auto &[w, c] : overlap(P, Q[g]))
                    {
                      if (!(w > 1e-12 * m1))
                        continue;
                      SurfacePoint<dim> p;
                      p.face                       = g;
                      std::tie(p.barycentric, p.x) = at(faces[g], Q[g], c);
                      p.weight                     = w;
                      e.points.push_back(p);
                      if (std::find(e.faces.begin(), e.faces.end(), g) ==
                          e.faces.end())
                        e.faces.push_back(g);
                      e.gap_integral +=
                        w * ((p.x - at(F1, P, c).second) * e1.normal);
                      covered += w;
                    }
                }
              if (std::abs(covered - m1) > 1e-9 * m1)
                throw InputError(
                  "Contact: the face of " + first.opts.body + " at " +
                  internal::format_point(F1.centroid) + " is " +
                  (covered < m1 ? "not covered by" :
                                  "covered more than once by") +
                  " the projection of '" + opts.boundary + "' of " + opts.body +
                  " along the contact direction (enlarge the boundary of " +
                  opts.body + " or reduce Contact / Candidate half width)");
            }
        }
    }



    template <int dim>
    void
    ContactSurface<dim>::set_plane_gap(const dealii::Point<dim> &point)
    {
      for (auto &e : elements)
        {
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
  } // namespace contact_surface
} // namespace dpana

#endif
