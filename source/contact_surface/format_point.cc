// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/contact_surface/format_point.h>

#include <sstream>

namespace dpana
{
  namespace contact_surface
  {
    namespace internal
    {
      template <int dim>
      std::string
      format_point(const dealii::Point<dim> &p)
      {
        std::ostringstream s;
        s.precision(6);
        s << "(";
        for (unsigned int d = 0; d < dim; ++d)
          s << (d ? ", " : "") << p[d];
        s << ")";
        return s.str();
      }



      template std::string
      format_point(const dealii::Point<2> &);
      template std::string
      format_point(const dealii::Point<3> &);
    } // namespace internal
  }   // namespace contact_surface
} // namespace dpana
