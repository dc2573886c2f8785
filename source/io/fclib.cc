// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// FCLIB local problems in HDF5: see include/dpana/io/fclib.h for the layout
// and the sign convention.
//
// The numbers are read and written with deal.II's HDF5 wrappers. Two things
// those wrappers do not offer are done with the HDF5 C library underneath
// them (the same library deal.II is linked with): asking whether a group or
// dataset exists before opening it (so that a missing item gives a one-line
// error instead of an HDF5 error stack), and fixed-length string datasets,
// which is how FCLIB stores the text of `info` (the wrappers store strings
// only as attributes).

#include <dpana/base/exceptions.h>
#include <dpana/io/fclib.h>
#include <dpana/io/fclib_matrices.h>

#include <deal.II/base/hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <hdf5.h>

namespace dpana
{
  namespace io
  {
    using namespace internal;

    namespace
    {
      // @sect3{Small HDF5 helpers}

      // While an object of this class lives, the HDF5 library does not print
      // its error stack to stderr: failures are reported by dpana's own
      // one-line messages instead.
      class SilenceHDF5Errors
      {
      public:
        SilenceHDF5Errors()
        {
          H5Eget_auto2(H5E_DEFAULT, &old_function, &old_data);
          H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        }
        ~SilenceHDF5Errors()
        {
          H5Eset_auto2(H5E_DEFAULT, old_function, old_data);
        }

      private:
        H5E_auto2_t old_function = nullptr;
        void       *old_data     = nullptr;
      };

      // An HDF5 file opened with the C library, closed on destruction.
      class RawFile
      {
      public:
        RawFile(const std::string &filename, const bool read_write)
        {
          id = H5Fopen(filename.c_str(),
                       read_write ? H5F_ACC_RDWR : H5F_ACC_RDONLY,
                       H5P_DEFAULT);
          if (id < 0)
            throw InputError("fclib: cannot open HDF5 file '" + filename + "'");
        }
        ~RawFile()
        {
          H5Fclose(id);
        }
        RawFile(const RawFile &) = delete;
        RawFile &
        operator=(const RawFile &) = delete;

        // Whether the absolute path (e.g. "/fclib_local/W/x") exists. Every
        // prefix is tested in turn, as H5Lexists requires.
        bool
        exists(const std::string &path) const
        {
          std::string::size_type pos = 0;
          while (pos != std::string::npos)
            {
              pos                    = path.find('/', pos + 1);
              const std::string part = path.substr(0, pos);
              if (part.empty() || part == "/")
                continue;
              if (H5Lexists(id, part.c_str(), H5P_DEFAULT) <= 0)
                return false;
            }
          return true;
        }

        // A fixed-length string dataset, as FCLIB writes it.
        std::string
        read_string(const std::string &path) const
        {
          const hid_t dataset = H5Dopen2(id, path.c_str(), H5P_DEFAULT);
          if (dataset < 0)
            return "";
          const hid_t       type = H5Dget_type(dataset);
          const std::size_t size = H5Tget_size(type);
          std::string       text;
          if (H5Tget_class(type) == H5T_STRING && !H5Tis_variable_str(type))
            {
              std::vector<char> buffer(size + 1, '\0');
              if (H5Dread(dataset,
                          type,
                          H5S_ALL,
                          H5S_ALL,
                          H5P_DEFAULT,
                          buffer.data()) >= 0)
                text = std::string(buffer.data());
            }
          H5Tclose(type);
          H5Dclose(dataset);
          return text;
        }

