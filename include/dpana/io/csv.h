// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_io_csv_h
#define dpana_io_csv_h

#include <string>
#include <vector>

namespace dpana
{
  namespace io
  {
    /**
     * A comma separated table with a header line, as dpana writes
     * contact.csv: the names of the columns and the fields of every row,
     * trimmed. Rows with fewer fields than the header are skipped.
     */
    struct CsvTable
    {
      std::vector<std::string>              header;
      std::vector<std::vector<std::string>> rows;
      std::vector<unsigned int>             line_numbers; // of each row

      /**
       * Index of the first column named one of @p names; -1 if none.
       */
      int
      column(const std::vector<std::string> &names) const;

      /**
       * Field @p c of row @p i as a finite number. Throws dpana::InputError
       * "<what>: line N, column 'x': ... is not a number" otherwise (N is the
       * line of the file).
       */
      double
      number(const unsigned int i,
             const unsigned int c,
             const std::string &what) const;
    };

    /**
     * Reads @p file. Throws dpana::InputError naming @p what if the file
     * cannot be opened or has no header.
     */
    CsvTable
    read_csv(const std::string &file, const std::string &what);
  } // namespace io
} // namespace dpana

#endif
