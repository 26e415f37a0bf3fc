// Reading typed values out of the raw parameter arrays a MeasurementModel receives.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "common/math/rotation.h"

namespace giocal {

inline Eigen::Vector3d vec3At(const double* p) { return Eigen::Map<const Eigen::Vector3d>(p); }
inline Eigen::Quaterniond quatAt(const double* p) { return quatFromWxyz(p); }

}  // namespace giocal
