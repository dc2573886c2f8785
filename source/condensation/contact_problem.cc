// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/condensation/contact_problem.h>
#include <dpana/contact_surface/format_point.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

namespace dpana
{
  namespace condensation
  {
    // @sect3{The contact problem}
    //
    // Relative quantities add (A = A1 + A2, D = D1 + D2), the initial gap
    // enters the normal rows, the equality rows of the floating bodies are
    // stacked.
    template <int dim>
    contact::ContactProblem
    assemble_contact_problem(
      const std::vector<const Condenser<dim> *>  &condensers,
      const contact_surface::ContactSurface<dim> &surface,
      const double                                friction,
      const contact::ConeModel                    cone,
      const unsigned int                          polygon_sides)
    {
      const unsigned int      n = surface.n_elements();
      contact::ContactProblem problem;
      problem.dim           = dim;
      problem.A             = Eigen::MatrixXd::Zero(dim * n, dim * n);
      problem.D             = Eigen::VectorXd::Zero(dim * n);
      problem.mu            = Eigen::VectorXd::Constant(n, friction);
      problem.cone          = cone;
      problem.polygon_sides = polygon_sides;
      unsigned int m        = 0;
      for (const Condenser<dim> *c : condensers)
        {
          if (c->compliance().size() > 0) // empty off rank 0 (MPI route)
            problem.A += c->compliance();
          problem.D += c->load_term();
          m += c->n_free_modes();
        }
      for (unsigned int j = 0; j < n; ++j)
        problem.D(dim * j) -= surface.element(j).gap_integral;

      problem.G.resize(m, dim * n);
      problem.e.resize(m);
      unsigned int row = 0;
      for (const Condenser<dim> *c : condensers)
        {
          const unsigned int mb = c->n_free_modes();
          if (mb == 0)
            continue;
          problem.G.middleRows(row, mb) = c->equilibrium_matrix();
          problem.e.segment(row, mb)    = c->equilibrium_rhs();
          row += mb;
        }
      return problem;
    }



    template <int dim>
    bool
    held_to_zero(const Body<dim> &body, const dealii::types::global_dof_index i)
    {
      const auto &constraints = body.constraints();
      const auto &stored      = constraints.get_local_lines();
      return (stored.size() == 0 || stored.is_element(i)) &&
             constraints.is_constrained(i) &&
             !constraints.is_inhomogeneously_constrained(i) &&
             constraints.get_constraint_entries(i)->empty();
    }



    namespace
    {
      // The components of the displacement of vertex @p v of the face @p F
      // that a constraint of @p body holds at zero, and how many they are
      // (dim: a fixed vertex).
      template <int dim>
      std::pair<std::array<bool, dim>, unsigned int>
      held_components(const Body<dim>                  &body,
                      const contact_surface::Face<dim> &F,
                      const unsigned int                v)
      {
        std::array<bool, dim> held{};
        unsigned int          n_held = 0;
        for (unsigned int c = 0; c < dim; ++c)
          {
            held[c] = held_to_zero(body, F.dofs[dim * v + c]);
            n_held += held[c];
          }
        return {held, n_held};
      }
    } // namespace



    // @sect3{Patches on symmetry lines and planes}
    //
    // The vertex of a patch is the corner of its first piece at which the
    // barycentric coordinate is 1 (group_around_vertices()). A component c
    // of its displacement is held if a constraint without entries sets it
    // to zero. The tangential displacement along tau_k counts as held if
    // the held components make up more than half of tau_k (tau_kc^2 >
    // 1/2): with the elements' own normals the patch at the axis is tilted
    // by half its angle on the arc, and its tangent is not exactly the
    // held direction.
    template <int dim>
    std::vector<unsigned int>
    tangentially_held_unknowns(
      const Body<dim>                            &body,
      const contact_surface::ContactSurface<dim> &surface)
    {
      using contact_surface::ElementShape;
      if (surface.options().shape != ElementShape::vertex_patches)
        return {};
      const auto               &faces = surface.get_faces();
      std::vector<unsigned int> held(dim * surface.n_elements(), 0);
      for (unsigned int j = 0; j < surface.n_elements(); ++j)
        {
          const auto  &e     = surface.element(j);
          const auto  &piece = e.pieces[0];
          const auto  &F     = faces[piece.face];
          unsigned int v     = 0;
          while (v < dim && piece.corners[0][v] != 1.0)
            ++v;
          AssertThrow(v < dim, dealii::ExcInternalError());
          const auto [held_c, n_held] = held_components(body, F, v);
          for (unsigned int c = 0; c < dim; ++c)
            if (held_c[c])
              for (unsigned int k = 0; k + 1 < dim; ++k)
                if (e.tangents[k][c] * e.tangents[k][c] > 0.5)
                  held[dim * j + 1 + k] = 1;
          if (n_held == dim)
            throw InputError(
              "Contact / Contact elements = vertices: the vertex at " +
              contact_surface::internal::format_point(F.points[v]) +
              " of the candidate surface of " + surface.options().body +
              " is held in every direction, so no free displacement resists "
              "the tractions of its patch (leave it out of the candidate "
              "region, or use Contact elements = faces)");
        }
      // Every rank holds the constraints of the whole body (Body::
      // constraints()), so every rank finds the same list; the maximum over
      // the ranks keeps it so should a rank hold only those of its dofs.
      std::vector<unsigned int> any(held.size());
      dealii::Utilities::MPI::max(held, body.communicator(), any);
      std::vector<unsigned int> list;
      for (unsigned int i = 0; i < any.size(); ++i)
        if (any[i] != 0)
          list.push_back(i);
      return list;
    }



