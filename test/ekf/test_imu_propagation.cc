#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "common/geodesy/wgs84.h"
#include "common/math/rotation.h"
#include "ekf/imu_propagation.h"

namespace giocal {
namespace {

struct ImuCase {
  LocalFrame frame{ecefFromGeodetic({0.61, 2.39, 40.0})};
  ImuNoise noise;
  std::vector<ImuSample> samples;
  NavState x0;
  ImuCase() {
    noise.gyro_noise_density = 0.005;
    noise.accel_noise_density = 0.05;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int k = 0; k <= 100; ++k) {
      samples.push_back({k * 0.01, Eigen::Vector3d(0.1 * std::sin(k * 0.05), 0.05 * u(rng), 0.4),
                         Eigen::Vector3d(0.3 + 0.1 * u(rng), 0.2, 9.8 + 0.05 * u(rng))});
    }
    x0.p_n_b = {1, 2, 3};
    x0.v_n_b = {0.5, -0.2, 0.0};
    x0.q_n_b = Quat(rotationFromRpy(Vec3(0.02, -0.01, 1.0)));
    x0.b_a = {0.01, -0.02, 0.03};
    x0.b_g = {1e-3, -2e-3, 5e-4};
  }
  void fill(StateRegistry& s) const {
    Eigen::VectorXd q(4);
    quatToWxyz(x0.q_n_b, q.data());
    s.add(vectorBlock(state::kSv, 1), Eigen::VectorXd::Constant(1, 0.02),
          Eigen::MatrixXd::Constant(1, 1, 1e-4));
    s.add(vectorBlock(state::kP), x0.p_n_b, Eigen::Matrix3d::Zero());
    s.add(rotationBlock(state::kQ), q, Eigen::Matrix3d::Zero());
    s.add(vectorBlock(state::kV), x0.v_n_b, Eigen::Matrix3d::Zero());
    s.add(vectorBlock(state::kBa), x0.b_a, Eigen::Matrix3d::Zero());
    s.add(vectorBlock(state::kBg), x0.b_g, Eigen::Matrix3d::Zero());
  }
};

TEST(ImuPropagation, PerSampleEqualsOneShotPreintegration) {
  const ImuCase su;
  StateRegistry s;
  su.fill(s);
  for (size_t k = 0; k + 1 < su.samples.size(); ++k) {
    ImuPreintegration step(su.noise, su.frame.gravity_n(), su.frame.omega_ie_n(), su.x0.b_a,
                           su.x0.b_g);
    step.integrateSamples(su.samples, su.samples[k].t, su.samples[k + 1].t);
    propagateImu(s, step);
  }
  ImuPreintegration whole(su.noise, su.frame.gravity_n(), su.frame.omega_ie_n(), su.x0.b_a,
                          su.x0.b_g);
  whole.integrateSamples(su.samples, 0.0, 1.0);
  const NavState xj = whole.predict(su.x0);
  const NavState xe = navState(s);
  // Below 1 um without Earth rotation; with it the one-shot's first-order Earth-rotation terms over
  // 1 s differ from the per-sample chain by about 3 um.
  EXPECT_LT((xe.p_n_b - xj.p_n_b).norm(), 1e-5);
  EXPECT_LT((xe.v_n_b - xj.v_n_b).norm(), 1e-5);
  EXPECT_LT(xe.q_n_b.angularDistance(xj.q_n_b), 1e-8);
  // From a known start, the per-sample covariance equals the one-shot preintegration's covariance
  // mapped to the end state (J_j^-1 S J_j^-T).
  const ImuResidual r = whole.evaluate(su.x0, xj);
  Eigen::Matrix<double, 15, 15> Jj;
  Jj << r.J_p_j, r.J_q_j, r.J_v_j, r.J_ba_j, r.J_bg_j;
  const Eigen::Matrix<double, 15, 15> expected =
      Jj.inverse() * whole.covariance() * Jj.inverse().transpose();
  const Eigen::MatrixXd got = s.covariance().bottomRightCorner(15, 15);
  for (int i = 0; i < 15; ++i) {
    EXPECT_NEAR(got(i, i) / expected(i, i), 1.0, 0.02) << "component " << i;
    // The correlations too, each against the expected variances of its pair.
    for (int j = 0; j < i; ++j) {
      const double scale = std::sqrt(expected(i, i) * expected(j, j));
      EXPECT_NEAR(got(i, j) / scale, expected(i, j) / scale, 0.02) << i << ", " << j;
    }
  }
  // The scale factor's variance and its (zero) correlation are untouched.
  EXPECT_DOUBLE_EQ(s.covariance()(0, 0), 1e-4);
  EXPECT_EQ(s.covariance().row(0).tail(15).norm(), 0.0);
}

// With the gyro's tilt estimated, the propagation carries its uncertainty into the navigation
// state through d x_j / d tilt: from a state known exactly but for the tilt, the cross-covariance
// of position, attitude and velocity with the tilt is that derivative (numeric here) times the
// tilt's variance.
TEST(ImuPropagation, TheGyroTiltEntersThroughItsJacobian) {
  const ImuCase su;
  StateRegistry s;
  su.fill(s);
  const GyroTilt t0(1e-3, -2e-3);
  const double var = 1e-6;
  s.add(vectorBlock(state::kGyroTilt, 2), t0, Eigen::Matrix2d::Identity() * var);
  ImuPreintegration step(su.noise, su.frame.gravity_n(), su.frame.omega_ie_n(), su.x0.b_a,
                         su.x0.b_g, t0);
  step.integrateSamples(su.samples, 0.0, 1.0);
  propagateImu(s, step);
  const double h = 1e-6;
  for (int k = 0; k < 2; ++k) {
    GyroTilt up = t0, down = t0;
    up[k] += h;
    down[k] -= h;
    const NavState a = step.predict(su.x0, up), b = step.predict(su.x0, down);
    Eigen::Matrix<double, 9, 1> d;
    d << (a.p_n_b - b.p_n_b) / (2 * h), boxMinus(a.q_n_b, b.q_n_b) / (2 * h),
        (a.v_n_b - b.v_n_b) / (2 * h);
    const int col = s.offset(state::kGyroTilt) + k;
    Eigen::Matrix<double, 9, 1> got;
    for (int r = 0; r < 3; ++r) {
      got[r] = s.covariance()(s.offset(state::kP) + r, col);
      got[3 + r] = s.covariance()(s.offset(state::kQ) + r, col);
      got[6 + r] = s.covariance()(s.offset(state::kV) + r, col);
    }
    EXPECT_GT(d.norm(), 1e-3) << "tilt " << k;
    EXPECT_LT((got - d * var).norm(), 1e-5 * d.norm() * var) << "tilt " << k;
  }
}

TEST(ImuPropagation, CarriesCrossCovarianceWithOtherVariables) {
  const ImuCase su;
  StateRegistry s;
  su.fill(s);
  // Correlate the scale with the velocity, then propagate: Phi carries the correlation onward.
  s.covariance()(0, s.offset(state::kV)) = s.covariance()(s.offset(state::kV), 0) = 1e-4;
  s.covariance().block(s.offset(state::kV), s.offset(state::kV), 3, 3) =
      Eigen::Matrix3d::Identity() * 1e-2;
  ImuPreintegration step(su.noise, su.frame.gravity_n(), su.frame.omega_ie_n(), su.x0.b_a,
                         su.x0.b_g);
  step.integrateSamples(su.samples, 0.0, 0.5);
  propagateImu(s, step);
  // A velocity error becomes a position error: cov(s_v, p) = cov(s_v, v) * T (first component).
  EXPECT_NEAR(s.covariance()(0, s.offset(state::kP)), 1e-4 * 0.5, 1e-6);
  const Eigen::MatrixXd P = s.covariance();
  EXPECT_LT((P - P.transpose()).norm(), 1e-15);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P).eigenvalues().minCoeff(), -1e-15);
}

