#include "apps/interrupt_watch.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>

namespace giocal {

namespace {

// The request a handler sets: a signal handler takes no argument, so the one watch of the process
// is reached through this. Only lock-free atomic operations and _exit run in the handler
// (async-signal-safe). A handler rather than a thread blocked in sigwait: under qemu-user such a
// thread kept the process from exiting (the 64-bit ARM tests, scripts/build_aarch64.sh).
std::atomic<StopRequest*> watched{nullptr};
static_assert(std::atomic<StopRequest*>::is_always_lock_free);

extern "C" void onStopSignal(int signal) {
  StopRequest* stop = watched.load();
  if (stop == nullptr || stop->requested()) _exit(128 + signal);
  stop->request(signal);
}

void setAction(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // reads and writes in progress go on; the work checks the request
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

InterruptWatch::InterruptWatch() {
  watched.store(stop_.get());
  setAction(onStopSignal);
}

InterruptWatch::~InterruptWatch() {
  setAction(SIG_DFL);
  watched.store(nullptr);
}

}  // namespace giocal
