#pragma once

// A tiny check harness for amfrac's ctest programs: every failed check
// prints where and why, and the program's exit code counts the failures.

#include <cmath>
#include <iostream>
#include <string>

namespace amfrac_test
{
  inline int failures = 0;

  inline void
  check(const bool         condition,
        const std::string &what,
        const char        *file,
        const int          line)
  {
    if (!condition)
      {
        ++failures;
        std::cerr << file << ":" << line << ": check failed: " << what
                  << std::endl;
      }
  }

  inline void
  check_close(const double       value,
              const double       expected,
              const double       tol,
              const std::string &what,
              const char        *file,
              const int          line)
  {
    const bool ok = std::abs(value - expected) <= tol;
    if (!ok)
      {
        ++failures;
        std::cerr << file << ":" << line << ": " << what << " = " << value
                  << ", expected " << expected << " +- " << tol << std::endl;
      }
  }

  /** @p text with every occurrence of @p key replaced by @p value (the
   * tests fill placeholders such as @N@ in parameter-file templates). */
  inline std::string
  substitute(std::string text, const std::string &key, const std::string &value)
  {
    for (std::size_t at = text.find(key); at != std::string::npos;
         at             = text.find(key))
      text.replace(at, key.size(), value);
    return text;
  }

  inline int
  summary()
  {
    std::cout << (failures == 0 ? "all checks passed" : "checks failed: ")
              << (failures == 0 ? "" : std::to_string(failures)) << std::endl;
    return failures == 0 ? 0 : 1;
  }
} // namespace amfrac_test

#define CHECK(condition) \
  amfrac_test::check((condition), #condition, __FILE__, __LINE__)
#define CHECK_CLOSE(value, expected, tol) \
  amfrac_test::check_close(               \
    (value), (expected), (tol), #value, __FILE__, __LINE__)
