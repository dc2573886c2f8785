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
     * What must be known of a parameter file before its entries can be
     * declared: the bodies are templates on the space dimension, a run
     * declares one subsection per body, and a file with a top-level
     * `subsection Contact` declares the entries of the contact phases
     * (dpana::scene::Scene).
     */
    struct FileOutline
    {
      // Top-level "set Dimension = 2|3" (2 if absent).
      unsigned int dimension = 2;
      // Top-level "set Number of bodies = 1|2" (1 if absent).
      unsigned int n_bodies = 1;
      // True if the file has a top-level "subsection Contact".
      bool has_contact = false;
    };

    /**
     * The one pre-scan of a parameter file: reads its top level (the lines
     * outside any subsection, with the ParameterHandler's syntax: '#'
     * starts a comment unless escaped, a trailing backslash continues the
     * line) for FileOutline. Everything else is left to parse_file(), which
     * reads the file with all entries declared. Throws dpana::InputError if
     * the file cannot be read, or if Dimension is not 2 or 3 or Number of
     * bodies not 1 or 2 (message "a.prm, line 3: Dimension: must be 2 or 3,
     * got '4'").
     */
    FileOutline
    scan_file(const std::string &filename);

    /**
     * Declares the top-level entry "Dimension".
     */
    void
    declare_dimension(dealii::ParameterHandler &prm);

    /**
     * Reads a parameter file; any error of the ParameterHandler (an unknown
     * entry or subsection, a value that does not match the entry's pattern,
     * a missing "end") becomes a dpana::InputError with a one-line message
     * that names the file, the line and the entry. An entry set twice in
     * the same subsection is an error too ("a.prm, line 9: entry 'Radius'
     * of subsection 'Body 1 / Geometry' is already set on line 7"): the
     * ParameterHandler would keep the last value without a word.
     */
    void
    parse_file(dealii::ParameterHandler &prm, const std::string &filename);

    /**
     * The one way a message quotes text of the input: @p text in single
     * quotes, every byte that is not printable ASCII (a control character,
     * an escape sequence, a byte of a binary file) written as `\xNN`, and
     * cut after 60 characters with "..." appended, so that a message stays
     * one short, harmless line whatever the input holds.
     */
    std::string
    quote(const std::string &text);

    /**
     * The message of an exception on one line: deal.II's multi-line
     * exception texts are reduced to their "additional information" and
     * their whitespace collapsed; the text the ParameterHandler quotes in
     * angle brackets is quoted by quote(). The message as a whole keeps
     * printable bytes only and at most 1000 characters.
     */
    std::string
    one_line_message(const std::exception &e);
  } // namespace parameters
} // namespace dpana

#endif
