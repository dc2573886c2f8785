// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_io_fclib_matrices_h
#define dpana_io_fclib_matrices_h

#include <deal.II/base/hdf5.h>

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace dpana
{
  namespace io
  {
    namespace internal
    {
      /**
       * The matrices of an FCLIB file in the CSparse layout of FCLIB: nz >= 0
       * triplets, nz = -1 compressed columns, nz = -2 compressed rows.
       */
      struct SparseMatrix
      {
        int                 m = 0, n = 0, nz = -1, nzmax = 0;
        std::vector<int>    p, i;
        std::vector<double> x;
      };

      /**
       * A dense matrix in compressed columns, entries with |x| <= threshold
       * dropped.
       */
      SparseMatrix
      compress_columns(const Eigen::MatrixXd &dense, const double threshold);

      /**
       * Writes @p matrix as the group @p name of @p parent.
       */
      void
      write_matrix(const dealii::HDF5::Group &parent,
                   const std::string         &name,
                   const SparseMatrix        &matrix);

      /**
       * The arrays of a sparse matrix group as read, unchecked. They are
       * checked by to_dense() after every deal.II HDF5 object is closed:
       * deal.II aborts the program if an exception passes while one of its
       * HDF5 objects is alive.
       */
      struct RawSparse
      {
        std::vector<int>    nzmax, m, n, nz, p, i;
        std::vector<double> x;
      };

      RawSparse
      read_raw_sparse(const dealii::HDF5::Group &parent,
                      const std::string         &name);

      /**
       * The one integer of @p v; otherwise an InputError naming @p path.
       */
      int
      single_int(const std::vector<int> &v, const std::string &path);

      /**
       * Expands a sparse matrix to a dense one. Every size and index is
       * checked, with a one-line dpana::InputError naming the item; @p path
       * is the start of the message, e.g. "fclib: file 'x.hdf5':
       * /fclib_local/W".
       */
      Eigen::MatrixXd
      to_dense(const RawSparse &s, const std::string &path);

      /**
       * A vector of @p expected_size doubles; otherwise an InputError naming
       * @p path.
       */
      Eigen::VectorXd
      to_vector(const std::vector<double> &v,
                const std::string         &path,
                const Eigen::Index         expected_size);

      std::vector<double>
      to_std(const Eigen::VectorXd &v);
    } // namespace internal
  }   // namespace io
} // namespace dpana

#endif
