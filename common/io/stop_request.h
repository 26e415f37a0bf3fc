// StopRequest: a request, from another thread (the command line's signal watcher), that long work
// stop at its next safe point; the work throws Interrupted so that destructors clean up.
#pragma once

#include <atomic>
#include <stdexcept>
#include <string>

namespace giocal {

/// Thrown by work that honours a StopRequest; outputs in progress are discarded.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal)
      : std::runtime_error("interrupted by signal " + std::to_string(signal)), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

class StopRequest {
 public:
  void request(int signal) { signal_.store(signal); }
  bool requested() const { return signal_.load() != 0; }
  /// Throws Interrupted when a stop was requested.
  void check() const {
    const int s = signal_.load();
    if (s != 0) throw Interrupted(s);
  }

 private:
  std::atomic<int> signal_{0};
};

/// check() on a StopRequest that may be absent.
inline void checkStop(const StopRequest* stop) {
  if (stop) stop->check();
}

}  // namespace giocal
