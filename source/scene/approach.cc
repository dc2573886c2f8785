// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/scene/approach.h>

#include <deal.II/lac/vector.h>

#include <deal.II/numerics/vector_tools_point_value.h>

#include <cmath>

namespace dpana
{
  namespace scene
  {
    namespace
    {
      // u(x) . n of the finite element displacement of @p body.
      template <int dim>
      double
      normal_displacement(const Body<dim>              &body,
                          const dealii::Point<dim>     &x,
                          const dealii::Tensor<1, dim> &n)
      {
        dealii::Vector<double> u(dim);
        dealii::VectorTools::point_value(
          body.mapping(), body.dof_handler(), body.solution(), x, u);
        double un = 0;
        for (unsigned int d = 0; d < dim; ++d)
          un += u[d] * n[d];
        return un;
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
