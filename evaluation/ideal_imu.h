// idealImuAlong(): the samples an error-free IMU (errorFreeImu) would give along a reference
// trajectory, at the times of the recorded ones (the observability advisor's covariance recursion,
// linearized at the motion itself rather than at the IMU's noise).
#pragma once

#include <vector>

#include "common/calibration/reference_trajectory.h"
#include "common/imu/imu_sample.h"

namespace giocal {

/// Angular rate and specific force of the reference's motion at each recorded sample's time
/// (central differences over half the neighbouring sample intervals, Earth rate and Coriolis
/// included, normal gravity); a sample where the reference does not reach keeps its recorded
/// values.
std::vector<ImuSample> idealImuAlong(const ReferenceTrajectory& reference,
                                     const std::vector<ImuSample>& recorded);

}  // namespace giocal
