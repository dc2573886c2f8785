// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
//
// Explicit instantiation of the elastic body and its conditions for dim = 2
// and 3.

#include <dpana/body/body.templates.h>
#include <dpana/body/boundary_conditions.templates.h>

namespace dpana
{
  template struct BoundaryConditions<2>;
  template struct BoundaryConditions<3>;
  template struct Loads<2>;
  template struct Loads<3>;
  template class Body<2>;
  template class Body<3>;
} // namespace dpana
