// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_contact_surface_contact_surface_h
#define dpana_contact_surface_contact_surface_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/cell_id.h>

#include <array>
#include <set>
#include <string>
#include <vector>

namespace dpana
{
  namespace contact_surface
  {
    /**
     * One boundary face of a body on the candidate contact surface, with its
     * (flat, P1) geometry and the degrees of freedom of its vertices. It
     * refers to no mesh object, so that the faces of a body whose cells are
     * split over MPI ranks, or whose mesh is, can be gathered on every rank:
     * the cell's id and the face's number in the cell give the order of the
     * faces, the same on any number of ranks (the order of the active cells
     * of one process is that of their ids, for the meshes dpana makes: flat
     * or refined uniformly).
     */
    template <int dim>
    struct Face
    {
      dealii::CellId         cell;
      unsigned int           face_no;
      dealii::Point<dim>     centroid;
      dealii::Tensor<1, dim> normal;
      double                 area;
      // A key of each vertex: the number of its first degree of freedom
      // (the same vertex has the same key on every rank).
      std::vector<unsigned int>       vertices;
      std::vector<dealii::Point<dim>> points;
      // The degrees of freedom of the vertices, vertex by vertex, component
      // by component within a vertex (dim per vertex).
      std::vector<dealii::types::global_dof_index> dofs;
    };

    /**
     * A point of the quadrature rule of a contact element on one body: the
     * face it lies on (an index into ContactSurface::get_faces()), its
     * barycentric coordinates with respect to the face's vertices (in the
     * order of Face::vertices), its position and its weight. The integrand
     * of the coupling operator V is a P1 shape function times a constant
     * traction, linear on each face, and the rules are exact for it: one
     * point at the centroid of each piece of face of the element (a whole
     * face, a half edge, whose midpoint has the barycentric coordinates
     * 3/4 and 1/4, or a sixth of a triangle), or one at the centroid of each
     * overlap of such a piece with a face of the other body (the second body of
     * a pair).
     */
    template <int dim>
    struct SurfacePoint
    {
      unsigned int            face;
      std::array<double, dim> barycentric;
      dealii::Point<dim>      x;
      double                  weight;
    };

    /**
     * The part of a face that belongs to a contact element: a simplex
     * inside the face, given by the barycentric coordinates of its corners
     * with respect to the face's vertices (corner k is sum_v corners[k][v]
     * times vertex v). A whole face has the unit corners; in 2D the half of
     * an edge next to its vertex v has the corners e_v and (1/2, 1/2); in 3D
     * a sixth of a triangle next to its vertex v the corners e_v, the
     * midpoint of an edge at v and the centroid (1/3, 1/3, 1/3).
     */
    template <int dim>
    struct FacePiece
    {
      unsigned int                             face;
      std::array<std::array<double, dim>, dim> corners;

      /**
       * The piece's share of the face's area: |det(corners)|.
       */
      double
      fraction() const;

      /**
       * The point of @p F at the barycentric coordinates @p lambda.
       */
      static dealii::Point<dim>
      point(const Face<dim> &F, const std::array<double, dim> &lambda);

      /**
       * The corners of the piece on its face @p F.
       */
      std::array<dealii::Point<dim>, dim>
      corner_points(const Face<dim> &F) const;

      /**
       * The barycentric coordinates of the piece's centroid in its face.
       */
      std::array<double, dim>
      centroid() const;

      /**
       * The piece as a flat face of its own: the face @p F with the piece's
       * corners as points, its centroid and its area. The rest is F's (cell,
       * normal, and the vertex keys and dofs of F's vertices, which do not
       * belong to the piece's corners): a face to integrate over, not one
       * of the mesh.
       */
      Face<dim>
      as_face(const Face<dim> &F) const;
    };

    /**
     * The shape of the contact elements: groups of whole faces, or
     * one element around each vertex of the candidate surface.
     */
    enum class ElementShape
    {
      face_groups,
      vertex_patches
    };

