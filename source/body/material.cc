// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/base/exceptions.h>
#include <dpana/body/material.h>

#include <cmath>
#include <sstream>

namespace dpana
{
  Material::Material(const double E, const double nu, const PlaneState state)
    : E(E)
    , nu(nu)
    , state(state)
  {
  }



  void
  Material::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Young's modulus",
                      "130000",
                      dealii::Patterns::Double(),
                      "Young's modulus E of the body (MPa = N/mm^2); must be "
                      "positive. 130000 MPa is the value of the examples of "
                      "the reference formulation.");
    prm.declare_entry("Poisson's ratio",
                      "0.2",
                      dealii::Patterns::Double(),
                      "Poisson's ratio nu (dimensionless); must satisfy "
                      "-1 < nu < 0.5 (0.5 would be an incompressible "
                      "material, which P1 elements cannot represent).");
    prm.declare_entry("Plane state",
                      "plane strain",
                      dealii::Patterns::Selection("plane strain|plane stress"),
                      "2D only: 'plane strain' (a slice of a long body, "
                      "eps_zz = 0; loads are per mm of thickness) or 'plane "
                      "stress' (a thin plate of unit thickness, sigma_zz = "
                      "0). Ignored in 3D.");
  }



  void
  Material::parse_parameters(dealii::ParameterHandler &prm,
                             const std::string        &path)
  {
    E     = prm.get_double("Young's modulus");
    nu    = prm.get_double("Poisson's ratio");
    state = prm.get("Plane state") == "plane stress" ?
              PlaneState::plane_stress :
              PlaneState::plane_strain;
    check(path);
  }



  void
  Material::check(const std::string &path) const
  {
    if (!std::isfinite(E) || !(E > 0.0))
      {
        std::ostringstream s;
        s << path << " / Young's modulus: must be a positive number of MPa, "
          << "got " << E;
        throw InputError(s.str());
      }
    if (!std::isfinite(nu) || !(nu > -1.0) || !(nu < 0.5))
      {
        std::ostringstream s;
        s << path << " / Poisson's ratio: must satisfy -1 < nu < 0.5, got "
          << nu;
        throw InputError(s.str());
      }
  }



  double
  Material::youngs_modulus() const
  {
    return E;
  }



  double
  Material::poissons_ratio() const
  {
    return nu;
  }



  Material::PlaneState
  Material::plane_state() const
  {
    return state;
  }



  double
  Material::mu() const
  {
    return E / (2.0 * (1.0 + nu));
  }



  double
  Material::lambda(const int dim) const
  {
    if (dim == 2 && state == PlaneState::plane_stress)
      return E * nu / (1.0 - nu * nu);
    return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  }



  double
  Material::out_of_plane_stress(
    const dealii::SymmetricTensor<2, 2> &stress) const
  {
    if (state == PlaneState::plane_stress)
      return 0.0;
    // eps_zz = 0 gives sigma_zz = lambda (eps_xx + eps_yy) = nu (sigma_xx +
    // sigma_yy).
    return nu * (stress[0][0] + stress[1][1]);
  }



  std::string
  Material::description(const int dim) const
  {
    std::ostringstream s;
    s << "E = " << E << " MPa, nu = " << nu;
    if (dim == 2)
      s << (state == PlaneState::plane_stress ? ", plane stress" :
                                                ", plane strain");
    return s.str();
  }
} // namespace dpana
