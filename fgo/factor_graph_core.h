// FactorGraphCore: the sliding-window factor graph as the online Calibrator's estimator: one state
// per GNSS epoch joined by IMU and odometer preintegration, DD code/phase and Doppler factors,
// motion constraints, ambiguity fixes; the oldest epoch is marginalized into a prior.
#pragma once

#include <algorithm>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_options.h"
#include "common/calibration/initial_state.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/code_outlier_check.h"
#include "common/gnss/dd_epoch.h"
#include "common/gnss/doppler.h"
#include "common/gnss/time_differenced_phase.h"
#include "common/imu/imu_preintegration.h"
#include "common/models/dd_gnss_model.h"
#include "common/motion/motion_detector.h"
#include "common/online/estimator_core.h"
#include "fgo/sliding_window.h"
#include "options/fgo_options.h"

namespace giocal {

/// The variables of one GNSS epoch.
struct FgoEpoch {
  double t = 0.0;
  int k = 0;
  bool still = false;
  bool diverged = false;  // its code rows as a whole far outside their noise (as the EKF's test)
  StateKey p, q, v, ba, bg, sv, sw, cd;  // the quantities at epoch k
  StateKey vt;                           // and the time differences' drift, where it has one
  bool drift = false;
  StateKey bs;  // and the single point positions' bias, where it has one
  bool spp_bias = false;
  DdEpoch dd;
  std::vector<DdObservation> code_rows, phase_rows;
  std::vector<DopplerObservation> doppler;
  TdcpPair tdcp;  // the single-receiver scheme: the phase changes since the previous epoch
  Eigen::Vector3d gyro = Eigen::Vector3d::Zero();

  std::vector<StateKey> all() const {
    std::vector<StateKey> keys{p, q, v, ba, bg, sv, sw, cd};
    if (drift) keys.push_back(vt);
    if (spp_bias) keys.push_back(bs);
    return keys;
  }
};

class FactorGraphCore : public EstimatorCore {
 public:
  /// `sensors` (the Calibrator's buffers) and `orbits` must outlive the core.
  FactorGraphCore(const CalibrationInputs& sensors, const BroadcastOrbits& orbits,
                  const CalibrationOptions& options, const FgoOptions& fgo_options,
                  const InitialState& init);

  bool takesOdometerEvents() const override { return false; }
  double time() const override { return epochs_.back().t; }
  bool acceptsEpoch(double t) const override { return t > epochs_.back().t + 1e-6; }
  EpochOutcome gnss(const ObsEpoch& rover, const ObsEpoch& base, CalibrationRun& run) override;
  CalibrationEstimate calibration() const override { return estimate(epochs_.back()); }
  NavState nav() const override { return nav(epochs_.back()); }
  void trajectoryUpTo(double t, const std::function<void(const TruthSample&)>& out) override;
  double oldestSampleNeeded() const override;

 private:
  FgoEpoch newEpoch(double t);
  void addNavVariables(const FgoEpoch& e, const NavState& x, double s_v, double s_w, double cd);
  NavState nav(const FgoEpoch& e) const;
  /// The gyro's tilt where it is estimated (calibration.estimate_gyro_tilt), else none.
  std::optional<GyroTilt> gyroTilt() const;
  /// Feeds the motion detector up to t, the IMU samples up to each odometer sample before it (as
  /// the EKF does), and counts the odometer samples at which NHC applies (nhc_samples_).
  void feedMotion(double t, const Eigen::Vector3d& b_g);
  void start(const InitialState& init);
  CalibrationEstimate estimate(const FgoEpoch& e) const;
  void outputTrajectory(const FgoEpoch& from, const FgoEpoch& to);
  void marginalizeOldest();
  /// With p_b_m.z held (planar motion), vehicle-motion factors are blind to p_b_m along the
  /// vehicle's vertical axis (common/models/planar_motion_projection.h).
  std::shared_ptr<const MeasurementModel> planar(std::shared_ptr<const MeasurementModel> m) const;

