#include "common/math/so3.h"

#include <cmath>

namespace giocal {

namespace {
// Below this angle the closed forms lose precision and their Taylor series are used instead.
constexpr double kSmallAngle = 1e-5;
}  // namespace

Mat3 skew(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

Mat3 expSO3(const Vec3& phi) {
  const double theta = phi.norm();
  const Mat3 K = skew(phi);
  if (theta < kSmallAngle) {
    return Mat3::Identity() + K + 0.5 * K * K;
  }
  const double a = std::sin(theta) / theta;
  const double b = (1.0 - std::cos(theta)) / (theta * theta);
  return Mat3::Identity() + a * K + b * K * K;
}

Vec3 logSO3(const Mat3& R) {
  // The quaternion route is accurate for every angle, including near pi.
  Quat q(R);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() *= -1.0;
  const Vec3 v = q.vec();
  const double s = v.norm();
  if (s < kSmallAngle) {
    return 2.0 * v / q.w() * (1.0 - s * s / (3.0 * q.w() * q.w()));
  }
  const double theta = 2.0 * std::atan2(s, q.w());
  return theta / s * v;
}

Mat3 rightJacobianSO3(const Vec3& phi) {
  const double theta = phi.norm();
  const Mat3 K = skew(phi);
  if (theta < kSmallAngle) {
    return Mat3::Identity() - 0.5 * K + K * K / 6.0;
  }
  const double t2 = theta * theta;
  return Mat3::Identity() - (1.0 - std::cos(theta)) / t2 * K +
         (theta - std::sin(theta)) / (t2 * theta) * K * K;
}

Mat3 rightJacobianInvSO3(const Vec3& phi) {
  const double theta = phi.norm();
  const Mat3 K = skew(phi);
  if (theta < kSmallAngle) {
    return Mat3::Identity() + 0.5 * K + K * K / 12.0;
  }
  const double t2 = theta * theta;
  const double c = 1.0 / t2 - (1.0 + std::cos(theta)) / (2.0 * theta * std::sin(theta));
  return Mat3::Identity() + 0.5 * K + c * K * K;
}

Mat3 normalizeRotation(const Mat3& R) {
  Quat q(R);
  q.normalize();
  return q.toRotationMatrix();
}

}  // namespace giocal