    // A held component T_k is zero at the solution only if the friction set
    // is symmetric under T_k -> -T_k: the disc always, the polygon of s
    // sides (facet normals at the angles 2 pi i / s from tau_1) under T_2 ->
    // -T_2 for every s, under T_1 -> -T_1 only for even s.
    void
    hold_tangential_tractions(contact::ContactProblem         &problem,
                              const std::vector<unsigned int> &unknowns)
    {
      for (const unsigned int t : unknowns)
        {
          Assert(t % problem.dim != 0, dealii::ExcInternalError());
          if (problem.cone == contact::ConeModel::polygon &&
              problem.polygon_sides % 2 == 1 && t % problem.dim == 1)
            throw InputError(
              "Contact / Polygon sides = " +
              std::to_string(problem.polygon_sides) +
              ": patches around vertices on a symmetry plane across tau_1 "
              "need a friction polygon symmetric under T_1 -> -T_1, an even "
              "number of sides");
          const double diagonal = problem.A(t, t);
          problem.A.row(t).setZero();
          problem.A.col(t).setZero();
          problem.A(t, t) = diagonal;
          problem.D(t)    = 0;
          if (problem.G.rows() > 0)
            problem.G.col(t).setZero();
        }
    }



    template <int dim>
    std::string
    polygon_symmetry_warning(
      const Body<dim>                            &body,
      const contact_surface::ContactSurface<dim> &surface,
      const contact::ConeModel                    cone,
      const unsigned int                          sides)
    {
      if (dim != 3 || cone != contact::ConeModel::polygon ||
          surface.options().shape != contact_surface::ElementShape::face_groups)
        return {};
      const auto &faces = surface.get_faces();
      for (const auto &e : surface.get_elements())
        for (const auto &piece : e.pieces)
          {
            const auto &F = faces[piece.face];
            for (unsigned int v = 0; v < dim; ++v)
              {
                const auto [held, n_held] = held_components(body, F, v);
                // A fixed vertex is no symmetry plane.
                if (n_held == dim)
                  continue;
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    if (!held[c] || std::abs(e.normal[c]) > 1e-9)
                      continue;
                    // tau_2 in 3D (the last tangent: in bounds for the
                    // instance of dim = 2 too, which returned above).
                    const auto  &tau_2 = e.tangents.back();
                    const double angle =
                      std::atan2(tau_2[c], e.tangents[0][c]) + M_PI / 2;
                    const double k = angle * sides / M_PI;
                    if (std::abs(k - std::round(k)) < 1e-6)
                      continue;
                    return "Contact / Polygon sides = " +
                           std::to_string(sides) +
                           ": the friction polygon is not symmetric about "
                           "the symmetry plane normal to the " +
                           std::string(1, "xyz"[c]) + " axis at " +
                           contact_surface::internal::format_point(
                             F.points[v]) +
                           " on the candidate surface of " +
                           surface.options().body +
                           ", so this part model's tractions are not those "
                           "of the whole body under this polygon (its "
                           "mirror lines lie at multiples of 180/" +
                           std::to_string(sides) +
                           " degrees from tau_1; an even number of sides "
                           "suits planes along the axes)";
                  }
              }
          }
      return {};
    }



    template <int dim>
    double
    largest_asymmetry(const std::vector<const Condenser<dim> *> &condensers)
    {
      double asymmetry = 0;
      for (const Condenser<dim> *c : condensers)
        asymmetry = std::max(asymmetry, c->asymmetry());
      return asymmetry;
    }



    template contact::ContactProblem
    assemble_contact_problem(const std::vector<const Condenser<2> *> &,
                             const contact_surface::ContactSurface<2> &,
                             const double,
                             const contact::ConeModel,
                             const unsigned int);
    template contact::ContactProblem
    assemble_contact_problem(const std::vector<const Condenser<3> *> &,
                             const contact_surface::ContactSurface<3> &,
                             const double,
                             const contact::ConeModel,
                             const unsigned int);
    template bool
    held_to_zero(const Body<2> &, const dealii::types::global_dof_index);
    template bool
    held_to_zero(const Body<3> &, const dealii::types::global_dof_index);
    template std::string
    polygon_symmetry_warning(const Body<2> &,
                             const contact_surface::ContactSurface<2> &,
                             const contact::ConeModel,
                             const unsigned int);
    template std::string
    polygon_symmetry_warning(const Body<3> &,
                             const contact_surface::ContactSurface<3> &,
                             const contact::ConeModel,
                             const unsigned int);
    template std::vector<unsigned int>
    tangentially_held_unknowns(const Body<2> &,
                               const contact_surface::ContactSurface<2> &);
    template std::vector<unsigned int>
    tangentially_held_unknowns(const Body<3> &,
                               const contact_surface::ContactSurface<3> &);
    template double
    largest_asymmetry(const std::vector<const Condenser<2> *> &);
    template double
    largest_asymmetry(const std::vector<const Condenser<3> *> &);
  } // namespace condensation
} // namespace dpana
