// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------

#include <dpana/base/simulation.templates.h>

namespace dpana
{
  template class Simulation<2>;
  template class Simulation<3>;
} // namespace dpana
