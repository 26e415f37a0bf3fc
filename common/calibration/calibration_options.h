// CalibrationOptions: the options both calibrators (EKF and factor graph) share, with their
// defaults, loadable from the "calibration", "models" and "rtk" sections of a giocal YAML config.
#pragma once

#include <Eigen/Core>
#include <string>

#include "common/calibration/warm_start.h"
#include "common/gnss/code_outlier_check.h"
#include "common/gnss/dd_epoch.h"
#include "common/gnss/doppler.h"
#include "common/gnss/lambda.h"
#include "common/gnss/time_differenced_phase.h"
#include "common/io/model_options.h"
#include "common/models/position_model.h"
#include "common/online/convergence.h"

namespace giocal {

class YamlFields;

/// How the filter finds its first state: a static window for roll, pitch and gyro bias, then the
/// heading from the GNSS displacement of the first straight-ish drive.
struct InitOptions {
  double static_speed = 0.01;  // mean odometer speed over the motion window below this: still [m/s]
  double min_static_s = 2.0;   // shortest static window used for alignment [s]
  double min_distance = 1.0;   // antenna travel that gives the heading [m]
  double max_heading_sigma_deg = 3.0;  // the displacement must fix the heading this well [deg]
  double max_turn_deg = 20.0;          // yaw change allowed over that travel [deg]
  double velocity_sigma = 0.05;        // initial velocity 1-sigma [m/s]
  double attitude_sigma_deg = 1.0;     // roll and pitch 1-sigma without a static window [deg]
};

/// The online calibrator's buffering and its live reports ("online" section).
struct OnlineOptions {
  // Data are put back in time order across sensors within this lag behind the newest datum;
  // anything older on arrival is counted and dropped [s].
  double reorder_lag_s = 0.5;
  // A datum more than this ahead of every datum received so far waits for its own sensor's next
  // one: if that one goes on from it, the sensor really jumped (a gap); if it goes back, the stamp
  // was a glitch (a GPS week rollover, say), and the datum is counted and dropped instead of
  // moving the reorder frontier into the future [s].
  double max_lead_s = 2.0;
  // Odometer and GNSS events wait this long (data time) for IMU samples past them; then, the IMU
  // being silent, they are dropped with a warning [s].
  double max_imu_wait_s = 2.0;
  // Initialization searches at most this far back; older data are let go [s].
  double max_init_window_s = 600.0;
  double progress_interval_s = 60.0;  // live report of what has not converged yet [s]
  ConvergenceOptions convergence;
};

/// The single-receiver scheme's settings (YAML section calibration.single).
struct SingleReceiverOptions {
  TdcpOptions tdcp;
  // Single point positions anchor the frame and the heading only: their errors (ionosphere,
  // orbits, multipath) are metres and slow, so each enters with at least this sigma per axis [m].
  double position_sigma_min_m = 3.0;
  double tdcp_screen_gate = 4.0;  // a signal's phase change this many sigma off the predicted
                                  // displacement is left out of its pair (screenTdcp)
  // The time differences' slow error: each satellite's range rate off by this much, 1-sigma
  // [m/s], correlated over tdcp_drift_tau_s, estimated as the antenna velocity it makes
  // (state::kTdcpDrift, TdcpModel); 0: the rows' errors taken as white.
  double tdcp_drift_sigma = 7e-4;
  double tdcp_drift_tau_s = 60.0;
  // The single point positions' slow error: each satellite's range off by spp_bias_sigma [m]
  // for about spp_bias_tau_s (broadcast orbits and clocks, the atmosphere models), which the
  // solution's geometry turns into a position offset (sppBiasCovariance: metres under a few
  // satellites), estimated as a first-order Gauss-Markov offset (state::kSppBias,
  // PositionModel::withBias); 0: their errors taken as white.
  double spp_bias_sigma = 2.0;
  double spp_bias_tau_s = 600.0;
};

struct CalibrationOptions {
  WarmStartOptions warm_start;    // "warm_start" section: drift per sqrt(day) of a carried prior
  ModelOptions models;            // motion detectors, ZUPT and NHC noise
  DdOptions dd;                   // "rtk" section: mask, frequencies, systems, code/phase noise
  LambdaOptions lambda;           // "rtk" section: ratio test, partial AR
  double ambiguity_noise = 1e-4;  // "rtk" section: SD ambiguity random walk [cycles/sqrt(s)]
  DopplerOptions doppler;
  CodeOutlierOptions code_outliers;
  InitOptions init;

