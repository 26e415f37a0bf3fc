// FittedPath: a differential-drive vehicle path fitted to an antenna position solution. Speed,
// heading and pitch are cubic B-splines and the position is their integral, so the kinematics
// are exact for a ground vehicle (no lateral or vertical velocity in m, no roll); the antenna,
// through its lever arm, follows the solution as closely as that model and the smoothing allow
// (a robust fit: wrong fixes are left aside).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "sim/trajectory.h"

namespace giocal::sim {

/// One antenna position: time since the path's start [s], position in n [m], 1-sigma east,
/// north, up [m].
struct AntennaFix {
  double t = 0.0;
  Eigen::Vector3d p_n = Eigen::Vector3d::Zero();
  Eigen::Vector3d sigma = Eigen::Vector3d::Constant(0.01);
};

struct FittedPathOptions {
  double knot_spacing = 0.5;       // [s] between the splines' knots
  double jerk_sigma = 1.0;         // smoothness prior on the speed [m/s^3]
  double yaw_accel_sigma = 0.5;    // on the heading [rad/s^2]
  double pitch_accel_sigma = 0.2;  // on the pitch [rad/s^2]
  double pitch_sigma = 0.3;        // the pitch's prior about level [rad]
  double min_sigma = 0.005;        // floor of the fixes' sigma [m]
};

class FittedPath : public VehiclePath {
 public:
  /// `fixes` in rising time from t = 0; p_m_g: the antenna in m. Robust: the fit starts from the
  /// fixes' running median of five and weighs them with a Cauchy loss (3 sigma), so a wrong fix
  /// off its neighbours is left aside.
  /// Throws std::invalid_argument with fewer than 10 fixes, a gap over 30 s between two, fixes
  /// before t = 0 or knots not 0.05 to 30 s apart.
  FittedPath(const std::vector<AntennaFix>& fixes, const Eigen::Vector3d& p_m_g,
             const FittedPathOptions& options = {});

  double duration() const override { return duration_; }
  VehicleKinematics at(double t) const override;
  /// The antenna of the path at time t.
  Eigen::Vector3d antennaAt(double t) const;
  /// Median and largest distance between the path's antenna and the fixes [m], and the fixes
  /// more than 5 sigma from it (wrong fixes the robust fit left aside).
  double medianMiss() const { return median_; }
  double maxMiss() const { return max_; }
  int outliers() const { return outliers_; }

 private:
  PlanarMotion motionAt(int segment, double x) const;
  Eigen::Vector3d displacement(int segment, double x) const;  // from the segment's start
  double h_ = 0.5, duration_ = 0.0;
  std::vector<Eigen::Vector3d> control_;  // (speed, heading, pitch) per control point
  std::vector<Eigen::Vector3d> anchor_;   // position of m at each segment's start
  Eigen::Vector3d p_m_g_;
  double median_ = 0.0, max_ = 0.0;
  int outliers_ = 0;
};

}  // namespace giocal::sim
