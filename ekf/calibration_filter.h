// CalibrationFilter: the error-state EKF over navigation, odometer calibration, GNSS lever arm,
// receiver clock drift and SD ambiguities; IMU time update, odometer and motion-constraint
// updates. GNSS epochs are handled by GnssUpdate (ekf/gnss_update.h) through update().
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/calibration/calibration_options.h"
#include "common/calibration/calibration_run.h"
#include "common/calibration/initial_state.h"
#include "common/geodesy/wgs84.h"
#include "common/gnss/pos_reader.h"
#include "common/imu/imu_preintegration.h"
#include "common/imu/imu_sample.h"
#include "common/math/kalman_update.h"
#include "common/models/odometer_preintegration_model.h"
#include "common/motion/motion_detector.h"
#include "common/odometer/odom_sample.h"
#include "common/odometer/odometer_preintegration.h"
#include "ekf/imu_propagation.h"
#include "ekf/linearization_cache.h"
#include "ekf/state_registry.h"

namespace giocal {

/// The filter's stochastic clones: the attitude when the robot stopped, the pose at the start of
/// the odometer interval, the pose at the previous GNSS epoch.
inline const StateKey kHeadingClone = at(state::kQ, Copy::kStill);
inline const StateKey kOdoP = at(state::kP, Copy::kOdo);
inline const StateKey kOdoQ = at(state::kQ, Copy::kOdo);
inline const StateKey kGnssP = at(state::kP, Copy::kGnss);  // the pose at the previous GNSS
inline const StateKey kGnssQ = at(state::kQ, Copy::kGnss);  // epoch (single receiver's TDCP)

/// What one odometer sample did to the filter.
struct OdometerStep {
  bool interval = false;  // it closed an odometer interval, which updated the filter
  bool rejected = false;  // that update was gated out
  bool reopened = false;  // max_odometer_rejections in a row before it: the extrinsic
                          // covariance was increased by the prior's first
};

/// Registry indices of the calibration's tangent coordinates, in calib_index order.
std::array<int, 8> calibrationIndices(const StateRegistry& s);

class CalibrationFilter {
 public:
  /// `imu` must outlive the filter. The state starts at init.x.t.
  CalibrationFilter(const CalibrationOptions& options, const DatasetDescription& dataset,
                    const std::vector<ImuSample>& imu, const InitialState& init);

  double time() const { return t_; }
  const LocalFrame& frame() const { return frame_; }
  const StateRegistry& state() const { return s_; }
  StateRegistry& state() { return s_; }
  const CalibrationOptions& options() const { return options_; }

  /// Time update to t >= time(): every IMU sample in between is integrated (the covariance moves
  /// once per call with the interval's preintegrated noise); scales, clock drift and ambiguities
  /// get their random-walk noise. Returns the longest IMU gap crossed [s].
  double propagateTo(double t);

  /// Odometer sample at its time (propagate first). The samples are preintegrated (the paper's
  /// integral measurement) from a stochastic clone of the pose; every odometer_interval_s the
  /// interval updates the filter and the clone restarts. Then ZUPT, heading and NHC constraints
  /// when the motion detectors fire.
  OdometerStep updateOdometer(const OdomSample& sample);

  /// One gated Kalman update from a shared model whose blocks are the registry variables `keys`;
  /// consider states (p_b_m.z when held) are not corrected. Models that take a raw gyro sample
  /// pass its per-axis variance: the sample enters as (gyro - b_g), so its noise reaches the
  /// residual through the b_g columns of H and is added to R as gyro_variance H_bg H_bg^T.
  /// iterations > 1: iterated EKF, relinearized at each new estimate. The correction is applied
  /// to the state; the result says what happened (its dx is empty).
  UpdateResult update(const MeasurementModel& model, const std::vector<StateKey>& keys,
                      double chi2_gate, double gyro_variance = 0.0, int iterations = 1);

  /// The rows update() linearizes at the current state (the gyro variance added to R as there).
  MeasurementRows rows(const MeasurementModel& model, const std::vector<StateKey>& keys,
                       double gyro_variance = 0.0) const;

  /// One Kalman update from rows already linearized at the current state (a caller that screened
  /// them need not linearize again); held states as in update().
  UpdateResult updateLinearized(const MeasurementRows& rows, double chi2_gate);
  /// Updates that failed numerically (not gated: UpdateResult::numerical_failure) since the last
  /// call, with those a caller counted (a LAMBDA search on a covariance that is not positive
  /// definite).
  long takeNumericalFailures() {
    const long n = numerical_failures_;
    numerical_failures_ = 0;
    return n;
  }
  void countNumericalFailure() { ++numerical_failures_; }