    /**
     * A contact element: a group of adjacent faces, or the patch
     * around one vertex, that carries one piecewise constant traction
     * (N, T) in its local frame.
     *
     * - normal: the direction n along which the normal traction acts and the
     *   normal displacement is measured. It points out of the body, towards
     *   the obstacle or the other body.
     * - tangents: tau (2D) or tau_1, tau_2 (3D), so that (n, tau) or
     *   (n, tau_1, tau_2) is a right-handed orthonormal frame (for the second
     *   body of a pair the frame of its partner, negated).
     * - area: the area of the element's projection on the plane normal to
     *   n (in 2D its length). Tractions are forces per unit projected area,
     *   so that the forces on two paired surfaces balance exactly even when
     *   one is curved (the cylinder) and the other flat (the foundation);
     *   on a flat element it is the plain area.
     * - pieces: the parts of faces the element covers on the first body
     *   (whole faces for groups of faces; for vertex patches half edges in
     *   2D, the two sixths of each triangle next to the vertex in 3D);
     *   faces lists the faces they lie on.
     * - points: the quadrature rule of this body's side of the element; the
     *   weights add up to area.
     * - gap_integral: the integral over the element of the initial gap
     *   g_o(x) >= 0 measured along n (mm^3 in 3D, mm^2 in 2D); the mean gap
     *   is gap_integral / area.
     * - s_min, s_max (and t_min, t_max in 3D): the extent of the element
     *   along the surface's tangent directions, used for plots and zone
     *   extents.
     */
    template <int dim>
    struct ContactElement
    {
      std::vector<unsigned int>                   faces;
      std::vector<FacePiece<dim>>                 pieces;
      std::vector<SurfacePoint<dim>>              points;
      dealii::Tensor<1, dim>                      normal;
      std::array<dealii::Tensor<1, dim>, dim - 1> tangents;
      double                                      area = 0;
      dealii::Point<dim>                          centroid;
      double                                      gap_integral = 0;
      double                                      s = 0, s_min = 0, s_max = 0;
      double                                      t = 0, t_min = 0, t_max = 0;
      // The vertices of the element that a boundary face outside the
      // candidate surface shares, a face that faces the obstacle
      // (find_open_edges()). On a pair, only those beyond which the second
      // body's surface goes on (pair_projected()).
      std::vector<dealii::Point<dim>> open_edge_points;

      double
      mean_gap() const
      {
        return gap_integral / area;
      }

      // Contact reaching an element at an open edge means that the
      // candidate surface may be too small.
      bool
      at_open_edge() const
      {
        return !open_edge_points.empty();
      }
    };

