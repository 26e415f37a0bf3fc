// `giocal deadreckon --data <dir> --calibration <source> [--start <s>] [--duration <s>]
// [--reference <trajectory.csv|file.pos>] [--gnss lc --pos <file.pos>] [--config <yaml>]
// --out <dir> [--overwrite]`.
#pragma once

#include <iosfwd>
#include <string>

#include "common/io/stop_request.h"

namespace giocal {

struct DeadReckonJob {
  std::string data, calibration, reference, config, out;  // reference empty: the dataset's truth
  std::string positions;  // --gnss lc --pos: GNSS aiding before the start from these solutions
  bool single = false;    // --gnss single: one receiver's aiding (also without a base)
  double start_s = 100.0, duration_s = 1000.0;
  bool overwrite = false;
  bool quiet = false;  // no progress line
  const StopRequest* stop = nullptr;
};

/// Dead-reckons through the outage with the named calibration, writes trajectory.csv, error.csv
/// and summary.json into job.out as one set, and prints the figures.
void runDeadReckon(const DeadReckonJob& job, std::ostream& log);

}  // namespace giocal