        void
        write_string(const std::string &path, const std::string &text) const
        {
          const hid_t type = H5Tcopy(H5T_C_S1);
          H5Tset_size(type, text.size() + 1);
          H5Tset_strpad(type, H5T_STR_NULLTERM);
          const hid_t space   = H5Screate(H5S_SCALAR);
          const hid_t dataset = H5Dcreate2(id,
                                           path.c_str(),
                                           type,
                                           space,
                                           H5P_DEFAULT,
                                           H5P_DEFAULT,
                                           H5P_DEFAULT);
          const bool  ok      = dataset >= 0 && H5Dwrite(dataset,
                                                   type,
                                                   H5S_ALL,
                                                   H5S_ALL,
                                                   H5P_DEFAULT,
                                                   text.c_str()) >= 0;
          if (dataset >= 0)
            H5Dclose(dataset);
          H5Sclose(space);
          H5Tclose(type);
          if (!ok)
            throw InputError("fclib: cannot write the string dataset '" + path +
                             "'");
        }

      private:
        hid_t id = -1;
      };

      // Check that @p filename exists and is an HDF5 file, with one-line
      // errors otherwise.
      void
      check_readable_hdf5(const std::string &filename)
      {
        if (!std::filesystem::exists(filename))
          throw InputError("fclib: file '" + filename + "' does not exist");
        if (!std::ifstream(filename).good())
          throw InputError("fclib: file '" + filename +
                           "' cannot be opened for reading");
        SilenceHDF5Errors silence;
        if (H5Fis_hdf5(filename.c_str()) <= 0)
          throw InputError("fclib: file '" + filename +
                           "' is not an HDF5 file");
      }

    } // namespace

    // @sect3{Writing}

    void
    write_fclib_local(const std::string             &filename,
                      const contact::ContactProblem &problem,
                      const FclibInfo               &info,
                      const double                   drop_tolerance)
    {
      problem.validate();
      if (!(drop_tolerance >= 0.0))
        throw std::invalid_argument(
          "write_fclib_local: drop_tolerance must be >= 0");
      const std::filesystem::path parent =
        std::filesystem::path(filename).parent_path();
      if (!parent.empty() && !std::filesystem::is_directory(parent))
        throw InputError("fclib: cannot create file '" + filename +
                         "': directory '" + parent.string() +
                         "' does not exist");

      const double threshold =
        drop_tolerance *
        (problem.A.size() > 0 ? problem.A.cwiseAbs().maxCoeff() : 0.0);

      FclibInfo text = info;
      if (problem.cone == contact::ConeModel::polygon)
        text.math_info +=
          std::string(text.math_info.empty() ? "" : " ") +
          "dpana: the problem used a " + std::to_string(problem.polygon_sides) +
          "-sided friction polygon; FCLIB stores the exact disc.";
      const bool has_info = !text.title.empty() || !text.description.empty() ||
                            !text.math_info.empty();

      // The compressed matrices are built before the file is opened: no
      // exception may pass while a deal.II HDF5 object is alive (deal.II
      // then aborts the program), and the only remaining failure, creating
      // the file, is ruled out as far as possible by the checks above.
      const SparseMatrix W = compress_columns(problem.A, threshold);
      SparseMatrix       V, R;
      if (problem.n_equalities() > 0)
        {
          V = compress_columns(problem.G.transpose(), 0.0);
          R = compress_columns(Eigen::MatrixXd::Zero(problem.n_equalities(),
                                                     problem.n_equalities()),
                               0.0);
        }
      {
        SilenceHDF5Errors   silence;
        dealii::HDF5::File  file(filename,
                                dealii::HDF5::File::FileAccessMode::create);
        dealii::HDF5::Group local = file.create_group("fclib_local");
        local.write_dataset("spacedim",
                            std::vector<int>{static_cast<int>(problem.dim)});

        // W = A, the Delassus matrix in FCLIB's words.
        write_matrix(local, "W", W);

        // Equality rows of floating bodies: V = G^T, R = 0, s = e.
        if (problem.n_equalities() > 0)
          {
            write_matrix(local, "V", V);
            write_matrix(local, "R", R);
          }

        dealii::HDF5::Group vectors = local.create_group("vectors");
        vectors.write_dataset("q", to_std(-problem.D));
        vectors.write_dataset("mu", to_std(problem.mu));
        if (problem.n_equalities() > 0)
          vectors.write_dataset("s", to_std(problem.e));
        if (has_info)
          local.create_group("info");
      }

      // The text of info as FCLIB's string datasets (see the top of this
      // file for why the C library is used here).
      if (has_info)
        {
          SilenceHDF5Errors silence;
          RawFile           raw(filename, true);
          if (!text.title.empty())
            raw.write_string("/fclib_local/info/title", text.title);
          if (!text.description.empty())
            raw.write_string("/fclib_local/info/description", text.description);
          if (!text.math_info.empty())
            raw.write_string("/fclib_local/info/math_info", text.math_info);
        }
    }

