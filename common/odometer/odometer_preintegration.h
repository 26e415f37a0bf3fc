// OdometerPreintegration: the paper's integral odometer measurement between two epochs.
//
// Differential-drive motion is integrated in the vehicle frame m_k of the first epoch, where it is
// planar: yaw theta = (1 + s_w) * Theta with Theta = int w dt, and position
// dp_m = (1 + s_v) * P(s_w) with P = int Rz(theta) e_y v dt. s_v enters exactly, s_w through one
// first-order Jacobian dP/ds_w, and the extrinsic maps the result into b exactly:
//   R_bk_bj = R_b_m Rz(theta) R_m_b,  p_bk_bj = p_b_m + R_b_m dp_m - R_bk_bj p_b_m,
// so a new linearization point of s_v, p_b_m, q_b_m needs no re-integration at all.
// The covariance of (dp_m, dtheta_m) is propagated with the paper's F_t and G_t written in m
// (R_b_m = I, p_b_m = 0 there), extended by out-of-plane noise (lateral and vertical velocity,
// roll and pitch rate) so that uneven ground is not a hard constraint.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/io/dataset_description.h"
#include "common/math/so3.h"
#include "common/odometer/odom_sample.h"
#include "common/odometer/odometer_calibration.h"

namespace giocal {

/// Noise of the integral measurement, per odometer sample interval.
struct OdometerPreintegrationNoise {
  double speed_sigma = 0.01;        // measured speed white noise [m/s]
  double yaw_rate_sigma = 0.01745;  // measured yaw rate white noise [rad/s]
  double lateral_speed_density =
      0.01;                          // slip and uneven ground, lateral and vertical [m/s/sqrt(Hz)]
  double tilt_rate_density = 0.005;  // roll and pitch rate of uneven ground [rad/s/sqrt(Hz)]
  double gyro_noise_density = 0.0;   // the IMU's, for the lever-arm test below [rad/s/sqrt(Hz)]
  double lever_arm_min_turn = 6.0;   // see OdometerPreintegrationModel [sigma]
};

/// Whether a turn (rotation vector of R_bi_bj, in b) is beyond min_turn of its noise: about the
/// vehicle's vertical up_b with yaw_sigma, about the other axes with tilt_sigma (chi-square of
/// three axes against min_turn^2); min_turn 0: true. The lever-arm term (R_bi_bj - I) p_b_m informs
/// p_b_m only through such a turn; within the noise R_bi_bj - I is noise, and a regressor that is
/// noise yields information the motion does not hold (errors in variables; docs/design.md "A
/// straight says nothing of the lever arm").
bool turnBeyondNoise(const Vec3& turn_b, const Vec3& up_b, double yaw_sigma, double tilt_sigma,
                     double min_turn);

/// The longest time between two readings over [t0, t1]: between two samples that bracket part of
/// it, from t0 to the first sample when none is at or before t0, from the last to t1 when none is
/// at or after t1 (where integrateSamples interpolates or holds). Samples in time order. A stretch
/// longer than calibration.max_odometer_gap_s is a gap the odometer did not measure: the factor
/// graph gives such an interval no odometer factor, as the EKF restarts its interval at a gap
/// between consecutive samples (CalibrationFilter::updateOdometer); the IMU carries both across.
double longestOdometerGap(const std::vector<OdomSample>& samples, double t0, double t1);

/// Residual [r_p (3), r_theta (3)] in m_k with Jacobians with respect to the right-perturbed
/// blocks: p and q of states i and j, the scales and the extrinsic.
struct OdometerResidual {
  Eigen::Matrix<double, 6, 1> r;
  Eigen::Matrix<double, 6, 3> J_p_i, J_q_i, J_p_j, J_q_j, J_p_b_m, J_q_b_m;
  Eigen::Matrix<double, 6, 1> J_s_v, J_s_w;
};

class OdometerPreintegration {
 public:
  /// s_v and s_w are the linearization point of the scales.
  OdometerPreintegration(const OdometerPreintegrationNoise& noise, double s_v, double s_w);

  /// Adds dt seconds over which the measured speed v and yaw rate w are constant (an arc).
  void integrate(double dt, double v, double w);

  /// Integrates the samples covering [t0, t1], interpolating linearly between samples (the last
  /// one holds).
  void integrateSamples(const std::vector<OdomSample>& samples, double t0, double t1);

  double dt() const { return dt_sum_; }
  const OdometerPreintegrationNoise& noise() const { return noise_; }
  double linSv() const { return s_v_lin_; }
  double linSw() const { return s_w_lin_; }
  /// Yaw of m_j in m_k and position of m_j in m_k for the given scales (first order in s_w).
  double yaw(double s_w) const;
  Vec3 deltaP_m(double s_v, double s_w) const;
  /// The paper's (dp, dq): pose of b_j in b_k for a full calibration.
  Mat3 deltaR_b(const OdometerCalibration& c) const;
  Vec3 deltaP_b(const OdometerCalibration& c) const;
  /// Covariance of [dp_m, dtheta_m].
  const Eigen::Matrix<double, 6, 6>& covariance() const { return cov_; }
  /// The same for other scales: the measured speed's and yaw rate's noise enter multiplied by
  /// (1 + s_v) and (1 + s_w) (the other noise does not).
  Eigen::Matrix<double, 6, 6> covarianceAt(double s_v, double s_w) const;

  /// Residual between IMU poses (R_n_bi, p_n_bi), (R_n_bj, p_n_bj) and the calibration.
  OdometerResidual evaluate(const Vec3& p_i, const Eigen::Quaterniond& q_i, const Vec3& p_j,
                            const Eigen::Quaterniond& q_j, const OdometerCalibration& c) const;

 private:
  OdometerPreintegrationNoise noise_;
  double s_v_lin_, s_w_lin_;
  double dt_sum_ = 0.0;
  double Theta_ = 0.0;     // int w dt (measured)
  Vec3 P_ = Vec3::Zero();  // int Rz(theta) e_y v dt at s_w_lin
  Vec3 dP_dsw_ = Vec3::Zero();
  Eigen::Matrix<double, 6, 6> cov_ = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 6> cov_speed_ = Eigen::Matrix<double, 6, 6>::Zero();     // part of cov_
  Eigen::Matrix<double, 6, 6> cov_yaw_rate_ = Eigen::Matrix<double, 6, 6>::Zero();  // part of cov_
};

}  // namespace giocal
