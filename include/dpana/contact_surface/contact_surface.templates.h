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
    // with the centre of the cell.
    template <int dim>
    void
    ContactSurface<dim>::collect_faces(const dealii::Triangulation<dim> &tria)
    {
      faces.clear();
      excluded_vertices.clear();
      const double w = opts.region_half_width;
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
      collect_faces(tria);

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



    // Area, centroid, frame and tangential extents of every element.
    template <int dim>
    void
    ContactSurface<dim>::finish_elements()
    {
      for (auto &e : elements)
        {
          e.area     = 0;
          e.centroid = dealii::Point<dim>();
          dealii::Tensor<1, dim> n;
          e.s_min = e.t_min = std::numeric_limits<double>::max();
          e.s_max = e.t_max = -std::numeric_limits<double>::max();
          e.at_open_edge    = false;
          for (const unsigned int f : e.faces)
            {
              const auto &F = faces[f];
              e.area += F.area;
              e.centroid += F.area * F.centroid;
              n += F.area * F.normal;
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
          e.normal   = opts.direction.norm() > 0 ? n_surface : n / n.norm();
          e.tangents = tangential_frame(e.normal);
          e.s        = e.centroid * tau_surface[0];
          e.t        = dim == 3 ? e.centroid * tau_surface[dim - 2] : 0.0;
          if (dim == 2)
            e.t_min = e.t_max = 0;
          e.gap_integral = 0;
        }
    }



    // @sect3{Two bodies: matching surfaces}
    //
    // The faces of the second body are matched to those of the first by the
    // position of their centroids in the tangent plane of the first (a
    // tolerance of 1e-6 of the face size) and by their areas; the elements
    // of the second body are then the same groups, with the frame negated:
    // the traction N n + T tau on the first body is -(N n + T tau) on the
    // second, and the relative normal displacement (u_1 - u_2) . n is the sum
    // of the normal displacements of both bodies each along its own normal.
    template <int dim>
    void
    ContactSurface<dim>::pair(const dealii::Triangulation<dim> &tria,
                              const Options                    &options,
                              ContactSurface<dim>              &first)
    {
      opts = options;
      collect_faces(tria);
      const auto &F1 = first.faces;
      if (faces.size() != F1.size())
        throw InputError(
          "Contact: the candidate surfaces do not match: " + first.opts.body +
          " has " + std::to_string(F1.size()) + " faces on '" +
          first.opts.boundary + "', " + opts.body + " has " +
          std::to_string(faces.size()) + " on '" + opts.boundary +
          "' (two-body contact needs matching meshes on Gamma_c)");
      const auto             n = first.n_surface;
      std::vector<Face<dim>> matched(F1.size());
      std::vector<bool>      used(faces.size(), false);
      for (unsigned int k = 0; k < F1.size(); ++k)
        {
          const double tol =
            1e-6 * (dim == 2 ? F1[k].area : std::sqrt(F1[k].area));
          bool found = false;
          for (unsigned int m = 0; m < faces.size() && !found; ++m)
            {
              if (used[m])
                continue;
              auto d = faces[m].centroid - F1[k].centroid;
              d -= (d * n) * n;
              if (d.norm() < tol &&
                  std::abs(faces[m].area - F1[k].area) < 1e-6 * F1[k].area)
                {
                  matched[k] = faces[m];
                  used[m]    = true;
                  found      = true;
                }
            }
          if (!found)
            throw InputError(
              "Contact: the candidate surfaces do not match: the face of " +
              first.opts.body + " at " +
              internal::format_point(F1[k].centroid) + " has no partner on '" +
              opts.boundary + "' of " + opts.body +
              " (two-body contact needs matching meshes on Gamma_c)");
        }
      faces       = matched;
      n_surface   = -first.n_surface;
      tau_surface = first.tau_surface;
      for (auto &t : tau_surface)
        t *= -1.0;

      // Same groups; geometry of this side; frame of the first negated. The
      // tangential coordinates s, t are those of the first body.
      elements = first.elements;
      for (unsigned int j = 0; j < elements.size(); ++j)
        {
          auto &e    = elements[j];
          e.area     = 0;
          e.centroid = dealii::Point<dim>();
          for (const unsigned int f : e.faces)
            {
              e.area += faces[f].area;
              e.centroid += faces[f].area * faces[f].centroid;
              for (const unsigned int v : faces[f].vertices)
                if (excluded_vertices.count(v))
                  {
                    e.at_open_edge                 = true;
                    first.elements[j].at_open_edge = true;
                  }
            }
          e.centroid /= e.area;
          e.normal = -first.elements[j].normal;
          for (unsigned int k = 0; k < dim - 1; ++k)
            e.tangents[k] = -first.elements[j].tangents[k];

          // The gap along n of the first body: the distance from its face to
          // the paired face, g = (x_2 - x_1) . n, exact for flat faces.
          double g = 0;
          for (const unsigned int f : e.faces)
            g += F1[f].area * ((faces[f].centroid - F1[f].centroid) *
                               first.elements[j].normal);
          first.elements[j].gap_integral = g;
          e.gap_integral                 = g;
        }
    }



    template <int dim>
    void
    ContactSurface<dim>::set_plane_gap(const dealii::Point<dim> &point)
    {
      for (auto &e : elements)
        {
          e.gap_integral = 0;
          for (const unsigned int f : e.faces)
            e.gap_integral +=
              faces[f].area * ((point - faces[f].centroid) * e.normal);
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
