#include "common/math/so3.h"

#include <cmath>

namespace giocal {

namespace {
// Below this angle logSO3's closed form loses precision and its Taylor series is used instead.
constexpr double kSmallAngle = 1e-5;
// Below this angle the coefficients come from their Taylor series: the closed forms subtract
// nearly equal numbers (d's relative error is about 1e-16 / theta^4), and with terms up to
// theta^8 the series is exact to rounding here.
constexpr double kSeriesAngle = 0.1;
}  // namespace

So3Coefficients so3Coefficients(double theta) {
  const double t2 = theta * theta;
  if (theta < kSeriesAngle) {
    const double t4 = t2 * t2, t6 = t4 * t2, t8 = t4 * t4;
    return {1.0 - t2 / 6.0 + t4 / 120.0 - t6 / 5040.0 + t8 / 362880.0,
            0.5 - t2 / 24.0 + t4 / 720.0 - t6 / 40320.0 + t8 / 3628800.0,
            1.0 / 6.0 - t2 / 120.0 + t4 / 5040.0 - t6 / 362880.0 + t8 / 39916800.0,
            1.0 / 24.0 - t2 / 720.0 + t4 / 40320.0 - t6 / 3628800.0 + t8 / 479001600.0};
  }
  const double s = std::sin(theta), c = std::cos(theta);
  return {s / theta, (1.0 - c) / t2, (theta - s) / (t2 * theta),
          (t2 + 2.0 * c - 2.0) / (2.0 * t2 * t2)};
}

Mat3 skew(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

Mat3 expSO3(const Vec3& phi) {
  const So3Coefficients k = so3Coefficients(phi.norm());
  const Mat3 K = skew(phi);
  return Mat3::Identity() + k.a * K + k.b * K * K;
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
  const So3Coefficients k = so3Coefficients(phi.norm());
  const Mat3 K = skew(phi);
  return Mat3::Identity() - k.b * K + k.c * K * K;
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
