#include "apps/interrupt_watch.h"

#include <signal.h>
#include <unistd.h>

#include <thread>

namespace giocal {

InterruptWatch::InterruptWatch() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  // A thread waiting with sigwait is an ordinary thread, so no async-signal-safety limits apply;
  // the main thread's work sees the request at its next check and unwinds, cleaning up.
  std::thread([set, stop = stop_]() {
    int signal = 0;
    while (sigwait(&set, &signal) == 0) {
      if (stop->requested()) _exit(128 + signal);
      stop->request(signal);
    }
  }).detach();
}

}  // namespace giocal
