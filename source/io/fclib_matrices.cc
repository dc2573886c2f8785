// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The sparse matrices of FCLIB files (include/dpana/io/fclib_matrices.h).

#include <dpana/base/exceptions.h>
#include <dpana/io/fclib_matrices.h>

#include <cmath>

namespace dpana
{
  namespace io
  {
    namespace internal
    {
      // @sect3{Sparse matrices in the CSparse layout}

      // Compressed columns of a dense matrix, keeping |a_ij| > threshold
      // (and a_ij != 0).
      SparseMatrix
      compress_columns(const Eigen::MatrixXd &dense, const double threshold)
      {
        SparseMatrix s;
        s.m  = static_cast<int>(dense.rows());
        s.n  = static_cast<int>(dense.cols());
        s.nz = -1;
        s.p.assign(s.n + 1, 0);
        for (int col = 0; col < s.n; ++col)
          {
            for (int row = 0; row < s.m; ++row)
              {
                const double value = dense(row, col);
                if (value != 0.0 && std::abs(value) > threshold)
                  {
                    s.i.push_back(row);
                    s.x.push_back(value);
                  }
              }
            s.p[col + 1] = static_cast<int>(s.x.size());
          }
        s.nzmax = static_cast<int>(s.x.size());
        return s;
      }

      void
      write_matrix(const dealii::HDF5::Group &parent,
                   const std::string         &name,
                   const SparseMatrix        &s)
      {
        dealii::HDF5::Group group = parent.create_group(name);
        group.write_dataset("nzmax", std::vector<int>{s.nzmax});
        group.write_dataset("m", std::vector<int>{s.m});
        group.write_dataset("n", std::vector<int>{s.n});
        group.write_dataset("nz", std::vector<int>{s.nz});
        group.write_dataset("p", s.p);
        group.write_dataset("i", s.i);
        group.write_dataset("x", s.x);
      }


      RawSparse
      read_raw_sparse(const dealii::HDF5::Group &parent,
                      const std::string         &name)
      {
        const dealii::HDF5::Group group = parent.open_group(name);
        RawSparse                 raw;
        raw.nzmax = group.open_dataset("nzmax").read<std::vector<int>>();
        raw.m     = group.open_dataset("m").read<std::vector<int>>();
        raw.n     = group.open_dataset("n").read<std::vector<int>>();
        raw.nz    = group.open_dataset("nz").read<std::vector<int>>();
        raw.p     = group.open_dataset("p").read<std::vector<int>>();
        raw.i     = group.open_dataset("i").read<std::vector<int>>();
        raw.x     = group.open_dataset("x").read<std::vector<double>>();
        return raw;
      }

      int
      single_int(const std::vector<int> &v, const std::string &path)
      {
        if (v.size() != 1)
          throw InputError(path + " must hold one integer");
        return v[0];
      }

      // Expand a sparse matrix to a dense one. Every size and index is
      // checked, with a one-line error naming the item; @p path is the
      // start of the message, e.g. "fclib: file 'x.hdf5': /fclib_local/W".
      Eigen::MatrixXd
      to_dense(const RawSparse &s, const std::string &path)
      {
        const int                  m     = single_int(s.m, path + "/m");
        const int                  n     = single_int(s.n, path + "/n");
        const int                  nz    = single_int(s.nz, path + "/nz");
        const int                  nzmax = single_int(s.nzmax, path + "/nzmax");
        const std::vector<int>    &p     = s.p;
        const std::vector<int>    &i     = s.i;
        const std::vector<double> &x     = s.x;
        if (m < 0 || n < 0 || nzmax < 0)
          throw InputError(path + " has negative sizes");

        Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(m, n);
        auto            bad   = [&](const std::string &what) {
          return InputError(path + ": " + what);
        };
        if (nz >= 0)
          {
            // Triplets: i row indices, p column indices, x values.
            if (static_cast<int>(i.size()) < nz ||
                static_cast<int>(p.size()) < nz ||
                static_cast<int>(x.size()) < nz)
              throw bad("triplet arrays p, i, x shorter than nz = " +
                        std::to_string(nz));
            for (int k = 0; k < nz; ++k)
              {
                if (i[k] < 0 || i[k] >= m || p[k] < 0 || p[k] >= n)
                  throw bad("triplet index out of range at entry " +
                            std::to_string(k));
                dense(i[k], p[k]) += x[k];
              }
          }
        else if (nz == -1 || nz == -2)
          {
            // Compressed columns (p: n+1 column pointers, i: row indices)
            // or compressed rows (p: m+1 row pointers, i: column indices).
            const bool columns = (nz == -1);
            const int  outer   = columns ? n : m;
            const int  inner   = columns ? m : n;
            if (static_cast<int>(p.size()) != outer + 1)
              throw bad("p must have " + std::to_string(outer + 1) +
                        " entries, has " + std::to_string(p.size()));
            if (p[0] != 0 || p[outer] > nzmax ||
                static_cast<int>(i.size()) < p[outer] ||
                static_cast<int>(x.size()) < p[outer])
              throw bad("inconsistent pointers p, nzmax, i, x");
            for (int o = 0; o < outer; ++o)
              {
                if (p[o + 1] < p[o])
                  throw bad("pointers p are not monotone");
                for (int k = p[o]; k < p[o + 1]; ++k)
                  {
                    if (i[k] < 0 || i[k] >= inner)
                      throw bad("index out of range at entry " +
                                std::to_string(k));
                    if (columns)
                      dense(i[k], o) += x[k];
                    else
                      dense(o, i[k]) += x[k];
                  }
              }
          }
        else
          throw bad("unknown storage nz = " + std::to_string(nz));
        return dense;
      }

      // A double vector of a given size.
      Eigen::VectorXd
      to_vector(const std::vector<double> &v,
                const std::string         &path,
                const Eigen::Index         expected_size)
      {
        if (static_cast<Eigen::Index>(v.size()) != expected_size)
          throw InputError(path + " has " + std::to_string(v.size()) +
                           " entries, expected " +
                           std::to_string(expected_size));
        return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
      }

      std::vector<double>
      to_std(const Eigen::VectorXd &v)
      {
        return std::vector<double>(v.data(), v.data() + v.size());
      }
    } // namespace internal
  }   // namespace io
} // namespace dpana