  // GNSS factors (fgo/factor_graph_gnss.cc).
  void gnssFactors(FgoEpoch& e, const ObsEpoch& rover, const ObsEpoch& base);
  void addGnssRowFactors(const FgoEpoch& e);
  /// The clock drift's start value from the epoch's Doppler, once (the median residual at zero).
  void startClockDrift(const FgoEpoch& e);
  // The single-receiver scheme (fgo/factor_graph_single.cc).
  Eigen::Vector3d antennaOf(const FgoEpoch& e) const;
  void singleFactors(FgoEpoch& e, const FgoEpoch& prev, const ObsEpoch& rover);
  void addTdcpFactor(const FgoEpoch& e, const FgoEpoch& prev);
  /// After a solve: the TDCP row beyond fgo.rejection_sigma goes with its signal; true if one did.
  bool rejectWorstTdcp(FgoEpoch& e, const FgoEpoch& prev);
  /// The time differences' drift at e (state::kTdcpDrift, single receiver): a Gauss-Markov
  /// process from prev's, its stationary covariance from e's sky (the last sky that fixed it).
  void addDrift(FgoEpoch& e, const FgoEpoch& prev, const Eigen::Vector3d& ant_e);
  /// The single point positions' bias at e (state::kSppBias): a Gauss-Markov process from prev's,
  /// its stationary covariance from the last solution's sky (sppBiasCovariance).
  void addSppBias(FgoEpoch& e, const FgoEpoch& prev);
  /// A first-order Gauss-Markov 3-vector at e (`now`) of stationary covariance Q: from `before`
  /// (the previous epoch's, at t_before) by RandomWalkModel's Gauss-Markov form, or with a prior
  /// of Q where there is none, tagged `tag` or `prior_tag`.
  void addGaussMarkov(const FgoEpoch& e, const StateKey* before, const StateKey& now,
                      double t_before, double tau_s, const Eigen::Matrix3d& Q, const char* tag,
                      const char* prior_tag);
  /// The LC scheme's position factor of epoch e removed when its solved residual fails the
  /// chi-square gate (calibration.chi2_probability); true when it was.
  bool rejectPosition(const FgoEpoch& e, const PositionFix& fix);
  bool rejectOdometer(const FgoEpoch& e);
  // Odometer intervals (fgo/odometer_slip_check.cc).
  /// The odometer samples over [t0, t1] with the one before t0 and the one after t1.
  std::vector<OdomSample> odometerSamples(double t0, double t1) const;
  /// The samples of the interval from prev to e, empty when it has no odometer factor: before the
  /// first sample, or across a gap longer than calibration.max_odometer_gap_s (the IMU alone).
  std::vector<OdomSample> intervalSamples(const FgoEpoch& prev, const FgoEpoch& e) const;
  void addOdometerFactor(const FgoEpoch& prev, const FgoEpoch& e,
                         const std::vector<OdomSample>& samples);
  /// After a solve: samples of the interval prev-e whose speed leaves the interval's common
  /// offset from the IMU (pinned to the solved states at both ends) by more than
  /// fgo.odometer_slip_sigma are wheel slip; the factor is made again without them.
  bool leaveOutSlips(const FgoEpoch& prev, const FgoEpoch& e);
  /// The current version of the SD ambiguity of (sat, band); none before its first.
  std::optional<StateKey> ambiguityVar(const SatId& sat, char band) const;
  void newAmbiguity(const SatId& sat, char band, double value, double lambda);
  std::vector<StateKey> phaseVars(const DdGnssModel& model,
                                  const std::vector<DdObservation>& rows) const;
  /// |residual| / sigma of each of the epoch's code or phase rows at the current values.
  Eigen::VectorXd normalizedRowResiduals(const FgoEpoch& e, bool phase) const;
  bool rejectWorstRow(FgoEpoch& e);
  /// Solves the window; a solve that fails numerically is counted (numerical_failures), once
  /// named in the warnings.
  void solveWindow();
  bool resolve(FgoEpoch& e, const std::vector<SatId>& excluded = {});

  const CalibrationInputs& in_;
  CalibrationOptions o_;
  FgoOptions fo_;
  CalibrationRun* run_ = nullptr;  // the run being counted into, during gnss()
  LocalFrame frame_;
  const BroadcastOrbits& orbits_;
  DdEpochBuilder builder_;
  TdcpBuilder tdcp_;                                                   // the single-receiver scheme
  Eigen::Matrix3d drift_covariance_ = Eigen::Matrix3d::Constant(NAN);  // the last sky's
  Eigen::Matrix3d spp_bias_covariance_ = Eigen::Matrix3d::Constant(NAN);  // the last sky's
  CodeOutlierCheck rover_check_, base_check_;
  MotionDetector motion_;
  std::vector<int> held_;  // calibration states the run keeps at the prior (heldStates)
  bool holds(int state) const { return std::count(held_.begin(), held_.end(), state) != 0; }
  SlidingWindow w_;
  std::deque<FgoEpoch> epochs_;
  int next_k_ = 0;
  std::map<std::pair<SatId, char>, int> amb_version_;
  std::set<std::pair<StateKey, StateKey>> held_fixes_;
  double motion_fed_t_ = -INFINITY;
  int nhc_samples_ = 0;  // odometer samples since the last NHC factor at which NHC applied
  double next_output_ = 0.0;
  bool clock_drift_started_ = false;
  std::vector<TruthSample> trajectory_;  // computed with the epoch, handed out by trajectoryUpTo
};

}  // namespace giocal
