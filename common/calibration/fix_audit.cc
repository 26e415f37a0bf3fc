#include "common/calibration/fix_audit.h"

#include <cstdio>
#include <filesystem>

#include "common/calibration/reference_trajectory.h"
#include "common/geodesy/wgs84.h"
#include "common/io/dataset_description.h"
#include "common/math/rotation.h"

namespace giocal {

FixAudit::FixAudit(const std::string& truth_csv, const Eigen::Vector3d& p_b_g, RunSink* next,
                   double threshold_m, std::vector<SceneSpan> scenes)
    : truth_(truth_csv),
      p_b_g_(p_b_g),
      next_(next),
      threshold_m_(threshold_m),
      scenes_(std::move(scenes)) {}

std::optional<TruthSample> FixAudit::truthAt(double t) {
  while (!truth_ended_ && (!after_ || after_->t < t)) {
    TruthSample s;
    if (!truth_.next(s)) {
      truth_ended_ = true;
      break;
    }
    before_ = after_;
    after_ = s;
  }
  if (after_ && after_->t == t) return after_;
  // Bracketed by two rows less than a second apart: interpolated.
  if (!before_ || !after_ || before_->t > t || after_->t < t || after_->t - before_->t > 1.0)
    return std::nullopt;
  return interpolateTruth(*before_, *after_, t);
}

void FixAudit::gnssEpoch(const GnssEpochRecord& g) {
  next_->gnssEpoch(g);
  SceneTally* scene = nullptr;
  if (const std::string type = sceneAt(scenes_, g.t); !type.empty()) {
    scene = &by_scene_[type];
    if (g.used) ++scene->epochs;
  }
  if (!g.fixed || !g.antenna_e.allFinite()) return;
  const std::optional<TruthSample> truth = truthAt(g.t);
  if (!truth) return;
  // Horizontal, as the RTK benches count: the vertical carries centimetres of differential
  // troposphere wherever the data's atmosphere is not the estimators' model (6 cm on the
  // simulated paper preset, in giocal rtk and the calibrators alike).
  const double lat = truth->lat_deg * kDegToRad, lon = truth->lon_deg * kDegToRad;
  const Eigen::Vector3d d_enu =
      rotationEcefFromEnu(lat, lon).transpose() * (g.antenna_e - antennaOfRow(*truth, p_b_g_));
  const double d = d_enu.head<2>().norm();
  ++checked_;
  if (d > threshold_m_) ++wrong_;
  if (scene) {
    ++scene->fixed;
    if (d > threshold_m_) ++scene->wrong;
  }
  if (d > worst_m_) {
    worst_m_ = d;
    t_worst_ = g.t;
  }
}

void FixAudit::addTo(CalibrationRun& run) const {
  run.counters["fixes_checked_against_truth"] = checked_;
  run.counters["wrong_fixes"] = wrong_;
  for (const auto& [type, n] : by_scene_) {
    run.counters["scene." + type + ".gnss_epochs"] = n.epochs;
    run.counters["scene." + type + ".fixed_epochs"] = n.fixed;
    run.counters["scene." + type + ".wrong_fixes"] = n.wrong;
  }
  if (wrong_ == 0) return;
  char text[200];
  std::snprintf(
      text, sizeof text,
      "%ld of %ld fixed epochs put the antenna more than %.2f m (horizontal) from the truth (worst "
      "%.2f m at t=%.1f)",
      wrong_, checked_, threshold_m_, worst_m_, t_worst_);
  run.warn(text);
}

std::unique_ptr<FixAudit> fixAuditOf(const DatasetFolder& data, RunSink* next) {
  if (!data.hasTruthTrajectory()) return nullptr;
  return std::make_unique<FixAudit>(data.path(data.description.truth), data.description.p_b_g, next,
                                    0.05, data.scenes);
}

}  // namespace giocal
