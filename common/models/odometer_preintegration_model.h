// OdometerPreintegrationModel: the integral odometer residual between two IMU poses, through the
// scale factors (those of state i) and the extrinsic, whitened by its covariance at the current
// scales (covariance() is the identity).
//
// Why whitened here: the measured speed and yaw rate are noisy and multiplied by the unknown
// (1 + s). Least squares with a fixed weight then shrinks the scales by about
// sigma^2 / E[(int w dt)^2] (regression dilution, errors in variables); with the weight at the
// current scales the cost is the profile likelihood over the true readings, which is unbiased
// (docs/results.md: field preset, W scale).
//
// The odometer's delay t_d (a stamp t measures the motion at t - t_d; block t_d_odo): the samples
// over the stamps [t_i, t_j] measure the motion between the IMU poses at t_i - t_d and t_j - t_d,
// taken to first order from the poses at t_i, t_j and their rates (PoseRates):
//   p(t - t_d) = p(t) - t_d v_n_b,  R(t - t_d) = R(t) Exp(-t_d w_b).
// Why the IMU's rates and not the odometer's readings at the ends: the delay is seen only where
// the motion changes (a steady arc looks the same at any delay), and a single noisy reading as
// the regressor shrinks the estimate (errors in variables: 50 ms came out as 20-30 ms on the
// field preset); the IMU's velocity and mean rate are far less noisy.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "common/imu/imu_sample.h"
#include "common/io/dataset_description.h"
#include "common/io/model_options.h"
#include "common/models/measurement_model.h"
#include "common/odometer/odometer_preintegration.h"

namespace giocal {

/// The IMU's velocity (in n) and angular rate (in b, bias removed) at the interval's two ends: the
/// odometer delay's first-order terms.
/// The rate is the gyro's mean over +-kPoseRateHalfWindow [s] (Earth rate, 7e-5 rad/s, left in).
constexpr double kPoseRateHalfWindow = 0.05;
struct PoseRates {
  Eigen::Vector3d v_n_i = Eigen::Vector3d::Zero(), w_b_i = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_n_j = Eigen::Vector3d::Zero(), w_b_j = Eigen::Vector3d::Zero();
};
/// The IMU's rate at t for PoseRates: the gyro's mean over +-kPoseRateHalfWindow less b_g.
Eigen::Vector3d poseRate(const std::vector<ImuSample>& imu, double t, const Eigen::Vector3d& b_g,
                         double gyro_noise_density);

class OdometerPreintegrationModel : public MeasurementModel {
 public:
  /// position_only: a speed-only odometer, whose heading change was taken from the gyro: only
  /// the position rows are a measurement, evaluated at the s_w of the interval's start (the
  /// s_w block is not seen; its Jacobian is zero).
  /// With `rates`, the model has the odometer's delay as a ninth block.
  explicit OdometerPreintegrationModel(std::shared_ptr<const OdometerPreintegration> pre,
                                       bool position_only = false,
                                       std::optional<PoseRates> rates = std::nullopt)
      : pre_(std::move(pre)), rows_(position_only ? 3 : 6), rates_(std::move(rates)) {}
  std::string name() const override {
    return rows_ == 6 ? "odometer_preintegration" : "odometer_speed_preintegration";
  }
  /// p@i, q@i, p@j, q@j, s_v@i, s_w@i, p_b_m, q_b_m[, t_d_odo (the odometer's delay)]
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return rows_; }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override { return Eigen::MatrixXd::Identity(rows_, rows_); }
  void covarianceInto(Eigen::MatrixXd& R) const override;

 private:
  /// Whether the states' turn between the interval's ends is beyond models.lever_arm_min_turn of
  /// its noise (turnBeyondNoise: the gyro's white noise over the interval, about the vehicle's
  /// vertical fused with the odometer's yaw when it measures one). Otherwise p_b_m's Jacobian is
  /// left out: its regressor would be noise (errors in variables). A gyro without a stated noise
  /// density keeps the exact Jacobian.
  bool informsLeverArm(const Eigen::Quaterniond& q_i, const Eigen::Quaterniond& q_j,
                       const Eigen::Quaterniond& q_b_m) const;
  /// W with W^T W = covariance^-1 (of the rows in use) at these scales; on the stack.
  using Whitener = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
  Whitener whitenerAt(double s_v, double s_w) const;
  std::shared_ptr<const OdometerPreintegration> pre_;
  int rows_;
  std::optional<PoseRates> rates_;
};

/// The integral measurement's noise: the odometer's own, and the models' out-of-plane noise;
/// the gyro's white noise [rad/s/sqrt(Hz)] for the lever-arm test.
OdometerPreintegrationNoise odometerPreintegrationNoise(const OdometerNoise& odometer,
                                                        double gyro_noise_density,
                                                        const ModelOptions& models);

}  // namespace giocal
