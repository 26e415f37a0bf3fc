#include <gtest/gtest.h>

#include "common/imu/static_alignment.h"
#include "common/math/rotation.h"
#include "sim/simulator.h"

namespace giocal {
namespace {

TEST(StaticAlignment, RecoversTiltAndGyroBiasOfTheSimulatedPaperPreset) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  cfg.gnss.enabled = false;
  for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    const sim::SimulatedLogs logs = sim::simulate(cfg, seed);
    // The paper preset stands still for the first 18 s: align on 15 s of it.
    std::vector<ImuSample> window(logs.imu.begin(), logs.imu.begin() + 1501);
    const NavState& truth = logs.truth_n.front();
    const Vec3 rpy = rpyFromRotation(truth.q_n_b.toRotationMatrix());
    const StaticAlignment a = alignStatic(window, rpy.z(), logs.frame.omega_ie_n(),
                                          logs.description.imu_noise.gyro_noise_density,
                                          logs.description.imu_noise.accel_noise_density);
    // Errors within four of the reported sigmas (plus the accelerometer bias for the tilt).
    const double tilt_bias = 5e-5 / 9.8;  // 5 mGal turn-on bias
    EXPECT_LT(std::abs(a.roll - rpy.x()), 4 * a.sd_tilt + 4 * tilt_bias) << "seed " << seed;
    EXPECT_LT(std::abs(a.pitch - rpy.y()), 4 * a.sd_tilt + 4 * tilt_bias) << "seed " << seed;
    for (int i = 0; i < 3; ++i) {
      EXPECT_LT(std::abs(a.b_g[i] - truth.b_g[i]), 4 * a.sd_b_g[i])
          << "seed " << seed << " axis " << i;
    }
    EXPECT_LT(a.q_n_b.angularDistance(truth.q_n_b), 0.01);
  }
  EXPECT_THROW(alignStatic({}, 0, Vec3::Zero(), 0, 0), std::invalid_argument);
}

TEST(StaticAlignment, GyroBiasPriorCombinesByInverseVariance) {
  StaticAlignment a;
  a.b_g = Vec3(0.01, -0.02, 0.03);
  a.sd_b_g = Vec3(0.001, 0.002, 0.004);
  const StaticAlignment f = withGyroBiasPrior(a, 0.002);
  for (int i = 0; i < 3; ++i) {
    const double wp = 1.0 / (0.002 * 0.002), ws = 1.0 / (a.sd_b_g[i] * a.sd_b_g[i]);
    EXPECT_NEAR(f.b_g[i], a.b_g[i] * ws / (ws + wp), 1e-15) << i;
    EXPECT_NEAR(f.sd_b_g[i], 1.0 / std::sqrt(ws + wp), 1e-15) << i;
    EXPECT_LT(f.sd_b_g[i], std::min(a.sd_b_g[i], 0.002)) << i;
  }
  // Equal sigmas: halfway to the prior's zero mean, sigma / sqrt(2).
  EXPECT_NEAR(f.b_g[1], -0.01, 1e-15);
  EXPECT_NEAR(f.sd_b_g[1], 0.002 / std::sqrt(2.0), 1e-15);
  // No prior: unchanged.
  const StaticAlignment u = withGyroBiasPrior(a, 0.0);
  EXPECT_EQ(u.b_g, a.b_g);
  EXPECT_EQ(u.sd_b_g, a.sd_b_g);
}

}  // namespace
}  // namespace giocal
