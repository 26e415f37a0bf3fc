#include "common/calibration/weak_directions.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "common/calibration/initial_state.h"

namespace giocal {

namespace {
const std::array<const char*, 8> kName{
    "s_v",     "s_w",           "p_b_m.x",        "p_b_m.y",
    "p_b_m.z", "roll of q_b_m", "pitch of q_b_m", "yaw of q_b_m"};
const std::array<const char*, 8> kUnit{"", "", " m", " m", " m", " deg", " deg", " deg"};
}  // namespace

const char* calibrationStateName(int k) { return kName.at(static_cast<size_t>(k)); }
const char* calibrationStateUnit(int k) { return kUnit.at(static_cast<size_t>(k)); }

/// The motion that informs each state (the paper's observability analysis, in words).
const char* motionThatInforms(int k) {
  static const std::array<const char*, 8> kMotion = {
      "distance at a known speed: a longer straight, with changes of speed",
      "turning: more turns, at a higher yaw rate",
      "turns in both directions at varying yaw rate, where the lever arm shows as w x p",
      "turns in both directions at varying yaw rate, where the lever arm shows as w x p",
      "turns in both directions at varying yaw rate, where the lever arm shows as w x p",
      "turns, where the IMU sees the turning axis tilted",
      "turns, and driving at speed, which a pitch tilts into the vertical",
      "accelerating and braking on straights, turns in both directions and stops, which split "
      "the extrinsic yaw from the IMU heading; or a better gyro"};
  return kMotion.at(static_cast<size_t>(k));
}

int verticalLeverState(const CalibrationPrior& prior) {
  // A mount tilted by a few degrees still has one b axis along the vehicle's vertical; the
  // projection of the motion models (PlanarMotionProjection) uses the exact direction.
  int axis = 0;
  (prior.mean.q_b_m * Eigen::Vector3d::UnitZ()).cwiseAbs().maxCoeff(&axis);
  return calib_index::kP + axis;
}

std::vector<int> heldStates(const CalibrationOptions& options, const DatasetDescription& d) {
  std::vector<int> held;
  if (!d.odom_noise.measures_yaw_rate) held.push_back(calib_index::kSw);
  if (options.hold_p_b_m_z) held.push_back(verticalLeverState(d.initial_calibration));
  return held;
}

std::vector<int> weakStates(const CalibrationEstimate& final, const CalibrationPrior& prior,
                            const std::vector<int>& held, double fraction) {
  // calibration.csv's order: s_v, s_w, p_b_m x, y, z [m], roll, pitch, yaw [deg].
  const Eigen::Matrix<double, 8, 1> sd = final.sigma();
  const Eigen::Matrix<double, 8, 1> sd0 =
      CalibrationEstimate{0.0, prior.mean, priorCalibrationCovariance(prior)}.sigma();
  std::vector<int> out;
  const int vertical = verticalLeverState(prior);
  for (int k = 0; k < 8; ++k) {
    if (k == vertical || std::count(held.begin(), held.end(), k) || sd0(k) <= 0.0 ||
        !(sd(k) > fraction * sd0(k))) {
      continue;
    }
    out.push_back(k);
  }
  return out;
}

std::vector<std::string> weakDirections(const CalibrationEstimate& final,
                                        const CalibrationPrior& prior, const std::vector<int>& held,
                                        double fraction) {
  const Eigen::Matrix<double, 8, 1> sd = final.sigma();
  const Eigen::Matrix<double, 8, 1> sd0 =
      CalibrationEstimate{0.0, prior.mean, priorCalibrationCovariance(prior)}.sigma();
  std::vector<std::string> out;
  for (const int k : weakStates(final, prior, held, fraction)) {
    char buf[600];
    std::snprintf(buf, sizeof buf,
                  "%s is weakly observed on this drive: 1-sigma %.3g%s against the prior's %.3g%s. "
                  "The estimate stays near the initial guess, and along such a direction the "
                  "reported sigma has been measured too small (docs/results.md). What informs "
                  "it: %s",
                  kName[static_cast<size_t>(k)], sd(k), kUnit[static_cast<size_t>(k)], sd0(k),
                  kUnit[static_cast<size_t>(k)], motionThatInforms(k));
    out.emplace_back(buf);
  }
  return out;
}

}  // namespace giocal