TEST(ImuPropagation, EqualsTheDenseTransitionOfTheWholeState) {
  // propagateImu's shortcuts (the end-state Jacobian inverted by blocks, only the navigation rows
  // moved, the bias rows copied) against Phi P Phi^T + Q written out densely, on a covariance
  // where every variable is correlated with every other.
  const ImuCase su;
  StateRegistry s;
  su.fill(s);
  const int n = s.dim();
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::MatrixXd L(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) L(i, j) = 1e-2 * g(rng);
  s.covariance() = L * L.transpose() + 1e-6 * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd P0 = s.covariance();
  ImuPreintegration step(su.noise, su.frame.gravity_n(), su.frame.omega_ie_n(), su.x0.b_a,
                         su.x0.b_g);
  step.integrateSamples(su.samples, 0.0, 0.5);
  const NavState xj = step.predict(su.x0);
  const ImuResidual r = step.evaluate(su.x0, xj);
  Eigen::Matrix<double, 15, 15> Ji, Jj;
  Ji << r.J_p_i, r.J_q_i, r.J_v_i, r.J_ba_i, r.J_bg_i;
  Jj << r.J_p_j, r.J_q_j, r.J_v_j, r.J_ba_j, r.J_bg_j;
  const Eigen::Matrix<double, 15, 15> Jj_inv = Jj.inverse();
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Identity(n, n), Q = Eigen::MatrixXd::Zero(n, n);
  const int nav = s.offset(state::kP);  // p, q, v, b_a, b_g follow one another
  ASSERT_EQ(s.offset(state::kBg), nav + 12);
  Phi.block(nav, nav, 15, 15) = -Jj_inv * Ji;
  Q.block(nav, nav, 15, 15) = Jj_inv * step.covariance() * Jj_inv.transpose();
  const Eigen::MatrixXd expected = Phi * P0 * Phi.transpose() + Q;
  propagateImu(s, step);
  EXPECT_LT((s.covariance() - expected).cwiseAbs().maxCoeff(),
            1e-12 * expected.cwiseAbs().maxCoeff());
  EXPECT_LT((s.value(state::kP) - xj.p_n_b).norm(), 1e-12);
}

}  // namespace
}  // namespace giocal
