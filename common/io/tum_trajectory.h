// TUM trajectory text ("t x y z qx qy qz qw" per line, the format evo and ov_eval read) of a
// truth.csv-format trajectory, positions in the ENU frame at an origin.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "common/io/sensor_logs.h"

namespace giocal {

/// Writes atomically; positions are ENU metres about `origin_e` (ECEF), orientation q_n_b.
void writeTumTrajectory(const std::string& path, const std::vector<TruthSample>& samples,
                        const Eigen::Vector3d& origin_e);

}  // namespace giocal
