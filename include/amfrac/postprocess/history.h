#pragma once

#include <string>
#include <utility>
#include <vector>

namespace amfrac
{
  /**
   * A CSV table of summary quantities, one row per step. Rank 0 creates
   * the file atomically with the first row and appends each further row as
   * one complete line, so rows on disk are never rewritten.
   */
  class History
  {
  public:
    History(const std::string &filename, const bool is_writer);

    /** Append a row of (column, value) pairs; the first row fixes the
     * columns. */
    void
    add_row(const std::vector<std::pair<std::string, double>> &row);

    std::size_t
    n_rows() const
    {
      return values.size();
    }

    const std::vector<std::string> &
    column_names() const
    {
      return columns;
    }

    const std::vector<std::vector<double>> &
    rows() const
    {
      return values;
    }

    /** Replace the table by @p column_names and @p rows (a restart) and
     * rewrite the file atomically with them: rows that a stopped run
     * wrote after its checkpoint are gone. */
    void
    restore(const std::vector<std::string>         &column_names,
            const std::vector<std::vector<double>> &rows);

    /** The value of @p column in row @p row; throws for unknown names. */
    double
    value(const std::size_t row, const std::string &column) const;

  private:
    const std::string                filename;
    const bool                       is_writer;
    std::vector<std::string>         columns;
    std::vector<std::vector<double>> values;
  };
} // namespace amfrac
