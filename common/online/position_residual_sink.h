// PositionResidualSink: passes a run's outputs on to the next sink and checks the LC scheme's
// position solutions against the trajectory as it streams past (PositionResidualCheck).
#pragma once

#include <string>

#include "common/calibration/position_residuals.h"
#include "common/online/run_sink.h"

namespace giocal {

class PositionResidualSink : public RunSink {
 public:
  PositionResidualSink(RunSink* next, std::vector<PositionFix> fixes, const Eigen::Vector3d& p_b_g)
      : next_(next), check_(std::move(fixes), p_b_g) {}
  void estimate(const CalibrationEstimate& e) override {
    if (next_) next_->estimate(e);
  }
  void gnssEpoch(const GnssEpochRecord& r) override {
    if (next_) next_->gnssEpoch(r);
  }
  void trajectory(const TruthSample& s) override {
    check_.add(s);
    if (next_) next_->trajectory(s);
  }
  void event(double t, const std::string& text) override {
    if (next_) next_->event(t, text);
  }
  PositionResiduals result() const { return check_.result(); }

 private:
  RunSink* next_;
  PositionResidualCheck check_;
};

/// Fixes supporting this much less than the run assumes get a warning (and summary.json says by
/// how much in every LC run).
constexpr double kUnderstatedSigmaWarning = 3.0;

/// The warning, or "" when the residuals are within kUnderstatedSigmaWarning of their sigmas.
std::string understatedSigmaWarning(const PositionResiduals& r);

}  // namespace giocal
