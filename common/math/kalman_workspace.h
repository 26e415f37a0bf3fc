// KalmanWorkspace: storage the Kalman update reuses from one update to the next.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

namespace giocal {

/// Buffers that only grow. A GNSS update's temporaries (P H^T, S, L^-1 H P: ~130 kB at 72 rows
/// and 75 states) freed after every update left glibc's heap top above its trim threshold, so
/// each update gave the pages back to the kernel and faulted them in again (about a seventh of
/// the EKF's time, measured with glibc's trimming turned off); kept here, they are allocated once.
class KalmanWorkspace {
 public:
  enum Slot : std::size_t { kPHt, kS, kW, kPBefore, kInnovation, kSInnovation, kPHeld, kSlots };
  /// A rows x cols matrix over the slot's buffer; its coefficients are unspecified.
  Eigen::Map<Eigen::MatrixXd> matrix(Slot slot, Eigen::Index rows, Eigen::Index cols) {
    std::vector<double>& b = buffers_[slot];
    const auto size = static_cast<std::size_t>(rows * cols);
    if (b.size() < size) b.resize(size);
    return {b.data(), rows, cols};
  }

 private:
  std::array<std::vector<double>, kSlots> buffers_;
};

}  // namespace giocal
