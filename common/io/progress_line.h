// ProgressLine: one self-overwriting line on standard error while long work runs (share of the
// data's time done, elapsed, remaining), only when standard error is a terminal and not --quiet.
#pragma once

#include <string>

namespace giocal {

class ProgressLine {
 public:
  /// Reports data times from t_begin to t_end; disabled when `quiet`, when standard error is not
  /// a terminal, or when the span is empty. `of_what` follows the percentage ("of the data",
  /// "of the seeds", "of the file").
  ProgressLine(std::string label, double t_begin, double t_end, bool quiet,
               std::string of_what = "of the data");
  ~ProgressLine() { clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// The work has reached data time t (redrawn at most 5 times a second).
  void update(double t);
  /// Erases the line (before other output, and at the end).
  void clear();
  bool enabled() const { return enabled_; }

 private:
  std::string label_, of_what_;
  double t_begin_, t_end_;
  bool enabled_;
  bool shown_ = false;
  double started_, last_drawn_ = -1.0;
};

}  // namespace giocal
