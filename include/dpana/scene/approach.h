// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_scene_approach_h
#define dpana_scene_approach_h

#include <dpana/body/body.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace dpana
{
  namespace scene
  {
    /**
     * The approach of one body towards the contact, measured from its
     * displacement u: the displacement along the contact normal n of a
     * point @p far_point far from the contact, relative to the contact
     * point @p contact_point of its surface,
     *     delta_i = sign (u(far_point) - u(contact_point)) . n,
     * with sign = +1 for the body whose outward normal at the contact is n
     * (Body 1) and -1 for its partner, so that delta_i > 0 when the body's
     * far point moves towards the contact. The sum over the bodies is their
     * mutual approach; for a body on a rigid plane it is its own. The
     * displacement is the finite element field, evaluated in the cell that
     * holds each point (the points may lie on the boundary and on symmetry
     * planes). Throws dealii::ExcMessage if a point lies outside the mesh.
     */
    template <int dim>
    double
    body_approach(const Body<dim>              &body,
                  const dealii::Point<dim>     &contact_point,
                  const dealii::Point<dim>     &far_point,
                  const dealii::Tensor<1, dim> &n,
                  const double                  sign);

    /**
     * The displacement along the axis at the depth @p depth below a point
     * force @p load normal to the surface of an elastic half-space
     * (Boussinesq 1885; Johnson, Contact Mechanics, 1985, section 3.2),
     *     u_z = P (1 + nu) (3 - 2 nu) / (2 pi E z).
     * Far below a Hertz contact (z >> a) the Hertz pressure acts as this
     * point force, so a point at depth z moves by delta_i - u_z(z) towards
     * the contact, delta_i the Hertz approach of the body's distant points.
     */
    double
    boussinesq_axial_displacement(const double load,
                                  const double youngs_modulus,
                                  const double poissons_ratio,
                                  const double depth);
  } // namespace scene
} // namespace dpana

#endif
