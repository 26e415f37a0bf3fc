// An earlier calibrate run's summary.json read as the prior of a later drive (calibrate --prior).
#pragma once

#include <map>
#include <string>

#include "common/io/dataset_description.h"

namespace giocal {

struct PriorFile {
  CalibrationPrior calibration;  // final values, covariance_tangent
  double t_final = 0.0;          // GPS time of that estimate
  std::map<std::string, double> robot;
};

/// Throws std::runtime_error naming the file and the key it lacks (an older format, a run that
/// never initialized) or that cannot be read.
PriorFile readPriorFile(const std::string& path);

}  // namespace giocal
