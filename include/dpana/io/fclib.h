// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Reading and writing condensed contact problems as FCLIB *local* problems
// (HDF5), the exchange format of the frictional contact community, so that
// a problem condensed by dpana can be handed to other solvers and problems
// from the FCLIB collection can be solved by dpana's contact solvers.
//
// @sect3{The file layout}
//
// One HDF5 file holds, under the group `/fclib_local`,
//   - `spacedim`          int[1], 2 or 3;
//   - `W/`                the Delassus (compliance) matrix, sparse, with the
//                         int[1] datasets `nzmax`, `m` (rows), `n` (columns),
//                         `nz` (-1: compressed columns, -2: compressed rows,
//                         >= 0: triplet with nz entries) and the arrays `p`,
//                         `i` (int) and `x` (double) of the CSparse
//                         convention (compressed columns: p[n+1] column
//                         pointers, i[nzmax] row indices; triplets: i row
//                         and p column indices);
//   - `V/`, `R/`          optional, same layout (equality constraints, see
//                         below);
//   - `vectors/q`         double[m], `vectors/mu` double[m / spacedim],
//                         `vectors/s` double[p] if V and R are present;
//   - `info/`             optional string datasets `title`, `description`,
//                         `math_info`;
// and, optionally, a solution under `/solution` with `r` and `u` (double[m]).
// dpana writes compressed columns (nz = -1) and reads all three forms.
//
// @sect3{The sign convention}
//
// FCLIB (like Siconos) writes the local problem as
// @f[
//   u_s = W r_s + V \lambda + q, \qquad V^T r_s + R \lambda + s = 0,
// @f]
// with the reaction r_s in the Coulomb cone ||r_{s,T}|| <= mu r_{s,N}
// (compression positive) and the velocity u_s with u_{s,N} >= 0
// (separation positive). dpana's problem (problem.h) is
// u = A r + D + G^T alpha, G r = e, with N <= 0 and u_N <= 0. The two are
// the same problem under
// @f[
//   r_s = -r,\quad u_s = -u,\quad W = A,\quad q = -D,\quad
//   V = G^T,\quad R = 0,\quad s = e,\quad \lambda = -\alpha ,
// @f]
// and the per-contact ordering [n, t1, t2] of FCLIB is dpana's interleaved
// ordering [N, T_1, T_2], so no permutation is needed. A file whose R is not
// zero has no dpana counterpart and is rejected. The friction set of a
// problem read from FCLIB is the exact Coulomb cone: ConeModel::interval in
// 2D, ConeModel::disc in 3D (a problem written with ConeModel::polygon is
// stored as the disc problem: FCLIB has no polygonal cone, and the writer
// says so in `info/math_info`).
#ifndef dpana_io_fclib_h
#define dpana_io_fclib_h

#include <dpana/contact/problem.h>

#include <Eigen/Dense>

#include <string>

namespace dpana
{
  namespace io
  {
    // The optional free text of `/fclib_local/info`.
    struct FclibInfo
    {
      std::string title;
      std::string description;
      std::string math_info;
    };

    // Write @p problem as an FCLIB local problem to @p filename (created or
    // truncated). Entries of A with |A_ij| <= drop_tolerance * max|A| are not
    // stored (the default 0 drops exact zeros only, so that the round trip
    // is exact). Throws dpana::InputError with a one-line message if the
    // file cannot be created, std::invalid_argument if the problem is
    // invalid (ContactProblem::validate()).
    void
    write_fclib_local(const std::string             &filename,
                      const contact::ContactProblem &problem,
                      const FclibInfo               &info           = {},
                      const double                   drop_tolerance = 0.0);

    // Read the FCLIB local problem of @p filename into a ContactProblem in
    // dpana's convention (see above). If @p info is not null, the text of
    // `/fclib_local/info` is stored there (empty strings where absent).
    // Throws dpana::InputError with a one-line message naming the file and
    // the missing or malformed item (no file, not HDF5, no `/fclib_local`,
    // wrong sizes, non-zero R).
    contact::ContactProblem
    read_fclib_local(const std::string &filename, FclibInfo *info = nullptr);

    // Add a solution (dpana convention: tractions r, displacements u, rigid
    // mode amplitudes alpha if the problem has equality rows) to an existing
    // FCLIB file written by write_fclib_local(), as `/solution/{r,u[,l]}` in
    // the FCLIB convention (r_s = -r, u_s = -u, l = -alpha).
    void
    write_fclib_solution(const std::string     &filename,
                         const Eigen::VectorXd &r,
                         const Eigen::VectorXd &u,
                         const Eigen::VectorXd &alpha = Eigen::VectorXd());

    // Read `/solution` back into dpana's convention. Returns false (and
    // leaves the vectors alone) if the file has no solution; throws
    // dpana::InputError if the file cannot be read.
    bool
    read_fclib_solution(const std::string &filename,
                        Eigen::VectorXd   &r,
                        Eigen::VectorXd   &u,
                        Eigen::VectorXd   *alpha = nullptr);
  } // namespace io
} // namespace dpana

#endif
