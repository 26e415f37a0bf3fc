// OdometerDelayEstimator: how late the odometer's stamps are against the IMU's, from the yaw rate
// both measure: the odometer's heading change over blocks of about 0.2 s (each yaw rate held over
// the interval its stamp ends, as giocal's odometer model reads it) fitted, scale and offset, to
// the gyro's turn about the vehicle's up axis over the same block shifted by each candidate delay;
// the delay of the smallest residual, refined between grid points, with its sigma from the
// residual's curvature. Streaming, bounded memory.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "common/containers/ring_queue.h"
namespace giocal {

struct OdometerDelay {
  bool valid = false;    // enough turning, a minimum inside the searched range, sigma under 20 ms
  double delay_s = 0.0;  // > 0: an odometer stamp t measures the motion at t - delay_s
  double sigma_s = 0.0;
  long samples = 0;           // odometer blocks compared
  double yaw_rate_rms = 0.0;  // of the gyro about up [rad/s]: how much the drive turned
};

/// Whether a run should be made again with `measured` taken out of the odometer's stamps: valid,
/// its sigma below `max_sigma_s` and its size above `min_delay_s` (both > 0).
inline bool worthApplying(const OdometerDelay& measured, double max_sigma_s, double min_delay_s) {
  return max_sigma_s > 0.0 && min_delay_s > 0.0 && measured.valid &&
         measured.sigma_s < max_sigma_s && std::abs(measured.delay_s) > min_delay_s;
}

class OdometerDelayEstimator {
 public:
  /// `up_b`: the vehicle's up axis in the IMU frame (R_b_m e_z); delays within +-max_delay_s are
  /// searched on a grid of step_s.
  explicit OdometerDelayEstimator(const Eigen::Vector3d& up_b, double max_delay_s = 0.5,
                                  double step_s = 0.002);
  /// IMU samples in rising time (others are ignored).
  void addImu(double t, const Eigen::Vector3d& gyro_b);
  /// Odometer samples in rising time, summed into blocks; a block is compared once the IMU covers
  /// its end + max_delay_s.
  void addOdometer(double t, double yaw_rate);
  OdometerDelay estimate() const;

 private:
  struct Block {
    double t0, t1, angle;  // odometer heading change over [t0, t1]
  };
  void compare(const Block& b);
  struct Rate {
    double t, rate, angle;  // rate about up, and its integral since the first sample
  };
  /// The integral of the rate about up from the first kept sample at t - d for every candidate
  /// delay d, into `out` (index as the sums); false when one of them falls outside `samples` or
  /// in an IMU gap.
  bool anglesAt(const std::vector<Rate>& samples, double t, std::vector<double>& out) const;

  Eigen::Vector3d up_b_;
  double max_delay_s_, step_s_;
  std::vector<double> delays_;  // the candidates, -max_delay_s_ + k step_s_
  RingQueue<Rate> gyro_;        // a ring: a deque allocated a block every few hundred samples
  std::vector<Rate> window_;    // the samples one comparison reads, contiguous
  // The angles at the end of the last compared block: blocks follow each other, so they are the
  // next block's start angles.
  std::vector<double> start_, end_;
  double end_t_ = NAN;
  RingQueue<Block> pending_;    // waiting for the IMU
  Block block_{NAN, NAN, 0.0};  // being summed
  double last_odometer_t_ = NAN, last_yaw_rate_ = 0.0;
  // Sums over compared blocks of the odometer's mean rate w: of w, w^2 and, per candidate delay,
  // x, x^2, x w (x the gyro's).
  long n_ = 0;
  double sum_w_ = 0.0, sum_ww_ = 0.0;
  std::vector<double> sum_x_, sum_xx_, sum_xw_;
};

}  // namespace giocal
