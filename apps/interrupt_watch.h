// InterruptWatch: turns SIGINT and SIGTERM into a StopRequest that the running command honours at
// its next safe point (its outputs in progress are removed, none are half-moved); a second signal
// ends the process at once.
#pragma once

#include <memory>

#include "common/io/stop_request.h"

namespace giocal {

class InterruptWatch {
 public:
  /// Blocks SIGINT and SIGTERM in this thread (and so in every thread started after it) and waits
  /// for them in a thread of its own. Construct it before any other thread starts.
  InterruptWatch();
  const StopRequest* stop() const { return stop_.get(); }

 private:
  std::shared_ptr<StopRequest> stop_ = std::make_shared<StopRequest>();  // shared with the thread
};

}  // namespace giocal
