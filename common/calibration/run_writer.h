// RunWriter: writes a calibration run's outputs into an OutputSet as the run goes
// (calibration.csv, trajectory.csv and gnss.csv row by row, so memory stays flat; with the
// odometer delay estimated, odometer_delay.csv beside calibration.csv, with the gyro's tilt,
// gyro_tilt.csv), then
// summary.json naming the others with their sizes; the set moves them into place together
// (io/output_set.h).
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "common/io/output_set.h"
#include "common/online/run_sink.h"

namespace giocal {

class RunWriter : public RunSink {
 public:
  /// Writes into `set` under `prefix` ("" or a sub-folder such as "ekf/").
  explicit RunWriter(OutputSet& set, std::string prefix = "");

  void estimate(const CalibrationEstimate& e) override;
  void gnssEpoch(const GnssEpochRecord& g) override;
  void trajectory(const TruthSample& s) override;

  /// Closes the CSV files and writes summary.json (the set's marker) naming them.
  void finish(const CalibrationRun& run, const OdometerCalibration* truth);
  /// finish() in two steps, for a caller that reads the closed files before the summary.
  void closeFiles();
  void writeSummary(const CalibrationRun& run, const OdometerCalibration* truth);

 private:
  OutputSet& set_;
  std::string prefix_;
  std::ostream& calibration_;
  std::ostream& trajectory_;
  std::ostream& gnss_;
  std::ostream* delay_ = nullptr;  // opened at the first estimate that has the delay state
  std::ostream* tilt_ = nullptr;   // opened at the first estimate that has the gyro's tilt
  std::map<std::string, std::uintmax_t> closed_;  // file -> size, once closed
};

}  // namespace giocal
