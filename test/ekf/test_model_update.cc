#include <gtest/gtest.h>

#include <random>

#include "common/math/rotation.h"
#include "common/models/odometer_velocity_model.h"
#include "ekf/model_update.h"

namespace giocal {
namespace {

TEST(ModelUpdate, OdometerSamplesCalibrateTheSpeedScale) {
  // A vehicle driving straight at 1.2 m/s with a well-known velocity; the odometer reads
  // 1.2 / (1 + 0.03). Repeated updates pull s_v from 0 to 0.03 and its sigma shrinks.
  StateRegistry s;
  Eigen::VectorXd q(4);
  quatToWxyz(Quat::Identity(), q.data());
  s.add(vectorBlock("v_n_b"), Eigen::Vector3d(0, 1.2, 0), Eigen::Matrix3d::Identity() * 1e-6);
  s.add(rotationBlock("q_n_b"), q, Eigen::Matrix3d::Identity() * 1e-8);
  s.add(vectorBlock("b_g"), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity() * 1e-10);
  s.add(vectorBlock("s_v", 1), Eigen::VectorXd::Zero(1),
        Eigen::MatrixXd::Constant(1, 1, 0.05 * 0.05));
  s.add(vectorBlock("s_w", 1), Eigen::VectorXd::Zero(1),
        Eigen::MatrixXd::Constant(1, 1, 0.05 * 0.05));
  s.add(vectorBlock("p_b_m"), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity() * 1e-10);
  s.add(rotationBlock("q_b_m"), q, Eigen::Matrix3d::Identity() * 1e-10);
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0.0, 0.01);
  const std::vector<std::string> names{"v_n_b", "q_n_b", "b_g", "s_v", "s_w", "p_b_m", "q_b_m"};
  int accepted = 0;
  for (int k = 0; k < 200; ++k) {
    // Keep the velocity known (a stand-in for GNSS) so that the scale is what is learned.
    s.value("v_n_b") = Eigen::Vector3d(0, 1.2, 0);
    const OdometerVelocityModel odo(OdomSample{k * 0.04, 1.2 / 1.03 + noise(rng), 0.0},
                                    Eigen::Vector3d::Zero(), 0.01, 0.01);
    accepted += updateWithModel(s, odo, names, 16.0).accepted;
  }
  EXPECT_GE(accepted, 195);
  EXPECT_NEAR(s.value("s_v")[0], 0.03, 3 * std::sqrt(s.marginal("s_v")(0, 0)) + 1e-3);
  EXPECT_LT(std::sqrt(s.marginal("s_v")(0, 0)), 0.002);
  // A wild sample is gated out and leaves the state alone.
  const double before = s.value("s_v")[0];
  const OdometerVelocityModel wild(OdomSample{9.0, 5.0, 0.0}, Eigen::Vector3d::Zero(), 0.01, 0.01);
  EXPECT_FALSE(updateWithModel(s, wild, names, 16.0).accepted);
  EXPECT_EQ(s.value("s_v")[0], before);
}

}  // namespace
}  // namespace giocal
