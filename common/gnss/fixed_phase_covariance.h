// The rover antenna's position covariance that one epoch's DD carrier phase gives with every
// ambiguity known: what a fixed RTK epoch can tell about the position, from the geometry and the
// phase noise model alone.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "common/gnss/dd_epoch.h"

namespace giocal {

/// ECEF covariance [m^2] from the epoch's phase rows at `rover_e`; none when they do not fix all
/// three axes (fewer than four satellites).
std::optional<Eigen::Matrix3d> fixedPhasePositionCovariance(const DdEpoch& epoch,
                                                            const Eigen::Vector3d& rover_e);

}  // namespace giocal
