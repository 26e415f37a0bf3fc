// `giocal report --run <dir> [--data <dataset>] --out <dir> [--overwrite]`: an HTML page with
// figures of a calibrate, compare, deadreckon or validate run (or a Monte Carlo --box-csv file),
// made by report/giocal_report.py with Debian's python3-matplotlib.
#pragma once

#include <iosfwd>
#include <string>

namespace giocal {

struct ReportJob {
  std::string run, data, out;  // data: the dataset, for its truth (may be empty)
  bool overwrite = false;
};

/// Writes <out>/index.html and its PNG figures as one set (index.html last).
void runReport(const ReportJob& job, std::ostream& log);

}  // namespace giocal
