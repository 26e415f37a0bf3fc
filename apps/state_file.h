// The calibration state a robot keeps across power cycles (calibrate --state-out): the latest
// calibration with its covariance, its time and the robot it belongs to, with a checksum,
// written atomically every N seconds of data and at the end; calibrate --prior reads it back.
#pragma once

#include <map>
#include <string>

#include "common/calibration/calibration_run.h"
#include "common/online/run_sink.h"

namespace giocal {

/// Writes the state file atomically (a temporary file renamed over the old one): a power cut
/// leaves the old file or the new one. Its keys are those of summary.json that --prior reads,
/// plus "format" and "checksum" (FNV-1a 64 of the rest, as serialized).
void writeStateFile(const std::string& path, const CalibrationEstimate& estimate,
                    const std::map<std::string, double>& robot);

/// The checksum over a state file's JSON without its "checksum" key.
std::string stateChecksum(const std::string& json_without_checksum);

/// A RunSink in front of another: passes everything on, and writes the state file each time the
/// data time has advanced `every_s` since the last write.
class StateFileSink : public RunSink {
 public:
  StateFileSink(RunSink* next, std::string path, double every_s,
                std::map<std::string, double> robot)
      : next_(next), path_(std::move(path)), every_s_(every_s), robot_(std::move(robot)) {}
  void estimate(const CalibrationEstimate& e) override;
  void gnssEpoch(const GnssEpochRecord& r) override {
    if (next_) next_->gnssEpoch(r);
  }
  void trajectory(const TruthSample& s) override {
    if (next_) next_->trajectory(s);
  }
  void event(double t, const std::string& text) override {
    if (next_) next_->event(t, text);
  }
  int writes() const { return writes_; }

 private:
  RunSink* next_;
  std::string path_;
  double every_s_;
  std::map<std::string, double> robot_;
  double last_written_ = -INFINITY;
  int writes_ = 0;
};

}  // namespace giocal
