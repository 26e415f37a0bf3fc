// ImuPreintegration: on-manifold preintegration of IMU samples between two epochs (Forster et al.
// 2017), its covariance and bias Jacobians, and the residual between two NavStates.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "common/imu/imu_sample.h"
#include "common/imu/nav_state.h"
#include "common/io/dataset_description.h"
#include "common/math/so3.h"

namespace giocal {

/// Residual and covariance order of the IMU factor: [r_p, r_theta, r_v, r_ba, r_bg].
namespace imu_index {
constexpr int kP = 0, kR = 3, kV = 6, kBa = 9, kBg = 12, kSize = 15;
}

/// The residual of two states against one preintegration, and the Jacobians with respect to the
/// right-perturbed states: p, theta (q * Exp(theta)), v, b_a, b_g of state i and of state j.
struct ImuResidual {
  Eigen::Matrix<double, 15, 1> r;
  Eigen::Matrix<double, 15, 3> J_p_i, J_q_i, J_v_i, J_ba_i, J_bg_i;
  Eigen::Matrix<double, 15, 3> J_p_j, J_q_j, J_v_j, J_ba_j, J_bg_j;
  Eigen::Matrix<double, 15, 2> J_tilt;  // with respect to the gyro's tilt (ImuPreintegration)
};

/// The inverse of the residual's Jacobian with respect to state j, [J_p_j J_q_j J_v_j J_ba_j
/// J_bg_j], from its 3x3 blocks: r_p moves with p_j, r_theta with theta_j, r_v with v_j and p_j
/// (the Earth's rate), the biases with themselves. What the EKF's propagation solves for at
/// every step, at a fraction of a general 15x15 inverse's cost.
Eigen::Matrix<double, 15, 15> endStateJacobianInverse(const ImuResidual& r);

/// The gyro triad's tilt against the accelerometer triad, (x, y) [rad]: the body frame b lies
/// halfway between them, the gyro measuring in Exp(+d/2) b and the accelerometer in Exp(-d/2) b,
/// d = (x, y, 0). A rotation of one triad about the common z axis is left out: it does not show
/// in the motion of a ground vehicle (docs/results.md, the field preset's yaw).
using GyroTilt = Eigen::Vector2d;

/// What the motion may do while the IMU is silent: a sample interval longer than
/// `min_interval_s` is bridged by linear interpolation in steps of at most `step_s`, with extra
/// white noise for what interpolation cannot know (a vehicle's rate changing by up to
/// `angular_accel` rad/s^2, its specific force by `jerk` m/s^3: over a bridge of T seconds the
/// interpolation error of the heading grows like angular_accel*T^2/4, which a noise density of
/// angular_accel*T^1.5/4 reproduces; likewise for velocity). Ground-robot bounds; docs/design.md.
struct ImuBridgeModel {
  double min_interval_s = 0.05;
  double step_s = 0.01;
  double angular_accel = 1.0;
  double jerk = 2.0;
};

class ImuPreintegration {
 public:
  /// One step's rotation terms: E = Exp(phi), Jr = Jr(phi), G1 = Jr(-phi), G2 = gamma2(phi).
  struct StepRotation {
    Mat3 E, Jr, G1, G2;
  };

  /// gravity_n and omega_ie_n come from the LocalFrame; biases (and the gyro's tilt) are the
  /// linearization point. Without a tilt it is zero and its Jacobian is not carried
  /// (tiltJacobian() stays zero): an estimator that does not estimate it saves the work.
  ImuPreintegration(const ImuNoise& noise, const Eigen::Vector3d& gravity_n,
                    const Eigen::Vector3d& omega_ie_n, const Eigen::Vector3d& b_a,
                    const Eigen::Vector3d& b_g, const std::optional<GyroTilt>& tilt = std::nullopt);

  /// Adds a step of dt seconds over which rate and specific force are constant (the caller passes
  /// the mean of the two bounding samples). The mean is exact for constant inputs. The extra
  /// densities add to the IMU's white noise over this step (bridged gaps).
  void integrate(double dt, const Eigen::Vector3d& gyro, const Eigen::Vector3d& acc,
                 double extra_gyro_density = 0.0, double extra_accel_density = 0.0);

  /// Integrates the samples covering [t0, t1], interpolating linearly at both ends and across
  /// intervals the IMU left empty (ImuBridgeModel): addSamples, then closeCovariance.
  void integrateSamples(const std::vector<ImuSample>& samples, double t0, double t1,
                        const ImuBridgeModel& bridge = {});
  /// The same samples into the deltas, with the covariance step they end left open: enough for
  /// predict() at t1 (a trajectory between updates), and the covariance's steps do not depend on
  /// where the caller stopped to predict.
  void addSamples(const std::vector<ImuSample>& samples, double t0, double t1,
                  const ImuBridgeModel& bridge = {});
  /// Closes the open covariance step: covariance(), biasJacobian() and tiltJacobian() then hold
  /// every sample added (integrate() and integrateSamples() close it themselves).
  void closeCovariance();
  /// From here on the deltas only, for predict() at the linearization point's biases (a
  /// trajectory row): covariance(), biasJacobian() and tiltJacobian() stay at their last step.
  void meanOnly() { mean_only_ = true; }

