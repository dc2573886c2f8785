// Mapping between dpana's condensed contact problem and the friction contact
// problem of Siconos numerics, used by the cross-check tests and by the
// benchmark benchmarks/solver_vs_siconos.
//
// @sect3{The two sign conventions}
//
// dpana follows the reference formulation: compressive normal traction N <= 0,
// admissible normal displacement u_N <= 0, and
// @f[
//   u = A r + D .
// @f]
// Siconos (and FCLIB) write the same problem with the reaction r_s in the
// Coulomb cone ||r_{s,T}|| <= mu r_{s,N} (so r_{s,N} >= 0) and the relative
// velocity u_s with u_{s,N} >= 0 (separation positive):
// @f[
//   u_s = M r_s + q .
// @f]
// Both problems are the same if r_s = -r and u_s = -u: then
// u_s = -(A r + D) = A r_s - D, that is M = A and q = -D. The slip rule
// u_T = -lambda T of the reference formulation becomes u_{s,T} = -lambda
// r_{s,T}, which is exactly Coulomb's law of maximal dissipation in the Siconos
// convention, and the per contact ordering [N, T_1, T_2] is the same on both
// sides, so no permutation is needed. In 3D Siconos knows only the exact disc,
// so the matching dpana cone model is ConeModel::disc (in 2D
// ConeModel::interval).
//
// The pure sign mapping (struct FrictionContactData and its two functions)
// needs nothing but Eigen and is always available; everything that calls
// Siconos itself is compiled only when DPANA_WITH_SICONOS is defined.
#ifndef dpana_tests_contact_siconos_adapter_h
#define dpana_tests_contact_siconos_adapter_h

#include <dpana/contact/problem.h>

#include <Eigen/Dense>

#include <stdexcept>
#include <string>

#ifdef DPANA_WITH_SICONOS
#  include <SiconosConfig.h>
// The order of the following includes matters little, they are C headers
// with their own extern "C" guards.
#  include <chrono>
#  include <cstdlib>
#  include <cstring>
#  include <memory>

#  include <CSparseMatrix.h>
#  include <FrictionContactProblem.h>
#  include <Friction_cst.h>
#  include <NonSmoothDrivers.h>
#  include <NumericsMatrix.h>
#  include <SolverOptions.h>
#  include <SparseBlockMatrix.h>
#endif

namespace dpana
{
  namespace contact
  {
    namespace siconos_adapter
    {
      // @sect4{The problem in the Siconos / FCLIB convention}
      //
      // A plain Eigen copy of (dimension, M, q, mu): the data of a Siconos
      // FrictionContactProblem before it is handed to the C library.
      struct FrictionContactData
      {
        unsigned int    dim = 2;
        Eigen::MatrixXd M;
        Eigen::VectorXd q;
        Eigen::VectorXd mu;
      };

      // dpana -> Siconos: M = A, q = -D. Floating bodies (rows G r = e) have
      // no counterpart in a Siconos FrictionContactProblem and are rejected,
      // and so is the friction polygon, which Siconos does not know.
      inline FrictionContactData
      to_siconos_convention(const ContactProblem &problem)
      {
        problem.validate();
        if (problem.n_equalities() != 0)
          throw std::invalid_argument(
            "siconos_adapter: ContactProblem.G must be empty (floating bodies "
            "have no Siconos FrictionContactProblem counterpart)");
        if (problem.cone == ConeModel::polygon)
          throw std::invalid_argument(
            "siconos_adapter: ContactProblem.cone must be interval (2D) or "
            "disc (3D), Siconos solves the exact Coulomb cone only");
        FrictionContactData data;
        data.dim = problem.dim;
        data.M   = problem.A;
        data.q   = -problem.D;
        data.mu  = problem.mu;
        return data;
      }

      // Siconos -> dpana: the inverse map, A = M, D = -q. The cone model is
      // the exact one of the dimension.
      inline ContactProblem
      from_siconos_convention(const FrictionContactData &data)
      {
        ContactProblem problem;
        problem.dim  = data.dim;
        problem.A    = data.M;
        problem.D    = -data.q;
        problem.mu   = data.mu;
        problem.cone = (data.dim == 3 ? ConeModel::disc : ConeModel::interval);
        problem.validate();
        return problem;
      }

      // Both unknowns, tractions and displacements, change sign.
      inline Eigen::VectorXd
      to_siconos_sign(const Eigen::VectorXd &dpana_vector)
      {
        return -dpana_vector;
      }

