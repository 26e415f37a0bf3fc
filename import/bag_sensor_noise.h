// What a bag's IMU and odometry messages say of their sensors: the accelerations' unit (m/s^2 by
// the message definition, g or mg by some drivers) and the noise their covariances give.
#pragma once

#include <string>
#include <vector>

#include "import/bag_dataset.h"

namespace giocal::import {

/// Converts out.imu's accelerations (and the acceleration entries 3..5 of `imu_covariance`) to
/// m/s^2 when the mean specific force is gravity in g or mg, with a warning and
/// out.imu_accel_unit; throws std::runtime_error naming the bag and topic when it is gravity in no
/// unit.
void convertAccelUnits(BagDataset& out, std::vector<double>& imu_covariance,
                       const std::string& bag);

/// out.imu_noise and out.odom_noise from the first messages' covariances (the IMU's diagonal
/// entries: gyro 0..2, accel 3..5; the odometry's speed and yaw-rate variances) where they lie in
/// the range a real sensor's can, else the defaults; out.noise_sources says which.
void setSensorNoise(BagDataset& out, const std::vector<double>& imu_covariance,
                    const std::vector<double>& odom_covariance);

}  // namespace giocal::import
