// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/geometry/geometry.templates.h>

namespace dpana
{
  namespace geometry
  {
    template class Geometry<2>;
    template class Geometry<3>;
  } // namespace geometry
} // namespace dpana
