// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/linear_algebra/last_block_ordering.h>

#include <deal.II/base/exceptions.h>

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <limits>

#include <metis.h>

namespace dpana
{
  namespace linear_algebra
  {
    std::string
    to_string(const LastBlockOrdering ordering)
    {
      switch (ordering)
        {
          case LastBlockOrdering::moved_last:
            return "moved last";
          case LastBlockOrdering::constrained_amd:
            return "constrained AMD";
          case LastBlockOrdering::interior_nested_dissection:
            return "interior nested dissection";
          case LastBlockOrdering::automatic:
            return "automatic";
        }
      return "";
    }



    namespace
    {
      // CHOLMOD's analysis of the whole matrix with its default strategy; its
      // permutation with the last unknowns moved to the end (a stable
      // partition).
      std::vector<CholmodIndex>
      moved_last(const CholmodMatrix     &K_lower,
                 const std::vector<bool> &is_last,
                 cholmod_common          &common)
      {
        cholmod_sparse A = Eigen::viewAsCholmod(
          K_lower.template selfadjointView<Eigen::Lower>());
        cholmod_factor *L = cholmod_l_analyze(&A, &common);
        AssertThrow(L != nullptr,
                    dealii::ExcMessage("CHOLMOD's symbolic analysis failed."));
        const auto *p = static_cast<const CholmodIndex *>(L->Perm);
        std::vector<CholmodIndex> given;
        given.reserve(L->n);
        for (std::size_t k = 0; k < L->n; ++k)
          if (!is_last[p[k]])
            given.push_back(p[k]);
        for (std::size_t k = 0; k < L->n; ++k)
          if (is_last[p[k]])
            given.push_back(p[k]);
        cholmod_l_free_factor(&L, &common);
        return given;
      }



      // CAMD with the constraint sets 0 (interior) and 1 (last).
      std::vector<CholmodIndex>
      constrained_amd(const CholmodMatrix     &K_lower,
                      const std::vector<bool> &is_last,
                      cholmod_common          &common)
      {
        cholmod_sparse A = Eigen::viewAsCholmod(
          K_lower.template selfadjointView<Eigen::Lower>());
        std::vector<CholmodIndex> member(is_last.begin(), is_last.end());
        std::vector<CholmodIndex> perm(is_last.size());
        AssertThrow(
          cholmod_l_camd(&A, nullptr, 0, member.data(), perm.data(), &common),
          dealii::ExcMessage("CHOLMOD's CAMD ordering failed."));
        return perm;
      }



      // The graph of the interior unknowns (the rows and columns of K_II),
      // both triangles and no diagonal, in compressed rows: row k lists the
      // interior unknowns coupled to k, in increasing order. Columns of
      // K_lower are visited in order and hold their rows sorted, so row k
      // receives first its neighbours j < k (from the columns j) and then
      // those j > k (from its own column): sorted without a sort.
      struct InteriorGraph
      {
        std::vector<CholmodIndex> start, adjacent;

        CholmodIndex
        degree(const CholmodIndex k) const
        {
          return start[k + 1] - start[k];
        }
      };

      InteriorGraph
      interior_graph(const CholmodMatrix             &K_lower,
                     const std::vector<CholmodIndex> &index,
                     const std::size_t                n_interior)
      {
        InteriorGraph g;
        g.start.assign(n_interior + 1, 0);
        const auto for_each_edge = [&](const auto &visit) {
          for (Eigen::Index c = 0; c < K_lower.outerSize(); ++c)
            for (CholmodMatrix::InnerIterator it(K_lower, c); it; ++it)
              if (it.row() != c && index[it.row()] >= 0 && index[c] >= 0)
                visit(index[c], index[it.row()]);
        };
        for_each_edge([&](const CholmodIndex j, const CholmodIndex k) {
          ++g.start[j + 1];
          ++g.start[k + 1];
        });
        for (std::size_t k = 0; k < n_interior; ++k)
          g.start[k + 1] += g.start[k];
        g.adjacent.resize(g.start.back());
        std::vector<CholmodIndex> next(g.start.begin(), g.start.end() - 1);
        for_each_edge([&](const CholmodIndex j, const CholmodIndex k) {
          g.adjacent[next[j]++] = k;
          g.adjacent[next[k]++] = j;
        });
        return g;
      }



