// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/condensation/condenser.templates.h>

namespace dpana
{
  namespace condensation
  {
    template class Condenser<2>;
    template class Condenser<3>;
  } // namespace condensation
} // namespace dpana
