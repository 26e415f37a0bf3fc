// FixHeights: how far a position solution's heights stray from the height profile the drive's own
// IMU and odometer give (the grade the accelerometer sees, times the distance the wheels roll),
// against the solution's own height sigmas. Consumer receivers' heights wander by metres while
// they report sigmas of one or two; a calibration that believes them tilts the vehicle.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "common/gnss/pos_reader.h"
#include "common/imu/imu_sample.h"
#include "common/odometer/odom_sample.h"

namespace giocal {

/// The drive in 0.1 s bins, built from the IMU and odometer as they stream (a few MB for hours):
/// the specific force along the vehicle's forward axis and the odometer's speed.
class DriveProfile {
 public:
  explicit DriveProfile(const Eigen::Matrix3d& R_b_m) : forward_b_(R_b_m.col(0)) {}
  void addImu(const ImuSample& s);
  void addOdometer(const OdomSample& o);

  struct Bin {
    double f_forward = 0.0, speed = 0.0;  // sums until finished, then means
    int imu = 0, odom = 0;
  };
  static constexpr double kBin = 0.1;  // [s]
  /// The bins with both sensors in them, their means formed; their times are index * kBin.
  std::vector<std::pair<double, Bin>> finished() const;
  double gravity() const {  // the mean |f| [m/s^2]
    return imu_ > 0 ? gravity_sum_ / static_cast<double>(imu_) : 0.0;
  }

 private:
  static constexpr long kMaxBins = 10 * 86400;  // a day of driving
  Bin* binAt(double t);                         // null outside the drive
  Eigen::Vector3d forward_b_;
  std::vector<Bin> bins_;
  long first_ = 0;  // the index of bins_[0]
  double gravity_sum_ = 0.0;
  long imu_ = 0;
};

struct FixHeights {
  bool decided = false;
  std::string why_not;            // when not decided
  int fixes = 0;                  // fixes inside the drive's span
  double distance_m = 0.0;        // driven over them
  double spread_m = 0.0;          // robust sigma of the heights about the motion's profile
  double reported_sigma_m = 0.0;  // the solution's median height sigma
  double grade = 0.0;             // the constant grade fitted with the profile (mounting pitch)
  /// spread / reported sigma: by how much the solution's height sigmas understate its errors.
  double scale() const { return reported_sigma_m > 0.0 ? spread_m / reported_sigma_m : 0.0; }
};

/// Needs at least 30 fixes over 50 m of driving. A constant error in the mounting's pitch is
/// fitted out as a grade, with the heights' offset.
FixHeights checkFixHeights(const std::vector<PositionFix>& fixes, const DriveProfile& drive);

}  // namespace giocal