      // Whether the interior unknowns k - 1 and k are indistinguishable: the
      // same closed neighbourhood (each coupled to the other and to the same
      // others), as the dim displacement components of a mesh vertex are.
      bool
      same_closed_neighbourhood(const InteriorGraph &g, const CholmodIndex k)
      {
        if (g.degree(k) != g.degree(k - 1))
          return false;
        const auto a = g.adjacent.begin() + g.start[k - 1];
        const auto b = g.adjacent.begin() + g.start[k];
        // Row k - 1 holds k where row k holds k - 1; all else must agree.
        for (CholmodIndex i = 0; i < g.degree(k); ++i)
          if ((a[i] == k ? k - 1 : a[i]) != b[i])
            return false;
        return std::binary_search(a, a + g.degree(k - 1), k);
      }



      // The graph of the mesh vertices of the interior: runs of consecutive
      // interior unknowns with the same closed neighbourhood (the components
      // of a mesh vertex, numbered together) are one vertex, weighted by
      // their number, in METIS' compressed rows.
      struct VertexGraph
      {
        std::vector<CholmodIndex> first; // first unknown of each vertex, n
        std::vector<idx_t>        start, adjacent, weight;
      };

      VertexGraph
      vertex_graph(const InteriorGraph &g)
      {
        const auto         n = static_cast<CholmodIndex>(g.start.size() - 1);
        VertexGraph        vg;
        std::vector<idx_t> vertex_of(n);
        for (CholmodIndex k = 0; k < n; ++k)
          {
            if (k == 0 || !same_closed_neighbourhood(g, k))
              vg.first.push_back(k);
            vertex_of[k] = vg.first.size() - 1;
          }
        const auto n_vertices = static_cast<idx_t>(vg.first.size());
        vg.first.push_back(n);
        vg.start.push_back(0);
        for (idx_t v = 0; v < n_vertices; ++v)
          {
            vg.weight.push_back(vg.first[v + 1] - vg.first[v]);
            // Those of its first unknown, mapped (sorted, so repeated
            // vertices are adjacent), itself left out.
            const CholmodIndex u = vg.first[v];
            for (CholmodIndex i = g.start[u]; i < g.start[u + 1]; ++i)
              {
                const idx_t w = vertex_of[g.adjacent[i]];
                if (w != v &&
                    (vg.adjacent.size() == std::size_t(vg.start.back()) ||
                     vg.adjacent.back() != w))
                  vg.adjacent.push_back(w);
              }
            AssertThrow(vg.adjacent.size() <
                          std::size_t(std::numeric_limits<idx_t>::max()),
                        dealii::ExcMessage(
                          "The interior graph is too large for METIS' "
                          "32-bit indices."));
            vg.start.push_back(vg.adjacent.size());
          }
        return vg;
      }



      // METIS' nested dissection of the vertex graph, so that METIS orders a
      // graph of the size of the mesh, not of the dofs; returns the interior
      // unknowns in elimination order (the unknowns of a vertex together).
      std::vector<CholmodIndex>
      metis_on_vertices(VertexGraph &vg)
      {
        idx_t              n_vertices = vg.weight.size();
        std::vector<idx_t> perm(n_vertices), inverse(n_vertices);
        for (idx_t v = 0; v < n_vertices; ++v)
          perm[v] = v;
        if (n_vertices > 1)
          {
            idx_t options[METIS_NOPTIONS];
            METIS_SetDefaultOptions(options);
            AssertThrow(METIS_NodeND(&n_vertices,
                                     vg.start.data(),
                                     vg.adjacent.data(),
                                     vg.weight.data(),
                                     options,
                                     perm.data(),
                                     inverse.data()) == METIS_OK,
                        dealii::ExcMessage("METIS' nested dissection failed."));
          }
        std::vector<CholmodIndex> order;
        order.reserve(vg.first.back());
        for (const idx_t v : perm)
          for (CholmodIndex k = vg.first[v]; k < vg.first[v + 1]; ++k)
            order.push_back(k);
        return order;
      }



      // CHOLMOD's symbolic analysis of the pattern A (symmetric, lower
      // triangle) under the ordering @p order found by @p method: the
      // postorder of its elimination tree, and the nonzeros and the flops
      // of the factor in common.lnz and common.fl.
      std::vector<CholmodIndex>
      analyze_ordering(cholmod_sparse            &A,
                       std::vector<CholmodIndex> &order,
                       const int                  method,
                       cholmod_common            &common)
      {
        const std::size_t         n = order.size();
        std::vector<CholmodIndex> parent(n), post(n), count(n), first(n),
          level(n);
        AssertThrow(cholmod_l_analyze_ordering(&A,
                                               method,
                                               order.data(),
                                               nullptr,
                                               0,
                                               parent.data(),
                                               post.data(),
                                               count.data(),
                                               first.data(),
                                               level.data(),
                                               &common),
                    dealii::ExcMessage("CHOLMOD's symbolic analysis of an "
                                       "ordering failed."));
        return post;
      }



