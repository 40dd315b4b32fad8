#include <amfrac/postprocess/atomic_file.h>
#include <amfrac/postprocess/history.h>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
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



  namespace
  {
    std::string
    format_row(const std::vector<double> &numbers)
    {
      std::ostringstream line;
      line << std::setprecision(12);
      for (unsigned int c = 0; c < numbers.size(); ++c)
        line << (c ? "," : "") << numbers[c];
      line << '\n';
      return line.str();
    }
  } // namespace



  void
  History::restore(const std::vector<std::string>         &column_names,
                   const std::vector<std::vector<double>> &rows)
  {
    columns = column_names;
    values  = rows;
    if (!is_writer || columns.empty())
      return;
    write_atomically(filename, [&](std::ostream &out) {
      for (unsigned int c = 0; c < columns.size(); ++c)
        out << (c ? "," : "") << columns[c];
      out << '\n';
      for (const auto &row : values)
        out << format_row(row);
    });
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
    // The first row creates the file atomically with its header; later
    // rows are appended as one complete line each, so earlier rows are
    // never rewritten (a long run stays O(rows), not O(rows^2)) and a crash
    // can at most lose the line being written.
    const std::string text = format_row(numbers);
    if (values.size() == 1)
      {
        write_atomically(filename, [&](std::ostream &out) {
          for (unsigned int c = 0; c < columns.size(); ++c)
            out << (c ? "," : "") << columns[c];
          out << '\n' << text;
        });
        return;
      }
    std::ofstream out(filename, std::ios::app);
    out.write(text.data(), text.size());
    out.flush();
    if (!out)
      throw std::runtime_error("cannot append to '" + filename + "'");
  }
} // namespace amfrac
