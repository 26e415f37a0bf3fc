#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "common/geodesy/wgs84.h"
#include "common/imu/imu_preintegration.h"
#include "common/math/rotation.h"
#include "numeric_jacobian.h"

namespace giocal {
namespace {

using Vec15 = Eigen::Matrix<double, 15, 1>;

Vec3 randomVec(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

NavState randomState(std::mt19937& rng) {
  NavState s;
  s.p_n_b = randomVec(rng, 50.0);
  s.v_n_b = randomVec(rng, 2.0);
  s.q_n_b = Quat(expSO3(randomVec(rng, 3.0)));
  s.b_a = randomVec(rng, 0.05);
  s.b_g = randomVec(rng, 0.01);
  return s;
}

struct Fixture {
  LocalFrame frame{ecefFromGeodetic({0.61, 2.39, 40.0})};
  ImuNoise noise;
  /// Half a second of random rates and specific forces, from random linearization biases.
  ImuPreintegration randomInterval(std::mt19937& rng) const {
    ImuPreintegration pre(noise, frame.gravity_n(), frame.omega_ie_n(), randomVec(rng, 0.05),
                          randomVec(rng, 0.01));
    for (int k = 0; k < 50; ++k)
      pre.integrate(0.01, randomVec(rng, 1.0), randomVec(rng, 3.0) + Vec3(0, 0, 9.8));
    return pre;
  }
};

TEST(ImuPreintegration, AllJacobiansMatchNumericDifferentiation) {
  std::mt19937 rng(11);
  Fixture f;
  for (int trial = 0; trial < 10; ++trial) {
    const ImuPreintegration pre = f.randomInterval(rng);
    // States away from the linearization point, with biases that differ from it.
    const NavState si = randomState(rng), sj = randomState(rng);
    const ImuResidual res = pre.evaluate(si, sj);

    using Perturb = std::function<void(NavState&, const Vec3&)>;
    const std::vector<std::tuple<const char*, bool, Perturb, Eigen::Matrix<double, 15, 3>>> blocks{
        {"p_i", true, [](NavState& s, const Vec3& d) { s.p_n_b += d; }, res.J_p_i},
        {"q_i", true, [](NavState& s, const Vec3& d) { s.q_n_b = boxPlus(s.q_n_b, d); }, res.J_q_i},
        {"v_i", true, [](NavState& s, const Vec3& d) { s.v_n_b += d; }, res.J_v_i},
        {"ba_i", true, [](NavState& s, const Vec3& d) { s.b_a += d; }, res.J_ba_i},
        {"bg_i", true, [](NavState& s, const Vec3& d) { s.b_g += d; }, res.J_bg_i},
        {"p_j", false, [](NavState& s, const Vec3& d) { s.p_n_b += d; }, res.J_p_j},
        {"q_j", false, [](NavState& s, const Vec3& d) { s.q_n_b = boxPlus(s.q_n_b, d); },
         res.J_q_j},
        {"v_j", false, [](NavState& s, const Vec3& d) { s.v_n_b += d; }, res.J_v_j},
        {"ba_j", false, [](NavState& s, const Vec3& d) { s.b_a += d; }, res.J_ba_j},
        {"bg_j", false, [](NavState& s, const Vec3& d) { s.b_g += d; }, res.J_bg_j},
    };
    for (const auto& [name, on_i, perturb, J] : blocks) {
      const auto fn = [&, on_i = on_i,
                       perturb = perturb](const Eigen::VectorXd& d) -> Eigen::VectorXd {
        NavState a = si, b = sj;
        perturb(on_i ? a : b, Vec3(d));
        return pre.evaluate(a, b).r;
      };
      EXPECT_LT(test::relativeDifference(J, test::numericJacobian(fn, 3)), 1e-6)
          << name << " trial " << trial;
    }
  }
}

TEST(ImuPreintegration, EndStateJacobianInverseIsTheInverse) {
  // The blockwise inverse relies on which residual rows state j moves; a new dependency in
  // evaluate() breaks it, and this test.
  std::mt19937 rng(12);
  Fixture f;
  for (int trial = 0; trial < 10; ++trial) {
    const ImuResidual res = f.randomInterval(rng).evaluate(randomState(rng), randomState(rng));
    Eigen::Matrix<double, 15, 15> Jj;
    Jj << res.J_p_j, res.J_q_j, res.J_v_j, res.J_ba_j, res.J_bg_j;
    const Eigen::Matrix<double, 15, 15> inv = endStateJacobianInverse(res);
    EXPECT_LT((inv * Jj - Eigen::Matrix<double, 15, 15>::Identity()).cwiseAbs().maxCoeff(), 1e-13)
        << trial;
    EXPECT_LT(test::relativeDifference(inv, Jj.inverse()), 1e-13) << trial;
    // The Earth's rate couples v_j into r_v through p_j: the block that a diagonal form misses.
    const Eigen::Matrix3d v_by_p = inv.block<3, 3>(imu_index::kV, imu_index::kP);
    EXPECT_GT(v_by_p.norm(), 1e-6);
  }
}

TEST(ImuPreintegration, ConstantRateAndAccelerationClosedForm) {
  // Body turning at w about z with a constant body-x specific force a, no gravity, no Earth
  // rotation: dv = a/w (sin wT, 1 - cos wT, 0), dp = a/w ((1 - cos wT)/w, T - sin(wT)/w, 0).
  ImuNoise noise;
  ImuPreintegration pre(noise, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
  const double w = 0.7, a = 1.3, dt = 0.01;
  const int n = 250;
  for (int k = 0; k < n; ++k) pre.integrate(dt, Vec3(0, 0, w), Vec3(a, 0, 0));
  const double T = n * dt;
  EXPECT_NEAR(pre.dt(), T, 1e-12);
  EXPECT_LT((pre.deltaR() - expSO3(Vec3(0, 0, w * T))).norm(), 1e-12);
  const Vec3 dv(a / w * std::sin(w * T), a / w * (1 - std::cos(w * T)), 0);
  const Vec3 dp(a / w * (1 - std::cos(w * T)) / w, a / w * (T - std::sin(w * T) / w), 0);
  EXPECT_LT((pre.deltaV() - dv).norm(), 1e-12);
  EXPECT_LT((pre.deltaP() - dp).norm(), 1e-12);
}

// Fine-step (RK4, 0.1 ms) strapdown in the Earth-fixed n frame with gravity and Earth rotation.
struct Strapdown {
  Vec3 g, w_ie;
  std::function<Vec3(double)> gyro, acc;
  void run(NavState& s, double t0, double t1) const {
    const double h = 1e-4;
    Mat3 R = s.q_n_b.toRotationMatrix();
    Vec3 p = s.p_n_b, v = s.v_n_b;
    const auto deriv = [&](double t, const Mat3& R_, const Vec3& v_, Mat3& dR, Vec3& dv, Vec3& dp) {
      dR = R_ * skew(gyro(t)) - skew(w_ie) * R_;
      dv = R_ * acc(t) + g - 2.0 * w_ie.cross(v_);
      dp = v_;
    };
    for (double t = t0; t < t1 - 1e-12; t += h) {
      Mat3 k1R, k2R, k3R, k4R;
      Vec3 k1v, k2v, k3v, k4v, k1p, k2p, k3p, k4p;
      deriv(t, R, v, k1R, k1v, k1p);
      deriv(t + h / 2, R + h / 2 * k1R, v + h / 2 * k1v, k2R, k2v, k2p);
      deriv(t + h / 2, R + h / 2 * k2R, v + h / 2 * k2v, k3R, k3v, k3p);
      deriv(t + h, R + h * k3R, v + h * k3v, k4R, k4v, k4p);
      R = normalizeRotation(R + h / 6 * (k1R + 2 * k2R + 2 * k3R + k4R));
      v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      p += h / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
    }
    s.q_n_b = Quat(R);
    s.v_n_b = v;
    s.p_n_b = p;
  }
};

TEST(ImuPreintegration, PredictMatchesFineStepStrapdownWithEarthRotation) {
  Fixture f;
  Strapdown sd;
  sd.g = f.frame.gravity_n();
  sd.w_ie = f.frame.omega_ie_n();
  // Smooth ground-robot-like motion: turning and accelerating while holding gravity.
  sd.gyro = [](double t) {
    return Vec3(0.02 * std::sin(t), -0.03 * std::cos(2 * t), 0.5 * std::sin(0.7 * t));
  };
  sd.acc = [](double t) {
    return Vec3(0.3 * std::cos(t), 0.5 * std::sin(1.3 * t), 9.79 + 0.05 * std::sin(t));
  };
  NavState s0;
  s0.p_n_b = {10, -5, 1};
  s0.v_n_b = {1.0, 0.5, 0.0};
  s0.q_n_b = Quat(rotationFromRpy({0.01, -0.02, 0.8}));
  const double T = 2.0, rate = 100.0;
  std::vector<ImuSample> samples;
  for (int k = 0; k <= static_cast<int>(T * rate); ++k) {
    const double t = k / rate;
    samples.push_back({t, sd.gyro(t), sd.acc(t)});
  }
  ImuPreintegration pre(f.noise, sd.g, sd.w_ie, Vec3::Zero(), Vec3::Zero());
  pre.integrateSamples(samples, 0.0, T);
  NavState truth = s0;
  sd.run(truth, 0.0, T);
  const NavState pred = pre.predict(s0);
  // 100 Hz samples with the midpoint rule leave errors of order (w dt)^2: well below a millimetre.
  EXPECT_LT((pred.p_n_b - truth.p_n_b).norm(), 2e-4);
  EXPECT_LT((pred.v_n_b - truth.v_n_b).norm(), 2e-4);
  EXPECT_LT(pred.q_n_b.angularDistance(truth.q_n_b), 2e-5);
  // Without the Earth-rotation terms the same prediction is measurably worse (the terms matter).
  ImuPreintegration no_earth(f.noise, sd.g, Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
  no_earth.integrateSamples(samples, 0.0, T);
  EXPECT_GT((no_earth.predict(s0).v_n_b - truth.v_n_b).norm(),
            5.0 * (pred.v_n_b - truth.v_n_b).norm());
  // The residual at the prediction is zero.
  EXPECT_LT(pre.evaluate(s0, pred).r.norm(), 1e-9);
}

TEST(ImuPreintegration, BiasCorrectionIsFirstOrderAccurate) {
  std::mt19937 rng(5);
  Fixture f;
  ImuPreintegration pre(f.noise, f.frame.gravity_n(), f.frame.omega_ie_n(), Vec3::Zero(),
                        Vec3::Zero());
  const Vec3 dba(0.02, -0.01, 0.015), dbg(0.003, -0.002, 0.004);
  // The same samples integrated again about the changed biases.
  ImuPreintegration re(f.noise, f.frame.gravity_n(), f.frame.omega_ie_n(), dba, dbg);
  for (int k = 0; k < 100; ++k) {
    const Vec3 gyro = randomVec(rng, 0.8), acc = randomVec(rng, 2.0) + Vec3(0, 0, 9.8);
    pre.integrate(0.01, gyro, acc);
    re.integrate(0.01, gyro, acc);
  }
  const double change_v = (re.deltaV() - pre.deltaV()).norm();
  const double change_p = (re.deltaP() - pre.deltaP()).norm();
  EXPECT_GT(change_v, 1e-3);
  // The first-order correction removes at least 99 % of the change.
  EXPECT_LT((pre.correctedDeltaV(dba, dbg) - re.deltaV()).norm(), 0.01 * change_v);
  EXPECT_LT((pre.correctedDeltaP(dba, dbg) - re.deltaP()).norm(), 0.01 * change_p);
  EXPECT_LT(logSO3(pre.correctedDeltaR(dbg).transpose() * re.deltaR()).norm(),
            0.01 * logSO3(pre.deltaR().transpose() * re.deltaR()).norm());
}

TEST(ImuPreintegration, GyroTiltCorrectionIsFirstOrderAccurate) {
  // The same samples integrated about a tilt 0.5 degrees away: the tilt Jacobian must predict the
  // change of every delta to first order, from a tilted linearization point as from zero.
  std::mt19937 rng(6);
  Fixture f;
  const GyroTilt t0(0.002, -0.001), dt(0.006, -0.005);
  ImuPreintegration pre(f.noise, f.frame.gravity_n(), f.frame.omega_ie_n(), Vec3::Zero(),
                        Vec3::Zero(), t0);
  ImuPreintegration re(f.noise, f.frame.gravity_n(), f.frame.omega_ie_n(), Vec3::Zero(),
                       Vec3::Zero(), t0 + dt);
  for (int k = 0; k < 200; ++k) {
    const Vec3 gyro = randomVec(rng, 0.8), acc = randomVec(rng, 2.0) + Vec3(0, 0, 9.8);
    pre.integrate(0.01, gyro, acc);
    re.integrate(0.01, gyro, acc);
  }
  const double change_v = (re.deltaV() - pre.deltaV()).norm();
  const double change_p = (re.deltaP() - pre.deltaP()).norm();
  const double change_r = logSO3(pre.deltaR().transpose() * re.deltaR()).norm();
  EXPECT_GT(change_v, 1e-3);
  EXPECT_GT(change_r, 1e-4);
  const Vec3 zero = Vec3::Zero();
  EXPECT_LT((pre.correctedDeltaV(zero, zero, t0 + dt) - re.deltaV()).norm(), 0.02 * change_v);
  EXPECT_LT((pre.correctedDeltaP(zero, zero, t0 + dt) - re.deltaP()).norm(), 0.02 * change_p);
  EXPECT_LT(logSO3(pre.correctedDeltaR(zero, t0 + dt).transpose() * re.deltaR()).norm(),
            0.02 * change_r);
  // Without a tilt the deltas are the linearization point's.
  EXPECT_EQ(pre.correctedDeltaV(zero, zero), pre.deltaV());
}

TEST(ImuPreintegration, WithoutATiltTheDeltasAreThoseAtZeroTiltAndNoTiltJacobianIsCarried) {
  std::mt19937 rng(7);
  Fixture f;
  ImuPreintegration plain(f.noise, f.frame.gravity_n(), f.frame.omega_ie_n(), Vec3::Zero(),
                          Vec3::Zero());
  ImuPreintegration zero(f.noise, f.frame.gravity_n(), f.frame.omega_ie_n(), Vec3::Zero(),
                         Vec3::Zero(), GyroTilt::Zero());
  for (int k = 0; k < 100; ++k) {
    const Vec3 gyro = randomVec(rng, 0.8), acc = randomVec(rng, 2.0) + Vec3(0, 0, 9.8);
    plain.integrate(0.01, gyro, acc);
    zero.integrate(0.01, gyro, acc);
  }
  EXPECT_EQ(plain.deltaP(), zero.deltaP());
  EXPECT_EQ(plain.deltaR(), zero.deltaR());
  EXPECT_EQ(plain.covariance(), zero.covariance());
  EXPECT_EQ(plain.biasJacobian(), zero.biasJacobian());
  EXPECT_GT(zero.tiltJacobian().norm(), 0.0);
  EXPECT_EQ(plain.tiltJacobian().norm(), 0.0);
}

TEST(ImuPreintegration, GyroTiltJacobianOfTheResidualMatchesNumericDifferentiation) {
  std::mt19937 rng(12);
  Fixture f;
  for (int trial = 0; trial < 5; ++trial) {
    const GyroTilt lin(0.001 * trial, -0.002);
    ImuPreintegration pre(f.noise, f.frame.gravity_n(), f.frame.omega_ie_n(), randomVec(rng, 0.05),
                          randomVec(rng, 0.01), lin);
    for (int k = 0; k < 50; ++k)
      pre.integrate(0.01, randomVec(rng, 1.0), randomVec(rng, 3.0) + Vec3(0, 0, 9.8));
    const NavState si = randomState(rng), sj = randomState(rng);
    const GyroTilt tilt = lin + GyroTilt(0.003, 0.002);  // away from the linearization point
    const auto fn = [&](const Eigen::VectorXd& d) -> Eigen::VectorXd {
      return pre.evaluate(si, sj, GyroTilt(tilt + d)).r;
    };
    EXPECT_LT(
        test::relativeDifference(pre.evaluate(si, sj, tilt).J_tilt, test::numericJacobian(fn, 2)),
        1e-6)
        << "trial " << trial;
  }
}

TEST(ImuPreintegration, CovarianceMatchesMonteCarlo) {
  // Integrates the same motion with sampled white noise and bias random walk many times; the sample
  // covariance of (dp, dtheta, dv) must match the propagated one.
  ImuNoise noise;
  noise.gyro_noise_density = 0.005;
  noise.accel_noise_density = 0.05;
  noise.gyro_bias_random_walk = 0.002;
  noise.accel_bias_random_walk = 0.02;
  const double dt = 0.01;
  const int steps = 100, runs = 2000;
  const Vec3 w0(0.1, -0.2, 0.5), a0(0.5, 0.2, 9.8);
  ImuPreintegration nominal(noise, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
  for (int k = 0; k < steps; ++k) nominal.integrate(dt, w0, a0);
  std::mt19937 rng(7);
  std::normal_distribution<double> n01;
  auto gauss = [&](double sd) -> Vec3 { return Vec3(n01(rng), n01(rng), n01(rng)) * sd; };
  Eigen::Matrix<double, 9, 9> S = Eigen::Matrix<double, 9, 9>::Zero();
  std::vector<Eigen::Matrix<double, 9, 1>> errors;
  for (int r = 0; r < runs; ++r) {
    ImuPreintegration p(noise, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
    Vec3 bg = Vec3::Zero(), ba = Vec3::Zero();
    for (int k = 0; k < steps; ++k) {
      p.integrate(dt, w0 + bg + gauss(noise.gyro_noise_density / std::sqrt(dt)),
                  a0 + ba + gauss(noise.accel_noise_density / std::sqrt(dt)));
      bg += gauss(noise.gyro_bias_random_walk * std::sqrt(dt));
      ba += gauss(noise.accel_bias_random_walk * std::sqrt(dt));
    }
    Eigen::Matrix<double, 9, 1> e;
    e << p.deltaP() - nominal.deltaP(), logSO3(nominal.deltaR().transpose() * p.deltaR()),
        p.deltaV() - nominal.deltaV();
    S += e * e.transpose() / runs;
    errors.push_back(e);
  }
  const Eigen::Matrix<double, 9, 9> P = nominal.covariance().topLeftCorner<9, 9>();
  EXPECT_LT((P - P.transpose()).norm(), 1e-15);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 15, 15>> eig(nominal.covariance());
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
  for (int i = 0; i < 9; ++i) {
    // 2000 samples give a variance to about 3 % (1 sigma); allow 12 %.
    EXPECT_NEAR(S(i, i) / P(i, i), 1.0, 0.12) << "component " << i;
    // A correlation to about (1 - rho^2) / sqrt(2000) = 0.022 (1 sigma); allow 0.1.
    for (int j = 0; j < i; ++j) {
      EXPECT_NEAR(S(i, j) / std::sqrt(S(i, i) * S(j, j)), P(i, j) / std::sqrt(P(i, i) * P(j, j)),
                  0.1)
          << i << ", " << j;
    }
  }
  // The whole matrix: the mean NEES of the runs' errors is 9 (chi-square, 9 dof), to
  // sqrt(2 * 9 / 2000) = 0.095 (1 sigma); allow 0.5.
  const Eigen::LDLT<Eigen::Matrix<double, 9, 9>> ldlt(P);
  double nees = 0.0;
  for (const auto& e : errors) nees += e.dot(ldlt.solve(e)) / runs;
  EXPECT_NEAR(nees, 9.0, 0.5);
}

TEST(ImuPreintegration, GapsAreBridgedWithACovarianceThatCoversTheInterpolationError) {
  // A vehicle turning and accelerating within ground-robot bounds (ImuBridgeModel), sampled at
  // 100 Hz; 0.3, 0.6 and 1 s of samples removed at several phases of the motion. The bridged
  // preintegration's error against the full one stays within 3 sigma of its covariance, and the
  // covariance stays positive definite (one long step left it singular).
  ImuNoise noise;
  const double kPi = 3.14159265358979;
  auto sample = [&](double t) {
    ImuSample s;
    s.t = t;
    s.gyro = Vec3(0.02 * std::sin(t), 0.01, 0.5 * std::sin(2 * kPi * 0.2 * t));  // <= 0.63 rad/s^2
    s.acc = Vec3(0.3 * std::sin(2 * kPi * 0.3 * t), 0.1, 9.8);                   // <= 0.57 m/s^3
    return s;
  };
  for (double gap : {0.3, 0.6, 1.0}) {
    for (double start : {0.5, 1.3, 2.1, 2.9}) {
      SCOPED_TRACE("gap " + std::to_string(gap) + " s at " + std::to_string(start) + " s");
      std::vector<ImuSample> all, holed;
      for (int k = 0; k <= 500; ++k) {
        all.push_back(sample(0.01 * k));
        if (all.back().t <= start || all.back().t >= start + gap) holed.push_back(all.back());
      }
      ImuPreintegration full(noise, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
      ImuPreintegration bridged(noise, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
      full.integrateSamples(all, 0.0, 5.0);
      bridged.integrateSamples(holed, 0.0, 5.0);
      const Eigen::Matrix<double, 15, 15> P = bridged.covariance();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 15, 15>> eig(P);
      EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
      Eigen::Matrix<double, 9, 1> e;
      e << bridged.deltaP() - full.deltaP(), logSO3(full.deltaR().transpose() * bridged.deltaR()),
          bridged.deltaV() - full.deltaV();
      for (int i = 0; i < 9; ++i) {
        EXPECT_LT(std::abs(e[i]), 3.0 * std::sqrt(P(i, i))) << "component " << i;
      }
      // Not vacuous: the bridge adds far more than the IMU's own noise over the same time.
      ImuPreintegration sampled(noise, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
      sampled.integrateSamples(all, 0.0, 5.0);
      EXPECT_GT(P(5, 5), 10.0 * sampled.covariance()(5, 5));
    }
  }
}

TEST(ImuPreintegration, RejectsBadSteps) {
  Fixture f;
  ImuPreintegration pre(f.noise, f.frame.gravity_n(), f.frame.omega_ie_n(), Vec3::Zero(),
                        Vec3::Zero());
  EXPECT_THROW(pre.integrate(0.0, Vec3::Zero(), Vec3::Zero()), std::invalid_argument);
  EXPECT_THROW(pre.integrate(-0.01, Vec3::Zero(), Vec3::Zero()), std::invalid_argument);
  EXPECT_THROW(pre.integrate(0.01, Vec3(NAN, 0, 0), Vec3::Zero()), std::invalid_argument);
  EXPECT_THROW(
      pre.integrateSamples({{0.0, Vec3::Zero(), Vec3::Zero()}, {1.0, Vec3::Zero(), Vec3::Zero()}},
                           0.5, 2.0),
      std::invalid_argument);
}

}  // namespace
}  // namespace giocal
