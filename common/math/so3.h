// SO(3) operations on rotation matrices: skew, Exp/Log and the right Jacobians.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace giocal {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

/// The scalar coefficients of the SO(3) series at angle t, so that with K = skew(phi):
/// Exp = I + a K + b K^2, Jr = I - b K + c K^2, Jr^T = I + b K + c K^2 and
/// int_0^1 int_0^u Exp(s phi) ds du = I/2 + c K + d K^2, where a = sin(t)/t,
/// b = (1 - cos(t))/t^2, c = (t - sin(t))/t^3 and d = (t^2 + 2 cos(t) - 2)/(2 t^4).
struct So3Coefficients {
  double a, b, c, d;
};
So3Coefficients so3Coefficients(double theta);

/// [v]x, the matrix with skew(a) * b = a x b.
Mat3 skew(const Vec3& v);

/// Rotation matrix of the rotation vector phi (axis times angle in radians).
Mat3 expSO3(const Vec3& phi);

/// Rotation vector of R, angle in [0, pi].
Vec3 logSO3(const Mat3& R);

/// Right Jacobian: Exp(phi + d) ~= Exp(phi) Exp(Jr(phi) d).
Mat3 rightJacobianSO3(const Vec3& phi);

/// Inverse of the right Jacobian: Log(Exp(phi) Exp(d)) ~= phi + Jr^-1(phi) d.
Mat3 rightJacobianInvSO3(const Vec3& phi);

/// Projects a nearly orthonormal matrix back onto SO(3) (keeps long integrations exact).
Mat3 normalizeRotation(const Mat3& R);

}  // namespace giocal