  /// The covariance and bias Jacobians advance in steps of at least this, one transition for
  /// the samples' mean rate and specific force: the transition then differs from the product of
  /// the samples' by about (rate * step)^2, 1e-4 at 0.5 rad/s, far below what the noise model
  /// knows, for an eighth of the work at 400 Hz and half at 100 Hz. A single sample keeps its own
  /// terms exactly. (10 ms until 2026-12-02: the Monte Carlo tables and the real runs equal to
  /// their printed digits at 20 ms, docs/results.md.)
  static constexpr double kCovarianceStep_s = 0.02;

  double dt() const { return dt_sum_; }
  const Mat3& deltaR() const { return dR_; }
  const Vec3& deltaV() const { return dv_; }
  const Vec3& deltaP() const { return dp_; }
  const Eigen::Vector3d& linBa() const { return b_a_lin_; }
  const Eigen::Vector3d& linBg() const { return b_g_lin_; }
  const GyroTilt& linTilt() const { return tilt_lin_; }
  /// Covariance of the residual [p, theta, v, b_a, b_g] (15x15), up to the last closed step.
  const Eigen::Matrix<double, 15, 15>& covariance() const { return cov_; }
  /// d(dp, dtheta, dv)/d(b_a, b_g): rows [p, theta, v], columns [b_a, b_g].
  const Eigen::Matrix<double, 9, 6>& biasJacobian() const { return J_bias_; }
  /// d(dp, dtheta, dv)/d(gyro tilt): rows [p, theta, v].
  const Eigen::Matrix<double, 9, 2>& tiltJacobian() const { return J_tilt_; }

  /// Deltas corrected to first order for biases (and a gyro tilt) that differ from the
  /// linearization point; without a tilt, the linearization point's.
  Mat3 correctedDeltaR(const Eigen::Vector3d& b_g,
                       const std::optional<GyroTilt>& tilt = std::nullopt) const;
  Vec3 correctedDeltaV(const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g,
                       const std::optional<GyroTilt>& tilt = std::nullopt) const;
  Vec3 correctedDeltaP(const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g,
                       const std::optional<GyroTilt>& tilt = std::nullopt) const;

  /// The state j this preintegration predicts from state i (biases carried over).
  NavState predict(const NavState& i, const std::optional<GyroTilt>& tilt = std::nullopt) const;

  /// Residual between states i and j with all Jacobians (see ImuResidual).
  ImuResidual evaluate(const NavState& i, const NavState& j,
                       const std::optional<GyroTilt>& tilt = std::nullopt) const;

 private:
  struct Step {
    double dt;
    Eigen::Vector3d gyro, acc;
    double extra_gyro_density, extra_accel_density;
  };
  // The samples since the covariance and bias Jacobians last advanced (kCovarianceStep_s).
  struct PendingCovariance {
    int samples = 0;
    double dt = 0.0;
    Vec3 phi = Vec3::Zero(), a_dt = Vec3::Zero();  // sums of the rate and specific force * dt
    double gyro_var_dt = 0.0, accel_var_dt = 0.0;  // sums of the extra densities^2 * dt
    Mat3 dR0;                                      // dR_ at the first sample
    // The first sample's rate, specific force, rotation terms and extra densities^2.
    Vec3 w, a;
    StepRotation rot;
    double eg2 = 0.0, ea2 = 0.0;
    /// Empties the sums; the first-sample fields are written before they are read.
    void clear() {
      samples = 0;
      dt = gyro_var_dt = accel_var_dt = 0.0;
      phi.setZero();
      a_dt.setZero();
    }
  };
  void reset();
  /// Checks a step's inputs (throws std::invalid_argument).
  static void checkStep(const Step& s);
  void addChecked(const Step& s);  // checkStep, then addStep
  void addStep(const Step& s);
  /// A translational delta (rows `row` of the Jacobians) corrected to first order.
  Vec3 corrected(int row, const Vec3& delta, const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g,
                 const std::optional<GyroTilt>& tilt) const;

  ImuNoise noise_;
  Eigen::Vector3d g_n_, w_ie_n_;
  Eigen::Vector3d b_a_lin_, b_g_lin_;
  GyroTilt tilt_lin_;
  bool with_tilt_;
  bool mean_only_ = false;  // meanOnly(): no covariance steps

  double dt_sum_ = 0.0;
  Mat3 dR_;
  Vec3 dv_, dp_;
  // First moments in time of the rotated specific force, for the Earth-rotation terms:
  // dv_t = int t dR a dt, dp_t = int int t dR a dt dt.
  Vec3 dv_t_, dp_t_;
  Eigen::Matrix<double, 15, 15> cov_;
  Eigen::Matrix<double, 9, 6> J_bias_;
  Eigen::Matrix<double, 9, 2> J_tilt_;
  PendingCovariance pending_;
};

}  // namespace giocal
