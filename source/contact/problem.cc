#include <dpana/contact/problem.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace dpana
{
  namespace contact
  {
    namespace
    {
      // The one list of the cone models, their names and the dimension they
      // belong to (the default of each dimension first).
      struct ConeModelName
      {
        ConeModel    cone;
        const char  *name;
        unsigned int dim;
      };
      const std::array<ConeModelName, 3> cone_model_table = {
        {{ConeModel::interval, "interval", 2},
         {ConeModel::disc, "disc", 3},
         {ConeModel::polygon, "polygon", 3}}};
    } // namespace



    std::string
    to_string(const ConeModel cone)
    {
      for (const auto &entry : cone_model_table)
        if (cone == entry.cone)
          return entry.name;
      return "unknown";
    }



    ConeModel
    cone_model_from_string(const std::string &name)
    {
      for (const auto &entry : cone_model_table)
        if (name == entry.name)
          return entry.cone;
      throw std::invalid_argument("contact problem: unknown cone model '" +
                                  name + "' (expected " + cone_model_names(2) +
                                  " in 2D, " + cone_model_names(3) + " in 3D)");
    }



    std::string
    cone_model_names(const unsigned int dim)
    {
      std::string names;
      for (const auto &entry : cone_model_table)
        if (entry.dim == dim)
          names += (names.empty() ? "" : "|") + std::string(entry.name);
      return names;
    }



    namespace
    {
      // max |A_ij - A_ji|, tile by tile: the transposed tile is read while
      // it is in cache (A - A^T, with one operand read across the rows of a
      // column-major matrix, took 2.5 s of a 10 092-unknown solve).
      double
      asymmetry(const Eigen::MatrixXd &A)
      {
        constexpr Eigen::Index tile = 64;
        const Eigen::Index     n    = A.rows();
        double                 most = 0.0;
        for (Eigen::Index j0 = 0; j0 < n; j0 += tile)
          for (Eigen::Index i0 = j0; i0 < n; i0 += tile)
            {
              const Eigen::Index ni = std::min(tile, n - i0),
                                 nj = std::min(tile, n - j0);
              most                  = std::max(most,
                              (A.block(i0, j0, ni, nj) -
                               A.block(j0, i0, nj, ni).transpose())
                                .cwiseAbs()
                                .maxCoeff());
            }
        return most;
      }
    } // namespace



    void
    ContactProblem::validate() const
    {
      auto fail = [](const std::string &message) {
        throw std::invalid_argument("contact problem: " + message);
      };
      if (dim != 2 && dim != 3)
        fail("dim must be 2 or 3, got " + std::to_string(dim));
      const Eigen::Index size = D.size();
      if (size % dim != 0)
        fail("D has size " + std::to_string(size) +
             ", not a multiple of dim = " + std::to_string(dim));
      const Eigen::Index n = size / dim;
      if (A.rows() != size || A.cols() != size)
        fail("A must be " + std::to_string(size) + " x " +
             std::to_string(size));
      if (mu.size() != n)
        fail("mu must have one entry per contact element (" +
             std::to_string(n) + ")");
      if (!A.allFinite())
        fail("A has a non-finite entry");
      if (!D.allFinite())
        fail("D has a non-finite entry");
      if (!mu.allFinite())
        fail("mu has a non-finite entry");
      for (Eigen::Index j = 0; j < n; ++j)
        if (mu[j] < 0)
          fail("mu[" + std::to_string(j) + "] = " + std::to_string(mu[j]) +
               " is negative");
      if (asymmetry(A) > 1e-10 * A.cwiseAbs().maxCoeff())
        fail("A is not symmetric");
      if (dim == 2 && cone != ConeModel::interval)
        fail("in 2D the friction set is the interval (cone = interval)");
      if (dim == 3 && cone == ConeModel::interval)
        fail("in 3D the friction set is a polygon or a disc, not an interval");
      if (cone == ConeModel::polygon && polygon_sides < 3)
        fail("polygon_sides must be >= 3, got " +
             std::to_string(polygon_sides));
      if (G.rows() != e.size())
        fail("G has " + std::to_string(G.rows()) + " rows but e has size " +
             std::to_string(e.size()));
      if (G.rows() > 0 && G.cols() != size)
        fail("G must have " + std::to_string(size) + " columns");
      if (!G.allFinite() || !e.allFinite())
        fail("G or e has a non-finite entry");
    }

    std::string
    to_string(const ContactStatus status)
    {
      switch (status)
        {
          case ContactStatus::separated:
            return "separated";
          case ContactStatus::stick:
            return "stick";
          case ContactStatus::slip:
            return "slip";
        }
      return "unknown";
    }
  } // namespace contact
} // namespace dpana
