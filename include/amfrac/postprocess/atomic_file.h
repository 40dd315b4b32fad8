#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace amfrac
{
  /**
   * Write a file through @p writer to a temporary name next to @p path,
   * check the stream, then rename it over @p path: an interrupted run never
   * leaves a truncated file, and an existing file survives a failed write.
   * Throws std::runtime_error naming the file on failure.
   */
  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &writer);

  /** Rename @p from to @p to, throwing a clear error on failure. */
  void
  rename_or_throw(const std::string &from, const std::string &to);
} // namespace amfrac
