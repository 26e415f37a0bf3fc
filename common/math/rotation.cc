#include "common/math/rotation.h"

#include <cmath>

namespace giocal {

Quat quatFromWxyz(const double* wxyz) {
  Quat q(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
  q.normalize();
  return q;
}

void quatToWxyz(const Quat& q, double* wxyz) {
  wxyz[0] = q.w();
  wxyz[1] = q.x();
  wxyz[2] = q.y();
  wxyz[3] = q.z();
}

Mat3 rotationFromRpy(const Vec3& rpy) {
  using Eigen::AngleAxisd;
  return (AngleAxisd(rpy.z(), Vec3::UnitZ()) * AngleAxisd(rpy.y(), Vec3::UnitY()) *
          AngleAxisd(rpy.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

Vec3 rpyFromRotation(const Mat3& R) {
  const double pitch = std::atan2(-R(2, 0), std::hypot(R(0, 0), R(1, 0)));
  const double roll = std::atan2(R(2, 1), R(2, 2));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  return {roll, pitch, yaw};
}

Quat boxPlus(const Quat& q, const Vec3& dtheta) {
  Quat out = q * Quat(expSO3(dtheta));
  out.normalize();
  return out;
}

Vec3 boxMinus(const Quat& q_b, const Quat& q_a) {
  return logSO3((q_a.conjugate() * q_b).toRotationMatrix());
}

}  // namespace giocal
