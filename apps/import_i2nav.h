// importI2nav: i2Nav text logs (IMU increments with an odometer speed column, GNSS positions,
// reference navigation) to a dataset folder for the LC scheme with a speed-only odometer.
#pragma once

#include <iosfwd>

#include "apps/import_command.h"

namespace giocal {

/// Writes imu.csv, odom.csv, gnss.pos (with --i2nav-pos), truth.csv (with --i2nav-nav),
/// dataset.yaml and import.json into job.out as one set.
void importI2nav(const ImportJob& job, std::ostream& log);

}  // namespace giocal
