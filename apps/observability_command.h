// `giocal observability --data <dir> [--calibration truth|guess] [--pos <file.pos>]
// [--gnss tc|single] [--window <s>] [--position-sigma <m>] [--config <yaml>] [--out <dir>]
// [--overwrite]`.
#pragma once

#include <iosfwd>
#include <string>

namespace giocal {

struct ObservabilityCommandJob {
  std::string data, calibration, positions, config, out;  // calibration empty: truth, else guess
  double window_s = 30.0;
  double position_sigma_m = 0.0;  // > 0: this sigma per axis instead of the DD phase's geometry
  bool overwrite = false;
  /// tc, or single: one receiver without a base (also taken for a dataset that names no base
  /// observations): the rover's own time-differenced phase, Doppler and single point positions.
  std::string gnss = "tc";
};

/// Analyzes what the dataset's drive can calibrate, prints it, and writes observability.json
/// into job.out when given.
void runObservability(const ObservabilityCommandJob& job, std::ostream& log);

}  // namespace giocal
