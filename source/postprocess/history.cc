#include <amfrac/postprocess/atomic_file.h>
#include <amfrac/postprocess/history.h>
#include <iomanip>
#include <ostream>
#include <stdexcept>

namespace amfrac
{
  History::History(const std::string &filename, const bool is_writer)
    : filename(filename)
    , is_writer(is_writer)
  {}



  double
  History::value(const std::size_t row, const std::string &column) const
  {
    for (unsigned int c = 0; c < columns.size(); ++c)
      if (columns[c] == column)
        return values.at(row)[c];
    throw std::invalid_argument("History: no column '" + column + "'");
  }



  void
  History::add_row(const std::vector<std::pair<std::string, double>> &row)
  {
    if (columns.empty())
      for (const auto &entry : row)
        columns.push_back(entry.first);
    if (row.size() != columns.size())
      throw std::logic_error("History: a row has a different column set");
    std::vector<double> numbers;
    for (const auto &entry : row)
      numbers.push_back(entry.second);
    values.push_back(numbers);
    if (!is_writer)
      return;
    write_atomically(filename, [&](std::ostream &out) {
      for (unsigned int c = 0; c < columns.size(); ++c)
        out << (c ? "," : "") << columns[c];
      out << '\n' << std::setprecision(12);
      for (const auto &line : values)
        {
          for (unsigned int c = 0; c < line.size(); ++c)
            out << (c ? "," : "") << line[c];
          out << '\n';
        }
    });
  }
} // namespace amfrac
