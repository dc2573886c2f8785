// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_condensation_condenser_h
#define dpana_condensation_condenser_h

#include <dpana/body/body.h>
#include <dpana/condensation/memory_estimate.h>
#include <dpana/condensation/parameters.h>
#include <dpana/contact_surface/contact_surface.h>
#include <dpana/linear_algebra/schur_factorization.h>
#include <dpana/linear_algebra/sparse_cholesky.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace dpana
{
  namespace condensation
  {
    /**
     * Thrown by Condenser::factorize() when its memory check fails only
     * because of the memory granted to condensations running at the same
     * time (MemoryReservations): the body is to be factorised again after
     * them, by a new Condenser.
     */
    struct Deferred : std::exception
    {
      const char *
      what() const noexcept override
      {
        return "condensation deferred until the others are done (memory)";
      }
    };



    /**
     * The condensation of one elastic body on its candidate contact surface
     * (the reference formulation, eqs. 4.1-4.9).
     *
     * <h3>The operator V</h3>
     *
     * The contact unknowns are the piecewise constant tractions
     * r = (N_0, T_0, N_1, T_1, ...) (interleaved; T has dim - 1 components)
     * of the contact elements, in the frame (n, tau) of each element. The
     * work of r on a displacement u is u^T V r, with column dim j + k of V the
     * nodal forces of the unit traction e_k (e_0 = n, e_k = tau_k) on the
     * faces of element j:
     * @f[
     *   V_{i, dj+k} = \int_{\Gamma_j} \varphi_i \cdot e_k \, ds ,
     * @f]
     * integrated with a QGaussSimplex face rule through the body's
     * MappingFE. Hence (V^T u)_{dj+k} is the integral of u . e_k over the
     * element: area times mean displacement.
     *
     * <h3>A and s_o</h3>
     *
     * With the kinematic conditions eliminated (u = M v + u_bar, reduced
     * stiffness K_r, see SparseCholesky), the displacement is
     * u = u_o + Z r, u_o = M K_r^{-1} f_r + u_bar, Z = M K_r^{-1} M^T V, and
     * the contact displacements are
     * @f[
     *   V^T u = A r + s_o, \qquad A = V^T Z, \quad s_o = V^T u_o .
     * @f]
     * A is positive definite when the columns of V_r = M^T V are
     * independent, which the grouping of faces into contact elements (LBB)
     * ensures. It is formed in one of two ways (Parameters::method):
     *
     * - <b>Schur complement</b> (Method::schur). V_r vanishes outside the
     *   n_Gamma unknowns of the dofs on the contact surface Gamma_c. With
     *   these ordered last in the factorisation, K_r = P^T L L^T P with
     *   P = [fill-reducing ordering of the other unknowns, then Gamma_c],
     *   W = L^{-1} P V_r vanishes outside the last block, where it is
     *   W_Gamma = L_22^{-1} V_Gamma, L_22 the last diagonal block of L (the
     *   Cholesky factor of the Schur complement of K_r on Gamma_c). Hence
     * @f[
     *   A = W_\Gamma^T W_\Gamma ,
     * @f]
     *   one triangular solve with L_22, on the factor itself (its dense
     *   supernodes, or the columns of a simplicial factor:
     *   SparseCholesky::solve_schur_factor()), and one
     *   symmetric rank update, dense work of size n_Gamma x n_c after the
     *   one factorisation (SparseCholesky::factorize_with_last()); no dense
     *   block of length n_dofs. A is symmetric by construction.
     *   The factorisation is a linear_algebra::SchurFactorization chosen by
     *   Parameters::backend: CHOLMOD with Gamma_c ordered last (its L_22 is
     *   the factor of the Schur complement S), or MUMPS through PETSc, which
     *   returns S itself, factored densely (S = L_S L_S^T, L_S in place of
     *   L_22). The load u_o and the recovery are solves with the same
     *   factorisation.
     *
     * - <b>Blocked solves</b> (Method::blocked_solves). Z is computed by
     *   blocked multi-right-hand-side solves with one sparse Cholesky
     *   factorisation and A = V^T Z, symmetric in exact arithmetic
     *   (V^T M K_r^{-1} M^T V); it is symmetrised, 1/2 (A + A^T), after the
     *   relative asymmetry ||A - A^T||_F / ||A||_F is recorded.
     *
     * <h3>Floating bodies</h3>
     *
     * If the kinematic conditions leave rigid motions free (the columns of
     * R, from Body::free_rigid_modes()), K_r is singular. m = rank(R) nodal
     * values are then held by fictitious supports: m free degrees of freedom
     * chosen by a pivoted QR of the rows of R so that R restricted to them is
     * invertible (a statically determinate support of the rigid motions).
     * With them K_s is positive definite and u = u_o + Z r + R alpha, alpha
     * the unknown rigid displacement. The reactions of the fictitious
     * supports vanish iff the body is in equilibrium, R^T (f + V r) = 0,
     * that is
     * @f[
     *   G r = e, \qquad G = R^T V, \quad e = -R^T f ,
     * @f]
     * and the contact displacements pick up V^T R alpha = G^T alpha: exactly
     * the equality rows of the ContactProblem.
     *
     * The condensations of the bodies are combined into the contact problem
     * by assemble_contact_problem() (contact_problem.h); the number of
     * columns per blocked solve is a parameter of the run
     * (condensation::Parameters, parameters.h).
     */
    template <int dim>
    class Condenser
    {
    public:
      Condenser(const Body<dim>                            &body,
                const contact_surface::ContactSurface<dim> &surface,
                const Parameters &parameters = Parameters());

      /**
       * Assemble V (sparse, n_dofs x dim n_elements). factorize() calls it
       * itself if the Schur route needs V before, condense() if V is not
       * assembled yet.
       */
      void
      assemble_coupling();

      /**
       * Choose the fictitious supports of the free rigid motions, factor the
       * reduced stiffness and solve for u_o.
       */
      void
      factorize();

      /**
       * The grants of the condensations running at the same time as this
       * one (MemoryReservations), which the memory check of factorize()
       * adds to its estimate; nullptr (the default): none. A check that
       * fails only because of them throws Deferred.
       */
      void
      set_memory_reservations(MemoryReservations *grants)
      {
        reservations = grants;
      }

      /**
       * A, s_o, G, e. By the Method of the parameters: through the factor of
       * the Schur complement, or by blocked solves, @p columns_per_pass
       * columns of V at a time (Parameters::columns_per_solve) handed to
       * SparseCholesky::solve() (which itself works in blocks of its block
       * size).
       */
      void
      condense(const unsigned int columns_per_pass = 256);

      Method
      method() const
      {
        return parameters.method;
      }

      /**
       * The displacement u = u_o + K_s^{-1} V r + R alpha of the body.
       */
      dealii::Vector<double>
      recover(const Eigen::VectorXd &r, const Eigen::VectorXd &alpha) const;

      /**
       * V^T u: the integrals of u . e_k over the contact elements.
       */
      Eigen::VectorXd
      surface_response(const dealii::Vector<double> &u) const;

      /**
       * A, the body's condensed compliance; empty on the ranks other than 0
       * on the MPI route, where rank 0 alone forms it and solves the
       * contact problem.
       */
      const Eigen::MatrixXd &
      compliance() const
      {
        return A;
      }
      const Eigen::VectorXd &
      load_term() const
      {
        return s_o;
      }
      const Eigen::MatrixXd &
      equilibrium_matrix() const
      {
        return G;
      }
      const Eigen::VectorXd &
      equilibrium_rhs() const
      {
        return e;
      }
      const Eigen::SparseMatrix<double> &
      coupling() const
      {
        return V;
      }
      double
      asymmetry() const
      {
        return relative_asymmetry;
      }
      unsigned int
      n_free_modes() const
      {
        return R.cols();
      }
      const std::vector<unsigned int> &
      fictitious_supports() const
      {
        return supports;
      }
      /**
       * The CHOLMOD factorisation of the blocked solves and of the Schur
       * route with Backend::cholmod (not factored with Backend::mumps).
       */
      const linear_algebra::SparseCholesky &
      factorization() const
      {
        return cholesky;
      }
      /**
       * The memory estimate made by factorize() after the symbolic analysis
       * (memory_estimate.h); factorize() refuses to go on, with an
       * InputError, if it exceeds Parameters::memory_limit_gb.
       */
      const MemoryEstimate &
      memory_estimate() const
      {
        return estimate;
      }

      /**
       * The factorisation behind the load, the recovery and the Schur route,
       * of the back end of the parameters; available after factorize().
       */
      const linear_algebra::SchurFactorization &
      schur_factorization() const
      {
        return *back_end;
      }

    private:
      /**
       * The fictitious supports of the free rigid motions among the free
       * degrees of freedom @p free; with patches around the vertices, off
       * the candidate contact surface where possible.
       */
      std::vector<unsigned int>
      choose_supports(const std::vector<unsigned int> &free) const;

      /**
       * The degrees of freedom of the nonzero rows of V.
       */
      std::vector<unsigned int>
      surface_dofs() const;

      /**
       * A = W_Gamma^T W_Gamma (see the class documentation).
       */
      void
      condense_through_schur_complement();

      /**
       * Estimate the memory of the run from @p analysis into #estimate and
       * throw an InputError if it exceeds the limit.
       */
      void
      check_memory(const linear_algebra::SparseCholesky::Analysis &analysis);

      /**
       * The factorisation back end MUMPS, whose analysis makes #estimate
       * and calls check_memory_limit() before the numerical factorisation.
       */
      std::unique_ptr<linear_algebra::SchurFactorization>
      make_mumps_back_end();

      /**
       * Throw an InputError if #estimate exceeds the memory limit, with
       * #reservations the grants of the others added (Deferred if they
       * alone make it exceed).
       */
      void
      check_memory_limit() const;

      /**
       * The lower triangle of @p A = W^T W, for @p W whose column k
       * vanishes above row first_rows[k] (increasing).
       */
      static void
      trapezoidal_gram(const Eigen::MatrixXd  &W,
                       const std::vector<int> &first_rows,
                       Eigen::MatrixXd        &A);

      /**
       * A = V^T Z, Z by blocked solves, then symmetrised.
       */
      void
      condense_by_blocked_solves(const unsigned int columns_per_pass);

      const Body<dim>                            &body;
      const contact_surface::ContactSurface<dim> &surface;
      const Parameters                            parameters;

      Eigen::SparseMatrix<double>       V;
      Eigen::MatrixXd                   R;
      std::vector<unsigned int>         supports;
      dealii::AffineConstraints<double> constraints;
      linear_algebra::SparseCholesky    cholesky;
      Eigen::VectorXd                   u_o;

      // The factorisation of the load, the recovery and the Schur route: an
      // adapter of #cholesky, or MUMPS.
      std::unique_ptr<linear_algebra::SchurFactorization> back_end;

      Eigen::MatrixXd     A;
      Eigen::VectorXd     s_o;
      Eigen::MatrixXd     G;
      Eigen::VectorXd     e;
      double              relative_asymmetry = 0;
      MemoryEstimate      estimate;
      MemoryReservations *reservations = nullptr;
    };
  } // namespace condensation
} // namespace dpana

#endif