      inline Eigen::VectorXd
      from_siconos_sign(const Eigen::VectorXd &siconos_vector)
      {
        return -siconos_vector;
      }

#ifdef DPANA_WITH_SICONOS
      // @sect4{Calling Siconos}

      // The Siconos solvers the tests and the benchmark use.
      enum class PeerSolver
      {
        fc2d_nsgs,   // 2D nonsmooth Gauss-Seidel (exact local solves)
        fc2d_lemke,  // 2D: reformulation as an LCP, Lemke's pivoting method
        fc2d_enum,   // 2D: enumeration of the LCP (tiny problems only)
        fc3d_nsgs,   // 3D nonsmooth Gauss-Seidel, local nonsmooth Newton
        fc3d_nsn_ac, // 3D nonsmooth Newton on Alart-Curnier's function
        fc3d_nsn_nm, // 3D nonsmooth Newton on the natural map
        fc3d_pfp     // 3D Panagiotopoulos fixed point (N/T splitting)
      };

      inline std::string
      to_string(const PeerSolver solver)
      {
        switch (solver)
          {
            case PeerSolver::fc2d_nsgs:
              return "siconos_fc2d_nsgs";
            case PeerSolver::fc2d_lemke:
              return "siconos_fc2d_lemke";
            case PeerSolver::fc2d_enum:
              return "siconos_fc2d_enum";
            case PeerSolver::fc3d_nsgs:
              return "siconos_fc3d_nsgs";
            case PeerSolver::fc3d_nsn_ac:
              return "siconos_fc3d_nsn_ac";
            case PeerSolver::fc3d_nsn_nm:
              return "siconos_fc3d_nsn_nm";
            case PeerSolver::fc3d_pfp:
              return "siconos_fc3d_pfp";
          }
        return "unknown";
      }

      inline bool
      is_2d(const PeerSolver solver)
      {
        return solver == PeerSolver::fc2d_nsgs ||
               solver == PeerSolver::fc2d_lemke ||
               solver == PeerSolver::fc2d_enum;
      }

      struct PeerOptions
      {
        PeerSolver solver = PeerSolver::fc3d_nsgs;
        // Tolerance on Siconos' own error measure (relative to ||q||; it is
        // NOT dpana's residual, which the caller must evaluate separately).
        double tolerance = 1e-12;
        // 0 keeps Siconos' default for the solver.
        int max_iterations = 0;
      };

      struct PeerResult
      {
        Eigen::VectorXd r; // tractions, dpana convention (N <= 0)
        Eigen::VectorXd u; // displacements u = A r + D, dpana convention
        int             info       = -1; // 0 when Siconos reports convergence
        int             iterations = 0;
        double          peer_error = 0; // Siconos' own error at the end
        double          seconds    = 0; // wall time of the driver call
      };

      namespace internal
      {
        // Owner of the C structures: a FrictionContactProblem whose M, q, mu
        // are allocated with malloc, so frictionContactProblem_free releases
        // all of them.
        struct ProblemDeleter
        {
          void
          operator()(::FrictionContactProblem *p) const
          {
            if (p != nullptr)
              frictionContactProblem_free(p);
          }
        };
        struct OptionsDeleter
        {
          void
          operator()(::SolverOptions *o) const
          {
            if (o != nullptr)
              solver_options_delete(o);
          }
        };
        using ProblemPtr =
          std::unique_ptr<::FrictionContactProblem, ProblemDeleter>;
        using OptionsPtr = std::unique_ptr<::SolverOptions, OptionsDeleter>;

        inline double *
        malloc_copy(const Eigen::VectorXd &v)
        {
          double *p = static_cast<double *>(
            std::malloc(sizeof(double) * std::max<Eigen::Index>(v.size(), 1)));
          if (p == nullptr)
            throw std::bad_alloc();
          std::memcpy(p, v.data(), sizeof(double) * v.size());
          return p;
        }

        // Dense M (column major, as Eigen and as Siconos' NM_DENSE). With
        // sparse_block = true the matrix is stored instead as a sparse block
        // matrix of d x d blocks, which the Panagiotopoulos fixed point of
        // Siconos needs (it splits M into its N and T parts block by block).
        inline ProblemPtr
        make_problem(const FrictionContactData &data, const bool sparse_block)
        {
          const int n  = static_cast<int>(data.q.size());
          const int nc = static_cast<int>(data.mu.size());

          NumericsMatrix *M = NM_create(NM_DENSE, n, n);
          std::memcpy(M->matrix0, data.M.data(), sizeof(double) * n * n);

          if (sparse_block)
            {
              // dense -> compressed column -> blocks of size d.
              NumericsMatrix *S = NM_create(NM_SPARSE, n, n);
              NM_copy_to_sparse(M, S, 0.0);
              NM_free(M);
              SparseBlockStructuredMatrix *sbm = SBM_new();
              const int                    err =
                SBM_from_csparse(static_cast<int>(data.dim), NM_csc(S), sbm);
              NM_free(S);
              if (err != 0)
                throw std::runtime_error(
                  "siconos_adapter: SBM_from_csparse failed");
              M = NM_new_SBM(n, n, sbm);
            }

          ::FrictionContactProblem *p =
            frictionContactProblem_new_with_data(static_cast<int>(data.dim),
                                                 nc,
                                                 M,
                                                 malloc_copy(data.q),
                                                 malloc_copy(data.mu));
          return ProblemPtr(p);
        }

