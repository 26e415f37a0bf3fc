// LiveRunWriter: a run's output files (common/calibration/run_writer.h) plus its live events
// printed as they happen ("  ekf t=+84.0 s: s_v converged: ..."), and the progress line.
#pragma once

#include <iomanip>
#include <ostream>
#include <string>

#include "common/calibration/run_writer.h"
#include "common/io/progress_line.h"

namespace giocal {

class LiveRunWriter : public RunWriter {
 public:
  LiveRunWriter(OutputSet& set, const std::string& prefix, std::string label, std::ostream& log,
                ProgressLine* progress = nullptr)
      : RunWriter(set, prefix), label_(std::move(label)), log_(log), progress_(progress) {}
  void trajectory(const TruthSample& s) override {
    RunWriter::trajectory(s);
    if (progress_) progress_->update(s.t);
  }
  void event(double t, const std::string& text) override {
    if (progress_) progress_->clear();
    const auto flags = log_.flags();
    log_ << "  " << label_ << " t=+" << std::fixed << std::setprecision(1) << t << " s: " << text
         << "\n";
    log_.flags(flags);
  }

 private:
  std::string label_;
  std::ostream& log_;
  ProgressLine* progress_;
};

}  // namespace giocal
