#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace amfrac
{
  /**
   * A bag of named arrays (reals, integers, texts) stored as one HDF5
   * file: every dataset carries a 64-bit FNV-1a checksum of its bytes, the
   * file a format name and version, so that read() rejects a damaged or
   * foreign file with a message naming it and the dataset.
   */
  class CheckpointData
  {
  public:
    /** Version of the layout; read() refuses any other. 4: the history of
     * a run with crack insertion has the column friction_cracks. */
    static constexpr std::int64_t format_version = 4;

    void
    put(const std::string &name, const std::vector<double> &values)
    {
      reals[name] = values;
    }
    void
    put(const std::string &name, const double value)
    {
      reals[name] = {value};
    }
    void
    put_integers(const std::string &name, const std::vector<std::int64_t> &v)
    {
      integers[name] = v;
    }
    void
    put_integer(const std::string &name, const std::int64_t value)
    {
      integers[name] = {value};
    }
    void
    put_text(const std::string &name, const std::string &text)
    {
      texts[name] = text;
    }

    bool
    has(const std::string &name) const
    {
      return reals.count(name) || integers.count(name) || texts.count(name);
    }

    bool
    is_real(const std::string &name) const
    {
      return reals.count(name);
    }
    bool
    is_integer(const std::string &name) const
    {
      return integers.count(name);
    }
    bool
    is_text(const std::string &name) const
    {
      return texts.count(name);
    }

    /** The names of all entries. */
    std::vector<std::string>
    names() const
    {
      std::vector<std::string> all;
      for (const auto &entry : reals)
        all.push_back(entry.first);
      for (const auto &entry : integers)
        all.push_back(entry.first);
      for (const auto &entry : texts)
        all.push_back(entry.first);
      return all;
    }

    /** The stored arrays; throw std::runtime_error naming @p name if it
     * is missing (or, for the scalars, not of size one). */
    const std::vector<double> &
    get(const std::string &name) const;
    double
    get_scalar(const std::string &name) const;
    const std::vector<std::int64_t> &
    get_integers(const std::string &name) const;
    std::int64_t
    get_integer(const std::string &name) const;
    const std::string &
    get_text(const std::string &name) const;

    /** Write every array to a new HDF5 file at @p path (overwritten);
     * throws std::runtime_error on failure. */
    void
    write(const std::string &path) const;

    /** Read a file written by write(), verifying the format, the version
     * and every checksum; throws std::runtime_error naming @p path. */
    static CheckpointData
    read(const std::string &path);

    /** Total bytes of the arrays (the payload of the file). */
    std::size_t
    payload_bytes() const;

  private:
    std::map<std::string, std::vector<double>>       reals;
    std::map<std::string, std::vector<std::int64_t>> integers;
    std::map<std::string, std::string>               texts;
  };
} // namespace amfrac