    /**
     * The candidate contact surface Gamma_c of one body, grouped into
     * contact elements.
     *
     * <h3>Candidate faces</h3>
     *
     * The faces of a named boundary, optionally only those whose centroid x
     * lies in the box |x_d - x0_d| <= w of a candidate region (centre x0,
     * half width w). The result must not depend on Gamma_c as long as it
     * contains the whole contact zone; the region makes this checkable.
     *
     * <h3>Contact elements</h3>
     *
     * The tractions are constant on each contact element. With one constant
     * per face the discrete inf-sup (LBB) condition fails for P1
     * displacements, so several faces are grouped: in 2D the edges are
     * sorted along the surface and consecutive runs of @p faces_per_element
     * adjacent edges (default 2) form an element. In 3D the default is 8
     * triangles, the 2 x 2 patch of quadrilaterals each split in two
     * triangles: on a structured surface (its vertices lie on the lines of a
     * tangential lattice) faces are grouped by lattice cells q x q with
     * 2 q^2 = faces_per_element; otherwise adjacent faces are agglomerated
     * greedily, each group grown from the first free face (in the order of
     * the tangential coordinates) by the adjacent free face nearest to its
     * centroid until it holds faces_per_element faces. A group that stops
     * with fewer than faces_per_element / 2 faces (its free neighbours taken
     * by earlier groups) then joins the neighbouring group of the smallest
     * area, so that no contact element is much smaller than the others: a
     * leftover of one or two triangles would carry a mean traction over a
     * much smaller area than its neighbours and stand out of the profile.
     *
     * <h3>Patches around the vertices</h3>
     *
     * With the shape ElementShape::vertex_patches (parameter Contact /
     * Contact elements = vertices) each vertex of the candidate surface
     * carries one contact element, the median dual cell of the vertex on
     * the surface: in 2D the halves of the candidate edges next to it, from
     * the vertex to their midpoints; in 3D the part of each candidate
     * triangle next to it bounded by the midpoints of its two edges at the
     * vertex and its centroid (two triangles, each a sixth of the face).
     * There are then as many constant tractions as surface vertices, the
     * traction form of the nodal contact conditions of displacement-based
     * contact codes. The element's quadrature points are the centroids of
     * its pieces (exact for the linear integrand).
     *
     * <h3>Frames and gaps</h3>
     *
     * If a contact direction is given (the normal of the tangent plane at
     * the first contact point, for the "increasing" problems of Hertz type),
     * every element uses it; otherwise, on the rigid plane
     * (Options::rigid_plane), every element uses the plane's normal, the
     * area-weighted mean outward normal of the candidate faces, and between
     * two bodies each element the area-weighted mean outward normal of its
     * faces. The initial gap is measured along n:
     * to a rigid plane (set_plane_gap()) or to the paired faces of the other
     * body (pair()). The faces are flat (P1 mapping), and the gap is linear on
     * each face, so the midpoint rule integrates it exactly.
     *
     * <h3>Two bodies</h3>
     *
     * The contact elements are those of the first body; the second body's
     * side of element j is the part of its surface that projects, along n,
     * onto element j (a mortar projection with piecewise constant
     * multipliers on the first body). The two discretisations need not
     * match: the faces of the second body are cut at the edges of the
     * projections of the first body's pieces of faces (intervals in 2D,
     * triangles clipped by triangles in 3D). A cylinder meshed along its arc
     * can rest on a foundation meshed on a grid, or in a cavity of another
     * radius; matching meshes are the special case of one partner per face.
     *
     * <h3>Where the code is</h3>
     *
     * source/contact_surface/contact_surface.cc: candidate faces, frames,
     * quadrature points and gaps to a plane; face_grouping.cc: the grouping
     * into contact elements; mortar_pairing.cc: pair() and the projection
     * of the second body. The entries of the parameter file that fill the
     * Options are declared and parsed by contact_surface::Parameters
     * (parameters.h).
     */
    template <int dim>
    class ContactSurface
    {
    public:
      struct Options
      {
        // Name of the boundary for messages, and its id.
        std::string                boundary;
        dealii::types::boundary_id boundary_id = 0;
        // Body name for messages ("Body 1").
        std::string body;
        // Candidate region: centre and half width (<= 0: whole boundary).
        dealii::Point<dim> region_centre;
        double             region_half_width = 0;
        // Faces per contact element (0: 2 in 2D, 8 in 3D).
        unsigned int faces_per_element = 0;
        // Groups of faces, or one patch around each vertex.
        ElementShape shape = ElementShape::face_groups;
        // Contact direction (zero: the mean outward normal of the
        // candidate faces on the rigid plane, each element's own between
        // two bodies).
        dealii::Tensor<1, dim> direction;
        // The obstacle is the rigid plane (one body): without a direction
        // every element takes the plane's normal, the mean outward normal
        // of the candidate faces.
        bool rigid_plane = false;
      };

