// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// The fictitious supports of a floating body's free rigid motions
// (Condenser::factorize()).

#include <dpana/condensation/condenser.h>

#include <Eigen/QR>

#include <algorithm>
#include <set>
#include <vector>

namespace dpana
{
  namespace condensation
  {
    // @sect3{Fictitious supports}
    //
    // The supports: among the free degrees of freedom @p free, the m rows of
    // R picked by the column pivoting of a QR factorisation of R_F^T, so
    // that R restricted to them is as well conditioned as possible. Many
    // rows tie (every dof of a translation has the same norm), and the
    // pivoting takes the first of equals: the free dofs are taken in their
    // serial order (Body::serial_dof_index()), so that a body partitioned
    // over ranks, numbered subdomain by subdomain, gets the supports of the
    // serial run, and the same A.
    //
    // With patches around the vertices the dofs of the candidate contact
    // surface are left out if the others hold the rigid motions. A support
    // there takes the forces that the tractions put on it, and with as many
    // normal tractions as surface vertices one combination of them would
    // act on the support alone: A_NN would be singular (on the quarter
    // sphere the first vertex of the gmsh file lies on the cap). Groups of
    // faces have fewer tractions than surface vertices and keep the support
    // where it was: moving it changes A (not the answer), and on the nearly
    // incompressible block of the hard-case tests it slowed NSGS past its
    // iteration limit.
    template <int dim>
    std::vector<unsigned int>
    Condenser<dim>::choose_supports(const std::vector<unsigned int> &free) const
    {
      if (R.cols() == 0)
        return {};
      std::vector<unsigned int> off_surface;
      if (surface.options().shape ==
          contact_surface::ElementShape::vertex_patches)
        {
          std::set<dealii::types::global_dof_index> on_surface;
          for (const auto &F : surface.get_faces())
            on_surface.insert(F.dofs.begin(), F.dofs.end());
          for (const unsigned int i : free)
            if (on_surface.count(i) == 0)
              off_surface.push_back(i);
        }

      for (std::vector<unsigned int> candidates : {off_surface, free})
        {
          if (candidates.size() < static_cast<std::size_t>(R.cols()))
            continue;
          std::sort(candidates.begin(),
                    candidates.end(),
                    [this](const unsigned int i, const unsigned int j) {
                      return body.serial_dof_index(i) <
                             body.serial_dof_index(j);
                    });
          Eigen::MatrixXd RFt(R.cols(), candidates.size());
          for (unsigned int k = 0; k < candidates.size(); ++k)
            RFt.col(k) = R.row(candidates[k]).transpose();
          Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(RFt);
          if (qr.rank() < R.cols())
            continue;
          std::vector<unsigned int> chosen;
          for (unsigned int k = 0; k < R.cols(); ++k)
            chosen.push_back(candidates[qr.colsPermutation().indices()(k)]);
          return chosen;
        }
      AssertThrow(false, dealii::ExcInternalError());
      return {};
    }



    template std::vector<unsigned int>
    Condenser<2>::choose_supports(const std::vector<unsigned int> &) const;
    template std::vector<unsigned int>
    Condenser<3>::choose_supports(const std::vector<unsigned int> &) const;
  } // namespace condensation
} // namespace dpana
