#include <gtest/gtest.h>

#include <random>

#include "common/math/rotation.h"
#include "common/models/odometer_preintegration_model.h"
#include "common/odometer/odometer_preintegration.h"
#include "common/odometer/vehicle_velocity.h"
#include "numeric_jacobian.h"

namespace giocal {
namespace {

Vec3 randomVec(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

OdometerCalibration randomCalibration(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  OdometerCalibration c;
  c.s_v = u(rng);
  c.s_w = u(rng);
  c.p_b_m = randomVec(rng, 0.5);
  c.q_b_m = Quat(expSO3(randomVec(rng, 0.2)));
  return c;
}

// A planar vehicle path: heading psi(t) and speed V(t), integrated finely; poses of m and of b.
struct PlanarPath {
  std::function<double(double)> speed, yaw_rate;
  double psi0 = 0.4;
  Vec3 p0{3.0, -2.0, 0.5};
  Mat3 R_n_m(double psi) const { return expSO3(Vec3(0, 0, psi)); }
  // Returns (psi, p_n_m) at each time in `times` (ascending, starting at 0).
  std::vector<std::pair<double, Vec3>> poses(const std::vector<double>& times) const {
    std::vector<std::pair<double, Vec3>> out;
    double psi = psi0, t = 0.0;
    Vec3 p = p0;
    const double h = 1e-4;
    for (double target : times) {
      while (t < target - 1e-12) {
        const double step = std::min(h, target - t);
        // Midpoint rule in time on the heading and speed.
        const double tm = t + step / 2;
        const double psim = psi + yaw_rate(t) * step / 2;
        p += R_n_m(psim) * Vec3(0, speed(tm), 0) * step;
        psi += yaw_rate(tm) * step;
        t += step;
      }
      out.emplace_back(psi, p);
    }
    return out;
  }
};

TEST(VehicleVelocity, JacobiansMatchNumericDifferentiation) {
  std::mt19937 rng(21);
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 v = randomVec(rng, 2.0), gyro = randomVec(rng, 1.0), bg = randomVec(rng, 0.01);
    const Quat q(expSO3(randomVec(rng, 3.0)));
    const OdometerCalibration c = randomCalibration(rng);
    const VehicleVelocity vv = vehicleVelocity(v, q, gyro, bg, c.p_b_m, c.q_b_m);
    auto fv = [&](int block) {
      return [&, block](const Eigen::VectorXd& d) -> Eigen::VectorXd {
        Vec3 v2 = v, bg2 = bg, p2 = c.p_b_m;
        Quat q2 = q, qbm2 = c.q_b_m;
        if (block == 0) v2 += Vec3(d);
        if (block == 1) q2 = boxPlus(q, Vec3(d));
        if (block == 2) bg2 += Vec3(d);
        if (block == 3) p2 += Vec3(d);
        if (block == 4) qbm2 = boxPlus(c.q_b_m, Vec3(d));
        const VehicleVelocity o = vehicleVelocity(v2, q2, gyro, bg2, p2, qbm2);
        Eigen::VectorXd r(6);
        r << o.v_m, o.w_m;
        return r;
      };
    };
    const Eigen::Matrix3d Z = Eigen::Matrix3d::Zero();
    const std::vector<std::pair<Eigen::Matrix3d, Eigen::Matrix3d>> J{{vv.dv_dv_n, Z},
                                                                     {vv.dv_dq_n_b, Z},
                                                                     {vv.dv_dbg, vv.dw_dbg},
                                                                     {vv.dv_dp_b_m, Z},
                                                                     {vv.dv_dq_b_m, vv.dw_dq_b_m}};
    for (int b = 0; b < 5; ++b) {
      Eigen::MatrixXd analytic(6, 3);
      analytic << J[b].first, J[b].second;
      EXPECT_LT(test::relativeDifference(analytic, test::numericJacobian(fv(b), 3)), 1e-7)
          << "block " << b;
    }
  }
}

TEST(VehicleVelocity, RigidBodyKinematics) {
  // A vehicle driving forward at 1 m/s and turning at 0.5 rad/s, IMU mounted rotated and offset:
  // the IMU velocity predicted from the true vehicle motion maps back onto (0, 1, 0).
  const Mat3 R_b_m = rotationFromRpy(Vec3(0.05, -0.03, 1.2));
  const Vec3 p_b_m(0.3, -0.1, 0.2);
  const Vec3 w_m(0, 0, 0.5), v_m(0, 1.0, 0);
  const Vec3 w_b = R_b_m * w_m;
  const Vec3 v_b = R_b_m * v_m - w_b.cross(p_b_m);  // the brief's v_b = R_b_m v_m - w_b x p_b_m
  const Quat q_n_b(rotationFromRpy(Vec3(0.01, 0.02, -0.7)));
  const VehicleVelocity vv =
      vehicleVelocity(q_n_b * v_b, q_n_b, w_b, Vec3::Zero(), p_b_m, Quat(R_b_m));
  EXPECT_LT((vv.v_m - v_m).norm(), 1e-14);
  EXPECT_LT((vv.w_m - w_m).norm(), 1e-14);
}

TEST(OdometerPreintegration, JacobiansMatchNumericDifferentiation) {
  std::mt19937 rng(22);
  OdometerPreintegrationNoise noise;
  for (int trial = 0; trial < 20; ++trial) {
    OdometerPreintegration pre(noise, 0.01, -0.02);
    for (int k = 0; k < 50; ++k)
      pre.integrate(0.02, 1.0 + randomVec(rng, 0.5).x(), randomVec(rng, 0.8).x());
    const Vec3 p_i = randomVec(rng, 10), p_j = randomVec(rng, 10);
    const Quat q_i(expSO3(randomVec(rng, 3))), q_j(expSO3(randomVec(rng, 3)));
    const OdometerCalibration c = randomCalibration(rng);
    const OdometerResidual res = pre.evaluate(p_i, q_i, p_j, q_j, c);
    auto eval = [&](int block, const Eigen::VectorXd& d) -> Eigen::VectorXd {
      Vec3 pi = p_i, pj = p_j;
      Quat qi = q_i, qj = q_j;
      OdometerCalibration cc = c;
      switch (block) {
        case 0:
          pi += Vec3(d);
          break;
        case 1:
          qi = boxPlus(q_i, Vec3(d));
          break;
        case 2:
          pj += Vec3(d);
          break;
        case 3:
          qj = boxPlus(q_j, Vec3(d));
          break;
        case 4:
          cc.p_b_m += Vec3(d);
          break;
        case 5:
          cc.q_b_m = boxPlus(c.q_b_m, Vec3(d));
          break;
        case 6:
          cc.s_v += d[0];
          break;
        case 7:
          cc.s_w += d[0];
          break;
      }
      return pre.evaluate(pi, qi, pj, qj, cc).r;
    };
    const std::vector<Eigen::MatrixXd> analytic{res.J_p_i,   res.J_q_i,   res.J_p_j, res.J_q_j,
                                                res.J_p_b_m, res.J_q_b_m, res.J_s_v, res.J_s_w};
    for (int b = 0; b < 8; ++b) {
      const int n = b < 6 ? 3 : 1;
      const auto num =
          test::numericJacobian([&](const Eigen::VectorXd& d) { return eval(b, d); }, n);
      EXPECT_LT(test::relativeDifference(analytic[b], num), 1e-6) << "block " << b;
    }
  }
}

struct PathCase {
  PlanarPath path;
  OdometerCalibration truth;
  std::vector<OdomSample> samples;
  std::vector<std::pair<double, Vec3>> poses;  // at t = 0 and t = T
  double T = 3.0;
};

PathCase makeCase(std::function<double(double)> speed, std::function<double(double)> yaw_rate) {
  PathCase c;
  c.path.speed = std::move(speed);
  c.path.yaw_rate = std::move(yaw_rate);
  c.truth.s_v = 0.02;
  c.truth.s_w = -0.03;
  c.truth.p_b_m = {0.25, -0.15, 0.3};
  c.truth.q_b_m = Quat(rotationFromRpy(Vec3(2.0, -1.5, 4.0) * kDegToRad));
  const double dt = 0.02;  // 50 Hz instantaneous readings, the last one at T
  for (double t = 0.0; t < c.T + 1e-9; t += dt) {
    c.samples.push_back(
        {t, c.path.speed(t) / (1 + c.truth.s_v), c.path.yaw_rate(t) / (1 + c.truth.s_w)});
  }
  c.poses = c.path.poses({0.0, c.T});
  return c;
}

// IMU poses from vehicle poses: T_n_b = T_n_m * T_m_b.
std::pair<Vec3, Quat> imuPose(const PlanarPath& path, double psi, const Vec3& p_n_m,
                              const OdometerCalibration& c) {
  const Mat3 R_n_b = path.R_n_m(psi) * c.q_b_m.toRotationMatrix().transpose();
  return {p_n_m - R_n_b * c.p_b_m, Quat(R_n_b)};
}

TEST(OdometerPreintegration, KnownCircleWithExtrinsicAndScalesIsExact) {
  PathCase pc = makeCase([](double) { return 1.5; }, [](double) { return 0.4; });
  OdometerPreintegration pre({}, pc.truth.s_v, pc.truth.s_w);
  pre.integrateSamples(pc.samples, 0.0, pc.T);
  const auto [p_i, q_i] = imuPose(pc.path, pc.poses[0].first, pc.poses[0].second, pc.truth);
  const auto [p_j, q_j] = imuPose(pc.path, pc.poses[1].first, pc.poses[1].second, pc.truth);
  const OdometerResidual r = pre.evaluate(p_i, q_i, p_j, q_j, pc.truth);
  EXPECT_LT(r.r.head<3>().norm(), 1e-6);  // limited only by the reference path's integration
  EXPECT_LT(r.r.tail<3>().norm(), 1e-10);
  // The paper's (dp, dq) in b equal the true relative IMU pose.
  EXPECT_LT((pre.deltaP_b(pc.truth) - q_i.conjugate() * (p_j - p_i)).norm(), 1e-6);
  EXPECT_LT(logSO3(pre.deltaR_b(pc.truth).transpose() * (q_i.conjugate() * q_j).toRotationMatrix())
                .norm(),
            1e-10);
}

TEST(OdometerPreintegration, KnownVaryingPathAndRelinearizedScales) {
  PathCase pc = makeCase([](double t) { return 0.5 + 0.8 * t - 0.1 * t * t; },
                         [](double t) { return 0.6 * std::sin(1.3 * t); });
  const auto [p_i, q_i] = imuPose(pc.path, pc.poses[0].first, pc.poses[0].second, pc.truth);
  const auto [p_j, q_j] = imuPose(pc.path, pc.poses[1].first, pc.poses[1].second, pc.truth);
  OdometerPreintegration exact({}, pc.truth.s_v, pc.truth.s_w);
  exact.integrateSamples(pc.samples, 0.0, pc.T);
  const OdometerResidual r = exact.evaluate(p_i, q_i, p_j, q_j, pc.truth);
  // 50 Hz samples of a smoothly varying path, integrated by the trapezoidal rule: its error
  // (T dt^2 / 12 times the second derivative) keeps both sub-millimetre and below 1e-4 rad over
  // 3 s (about 3 m).
  EXPECT_LT(r.r.head<3>().norm(), 1e-3);
  EXPECT_LT(r.r.tail<3>().norm(), 1e-4);
  // Integrated at scales of zero, then evaluated at the true scales through the first-order
  // Jacobian: no re-integration, and the residual stays at the millimetre level...
  OdometerPreintegration lin0({}, 0.0, 0.0);
  lin0.integrateSamples(pc.samples, 0.0, pc.T);
  const OdometerResidual r0 = lin0.evaluate(p_i, q_i, p_j, q_j, pc.truth);
  EXPECT_LT(r0.r.head<3>().norm(), 2e-3);
  EXPECT_LT(r0.r.tail<3>().norm(), 1e-4);
  // ...whereas ignoring the scales leaves centimetres.
  OdometerCalibration no_scale = pc.truth;
  no_scale.s_v = no_scale.s_w = 0.0;
  EXPECT_GT(lin0.evaluate(p_i, q_i, p_j, q_j, no_scale).r.head<3>().norm(), 3e-2);
}

// Stamps late by d: the samples over the stamps [0.5, 2.5] s measure the motion over
// [0.5 - d, 2.5 - d] s. The model with that delay, fed the IMU's velocity and rate at 0.5 and
// 2.5 s, leaves only its first-order error, of order d^2 (quadrupling when d doubles), where
// ignoring the delay leaves an error of order d (doubling).
TEST(OdometerPreintegrationModel, ADelayOfTheStampsIsTakenOutToFirstOrder) {
  struct Left {
    double with_delay, ignored;
  };
  const auto leftAt = [](double delay) {
    PathCase pc = makeCase([](double t) { return 0.5 + 0.8 * t - 0.1 * t * t; },
                           [](double t) { return 0.6 * std::sin(1.3 * t); });
    for (OdomSample& s : pc.samples) s.t += delay;
    auto pre = std::make_shared<OdometerPreintegration>(OdometerPreintegrationNoise{}, pc.truth.s_v,
                                                        pc.truth.s_w);
    pre->integrateSamples(pc.samples, 0.5, 2.5);
    std::vector<Eigen::VectorXd> values;
    PoseRates rates;
    for (double t : {0.5, 2.5}) {
      const double h = 1e-3;
      const auto poses = pc.path.poses({t - h, t, t + h});
      const auto before = imuPose(pc.path, poses[0].first, poses[0].second, pc.truth);
      const auto [p, q] = imuPose(pc.path, poses[1].first, poses[1].second, pc.truth);
      const auto after = imuPose(pc.path, poses[2].first, poses[2].second, pc.truth);
      const Vec3 v = (after.first - before.first) / (2 * h);
      const Vec3 w = pc.truth.q_b_m * Vec3(0, 0, pc.path.yaw_rate(t));
      (t < 1.0 ? rates.v_n_i : rates.v_n_j) = v;
      (t < 1.0 ? rates.w_b_i : rates.w_b_j) = w;
      Eigen::VectorXd qv(4);
      quatToWxyz(q, qv.data());
      values.push_back(p);
      values.push_back(qv);
    }
    Eigen::VectorXd q_bm(4);
    quatToWxyz(pc.truth.q_b_m, q_bm.data());
    values.push_back(Eigen::VectorXd::Constant(1, pc.truth.s_v));
    values.push_back(Eigen::VectorXd::Constant(1, pc.truth.s_w));
    values.push_back(pc.truth.p_b_m);
    values.push_back(q_bm);
    values.push_back(Eigen::VectorXd::Constant(1, delay));
    const OdometerPreintegrationModel model(pre, false, rates);
    std::vector<const double*> params;
    for (const Eigen::VectorXd& x : values) params.push_back(x.data());
    Left out{};
    Eigen::VectorXd r;
    model.evaluate(params.data(), r, nullptr);
    out.with_delay = r.norm();
    values.back()[0] = 0.0;
    model.evaluate(params.data(), r, nullptr);
    out.ignored = r.norm();
    return out;
  };
  const Left a = leftAt(0.03), b = leftAt(0.06);
  EXPECT_GT(a.ignored, 10.0 * a.with_delay);
  EXPECT_NEAR(b.with_delay / a.with_delay, 4.0, 1.0);  // second order
  EXPECT_NEAR(b.ignored / a.ignored, 2.0, 0.3);        // first order
}

TEST(OdometerPreintegration, CovarianceMatchesMonteCarlo) {
  OdometerPreintegrationNoise noise;
  noise.speed_sigma = 0.05;
  noise.yaw_rate_sigma = 0.05;
  noise.lateral_speed_density = 0.02;
  noise.tilt_rate_density = 0.01;
  const double dt = 0.02, v = 1.2, w = 0.3;
  const int steps = 100, runs = 3000;
  OdometerPreintegration nominal(noise, 0.0, 0.0);
  for (int k = 0; k < steps; ++k) nominal.integrate(dt, v, w);
  // The out-of-plane noise is injected as the same white inputs the model assumes.
  std::mt19937 rng(9);
  std::normal_distribution<double> n01;
  Eigen::Matrix<double, 6, 6> S = Eigen::Matrix<double, 6, 6>::Zero();
  for (int r = 0; r < runs; ++r) {
    Mat3 R = Mat3::Identity();
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < steps; ++k) {
      const Vec3 vel(noise.lateral_speed_density / std::sqrt(dt) * n01(rng),
                     v + noise.speed_sigma * n01(rng),
                     noise.lateral_speed_density / std::sqrt(dt) * n01(rng));
      const Vec3 rate(noise.tilt_rate_density / std::sqrt(dt) * n01(rng),
                      noise.tilt_rate_density / std::sqrt(dt) * n01(rng),
                      w + noise.yaw_rate_sigma * n01(rng));
      p += R * vel * dt;
      R = R * expSO3(rate * dt);
    }
    Eigen::Matrix<double, 6, 1> e;
    const Mat3 R_nom = expSO3(Vec3(0, 0, nominal.yaw(0.0)));
    e << p - nominal.deltaP_m(0.0, 0.0), logSO3(R_nom.transpose() * R);
    S += e * e.transpose() / runs;
  }
  const Eigen::Matrix<double, 6, 6> P = nominal.covariance();
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(S(i, i) / P(i, i), 1.0, 0.12) << "component " << i;
  }
  // The planar coupling (heading error moves the position) is captured too.
  EXPECT_NEAR(S(0, 5) / P(0, 5), 1.0, 0.15);
}

