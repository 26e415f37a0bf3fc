#include "common/calibration/reinitialization_prior.h"

#include <algorithm>
#include <cmath>

namespace giocal {

namespace {

// Whether every parameter of `c` lies within `k` sigmas of the prior's guess.
bool withinPrior(const OdometerCalibration& c, const CalibrationPrior& p, double k) {
  const double angle = Eigen::AngleAxisd(p.mean.q_b_m.inverse() * c.q_b_m).angle();
  return std::abs(c.s_v - p.mean.s_v) <= k * p.sd_s_v &&
         std::abs(c.s_w - p.mean.s_w) <= k * p.sd_s_w &&
         ((c.p_b_m - p.mean.p_b_m).cwiseAbs().array() <= k * p.sd_p_b_m.array()).all() &&
         angle <= k * p.sd_rpy_b_m.maxCoeff();
}

}  // namespace

DatasetDescription reinitializationPrior(DatasetDescription d, const CalibrationEstimate& e) {
  CalibrationPrior& p = d.initial_calibration;
  if (!withinPrior(e.calib, p, 3.0)) return d;
  p.mean = e.calib;
  p.sd_s_v = std::max(p.sd_s_v, std::sqrt(e.cov(calib_index::kSv, calib_index::kSv)));
  p.sd_s_w = std::max(p.sd_s_w, std::sqrt(e.cov(calib_index::kSw, calib_index::kSw)));
  return d;
}

}  // namespace giocal
