// ReferenceTrajectory: a trajectory to compare against or start from (truth.csv, or a calibrate
// run's trajectory.csv), interpolated in time and converted to and from a local frame's states.
#pragma once

#include <optional>
#include <vector>

#include "common/geodesy/wgs84.h"
#include "common/gnss/pos_reader.h"
#include "common/imu/nav_state.h"
#include "common/io/sensor_logs.h"

namespace giocal {

class ReferenceTrajectory {
 public:
  /// Samples in rising time (as the CSV readers check).
  explicit ReferenceTrajectory(std::vector<TruthSample> samples);

  double begin() const { return samples_.front().t; }
  double end() const { return samples_.back().t; }
  /// The sample at t, interpolated (linear in position and velocity, slerp in attitude); empty
  /// outside [begin, end] or across a gap of more than max_gap seconds between samples.
  std::optional<TruthSample> at(double t, double max_gap = 1.0) const;

 private:
  std::vector<TruthSample> samples_;
};

/// Position solutions as reference rows (no velocity or attitude).
std::vector<TruthSample> positionRows(const std::vector<PositionFix>& fixes);

/// The sample at t between rows a and b (a.t <= t <= b.t): linear in position and velocity, slerp
/// in attitude.
TruthSample interpolateTruth(const TruthSample& a, const TruthSample& b, double t);

/// The antenna (ECEF) of a truth.csv row: its IMU origin plus the lever arm p_b_g through the
/// row's local-level attitude.
Eigen::Vector3d antennaOfRow(const TruthSample& s, const Eigen::Vector3d& p_b_g);

/// The state a truth.csv row describes, in the local frame n (position, velocity, attitude; biases
/// zero): the inverse of truthRow (calibration_run.h).
NavState navStateFromRow(const LocalFrame& frame, const TruthSample& s);

}  // namespace giocal