    // @sect3{Reading}

    contact::ContactProblem
    read_fclib_local(const std::string &filename, FclibInfo *info)
    {
      check_readable_hdf5(filename);
      SilenceHDF5Errors silence;
      const std::string where = "fclib: file '" + filename + "': ";

      // Everything that must be there, checked with the C library before
      // deal.II opens the file (see RawSparse for why).
      bool has_V = false;
      {
        const RawFile            raw(filename, false);
        std::vector<std::string> required = {"/fclib_local",
                                             "/fclib_local/spacedim",
                                             "/fclib_local/W",
                                             "/fclib_local/vectors",
                                             "/fclib_local/vectors/q",
                                             "/fclib_local/vectors/mu"};
        has_V                             = raw.exists("/fclib_local/V");
        const bool has_R                  = raw.exists("/fclib_local/R");
        if (has_V != has_R)
          throw InputError(where + "/fclib_local/V and /fclib_local/R must "
                                   "be present together");
        for (const std::string matrix : {"W", "V", "R"})
          if (matrix == "W" || has_V)
            for (const char *item : {"nzmax", "m", "n", "nz", "p", "i", "x"})
              required.push_back("/fclib_local/" + matrix + "/" + item);
        if (has_V)
          required.push_back("/fclib_local/vectors/s");
        for (const std::string &item : required)
          if (!raw.exists(item))
            throw InputError(where + "no " + item +
                             (item == "/fclib_local" ?
                                " group (not an FCLIB local problem)" :
                                ""));
      }

      // Read the raw datasets.
      std::vector<int>    spacedim;
      RawSparse           W, V, R;
      std::vector<double> q, mu, s;
      {
        const dealii::HDF5::File  file(filename,
                                      dealii::HDF5::File::FileAccessMode::open);
        const dealii::HDF5::Group local = file.open_group("fclib_local");
        spacedim = local.open_dataset("spacedim").read<std::vector<int>>();
        W        = read_raw_sparse(local, "W");
        const dealii::HDF5::Group vectors = local.open_group("vectors");
        q  = vectors.open_dataset("q").read<std::vector<double>>();
        mu = vectors.open_dataset("mu").read<std::vector<double>>();
        if (has_V)
          {
            V = read_raw_sparse(local, "V");
            R = read_raw_sparse(local, "R");
            s = vectors.open_dataset("s").read<std::vector<double>>();
          }
      }

      // Check and convert to dpana's convention.
      contact::ContactProblem problem;
      const int dim = single_int(spacedim, where + "/fclib_local/spacedim");
      if (dim != 2 && dim != 3)
        throw InputError(where + "/fclib_local/spacedim must be 2 or 3, is " +
                         std::to_string(dim));
      problem.dim             = dim;
      problem.A               = to_dense(W, where + "/fclib_local/W");
      const Eigen::Index size = problem.A.rows();
      if (problem.A.cols() != size || size % dim != 0)
        throw InputError(where + "/fclib_local/W must be square with a "
                                 "multiple of spacedim rows");
      problem.D  = -to_vector(q, where + "/fclib_local/vectors/q", size);
      problem.mu = to_vector(mu, where + "/fclib_local/vectors/mu", size / dim);
      problem.cone =
        (dim == 3 ? contact::ConeModel::disc : contact::ConeModel::interval);
      if (has_V)
        {
          const Eigen::MatrixXd Vd = to_dense(V, where + "/fclib_local/V");
          const Eigen::MatrixXd Rd = to_dense(R, where + "/fclib_local/R");
          if (Vd.rows() != size || Rd.rows() != Vd.cols() ||
              Rd.cols() != Vd.cols())
            throw InputError(where + "/fclib_local/V must be " +
                             std::to_string(size) + " x p and R p x p");
          if (Rd.size() > 0 && Rd.cwiseAbs().maxCoeff() != 0.0)
            throw InputError(where + "/fclib_local/R is not zero; dpana's "
                                     "equality rows G r = e have no R term");
          problem.G = Vd.transpose();
          problem.e = to_vector(s, where + "/fclib_local/vectors/s", Vd.cols());
        }
      try
        {
          problem.validate();
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError(where + e.what());
        }

      if (info != nullptr)
        {
          const RawFile raw(filename, false);
          *info             = FclibInfo();
          info->title       = raw.read_string("/fclib_local/info/title");
          info->description = raw.read_string("/fclib_local/info/description");
          info->math_info   = raw.read_string("/fclib_local/info/math_info");
        }
      return problem;
    }

