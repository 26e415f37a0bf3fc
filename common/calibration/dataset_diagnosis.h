// diagnoseDataset: the conditions that make a dataset unusable for calibration, found from its
// files (rover and base without a common epoch, no ephemeris for the observed satellites, no
// carrier phase, no motion), each a line naming the file, so that `check` and a failed
// initialization say which one was met instead of a generic failure.
#pragma once

#include <string>
#include <vector>

#include "common/gnss/observation.h"
#include "common/gnss/rinex_nav.h"
#include "common/odometer/odom_sample.h"

namespace giocal {

struct DatasetFiles {
  const ObsData& rover;
  const ObsData& base;
  const NavData& nav;
  const std::vector<OdomSample>& odom;
  std::string rover_path, base_path, nav_path, odom_path;
  double max_base_offset = 0.5;  // [s], calibration.max_base_offset
};

/// One line per unusable condition met; empty when none is.
std::vector<std::string> diagnoseDataset(const DatasetFiles& files);

}  // namespace giocal
