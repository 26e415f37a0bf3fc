// RunSink: where an online calibrator hands what it produces as it goes: each calibration
// estimate, each GNSS epoch's sky and outcome, each trajectory sample, and live events
// (convergence, warnings) in words.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "common/calibration/calibration_run.h"
#include "common/io/sensor_logs.h"

namespace giocal {

/// One GNSS epoch as the estimator took it: the sky (SkyView) and what became of it.
struct GnssEpochRecord {
  double t = 0.0;
  int satellites = 0;  // rover satellites above the mask with an ephemeris (0 for the LC scheme)
  double pdop = 0.0;   // NaN with fewer than four
  bool used = false;   // counted as a GNSS epoch of the run
  bool fixed = false;  // validated ambiguity fixes held (LC: an RTK-fixed solution)
  // The estimated antenna (ECEF) after the epoch's update: checked against a truth (FixAudit).
  Eigen::Vector3d antenna_e = Eigen::Vector3d::Constant(NAN);
};

class RunSink {
 public:
  virtual ~RunSink() = default;
  virtual void estimate(const CalibrationEstimate&) {}
  virtual void gnssEpoch(const GnssEpochRecord&) {}
  virtual void trajectory(const TruthSample&) {}
  /// A live event: data time [s] and one line of text.
  virtual void event(double /*t*/, const std::string& /*text*/) {}
};

/// Keeps everything in memory: for tests and the Monte Carlo, not for long drives.
class RunRecording : public RunSink {
 public:
  void estimate(const CalibrationEstimate& e) override { history.push_back(e); }
  void trajectory(const TruthSample& s) override { trajectory_samples.push_back(s); }
  void event(double t, const std::string& text) override { events.push_back({t, text}); }

  std::vector<CalibrationEstimate> history;
  std::vector<TruthSample> trajectory_samples;
  std::vector<std::pair<double, std::string>> events;
};

}  // namespace giocal
