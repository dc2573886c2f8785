// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_parameters_parameters_h
#define dpana_parameters_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <exception>
#include <string>

namespace dpana
{
  namespace parameters
  {
    /**
     * The space dimension of a parameter file: the value of the top-level
     * entry "set Dimension = 2|3" (2 if absent). It has to be known before
     * the other entries are declared, because the bodies are templates on
     * the dimension. Throws dpana::InputError if the file cannot be read or
     * the value is not 2 or 3.
     */
    unsigned int
    read_dimension(const std::string &filename);

    /**
     * Declares the top-level entry "Dimension".
     */
    void
    declare_dimension(dealii::ParameterHandler &prm);

    /**
     * Reads a parameter file; any error of the ParameterHandler (an unknown
     * entry or subsection, a value that does not match the entry's pattern,
     * a missing "end") becomes a dpana::InputError with a one-line message
     * that names the file, the line and the entry.
     */
    void
    parse_file(dealii::ParameterHandler &prm, const std::string &filename);

    /**
     * The message of an exception on one line: deal.II's multi-line
     * exception texts are reduced to their "additional information" and
     * their whitespace collapsed.
     */
    std::string
    one_line_message(const std::exception &e);
  } // namespace parameters
} // namespace dpana

#endif