        inline int
        solver_id(const PeerSolver solver)
        {
          switch (solver)
            {
              case PeerSolver::fc2d_nsgs:
                return SICONOS_FRICTION_2D_NSGS;
              case PeerSolver::fc2d_lemke:
                return SICONOS_FRICTION_2D_LEMKE;
              case PeerSolver::fc2d_enum:
                return SICONOS_FRICTION_2D_ENUM;
              case PeerSolver::fc3d_nsgs:
                return SICONOS_FRICTION_3D_NSGS;
              case PeerSolver::fc3d_nsn_ac:
                return SICONOS_FRICTION_3D_NSN_AC;
              case PeerSolver::fc3d_nsn_nm:
                return SICONOS_FRICTION_3D_NSN_NM;
              case PeerSolver::fc3d_pfp:
                return SICONOS_FRICTION_3D_PFP;
            }
          return -1;
        }
      } // namespace internal

      // Solve a dpana ContactProblem with a Siconos solver and return the
      // solution in dpana's convention. The starting point is r = 0 unless
      // initial_r (dpana convention) is given.
      inline PeerResult
      solve(const ContactProblem  &problem,
            const PeerOptions     &options,
            const Eigen::VectorXd *initial_r = nullptr)
      {
        const FrictionContactData data = to_siconos_convention(problem);
        if (is_2d(options.solver) != (data.dim == 2))
          throw std::invalid_argument(
            "siconos_adapter: solver " + to_string(options.solver) +
            " does not match ContactProblem.dim = " + std::to_string(data.dim));

        internal::ProblemPtr fcp =
          internal::make_problem(data, options.solver == PeerSolver::fc3d_pfp);
        internal::OptionsPtr so(
          solver_options_create(internal::solver_id(options.solver)));
        if (!so)
          throw std::runtime_error("siconos_adapter: solver_options_create "
                                   "failed for " +
                                   to_string(options.solver));
        so->dparam[SICONOS_DPARAM_TOL] = options.tolerance;
        if (options.max_iterations > 0)
          so->iparam[SICONOS_IPARAM_MAX_ITER] = options.max_iterations;
        else if (options.solver == PeerSolver::fc3d_nsn_nm)
          // The default of this version of Siconos is a single Newton
          // iteration, which is not a usable solver; use the same default
          // as the Alart-Curnier Newton method.
          so->iparam[SICONOS_IPARAM_MAX_ITER] = 200;

        const Eigen::Index n = data.q.size();
        Eigen::VectorXd    r_s =
          (initial_r != nullptr ? to_siconos_sign(*initial_r) :
                                  Eigen::VectorXd::Zero(n));
        if (r_s.size() != n)
          throw std::invalid_argument(
            "siconos_adapter: initial_r has the wrong size");
        Eigen::VectorXd u_s = Eigen::VectorXd::Zero(n);

        PeerResult result;
        const auto start = std::chrono::steady_clock::now();
        if (data.dim == 2)
          result.info =
            fc2d_driver(fcp.get(), r_s.data(), u_s.data(), so.get());
        else
          result.info =
            fc3d_driver(fcp.get(), r_s.data(), u_s.data(), so.get());
        result.seconds = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start)
                           .count();

        result.iterations = so->iparam[SICONOS_IPARAM_ITER_DONE];
        result.peer_error = so->dparam[SICONOS_DPARAM_RESIDU];

        // Back to dpana's convention. The displacement is recomputed from
        // the tractions, u = A r + D, so that it is consistent with r even
        // if a solver returns a velocity of an earlier iterate.
        result.r = from_siconos_sign(r_s);
        result.u = problem.A * result.r + problem.D;
        return result;
      }
#endif // DPANA_WITH_SICONOS
    }  // namespace siconos_adapter
  }    // namespace contact
} // namespace dpana

#endif
