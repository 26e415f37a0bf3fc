// RunWriter: writes calibrate's three outputs as the run goes (calibration.csv and trajectory.csv
// row by row into temporary files, so memory stays flat), then summary.json, and renames them
// into place only when the run completes; an interrupted run leaves no partial output.
#pragma once

#include <memory>
#include <string>

#include "common/io/atomic_file.h"
#include "common/online/run_sink.h"

namespace giocal {

class RunWriter : public RunSink {
 public:
  /// Creates `folder` if needed and opens the temporary files (io/atomic_file.h) in it; they are
  /// removed again if the writer is destroyed before commit().
  explicit RunWriter(const std::string& folder);

  void estimate(const CalibrationEstimate& e) override;
  void trajectory(const TruthSample& s) override;

  /// Writes summary.json and renames the three files into place, summary.json last.
  void commit(const CalibrationRun& run, const OdometerCalibration* truth);

 private:
  std::string folder_;
  std::unique_ptr<AtomicFile> calibration_, trajectory_;
};

}  // namespace giocal
