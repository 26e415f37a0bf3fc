// `giocal import --ubx <file.ubx> --out <dir> [--overwrite]`: a receiver's log to RINEX 3.04
// observation and navigation files giocal and other tools read.
#pragma once

#include <iosfwd>
#include <string>

#include "common/io/stop_request.h"

namespace giocal {

struct ImportJob {
  std::string ubx, out;
  bool overwrite = false;
  const StopRequest* stop = nullptr;
};

/// Writes <out>/rover.obs, <out>/nav.rnx and <out>/import.json (what was read, skipped and
/// damaged) as one set, and prints the counts and every warning.
void runImport(const ImportJob& job, std::ostream& log);

}  // namespace giocal
