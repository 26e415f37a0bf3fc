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

}  // namespace
}  // namespace giocal
