// Attitude conventions of giocal: Hamilton quaternions stored [w, x, y, z], and
// roll/pitch/yaw with R = Rz(yaw) * Ry(pitch) * Rx(roll).
#pragma once

#include "common/math/so3.h"

namespace giocal {

/// Quaternion from four values in file/parameter order [w, x, y, z]; normalized.
Quat quatFromWxyz(const double* wxyz);

/// Writes q as [w, x, y, z].
void quatToWxyz(const Quat& q, double* wxyz);

/// R = Rz(yaw) Ry(pitch) Rx(roll); angles in radians.
Mat3 rotationFromRpy(const Vec3& rpy);

/// Roll, pitch, yaw (radians) of R; pitch in [-pi/2, pi/2], roll and yaw in (-pi, pi].
Vec3 rpyFromRotation(const Mat3& R);

/// q * Exp(dtheta), the right perturbation used by every estimator in giocal.
Quat boxPlus(const Quat& q, const Vec3& dtheta);

/// Log(q_a^-1 * q_b): the right-perturbation difference b "minus" a.
Vec3 boxMinus(const Quat& q_b, const Quat& q_a);

constexpr double kDegToRad = 0.017453292519943295;
constexpr double kRadToDeg = 57.29577951308232;

}  // namespace giocal
