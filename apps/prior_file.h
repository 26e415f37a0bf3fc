// An earlier calibrate run's summary.json read as the prior of a later drive (calibrate --prior).
#pragma once

#include <map>
#include <stdexcept>
#include <string>

#include "common/io/dataset_description.h"

namespace giocal {

struct PriorFile {
  CalibrationPrior calibration;  // final values, covariance_tangent
  double t_final = 0.0;          // GPS time of that estimate
  std::map<std::string, double> robot;
};

/// A state file that is not whole (cut, or its checksum fails): the run starts cold.
struct DamagedPrior : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Reads an earlier run's summary.json or a state file (calibrate --state-out). Throws
/// DamagedPrior for a state file that is not whole, std::runtime_error naming the file and the
/// key it lacks (an older format, a run that never initialized) or that cannot be read (a
/// summary.json that is not JSON).
PriorFile readPriorFile(const std::string& path);

}  // namespace giocal
