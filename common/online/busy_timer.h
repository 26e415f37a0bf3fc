// BusyTimer: adds the wall time of a scope to a total (the calibrator's own time, reading the
// files excluded).
#pragma once

#include <chrono>

namespace giocal {

class BusyTimer {
 public:
  explicit BusyTimer(double& total) : total_(total), t0_(std::chrono::steady_clock::now()) {}
  ~BusyTimer() {
    total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }

 private:
  double& total_;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace giocal