TEST(OdometerPreintegration, RejectsBadInput) {
  OdometerPreintegration pre({}, 0, 0);
  EXPECT_THROW(pre.integrate(0.0, 1, 0), std::invalid_argument);
  EXPECT_THROW(pre.integrate(0.02, NAN, 0), std::invalid_argument);
  EXPECT_THROW(pre.integrateSamples({{1.0, 1.0, 0.0}}, 0.0, 2.0), std::invalid_argument);
}

TEST(OdometerPreintegration, TheLongestGapCountsWhatTheIntegrationBridges) {
  // 10 Hz with a hole: the samples at 1.95 and 4.05 s bracket it, 2.1 s apart.
  std::vector<OdomSample> s;
  for (double t = 0.05; t < 6.0; t += 0.1)
    if (t < 2.0 || t > 4.0) s.push_back({t, 1.0, 0.0});
  EXPECT_NEAR(longestOdometerGap(s, 0.0, 1.0), 0.1, 1e-9);
  EXPECT_NEAR(longestOdometerGap(s, 3.0, 3.5), 2.1, 1e-9);  // inside the hole
  EXPECT_NEAR(longestOdometerGap(s, 1.5, 2.5), 2.1, 1e-9);  // the hole begins inside
  EXPECT_NEAR(longestOdometerGap(s, 3.5, 4.5), 2.1, 1e-9);  // the hole ends inside
  EXPECT_NEAR(longestOdometerGap(s, 4.5, 5.5), 0.1, 1e-9);
  // After the last sample its reading is held up to t1.
  EXPECT_NEAR(longestOdometerGap(s, 5.5, 7.0), 7.0 - s.back().t, 1e-9);
}