    // @sect3{Solutions}

    void
    write_fclib_solution(const std::string     &filename,
                         const Eigen::VectorXd &r,
                         const Eigen::VectorXd &u,
                         const Eigen::VectorXd &alpha)
    {
      const contact::ContactProblem problem = read_fclib_local(filename);
      const Eigen::Index            size    = problem.D.size();
      if (r.size() != size || u.size() != size)
        throw std::invalid_argument("write_fclib_solution: r and u must have " +
                                    std::to_string(size) + " entries");
      if (alpha.size() != problem.e.size())
        throw std::invalid_argument("write_fclib_solution: alpha must have " +
                                    std::to_string(problem.e.size()) +
                                    " entries");
      SilenceHDF5Errors silence;
      {
        const RawFile raw(filename, false);
        if (raw.exists("/solution"))
          throw InputError("fclib: file '" + filename +
                           "' already holds a /solution");
      }
      dealii::HDF5::File  file(filename,
                              dealii::HDF5::File::FileAccessMode::open);
      dealii::HDF5::Group solution = file.create_group("solution");
      solution.write_dataset("r", to_std(-r));
      solution.write_dataset("u", to_std(-u));
      if (alpha.size() > 0)
        solution.write_dataset("l", to_std(-alpha));
    }

    bool
    read_fclib_solution(const std::string &filename,
                        Eigen::VectorXd   &r,
                        Eigen::VectorXd   &u,
                        Eigen::VectorXd   *alpha)
    {
      const contact::ContactProblem problem = read_fclib_local(filename);
      SilenceHDF5Errors             silence;
      bool                          has_l = false;
      {
        const RawFile raw(filename, false);
        if (!raw.exists("/solution/r") || !raw.exists("/solution/u"))
          return false;
        has_l = raw.exists("/solution/l");
      }
      std::vector<double> rs, us, ls;
      {
        const dealii::HDF5::File  file(filename,
                                      dealii::HDF5::File::FileAccessMode::open);
        const dealii::HDF5::Group solution = file.open_group("solution");
        rs = solution.open_dataset("r").read<std::vector<double>>();
        us = solution.open_dataset("u").read<std::vector<double>>();
        if (has_l)
          ls = solution.open_dataset("l").read<std::vector<double>>();
      }
      const std::string  where = "fclib: file '" + filename + "': /solution";
      const Eigen::Index size  = problem.D.size();
      r                        = -to_vector(rs, where + "/r", size);
      u                        = -to_vector(us, where + "/u", size);
      if (alpha != nullptr)
        *alpha =
          has_l ?
            Eigen::VectorXd(-to_vector(ls, where + "/l", problem.e.size())) :
            Eigen::VectorXd();
      return true;
    }
  } // namespace io
} // namespace dpana
