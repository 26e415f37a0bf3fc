// errorFreeImu(): what an IMU without errors measures for a motion in an Earth-fixed local frame
// n: the angular rate against inertial space and the specific force (normal gravity, the Earth's
// rate and the Coriolis acceleration). The simulator's IMU and the observability advisor's
// reference IMU both come from it.
#pragma once

#include <Eigen/Core>

#include "common/geodesy/wgs84.h"
#include "common/imu/imu_sample.h"
#include "common/imu/nav_state.h"

namespace giocal {

/// The sample at x.t of the state x (position, velocity, attitude in n), its acceleration a_n_b in
/// n and its angular rate w_nb_b against n in b.
ImuSample errorFreeImu(const LocalFrame& frame, const NavState& x, const Eigen::Vector3d& a_n_b,
                       const Eigen::Vector3d& w_nb_b);

}  // namespace giocal
