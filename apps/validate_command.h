// `giocal validate --data <dir> --run <calibrate output> [--outage <s>] [--windows <n>]
// [--gnss lc --pos <file.pos>] [--config <yaml>] --out <dir> [--overwrite] [--quiet]`: a
// calibration checked on the user's own drive without a truth (evaluation/validation.h).
#pragma once

#include <iosfwd>
#include <string>

#include "common/io/stop_request.h"

namespace giocal {

struct ValidateJob {
  std::string data, run, config, out;
  std::string positions;  // --gnss lc --pos: the GNSS solution and aiding; else RTK of the data
  bool single = false;    // --gnss single: the rover alone (also without a base in the dataset)
  double outage_s = 60.0;
  int windows = 5;
  bool overwrite = false, quiet = false;
  const StopRequest* stop = nullptr;
};

/// Writes summary.json (and gnss_reference.pos, the RTK solution used, for raw GNSS) into
/// job.out as one set, prints one line per window and the verdict last.
void runValidate(const ValidateJob& job, std::ostream& log);

}  // namespace giocal