  /// The LC scheme's update: propagates to the solution's time and applies it through the antenna
  /// lever arm (weighted by options.lc), gated at options.chi2_probability; false if gated out.
  bool updatePosition(const PositionFix& fix);

  /// Raw gyro at t, linearly interpolated, and the per-axis variance of its white noise.
  struct Gyro {
    Eigen::Vector3d rate;
    double variance = 0.0;
  };
  Gyro gyroAt(double t) const;
  /// Mean raw gyro over [t - half_window, t + half_window] and the variance of that mean.
  Gyro gyroMean(double t, double half_window) const;

  /// Moves the pose and velocity to the given ones (biases, covariance and calibration kept),
  /// carrying the pose clones rigidly along so that the odometer interval stays consistent:
  /// dead reckoning starting from a reference state.
  void movePose(const Eigen::Vector3d& p_n_b, const Eigen::Vector3d& v_n_b,
                const Eigen::Quaterniond& q_n_b);

  NavState nav() const;
  CalibrationEstimate calibration() const;
  /// The navigation state predicted to t >= time() (mean only) as a truth.csv row: IMU origin,
  /// ENU velocity and attitude.
  TruthSample trajectorySample(double t);
  bool standingStill() const { return s_.has(kHeadingClone); }

 private:
  /// The filter was too sure of a wrong calibration (the odometer gated out again and again):
  /// the covariance of p_b_m and q_b_m grows by their prior covariance, the means stay. Not
  /// when it is already at least the prior's (a broken odometer must not grow it forever).
  void reopenCalibration();
  /// The error-state indices of the held states, into held_ (its storage reused).
  const std::vector<int>& heldIndices();
  /// rows() into the storage kept for this kind of model (no allocation once it has grown).
  MeasurementRows& linearizeRows(const MeasurementModel& model, const std::vector<StateKey>& keys,
                                 double gyro_variance);
  /// update() of a vehicle-motion model: with p_b_m.z held (planar motion) the model is made
  /// blind to p_b_m along the vehicle's vertical axis (common/models/planar_motion_projection.h),
  /// without allocating.
  UpdateResult updatePlanar(const MeasurementModel& model, const std::vector<StateKey>& keys,
                            double chi2_gate, double gyro_variance = 0.0, int iterations = 1);
  /// The odometer interval's update (the preintegration since the clones), without allocating.
  UpdateResult updateInterval(double t);
  void feedMotion(double t);  // bias-compensated IMU samples up to t into the motion detector
  /// The IMU preintegrated from time() to t; each sample is integrated once however often it
  /// is asked for (trajectory output, then the next update). Its covariance is complete only
  /// with_covariance (an update's propagation); a trajectory row reads the mean alone.
  const ImuPreintegration& pendingTo(double t, bool with_covariance);
  void restartOdometerInterval(const OdomSample& sample);

  CalibrationOptions options_;
  DatasetDescription dataset_;
  const std::vector<ImuSample>& imu_;
  LocalFrame frame_;
  StateRegistry s_;
  MotionDetector motion_;
  double t_ = 0.0;
  double motion_fed_t_ = 0.0;
  std::optional<ImuPreintegration> pending_;  // in place: one per propagation, not allocated
  double pending_t_ = 0.0;
  std::optional<OdometerPreintegration> odo_pre_;  // since the clone kOdoP/kOdoQ; in place
  OdomSample last_odo_;
  PoseRates odo_rates_;  // at the interval's ends, for the odometer's delay (when estimated)
  bool interval_moved_ = false;  // the motion detector saw motion during the odometer interval
  int odometer_rejected_in_row_ = 0;
  int nhc_pending_ = 0;         // odometer samples under NHC since its last update
  double nhc_last_t_ = -1e300;  // time of the last NHC update
  long numerical_failures_ = 0;
  KalmanWorkspace workspace_;
  StateRegistry iterate_prior_;  // the iterated update's prior, kept for its storage
  // An update's working storage, kept from one update to the next.
  std::vector<int> held_states_;  // heldStates() of the options and dataset (calibration order)
  std::vector<int> held_;
  std::vector<BlockBinding> bindings_;
  LinearizationCache linearization_;
  Eigen::VectorXd delta_, h_delta_;
  UpdateResult result_;                  // the last update's, its correction's storage kept
  std::vector<StateKey> interval_keys_;  // the odometer interval model's variables
  PropagationScratch propagation_;
};

}  // namespace giocal
