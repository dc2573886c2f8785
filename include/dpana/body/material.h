// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_body_material_h
#define dpana_body_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <string>

namespace dpana
{
  /**
   * An isotropic linear elastic material: Young's modulus E (MPa) and
   * Poisson's ratio nu. In 2D the body is either a slice of an infinitely
   * long body (plane strain, eps_zz = 0, the default) or a thin plate (plane
   * stress, sigma_zz = 0).
   *
   * The stress is sigma = lambda tr(eps) I + 2 mu eps with the Lamé
   * constants
   *   mu     = E / (2 (1 + nu)),
   *   lambda = E nu / ((1 + nu)(1 - 2 nu))            (3D and plane strain),
   *   lambda = E nu / (1 - nu^2) = 2 lambda mu / (lambda + 2 mu)
   *                                                   (plane stress),
   * so the 2D plane stress problem is the plane strain one with a modified
   * lambda.
   */
  class Material
  {
  public:
    enum class PlaneState
    {
      plane_strain,
      plane_stress
    };

    Material(const double     E           = 130000.,
             const double     nu          = 0.2,
             const PlaneState plane_state = PlaneState::plane_strain);

    /**
     * Declares "Young's modulus", "Poisson's ratio", "Plane state"; the
     * caller has entered the "Material" subsection.
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Reads them and checks E > 0 and -1 < nu < 0.5 (throws
     * dpana::InputError naming the entry, prefixed by @p path, e.g.
     * "Body 1 / Material").
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

    /**
     * Checks the values (throws dpana::InputError).
     */
    void
    check(const std::string &path) const;

    double
    youngs_modulus() const;
    double
    poissons_ratio() const;
    PlaneState
    plane_state() const;
    double
    mu() const;

    /**
     * The lambda of the stress-strain law in dimension @p dim (the plane
     * stress value when dim == 2 and plane stress is chosen).
     */
    double
    lambda(const int dim) const;

    /**
     * The stress sigma = lambda tr(eps) I + 2 mu eps.
     */
    template <int dim>
    dealii::SymmetricTensor<2, dim>
    stress(const dealii::SymmetricTensor<2, dim> &strain) const;

    /**
     * The out-of-plane stress sigma_zz of a 2D body: nu (sigma_xx +
     * sigma_yy) in plane strain, 0 in plane stress.
     */
    double
    out_of_plane_stress(const dealii::SymmetricTensor<2, 2> &stress) const;

    /**
     * The fourth-order elasticity tensor of the law above.
     */
    template <int dim>
    dealii::SymmetricTensor<4, dim>
    elasticity_tensor() const;

    std::string
    description(const int dim) const;

  private:
    double     E;
    double     nu;
    PlaneState state;
  };



  template <int dim>
  dealii::SymmetricTensor<2, dim>
  Material::stress(const dealii::SymmetricTensor<2, dim> &strain) const
  {
    return lambda(dim) * dealii::trace(strain) *
             dealii::unit_symmetric_tensor<dim>() +
           2.0 * mu() * strain;
  }



  template <int dim>
  dealii::SymmetricTensor<4, dim>
  Material::elasticity_tensor() const
  {
    return lambda(dim) *
             dealii::outer_product(dealii::unit_symmetric_tensor<dim>(),
                                   dealii::unit_symmetric_tensor<dim>()) +
           2.0 * mu() * dealii::identity_tensor<dim>();
  }
} // namespace dpana

#endif
