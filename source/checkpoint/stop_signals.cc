#include <amfrac/checkpoint/stop_signals.h>

namespace amfrac
{
  namespace
  {
    volatile std::sig_atomic_t received_signal = 0;

    extern "C" void
    record_signal(const int signal)
    {
      if (received_signal == signal)
        {
          // The second one: the user wants out now.
          std::signal(signal, SIG_DFL);
          std::raise(signal);
          return;
        }
      received_signal = signal;
    }
  } // namespace



  StopSignals::StopSignals()
  {
    received_signal         = 0;
    struct sigaction action = {};
    action.sa_handler       = record_signal;
    sigemptyset(&action.sa_mask);
    // System calls (MPI's polling, file writes) resume after the handler.
    action.sa_flags = SA_RESTART;
    sigaction(SIGTERM, &action, &previous_term);
    sigaction(SIGINT, &action, &previous_int);
  }



  StopSignals::~StopSignals()
  {
    sigaction(SIGTERM, &previous_term, nullptr);
    sigaction(SIGINT, &previous_int, nullptr);
  }



  int
  StopSignals::received()
  {
    return received_signal;
  }



  const char *
  StopSignals::name(const int signal)
  {
    return signal == SIGTERM ? "SIGTERM" :
           signal == SIGINT  ? "SIGINT" :
                               "a signal";
  }
} // namespace amfrac
