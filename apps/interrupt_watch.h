// InterruptWatch: turns SIGINT and SIGTERM into a StopRequest that the running command honours at
// its next safe point (its outputs in progress are removed, none are half-moved); a second signal
// ends the process at once.
#pragma once

#include <memory>

#include "common/io/stop_request.h"

namespace giocal {

class InterruptWatch {
 public:
  /// Installs the handlers of SIGINT and SIGTERM (one watch per process); the destructor puts the
  /// default actions back.
  InterruptWatch();
  ~InterruptWatch();
  InterruptWatch(const InterruptWatch&) = delete;
  InterruptWatch& operator=(const InterruptWatch&) = delete;
  const StopRequest* stop() const { return stop_.get(); }

 private:
  std::unique_ptr<StopRequest> stop_ = std::make_unique<StopRequest>();
};

}  // namespace giocal
