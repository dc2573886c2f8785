// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/base/exceptions.h>
#include <dpana/io/csv.h>
#include <dpana/parameters/list_syntax.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <fstream>

namespace dpana
{
  namespace io
  {
    int
    CsvTable::column(const std::vector<std::string> &names) const
    {
      for (unsigned int c = 0; c < header.size(); ++c)
        if (std::find(names.begin(), names.end(), header[c]) != names.end())
          return c;
      return -1;
    }



    double
    CsvTable::number(const unsigned int i,
                     const unsigned int c,
                     const std::string &what) const
    {
      return parameters::parse_double(rows[i][c],
                                      what + ": line " +
                                        std::to_string(line_numbers[i]) +
                                        ", column '" + header[c] + "'");
    }



    CsvTable
    read_csv(const std::string &file, const std::string &what)
    {
      std::ifstream in(file);
      if (!in)
        throw InputError(what + ": cannot open '" + file + "'");
      CsvTable    table;
      std::string line;
      if (!std::getline(in, line))
        throw InputError(what + ": '" + file + "' is empty");
      table.header = dealii::Utilities::split_string_list(line);
      for (unsigned int number = 2; std::getline(in, line); ++number)
        {
          auto fields = dealii::Utilities::split_string_list(line);
          if (fields.size() < table.header.size())
            continue;
          table.rows.push_back(std::move(fields));
          table.line_numbers.push_back(number);
        }
      return table;
    }
  } // namespace io
} // namespace dpana
