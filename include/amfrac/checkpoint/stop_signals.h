#pragma once

#include <csignal>

namespace amfrac
{
  /**
   * While alive, SIGTERM and SIGINT do not end the process: they are
   * recorded, so that the run can finish its step and write a checkpoint.
   * A second signal of the same kind ends the process at once (the default
   * action), for a user who does not want to wait. The previous handlers
   * come back on destruction.
   */
  class StopSignals
  {
  public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals &) = delete;
    StopSignals &
    operator=(const StopSignals &)
      = delete;

    /** The signal received since construction (0: none). */
    static int
    received();

    /** "SIGTERM", "SIGINT" or the number. */
    static const char *
    name(const int signal);

  private:
    struct sigaction previous_term, previous_int;
  };
} // namespace amfrac