  bool ambiguity_resolution = true;  // false: the paper's TC-WAR scheme (float ambiguities)
  double fix_sigma_cycles = 1e-3;    // DD ambiguity fixes enter as constraints of this sigma
  double max_fix_residual = 4.0;     // a fix is kept only if every fixed-solution DD phase
                                     // residual is below this many sigma
  double innovation_gate = 5.0;      // GNSS rows with larger normalized innovation are rejected
  double chi2_probability = 0.9999;  // NIS gate of odometer and motion-constraint updates
  double heading_sigma_deg = 0.05;   // heading constraint while standing still [deg]
  bool estimate_p_b_g = false;       // estimate the GNSS lever arm (else fixed at dataset.yaml)
  double p_b_g_sigma = 0.05;         // its prior 1-sigma when estimated [m]
  // Estimate the odometer's delay against the IMU (t_d_odo, after dataset.yaml's time_offsets) as
  // a calibration state, to first order: for delays up to about 0.1 s; larger ones belong in
  // time_offsets.odometer (summary.json's odometer_delay measures them). Not with a speed-only
  // odometer (its yaw rate is the gyro's).
  bool estimate_odometer_delay = false;
  double odometer_delay_sigma = 0.05;  // its prior 1-sigma about zero [s]
  // When the odometer's delay against the IMU, measured on the logs before calibrating (the yaw
  // rate both see), is known to better than `apply_odometer_delay_sigma` and larger than
  // `apply_odometer_delay_min`, `calibrate` and `compare` take it out of the odometer's stamps
  // (summary.json's odometer_delay.applied_s). Off by default (sigma 0): on the real Husky bag
  // (392 +- 10 ms late) with the default LC heights (lc.learn_heights) it moved the EKF's
  // validation from 10.3 m to 7.9 m (the guess 8.1 m) and the factor graph's from 8.0 to 8.2 m,
  // but with lc.use_height: 0 it turned the EKF's roll 5.6 deg off gravity (docs/results.md).
  // Not with estimate_odometer_delay.
  double apply_odometer_delay_sigma = 0.0;  // [s]; e.g. 0.010
  double apply_odometer_delay_min = 0.020;  // [s]
  // Estimate the gyro triad's tilt against the accelerometer triad (GyroTilt, two angles) as a
  // state: an IMU whose triads lean by hundredths of a degree turns the extrinsic yaw otherwise
  // (docs/results.md, the field preset).
  bool estimate_gyro_tilt = false;
  double gyro_tilt_sigma_deg = 0.1;  // its prior 1-sigma per axis about zero [deg]
  // Where the tilt starts [rad]: a calibrate run's estimate when dead-reckoning with it. Not a
  // YAML key.
  Eigen::Vector2d gyro_tilt_start = Eigen::Vector2d::Zero();
  bool hold_p_b_m_z = true;  // keep p_b_m.z at its prior (unobservable in planar motion)
  // Every calibration state held at its prior as a consider state (its covariance enters the
  // updates, it is never corrected): dead reckoning with a given calibration. Not a YAML key.
  bool hold_calibration = false;
  // The paper's LC scheme: GNSS enters as the antenna position solutions pushed with the rover
  // epochs (Calibrator::addPosition, calibrate --gnss lc --pos), not as double differences; the
  // initial heading comes from the solutions too. Without raw GNSS the solutions are the epochs.
  // Not a YAML key.
  bool loosely_coupled = false;
  PositionWeighting lc;  // calibration.lc.sigma_scale, .use_height, .learn_heights
  // One receiver and no base (calibrate --gnss single): time-differenced carrier phase between
  // consecutive rover epochs, Doppler, and single point positions with a loose weight. Not a
  // YAML key (the command line's); `single` holds its settings (calibration.single.*).
  bool single_receiver = false;
  SingleReceiverOptions single;
  double clock_drift_noise = 0.1;    // receiver clock drift random walk [m/s/sqrt(s)]
  double odometer_interval_s = 1.0;  // odometer preintegration interval (0: every sample) [s]
  // Iterated EKF (Gauss-Newton) updates of each odometer interval: 2 against 1 cut the V-scale
  // error of badly guessed seeds (100-seed Monte Carlo: 1.8e-3 -> 1.4e-3, docs/results.md).
  int odometer_iterations = 2;
  // This many odometer intervals in a row rejected by the NIS gate: the filter, not the odometer,
  // is wrong (overconfident in a wrong calibration); the covariance of p_b_m and q_b_m is
  // increased by their prior covariance before the next one.
  int max_odometer_rejections = 5;
  double max_odometer_gap_s = 0.5;  // a longer gap restarts the odometer interval [s]
  // Rover epochs further apart (and more than 2.5 of the receiver's intervals) are named as an
  // outage; a receiver interval beyond it is named once as sparse GNSS [s].
  double gnss_gap_warning_s = 5.0;
  double output_rate_hz = 10.0;  // trajectory.csv rate [Hz]
  double max_imu_gap_s = 0.5;    // longer IMU gaps are reported (and bridged) [s]
  // Longer IMU gaps end the stretch: the navigation state restarts from the data after the gap
  // (static window or motion, heading from GNSS), the calibration is carried over with its
  // covariance. Interpolating the IMU across a gap is a model error the preintegration noise
  // does not cover (a 10 s gap left p_b_m.y 4.4 sigma off) [s].
  double max_imu_bridge_s = 1.0;
  double max_base_offset = 0.5;    // "rtk" section: largest rover-base time-tag gap [s]
  double divergence_sigma = 50.0;  // DD code innovations this many sigma off: diverged
  OnlineOptions online;
};

/// Defaults, overridden by the keys present in `path` (empty: defaults only). Throws DataError
/// naming the file, line and problem.
CalibrationOptions readCalibrationOptions(const std::string& path);
/// The same from a configuration already parsed.
CalibrationOptions readCalibrationOptions(const YamlFields& y);

}  // namespace giocal