      /**
       * Collect the candidate faces of the mesh of @p dofs and group them.
       * Throws dpana::InputError if no face qualifies. On a @p communicator
       * of several ranks, each rank collects the faces of its own cells
       * (subdomain id = its rank) and the faces are gathered on all ranks,
       * in the order of one process.
       */
      void
      build(const dealii::DoFHandler<dim> &dofs,
            const Options                 &options,
            const MPI_Comm                 communicator = MPI_COMM_SELF);

      /**
       * Build the surface of the second body of a pair: the elements are
       * those of @p first, with its frame negated, and the gap of @p first is
       * set to the normal distance between the two surfaces. Only the faces
       * of the mesh of @p dofs that face the first body (outward normal . n < 0) take
       * part, whether or not they lie in the candidate region. Every piece
       * of face of @p first (a face, or a piece of a patch) must be
       * covered exactly once by the projections of these faces; otherwise
       * dpana::InputError with a one-line message.
       */
      void
      pair(const dealii::DoFHandler<dim> &dofs,
           const Options                 &options,
           ContactSurface<dim>           &first,
           const MPI_Comm                 communicator = MPI_COMM_SELF);

      /**
       * Gaps to the rigid plane through @p point with normal -n of each
       * element: g_o(x) = (point - x) . n.
       */
      void
      set_plane_gap(const dealii::Point<dim> &point);

      /**
       * The candidate vertex farthest along the contact direction (the first
       * contact point with a plane normal to it).
       */
      dealii::Point<dim>
      first_contact_point() const;

      unsigned int
      n_elements() const
      {
        return elements.size();
      }
      const ContactElement<dim> &
      element(const unsigned int j) const
      {
        return elements[j];
      }
      const std::vector<ContactElement<dim>> &
      get_elements() const
      {
        return elements;
      }
      const std::vector<Face<dim>> &
      get_faces() const
      {
        return faces;
      }
      const Options &
      options() const
      {
        return opts;
      }

      /**
       * Mean outward normal of the whole surface and the tangential frame
       * used for the coordinates s (and t).
       */
      const dealii::Tensor<1, dim> &
      surface_normal() const
      {
        return n_surface;
      }
      const std::array<dealii::Tensor<1, dim>, dim - 1> &
      surface_tangents() const
      {
        return tau_surface;
      }

      /**
       * The element indices sorted by the tangential coordinate (s, then t).
       */
      std::vector<unsigned int>
      sorted_elements() const;

      /**
       * The number of distinct mesh vertices of the candidate faces. With
       * more contact elements than vertices (one triangle per element on a
       * triangulated surface: about twice as many), the piecewise constant
       * normal tractions outnumber the surface displacements that resist
       * them: A_NN is singular and the tractions may oscillate from element
       * to element (Scene warns).
       */
      unsigned int
      n_vertices() const;

      /**
       * A one-line description for the log.
       */
      std::string
      description() const;

      /**
       * A right-handed orthonormal tangential frame for the unit normal n.
       */
      static std::array<dealii::Tensor<1, dim>, dim - 1>
      tangential_frame(const dealii::Tensor<1, dim> &n);

    private:
      Options                                     opts;
      std::vector<Face<dim>>                      faces;
      std::vector<ContactElement<dim>>            elements;
      dealii::Tensor<1, dim>                      n_surface;
      std::array<dealii::Tensor<1, dim>, dim - 1> tau_surface;
      std::set<dealii::types::global_dof_index>   open_edge_vertices;

      void
      collect_faces(const dealii::DoFHandler<dim> &dofs,
                    const double                   w,
                    const MPI_Comm                 communicator);
      void
      find_open_edges(const dealii::DoFHandler<dim> &dofs,
                      const MPI_Comm                 communicator);
      void
      group_faces();
      void
      group_around_vertices();
      bool
      group_on_lattice(const unsigned int q);
      void
      group_greedy(const unsigned int size);
      void
      merge_leftovers(const unsigned int size);
      void
      finish_elements();
      void
      pair_projected(ContactSurface<dim> &first);
    };
  } // namespace contact_surface
} // namespace dpana

#endif
