// propagateImu(): the EKF time update over one IMU interval, taken from the shared IMU model
// (no mechanization restated here): the interval's preintegration predicts the mean, and its
// residual Jacobians give the error-state transition F = -J_j^-1 J_i and noise J_j^-1 S J_j^-T.
#pragma once

#include <optional>

#include "common/imu/imu_preintegration.h"
#include "ekf/state_registry.h"

namespace giocal {

NavState navState(const StateRegistry& s);
void setNavState(StateRegistry& s, const NavState& x);
/// The gyro triad's tilt where the state estimates it, else none.
std::optional<GyroTilt> gyroTilt(const StateRegistry& s);

/// The propagation's dynamic temporaries, kept by a caller between propagations (no allocation
/// while the state's size stays).
struct PropagationScratch {
  Eigen::MatrixXd G, Pn, FPn, FPnn;
};

/// Moves the navigation variables to the end of `pre`'s interval and propagates the covariance of
/// the whole state (other variables keep their values and their cross-covariances are carried).
void propagateImu(StateRegistry& s, const ImuPreintegration& pre);
void propagateImu(StateRegistry& s, const ImuPreintegration& pre, PropagationScratch& scratch);

}  // namespace giocal
