#include "common/calibration/weak_directions.h"

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

std::vector<int> weakStates(const CalibrationEstimate& final, const CalibrationPrior& prior,
                            double fraction) {
  // calibration.csv's order: s_v, s_w, p_b_m x, y, z [m], roll, pitch, yaw [deg].
  const Eigen::Matrix<double, 8, 1> sd = final.sigma();
  const Eigen::Matrix<double, 8, 1> sd0 =
      CalibrationEstimate{0.0, prior.mean, priorCalibrationCovariance(prior)}.sigma();
  std::vector<int> out;
  for (int k = 0; k < 8; ++k) {
    if (k == calib_index::kP + 2 || sd0(k) <= 0.0 || !(sd(k) > fraction * sd0(k))) continue;
    out.push_back(k);
  }
  return out;
}

std::vector<std::string> weakDirections(const CalibrationEstimate& final,
                                        const CalibrationPrior& prior, double fraction) {
  const Eigen::Matrix<double, 8, 1> sd = final.sigma();
  const Eigen::Matrix<double, 8, 1> sd0 =
      CalibrationEstimate{0.0, prior.mean, priorCalibrationCovariance(prior)}.sigma();
  std::vector<std::string> out;
  for (const int k : weakStates(final, prior, fraction)) {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "%s is weakly observed on this drive: 1-sigma %.3g%s against the prior's %.3g%s. "
                  "The estimate stays near the initial guess, and along such a direction the "
                  "reported sigma has been measured too small (docs/results.md). More turning "
                  "and acceleration, or a better gyro, help",
                  kName[static_cast<size_t>(k)], sd(k), kUnit[static_cast<size_t>(k)], sd0(k),
                  kUnit[static_cast<size_t>(k)]);
    out.emplace_back(buf);
  }
  return out;
}

}  // namespace giocal