      // The ordering followed by a postorder of its elimination tree
      // (CHOLMOD's symbolic analysis of the graph), which makes the columns
      // of each supernode consecutive, as cholmod_metis() does. (CHOLMOD
      // takes the graph through non-const pointers; it does not change it.)
      void
      postorder(InteriorGraph             &g,
                std::vector<CholmodIndex> &order,
                cholmod_common            &common)
      {
        const std::size_t n = order.size();
        cholmod_sparse    A{};
        A.nrow = A.ncol = n;
        A.nzmax         = g.adjacent.size();
        A.p             = g.start.data();
        A.i             = g.adjacent.data();
        A.stype         = -1; // symmetric: the lower triangle is read
        A.itype         = CHOLMOD_LONG;
        A.xtype         = CHOLMOD_PATTERN;
        A.dtype         = CHOLMOD_DOUBLE;
        A.sorted        = 1;
        A.packed        = 1;
        const std::vector<CholmodIndex> post =
          analyze_ordering(A, order, CHOLMOD_METIS, common);
        std::vector<CholmodIndex> postordered(n);
        for (std::size_t k = 0; k < n; ++k)
          postordered[k] = order[post[k]];
        order.swap(postordered);
      }



      // METIS on the interior block K_II, then the last unknowns in
      // increasing order.
      std::vector<CholmodIndex>
      interior_nested_dissection(const CholmodMatrix     &K_lower,
                                 const std::vector<bool> &is_last,
                                 cholmod_common          &common)
      {
        std::vector<CholmodIndex> interior, index(is_last.size(), -1);
        for (std::size_t i = 0; i < is_last.size(); ++i)
          if (!is_last[i])
            {
              index[i] = interior.size();
              interior.push_back(i);
            }
        std::vector<CholmodIndex> given;
        if (!interior.empty())
          {
            InteriorGraph g  = interior_graph(K_lower, index, interior.size());
            VertexGraph   vg = vertex_graph(g);
            given            = metis_on_vertices(vg);
            postorder(g, given, common);
            for (CholmodIndex &k : given)
              k = interior[k];
          }
        for (std::size_t i = 0; i < is_last.size(); ++i)
          if (is_last[i])
            given.push_back(i);
        return given;
      }



      // The minimum degree ordering when CHOLMOD's test passes on the
      // column counts of its factor, the nested dissection otherwise.
      std::vector<CholmodIndex>
      automatic(const CholmodMatrix     &K_lower,
                const std::vector<bool> &is_last,
                cholmod_common          &common)
      {
        std::vector<CholmodIndex> given =
          constrained_amd(K_lower, is_last, common);
        cholmod_sparse A = Eigen::viewAsCholmod(
          K_lower.template selfadjointView<Eigen::Lower>());
        analyze_ordering(A, given, CHOLMOD_GIVEN, common);
        if (minimum_degree_suffices(common.fl, common.lnz, K_lower.nonZeros()))
          return given;
        return interior_nested_dissection(K_lower, is_last, common);
      }
    } // namespace



    bool
    minimum_degree_suffices(const double flops,
                            const double factor_nonzeros,
                            const double matrix_entries)
    {
      return flops < 500. * factor_nonzeros ||
             factor_nonzeros < 5. * matrix_entries;
    }



    std::vector<CholmodIndex>
    order_last_block(const CholmodMatrix     &K_lower,
                     const std::vector<bool> &is_last,
                     const LastBlockOrdering  ordering,
                     cholmod_common          &common)
    {
      AssertDimension(is_last.size(), K_lower.rows());
      switch (ordering)
        {
          case LastBlockOrdering::moved_last:
            return moved_last(K_lower, is_last, common);
          case LastBlockOrdering::constrained_amd:
            return constrained_amd(K_lower, is_last, common);
          case LastBlockOrdering::interior_nested_dissection:
            return interior_nested_dissection(K_lower, is_last, common);
          case LastBlockOrdering::automatic:
            return automatic(K_lower, is_last, common);
        }
      return {};
    }
  } // namespace linear_algebra
} // namespace dpana
