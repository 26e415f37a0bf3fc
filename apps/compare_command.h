// `giocal compare --data <dir> [--gnss lc --pos <file.pos>] [--config <yaml>] [--out <dir>]`: both
// estimators on one dataset, side by side.
#pragma once

#include <iosfwd>
#include <string>

#include "common/io/stop_request.h"

namespace giocal {

struct CompareJob {
  std::string data, config, out;  // out empty: <data>/giocal_compare
  std::string positions;          // --gnss lc --pos <file.pos>: the LC scheme
  bool single = false;            // --gnss single (also taken when dataset.yaml names no base)
  bool overwrite = false;
  bool quiet = false;                 // no progress line
  const StopRequest* stop = nullptr;  // Ctrl-C: the runs stop and nothing is written
};

/// Runs the EKF and the factor graph, writes each one's outputs into <out>/ekf and <out>/fgo and
/// the comparison table into <out>/compare.csv, and prints the table.
/// True when either run's status is "suspect" (the command then exits 3).
bool runCompare(const CompareJob& job, std::ostream& log);

}  // namespace giocal
