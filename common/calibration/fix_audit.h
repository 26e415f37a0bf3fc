// FixAudit: checks, while a run goes, each epoch held with ambiguity fixes against the dataset's
// truth: a fix that puts the estimated antenna more than a threshold (horizontal) from the true
// one is wrong.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "common/io/dataset_folder.h"
#include "common/io/scenes_csv.h"
#include "common/io/sensor_logs.h"
#include "common/online/run_sink.h"

namespace giocal {

class FixAudit : public RunSink {
 public:
  /// Reads `truth_csv` (the IMU's true track) alongside the run, in constant memory; the true
  /// antenna is at `p_b_g` from it. Everything the run hands over is passed on to `next`.
  /// With `scenes`, the tallies are also kept per scene.
  FixAudit(const std::string& truth_csv, const Eigen::Vector3d& p_b_g, RunSink* next,
           double threshold_m = 0.05, std::vector<SceneSpan> scenes = {});

  void estimate(const CalibrationEstimate& e) override { next_->estimate(e); }
  void gnssEpoch(const GnssEpochRecord& g) override;
  void trajectory(const TruthSample& s) override { next_->trajectory(s); }
  void event(double t, const std::string& text) override { next_->event(t, text); }

  /// Adds the tallies to the run's counters (fixes_checked_against_truth, wrong_fixes, and per
  /// scene scene.<type>.gnss_epochs / .fixed_epochs / .wrong_fixes) and a warning when a fix
  /// was wrong.
  void addTo(CalibrationRun& run) const;

 private:
  std::optional<TruthSample> truthAt(double t);  // interpolated; empty beyond the truth's span

  TruthLogReader truth_;
  Eigen::Vector3d p_b_g_;
  RunSink* next_;
  double threshold_m_;
  std::optional<TruthSample> before_, after_;  // the truth rows around the last time asked
  bool truth_ended_ = false;
  long checked_ = 0, wrong_ = 0;
  struct SceneTally {
    long epochs = 0, fixed = 0, wrong = 0;
  };
  std::vector<SceneSpan> scenes_;
  std::map<std::string, SceneTally> by_scene_;
  double worst_m_ = 0.0, t_worst_ = 0.0;
};

/// A FixAudit of the dataset folder's truth.csv when it has one (else null), per scene when it
/// has a scenes.csv, passing on to `next`.
std::unique_ptr<FixAudit> fixAuditOf(const DatasetFolder& data, RunSink* next);

}  // namespace giocal