TEST(OdometerPreintegration, OnlyATurnBeyondItsNoiseInformsTheLeverArm) {
  // The lever-arm term (R_bi_bj - I) p_b_m needs a turn of the states; within its noise the model
  // leaves p_b_m's Jacobian out (docs/design.md, "A straight says nothing of the lever arm").
  const Vec3 up(0, 0, 1);
  EXPECT_FALSE(turnBeyondNoise(Vec3(0, 0, 5.9), up, 1.0, 1.0, 6.0));
  EXPECT_TRUE(turnBeyondNoise(Vec3(0, 0, -6.1), up, 1.0, 1.0, 6.0));
  EXPECT_FALSE(turnBeyondNoise(Vec3(3, 0, -4), up, 1.0, 1.0, 6.0));   // 5 sigma over the axes
  EXPECT_TRUE(turnBeyondNoise(Vec3(0, 0.7, 0), up, 10.0, 0.1, 6.0));  // a hill's pitch turns too
  EXPECT_FALSE(turnBeyondNoise(Vec3(0.7, 0, 0), Vec3(1, 0, 0), 1.0, 0.1, 6.0));  // up is b's x
  EXPECT_TRUE(turnBeyondNoise(Vec3(0, 0, 1e-9), up, 1.0, 1.0, 0.0));             // 0: always

  // Through the model, with the paper preset's gyro (20 deg/sqrt(h)) and odometer (1 deg/s at
  // 50 Hz here): the states' yaw over 1 s has sigma 1 / sqrt(1 / 0.0058^2 + 1 / odo^2).
  OdometerPreintegrationNoise noise;
  noise.gyro_noise_density = 0.0058;
  noise.lever_arm_min_turn = 6.0;
  const double odo = noise.yaw_rate_sigma * 0.02 * std::sqrt(50.0);
  const double sigma = 1.0 / std::sqrt(1.0 / (0.0058 * 0.0058) + 1.0 / (odo * odo));
  const double p_i[3] = {0, 0, 0}, q_i[4] = {1, 0, 0, 0}, p_j[3] = {0.1, 1.0, 0};
  const double s_v = 0.0, s_w = 0.0, p_b_m[3] = {0.3, -0.2, 0.1}, q_b_m[4] = {1, 0, 0, 0};
  for (const double yaw : {5.0 * sigma, 7.0 * sigma}) {
    auto pre = std::make_shared<OdometerPreintegration>(noise, 0.0, 0.0);
    for (int k = 0; k < 50; ++k) pre->integrate(0.02, 1.0, yaw);
    EXPECT_NEAR(std::sqrt(pre->covariance()(5, 5)), odo, 1e-9);
    const Quat q_j(expSO3(Vec3(0, 0, yaw)));
    const double q_j_wxyz[4] = {q_j.w(), q_j.x(), q_j.y(), q_j.z()};
    const double* params[8] = {p_i, q_i, p_j, q_j_wxyz, &s_v, &s_w, p_b_m, q_b_m};
    Eigen::VectorXd r;
    std::vector<Eigen::MatrixXd> J;
    OdometerPreintegrationModel(pre).evaluate(params, r, &J);
    EXPECT_EQ(J[6].norm() > 0.0, yaw > 6.0 * sigma) << yaw / sigma << " sigma";
    // The preintegration's own Jacobian stays the exact one.
    EXPECT_GT(
        pre->evaluate(Vec3::Zero(), Quat::Identity(), Vec3(0.1, 1, 0), q_j, OdometerCalibration{})
            .J_p_b_m.norm(),
        0.0);
  }
}

}  // namespace
}  // namespace giocal
