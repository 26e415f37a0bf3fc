// The estimators by name: "ekf" (error-state EKF) and "fgo" (sliding-window factor graph).
#pragma once

#include <string>
#include <vector>

#include "common/online/calibrator.h"
#include "options/fgo_options.h"

namespace giocal {

std::vector<std::string> estimatorNames();

/// Throws std::invalid_argument naming the valid estimators when `name` is not one of them.
CoreFactory coreFactory(const std::string& name, const CalibrationOptions& options,
                        const FgoOptions& fgo_options = {});

/// An online Calibrator with the named estimator; `sink` may be null.
std::unique_ptr<Calibrator> makeCalibrator(const std::string& name,
                                           const DatasetDescription& dataset,
                                           const Eigen::Vector3d& base_e,
                                           const CalibrationOptions& options,
                                           const FgoOptions& fgo_options, RunSink* sink);

}  // namespace giocal
