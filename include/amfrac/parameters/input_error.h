#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace amfrac
{
  /** A number for a message, in the shortest of fixed and scientific
   * notation with @p digits significant digits (std::to_string() writes
   * 8.9e-9 as 0.000000; 17 digits tell any two doubles apart). */
  inline std::string
  number_text(const double value, const int digits = 6)
  {
    std::ostringstream text;
    text.precision(digits);
    text << value;
    return text.str();
  }

  /**
   * The one exception type for bad input. Its message always names the
   * parameter (as "Section/Entry") or the file that caused it, so that
   * main() can print a single clear line and exit with a non-zero code.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &parameter, const std::string &message)
      : std::runtime_error("parameter <" + parameter + ">: " + message)
    {}

    explicit InputError(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * An error that every MPI rank raises together (a failed solve, a
   * singular matrix): each rank can unwind and exit cleanly. Any other
   * exception may be local to one rank and makes main() abort the job.
   */
  class CollectiveError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A load or prescribed displacement that evaluates to NaN or infinity
   * (a sqrt or log of a negative number in an expression): raised on every
   * rank together, so that the run can write its last good state.
   */
  class NonFiniteValue : public CollectiveError
  {
  public:
    using CollectiveError::CollectiveError;
  };

  /**
   * A run that stopped on purpose with a checkpoint (a signal, or
   * Checkpoint/Stop after step): every rank throws it together; main()
   * prints the message (how to resume) and exits with status 75
   * (EX_TEMPFAIL: try again, i.e. resume).
   */
  class RunInterrupted : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /** Throw an InputError for @p parameter unless @p condition holds. */
  inline void
  require(const bool         condition,
          const std::string &parameter,
          const std::string &message)
  {
    if (!condition)
      throw InputError(parameter, message);
  }
} // namespace amfrac
