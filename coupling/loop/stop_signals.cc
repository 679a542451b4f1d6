// Signal handlers that only record the signal (an async-signal-safe store into a
// sig_atomic_t); everything else happens in the run's own thread when it next polls.
// A second signal of the same kind is recorded too; the run is already on its way out.
#include "coupling/loop/stop_signals.h"

#include <csignal>

namespace wear::coupling {

namespace {
volatile std::sig_atomic_t received = 0;
constexpr int handled[] = {SIGINT, SIGTERM, SIGUSR1};
struct sigaction previous[3];

extern "C" void record_signal(int signal) {
  received = signal;
}
} // namespace

StopSignals::StopSignals() {
  received = 0;
  struct sigaction action {};
  action.sa_handler = record_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (int k = 0; k < 3; ++k)
    sigaction(handled[k], &action, &previous[k]);
}

StopSignals::~StopSignals() {
  for (int k = 0; k < 3; ++k)
    sigaction(handled[k], &previous[k], nullptr);
}

int StopSignals::requested() const {
  return received;
}

const char* StopSignals::name(int signal) {
  switch (signal) {
  case SIGINT:
    return "SIGINT";
  case SIGTERM:
    return "SIGTERM";
  case SIGUSR1:
    return "SIGUSR1";
  default:
    return "a signal";
  }
}

} // namespace wear::coupling
