// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_base_exceptions_h
#define dpana_base_exceptions_h

#include <stdexcept>
#include <string>

namespace dpana
{
  /**
   * A user-input error: a wrong parameter value, a missing file, a boundary
   * name that no face of the mesh carries. Its what() is ONE line that names
   * the parameter or the file, so that the dpana executable can print it as
   * "dpana: error: <message>" and exit with status 1.
   *
   * Internal inconsistencies are not input errors: they are checked with
   * deal.II's Assert/AssertThrow and their own exception classes.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace dpana

#endif
