// The preintegration's covariance and bias Jacobians advance in steps of
// ImuPreintegration::kCovarianceStep_s over the samples' mean rate and specific force: at 400 Hz
// they must equal those of a step per sample to the approximation's order, (rate * step)^2, far
// within what a filter could notice, and the deltas exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/imu/imu_preintegration.h"

namespace giocal {
namespace {

// A turning, accelerating vehicle's IMU at 400 Hz over 1 s (up to 0.8 rad/s, 3 m/s^2).
std::vector<ImuSample> vehicleAt400Hz() {
  std::vector<ImuSample> out;
  for (int k = 0; k <= 400; ++k) {
    const double t = 0.0025 * k;
    ImuSample s;
    s.t = t;
    s.gyro = Vec3(0.05 * std::sin(7.0 * t), 0.03 * std::cos(5.0 * t), 0.8 * std::sin(3.0 * t));
    s.acc = Vec3(3.0 * std::sin(4.0 * t), 1.0 * std::cos(6.0 * t), 9.8 + 0.5 * std::sin(9.0 * t));
    out.push_back(s);
  }
  return out;
}

TEST(ImuPreintegration, CovarianceInStepsEqualsOneStepPerSampleToTheStepsOrder) {
  ImuNoise noise;
  noise.gyro_noise_density = 0.005;
  noise.accel_noise_density = 0.05;
  const Vec3 b_a(0.02, -0.01, 0.03), b_g(0.001, -0.002, 0.0005);
  const std::vector<ImuSample> samples = vehicleAt400Hz();
  ImuPreintegration stepped(noise, Vec3::Zero(), Vec3::Zero(), b_a, b_g, GyroTilt(0.01, -0.02));
  stepped.integrateSamples(samples, 0.0, 1.0);
  // integrate() advances the covariance at every call: one step per sample.
  ImuPreintegration each(noise, Vec3::Zero(), Vec3::Zero(), b_a, b_g, GyroTilt(0.01, -0.02));
  for (size_t k = 0; k + 1 < samples.size(); ++k) {
    each.integrate(samples[k + 1].t - samples[k].t, 0.5 * (samples[k].gyro + samples[k + 1].gyro),
                   0.5 * (samples[k].acc + samples[k + 1].acc));
  }
  EXPECT_EQ(stepped.deltaP(), each.deltaP());
  EXPECT_EQ(stepped.deltaV(), each.deltaV());
  EXPECT_EQ(stepped.deltaR(), each.deltaR());
  // Every entry, in units of its own variances (correlations), and the diagonal, to the
  // approximation's order at the drive's largest rate, 0.8 rad/s: (0.8 rad/s * 20 ms)^2 = 2.6e-4
  // (measured at 20 ms: 1.24e-4 on a correlation).
  const double rate_step = 0.8 * ImuPreintegration::kCovarianceStep_s;
  const double order = rate_step * rate_step;
  const Eigen::Matrix<double, 15, 15>& A = stepped.covariance();
  const Eigen::Matrix<double, 15, 15>& B = each.covariance();
  for (int i = 0; i < 15; ++i) {
    EXPECT_NEAR(A(i, i) / B(i, i), 1.0, order) << i;
    for (int j = 0; j < 15; ++j)
      EXPECT_LT(std::abs(A(i, j) - B(i, j)), order * std::sqrt(B(i, i) * B(j, j))) << i << "," << j;
  }
  EXPECT_LT((stepped.biasJacobian() - each.biasJacobian()).norm(),
            order * each.biasJacobian().norm());
  EXPECT_LT((stepped.tiltJacobian() - each.tiltJacobian()).norm(),
            order * each.tiltJacobian().norm());
  // Not the same computation: the steps do differ (rounding would be ~1e-16).
  EXPECT_GT((A - B).norm(), 1e-12 * B.norm());
}

}  // namespace
}  // namespace giocal
