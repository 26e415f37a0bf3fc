#include <gtest/gtest.h>

#include <random>

#include "common/math/rotation.h"
#include "common/math/so3.h"
#include "numeric_jacobian.h"

namespace giocal {
namespace {

Vec3 randomVec(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

TEST(So3, ExpLogRoundTripAcrossAngles) {
  std::mt19937 rng(1);
  for (double scale : {1e-9, 1e-6, 1e-3, 0.5, 1.5, 3.0}) {
    for (int k = 0; k < 50; ++k) {
      Vec3 phi = randomVec(rng, scale);
      if (phi.norm() > 3.1) phi *= 3.1 / phi.norm();
      EXPECT_LT((logSO3(expSO3(phi)) - phi).norm(), 1e-12 + 1e-10 * phi.norm()) << phi.transpose();
      const Mat3 R = expSO3(phi);
      EXPECT_LT((R.transpose() * R - Mat3::Identity()).norm(), 1e-14);
      EXPECT_NEAR(R.determinant(), 1.0, 1e-14);
    }
  }
}

TEST(So3, LogNearPi) {
  const Vec3 phi = Vec3(1, 2, -1).normalized() * (M_PI - 1e-9);
  EXPECT_LT((logSO3(expSO3(phi)) - phi).norm(), 1e-7);
}

TEST(So3, SkewIsCrossProduct) {
  const Vec3 a(1, -2, 3), b(0.5, 4, -1);
  EXPECT_LT((skew(a) * b - a.cross(b)).norm(), 1e-15);
}

TEST(So3, RightJacobianMatchesNumericDerivativeOfExp) {
  std::mt19937 rng(2);
  for (int k = 0; k < 20; ++k) {
    const Vec3 phi = randomVec(rng, k < 5 ? 1e-7 : 2.0);
    // Log(Exp(phi)^-1 Exp(phi + d)) = Jr(phi) d to first order.
    const auto f = [&](const Eigen::VectorXd& d) -> Eigen::VectorXd {
      return logSO3(expSO3(phi).transpose() * expSO3(phi + Vec3(d)));
    };
    const Eigen::MatrixXd num = test::numericJacobian(f, 3);
    EXPECT_LT(test::relativeDifference(rightJacobianSO3(phi), num), 1e-8);
    // Log(Exp(phi) Exp(d)) = phi + Jr^-1(phi) d.
    const auto g = [&](const Eigen::VectorXd& d) -> Eigen::VectorXd {
      return logSO3(expSO3(phi) * expSO3(Vec3(d)));
    };
    EXPECT_LT(test::relativeDifference(rightJacobianInvSO3(phi), test::numericJacobian(g, 3)),
              1e-8);
    EXPECT_LT((rightJacobianSO3(phi) * rightJacobianInvSO3(phi) - Mat3::Identity()).norm(), 1e-10);
  }
}

TEST(So3, CoefficientsAreContinuousAtTheSeriesBoundaryAndIntegrateExp) {
  // The series and the closed forms meet where the series hands over.
  const So3Coefficients lo = so3Coefficients(0.1 - 1e-12), hi = so3Coefficients(0.1 + 1e-12);
  EXPECT_NEAR(lo.a, hi.a, 1e-13);
  EXPECT_NEAR(lo.b, hi.b, 1e-13);
  EXPECT_NEAR(lo.c, hi.c, 1e-13);
  EXPECT_NEAR(lo.d, hi.d, 1e-11);
  // I/2 + c K + d K^2 is the double integral of Exp(s phi), by the midpoint rule, and
  // I + b K + c K^2 the single one.
  for (const Vec3& phi : {Vec3(1e-3, -2e-3, 5e-4), Vec3(0.05, 0.02, -0.07), Vec3(0.4, -1.0, 0.7)}) {
    const So3Coefficients k = so3Coefficients(phi.norm());
    const Mat3 K = skew(phi);
    const int n = 2000;
    Mat3 single = Mat3::Zero(), twice = Mat3::Zero();
    for (int i = 0; i < n; ++i) {
      const double s = (i + 0.5) / n;
      single += expSO3(s * phi) / n;
      twice += (1.0 - s) * expSO3(s * phi) / n;  // int_0^1 int_s^1 du ds
    }
    EXPECT_LT((single - (Mat3::Identity() + k.b * K + k.c * K * K)).norm(), 1e-7);
    EXPECT_LT((twice - (0.5 * Mat3::Identity() + k.c * K + k.d * K * K)).norm(), 1e-7);
    EXPECT_LT((single - rightJacobianSO3(phi).transpose()).norm(), 1e-7);
  }
}

TEST(Rotation, RpyRoundTripAndConvention) {
  const Vec3 rpy(0.1, -0.2, 2.5);
  const Mat3 R = rotationFromRpy(rpy);
  EXPECT_LT((rpyFromRotation(R) - rpy).norm(), 1e-14);
  // R = Rz(yaw) Ry(pitch) Rx(roll), checked against the elementary matrices.
  const Mat3 Rx = expSO3(Vec3::UnitX() * rpy.x());
  const Mat3 Ry = expSO3(Vec3::UnitY() * rpy.y());
  const Mat3 Rz = expSO3(Vec3::UnitZ() * rpy.z());
  EXPECT_LT((R - Rz * Ry * Rx).norm(), 1e-14);
  // Yaw of +90 deg maps the x axis onto y.
  EXPECT_LT((rotationFromRpy(Vec3(0, 0, M_PI / 2)) * Vec3::UnitX() - Vec3::UnitY()).norm(), 1e-15);
}

TEST(Rotation, QuaternionWxyzOrderAndBoxOperators) {
  const double wxyz[4] = {0.9, 0.1, -0.3, 0.2};
  const Quat q = quatFromWxyz(wxyz);
  EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  double back[4];
  quatToWxyz(q, back);
  EXPECT_NEAR(back[0] / back[3], 0.9 / 0.2, 1e-12);
  const Vec3 d(0.01, -0.02, 0.03);
  EXPECT_LT((boxMinus(boxPlus(q, d), q) - d).norm(), 1e-12);
  // Right perturbation: the increment acts in the body frame.
  EXPECT_LT((boxPlus(q, d).toRotationMatrix() - q.toRotationMatrix() * expSO3(d)).norm(), 1e-14);
}

}  // namespace
}  // namespace giocal
