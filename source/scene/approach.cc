// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/scene/approach.h>

#include <deal.II/base/mpi.h>

#include <deal.II/lac/vector.h>

#include <deal.II/numerics/vector_tools_point_value.h>

#include <deal.II/distributed/tria_base.h>

#include <cmath>
#include <stdexcept>

namespace dpana
{
  namespace scene
  {
    namespace
    {
      // u(x) . n of the finite element displacement of @p body. A mesh
      // distributed over MPI ranks: the ranks whose cells (own or ghost:
      // every rank holds the whole displacement) hold x evaluate it, and
      // the first of them broadcasts its value; a point outside every
      // rank's cells throws on all ranks alike. Collective then.
      template <int dim>
      double
      normal_displacement(const Body<dim>              &body,
                          const dealii::Point<dim>     &x,
                          const dealii::Tensor<1, dim> &n)
      {
        const auto *distributed =
          dynamic_cast<const dealii::parallel::TriangulationBase<dim> *>(
            &body.triangulation());
        dealii::Vector<double> u(dim);
        bool                   found = true;
        try
          {
            dealii::VectorTools::point_value(
              body.mapping(), body.dof_handler(), body.solution(), x, u);
          }
        catch (const std::exception &)
          {
            if (distributed == nullptr)
              throw;
            found = false;
          }
        double un = 0;
        for (unsigned int d = 0; d < dim; ++d)
          un += u[d] * n[d];
        if (distributed == nullptr)
          return un;
        const MPI_Comm     comm = distributed->get_communicator();
        const unsigned int n_ranks =
          dealii::Utilities::MPI::n_mpi_processes(comm);
        const unsigned int holder = dealii::Utilities::MPI::min(
          found ? dealii::Utilities::MPI::this_mpi_process(comm) : n_ranks,
          comm);
        if (holder == n_ranks)
          throw std::runtime_error("the point lies in no rank's cells");
        return dealii::Utilities::MPI::broadcast(comm, un, holder);
      }
    } // namespace



    template <int dim>
    double
    body_approach(const Body<dim>              &body,
                  const dealii::Point<dim>     &contact_point,
                  const dealii::Point<dim>     &far_point,
                  const dealii::Tensor<1, dim> &n,
                  const double                  sign)
    {
      return sign * (normal_displacement(body, far_point, n) -
                     normal_displacement(body, contact_point, n));
    }



    double
    boussinesq_axial_displacement(const double load,
                                  const double youngs_modulus,
                                  const double poissons_ratio,
                                  const double depth)
    {
      const double nu = poissons_ratio;
      return load * (1 + nu) * (3 - 2 * nu) /
             (2 * M_PI * youngs_modulus * depth);
    }



    template double
    body_approach(const Body<2> &,
                  const dealii::Point<2> &,
                  const dealii::Point<2> &,
                  const dealii::Tensor<1, 2> &,
                  const double);
    template double
    body_approach(const Body<3> &,
                  const dealii::Point<3> &,
                  const dealii::Point<3> &,
                  const dealii::Tensor<1, 3> &,
                  const double);
  } // namespace scene
} // namespace dpana
