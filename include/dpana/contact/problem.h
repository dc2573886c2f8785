// The condensed frictional contact problem of dpana (dual formulation).
//
// This header is the contract between the finite element side of dpana (the
// condenser, which produces A and D) and the contact solvers (which produce
// the tractions). It holds plain Eigen data and knows nothing of meshes.
//
// @sect3{Unknowns and ordering}
//
// There are n contact elements in dimension d (2 or 3). The traction unknowns
// are ordered *interleaved per element* (the ordering of FCLIB and Siconos):
// @f[
//   r = (N_0, T_{0,1}, [T_{0,2}], N_1, T_{1,1}, [T_{1,2}], \dots),
// @f]
// so that N_j = r[d j] and T_{j,k} = r[d j + 1 + k]. The reference
// formulation's blocks A_NN, A_NT, A_TT are the corresponding sub-matrices of
// A.
//
// @sect3{Sign convention (the reference formulation's)}
//
// Compressive normal traction is negative, N <= 0; the normal displacement
// u_N (initial gap already included through D_N = \hat D_N - g_o) is
// admissible when u_N <= 0. The displacements dual to the tractions are
// @f[
//   u = A r + D + G^T \alpha ,
// @f]
// with A the dense SPD compliance matrix condensed on the candidate contact
// surface, D = s_o the load term and, for floating bodies, alpha the free
// amplitudes of the rigid modes removed by fictitious supports. The problem
// is: find r, alpha with
//   - Signorini:  u_N <= 0,  N <= 0,  N u_N = 0             (per element),
//   - Coulomb:    ||T|| <= -mu N; u_T = 0 where ||T|| < -mu N;
//                 u_T = -lambda T, lambda >= 0 where ||T|| = -mu N,
//   - equilibrium of floating bodies:  G r = e.
// The Siconos / FCLIB convention is r_s = -r, u_s = -u, q = -D.
#ifndef dpana_contact_problem_h
#define dpana_contact_problem_h

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace dpana
{
  namespace contact
  {
    // The set K_j that bounds the tractions of one contact element.
    enum class ConeModel
    {
      // 2D: the exact interval |T| <= -mu N. (In 3D it is rejected.)
      interval,
      // 3D: the circumscribed regular polygon with s sides of the reference
      // formulation,
      //   T_1 cos(a_i) + T_2 sin(a_i) <= -mu N, a_i = 2 (i-1) pi / s.
      polygon,
      // 3D: the exact disc ||T|| <= -mu N (second order cone).
      disc
    };

    // The name of a cone model: "interval", "disc" or "polygon".
    std::string
    to_string(const ConeModel cone);

    // The cone model of a name (see to_string()); throws
    // std::invalid_argument for anything else.
    ConeModel
    cone_model_from_string(const std::string &name);

    // The names of the cone models of dimension dim, separated by '|', the
    // default first: "interval" in 2D, "disc|polygon" in 3D (the pattern of
    // a ParameterHandler Selection).
    std::string
    cone_model_names(const unsigned int dim);

    struct ContactProblem
    {
      // Space dimension d, 2 or 3.
      unsigned int dim = 2;

      // Compliance matrix, (d n) x (d n), symmetric positive definite,
      // interleaved ordering (see above).
      Eigen::MatrixXd A;

      // Load term s_o = (D_N, D_T) with the initial gap included, d n.
      Eigen::VectorXd D;

      // Friction coefficient of each contact element, mu_j >= 0, size n.
      Eigen::VectorXd mu;

      // Friction set. In 2D only ConeModel::interval is meaningful.
      ConeModel cone = ConeModel::interval;

      // Number of sides s of the friction polygon (ConeModel::polygon), s >= 3
      // (the reference formulation uses s = 2^m, m = 4..5).
      unsigned int polygon_sides = 16;

      // Equality rows of floating bodies: G is m x (d n), e has size m; both
      // empty when every body is held by its own supports.
      Eigen::MatrixXd G;
      Eigen::VectorXd e;

      // Number of contact elements n.
      unsigned int
      n_elements() const
      {
        return dim == 0 ? 0 : static_cast<unsigned int>(D.size()) / dim;
      }

      // Number of equality rows m.
      unsigned int
      n_equalities() const
      {
        return static_cast<unsigned int>(e.size());
      }

      // Check sizes, symmetry, finiteness, mu >= 0, the cone model against the
      // dimension. Throws std::invalid_argument with a one-line message that
      // names the offending field.
      void
      validate() const;
    };

    // The state of one contact element in a solution.
    enum class ContactStatus
    {
      separated, // N = 0 (no contact)
      stick,     // in contact, ||T|| < -mu N, u_T = 0
      slip       // in contact, ||T|| = -mu N
    };

    std::string
    to_string(const ContactStatus status);
  } // namespace contact
} // namespace dpana

#endif
