// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/contact_surface/contact_surface.templates.h>

namespace dpana
{
  namespace contact_surface
  {
    template class ContactSurface<2>;
    template class ContactSurface<3>;
  } // namespace contact_surface
} // namespace dpana
