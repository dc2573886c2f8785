// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The grouping of the candidate faces into contact elements: runs of
// adjacent edges in 2D; cells of a tangential lattice, or greedy
// agglomeration followed by the merging of its leftovers, in 3D.

#include <dpana/contact_surface/contact_surface.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace dpana
{
  namespace contact_surface
  {
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



    namespace
    {
      // The pieces of face f in the median dual cell of its vertex k
      // (group_around_vertices()), each with the vertex as its first corner
      // (in 3D also with the orientation of f, for the output).
      template <int dim>
      std::vector<FacePiece<dim>>
      pieces_at_vertex(const unsigned int f, const unsigned int k)
      {
        std::array<double, dim> vertex{}, centroid{};
        vertex[k] = 1;
        centroid.fill(1.0 / dim);
        if constexpr (dim == 2)
          return {FacePiece<dim>{f, {{vertex, centroid}}}};
        else
          {
            std::vector<FacePiece<dim>> pieces;
            std::array<double, dim>     m_kj{}, m_kl{};
            m_kj[k] = m_kj[(k + 1) % 3] = 0.5;
            m_kl[k] = m_kl[(k + 2) % 3] = 0.5;
            pieces.push_back(FacePiece<dim>{f, {{vertex, m_kj, centroid}}});
            pieces.push_back(FacePiece<dim>{f, {{vertex, centroid, m_kl}}});
            return pieces;
          }
      }
    } // namespace



    // @sect3{Patches around the vertices}
    //
    // Every vertex of the candidate faces carries one element, its median
    // dual cell on the surface mesh:
    // - 2D: the half of edge f next to its vertex k, with the corners e_k
    //   and (1/2, 1/2) in the barycentric coordinates of f;
    // - 3D: the quadrilateral of triangle f between its vertex k, the
    //   midpoints of the two edges at k and the centroid, as the two
    //   triangles (e_k, m_kj, c) and (e_k, c, m_kl), j = k + 1, l = k + 2
    //   (mod 3), each a sixth of f.
    // The first corner of every piece is the vertex
    // (condensation::tangentially_held_unknowns() reads it there). The elements
    // are numbered along the surface (by the tangential coordinates of their
    // vertex).
    template <int dim>
    void
    ContactSurface<dim>::group_around_vertices()
    {
      std::map<unsigned int, unsigned int>   element_of_vertex;
      std::vector<std::pair<double, double>> st_vertex;
      elements.clear();
      for (unsigned int f = 0; f < faces.size(); ++f)
        for (unsigned int k = 0; k < dim; ++k)
          {
            const auto [it, is_new] =
              element_of_vertex.emplace(faces[f].vertices[k], elements.size());
            if (is_new)
              {
                elements.emplace_back();
                const auto &x = faces[f].points[k];
                st_vertex.emplace_back(x * tau_surface[0],
                                       x * tau_surface[dim - 2]);
              }
            auto &e = elements[it->second];
            e.faces.push_back(f);
            for (const auto &piece : pieces_at_vertex<dim>(f, k))
              e.pieces.push_back(piece);
          }

      std::vector<unsigned int> order(elements.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(),
                order.end(),
                [&](const unsigned int a, const unsigned int b) {
                  return st_vertex[a] < st_vertex[b];
                });
      std::vector<ContactElement<dim>> sorted;
      for (const unsigned int j : order)
        sorted.push_back(std::move(elements[j]));
      elements = std::move(sorted);
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
      for (const unsigned int start : order)
        {
          if (taken[start])
            continue;
          std::vector<unsigned int> group(1, start);
          taken[start] = true;
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
      merge_leftovers(size);
    }



    // The greedy agglomeration leaves small groups where a group cannot grow
    // any more (its free neighbours taken by earlier groups). Each group of
    // fewer than size / 2 faces, the smallest first, joins the neighbouring
    // group (sharing an edge) of the smallest area, so that the elements
    // differ in area by a factor of about 2 at most, as on a lattice.
    template <int dim>
    void
    ContactSurface<dim>::merge_leftovers(const unsigned int size)
    {
      // The edges of a face (sorted vertex pairs), and the faces that share
      // each edge.
      const auto edges_of = [&](const unsigned int f) {
        const auto &v = faces[f].vertices;
        std::vector<std::pair<unsigned int, unsigned int>> edges;
        for (unsigned int i = 0; i < v.size(); ++i)
          edges.emplace_back(std::min(v[i], v[(i + 1) % v.size()]),
                             std::max(v[i], v[(i + 1) % v.size()]));
        return edges;
      };
      std::map<std::pair<unsigned int, unsigned int>, std::vector<unsigned int>>
        edge_faces;
      for (unsigned int f = 0; f < faces.size(); ++f)
        for (const auto &edge : edges_of(f))
          edge_faces[edge].push_back(f);
      std::vector<unsigned int> owner(faces.size());
      std::vector<double>       area(elements.size(), 0.);
      for (unsigned int j = 0; j < elements.size(); ++j)
        for (const unsigned int f : elements[j].faces)
          {
            owner[f] = j;
            area[j] += faces[f].area;
          }

      std::vector<unsigned int> small;
      for (unsigned int j = 0; j < elements.size(); ++j)
        if (2 * elements[j].faces.size() < size)
          small.push_back(j);
      std::stable_sort(small.begin(),
                       small.end(),
                       [&](const unsigned int a, const unsigned int b) {
                         return elements[a].faces.size() <
                                elements[b].faces.size();
                       });
      for (const unsigned int j : small)
        {
          unsigned int best = dealii::numbers::invalid_unsigned_int;
          for (const unsigned int f : elements[j].faces)
            for (const auto &edge : edges_of(f))
              for (const unsigned int g : edge_faces[edge])
                {
                  const unsigned int k = owner[g];
                  if (k != j &&
                      (best == dealii::numbers::invalid_unsigned_int ||
                       area[k] < area[best] ||
                       (area[k] == area[best] && k < best)))
                    best = k;
                }
          if (best == dealii::numbers::invalid_unsigned_int)
            continue;
          for (const unsigned int f : elements[j].faces)
            owner[f] = best;
          elements[best].faces.insert(elements[best].faces.end(),
                                      elements[j].faces.begin(),
                                      elements[j].faces.end());
          area[best] += area[j];
          elements[j].faces.clear();
        }
      elements.erase(std::remove_if(elements.begin(),
                                    elements.end(),
                                    [](const ContactElement<dim> &e) {
                                      return e.faces.empty();
                                    }),
                     elements.end());
    }



    template void
    ContactSurface<2>::group_faces();
    template void
    ContactSurface<3>::group_faces();
    template void
    ContactSurface<2>::group_around_vertices();
    template void
    ContactSurface<3>::group_around_vertices();
  } // namespace contact_surface
} // namespace dpana
