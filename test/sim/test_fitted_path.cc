// FittedPath: a ground vehicle's path fitted to antenna positions is kinematically exact (its
// velocity and acceleration are the derivatives of its position, the velocity along m's forward
// axis), runs through the positions, and leaves wrong fixes aside.
#include <gtest/gtest.h>

#include "common/geodesy/wgs84.h"
#include "common/math/so3.h"
#include "sim/fitted_path.h"
#include "sim/simulator.h"

namespace giocal::sim {
namespace {

TEST(FittedPath, IsExactKinematicsThroughTheFixesAndLeavesWrongFixesAside) {
  SimConfig cfg = readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  cfg.segments.resize(2 + 2 * 4);  // two laps, starting with 10 s standing
  const SimulatedLogs logs = simulate(cfg, 41);
  const LocalFrame frame(logs.antenna_e.front());
  const double t0 = logs.gnss.rover.front().t;
  std::vector<AntennaFix> fixes;
  std::vector<Eigen::Vector3d> truth;
  for (size_t k = 0; k < logs.antenna_e.size(); ++k) {
    const Eigen::Vector3d p = frame.enuFromEcef(logs.antenna_e[k]);
    truth.push_back(p);
    // Every 37th fix wrong by metres, with a centimetre's sigma (a wrong ambiguity fix).
    fixes.push_back({logs.gnss.rover[k].t - t0, k % 37 == 20 ? p + Eigen::Vector3d(3, -2, 1) : p,
                     Eigen::Vector3d::Constant(0.01)});
  }
  const Eigen::Matrix3d R_m_b = cfg.truth.q_b_m.toRotationMatrix().transpose();
  const FittedPath path(fixes, R_m_b * (cfg.p_b_g - cfg.truth.p_b_m), {});
  EXPECT_EQ(path.outliers(), static_cast<int>((fixes.size() + 16) / 37));
  double worst = 0.0;
  for (size_t k = 0; k < fixes.size(); ++k) {
    worst = std::max(worst, (path.antennaAt(fixes[k].t) - truth[k]).norm());
  }
  EXPECT_LT(worst, 0.02);  // the true antenna, wrong fixes or not
  EXPECT_LT(path.medianMiss(), 0.002);

  // Velocity and acceleration are the position's derivatives; no lateral or vertical velocity
  // in m, no roll; the angular rate is R_n_m's.
  const double h = 1e-3;
  for (double t = 1.0; t < path.duration() - 1.0; t += 7.3) {
    const VehicleKinematics m = path.at(t), a = path.at(t - h), b = path.at(t + h);
    EXPECT_LT((m.v_n_m - (b.p_n_m - a.p_n_m) / (2 * h)).norm(), 1e-6) << t;
    EXPECT_LT((m.a_n_m - (b.v_n_m - a.v_n_m) / (2 * h)).norm(), 1e-4) << t;
    const Eigen::Vector3d v_m = m.R_n_m.transpose() * m.v_n_m;
    EXPECT_LT(std::abs(v_m.x()) + std::abs(v_m.z()), 1e-12) << t;
    EXPECT_NEAR(v_m.y(), m.speed, 1e-12) << t;
    EXPECT_LT(std::abs((m.R_n_m * Eigen::Vector3d::UnitX()).z()), 1e-12) << t;  // no roll
    const Eigen::Vector3d w = logSO3(a.R_n_m.transpose() * b.R_n_m) / (2 * h);
    EXPECT_LT((m.w_m - w).norm(), 1e-5) << t;
  }
  // Standing at the start: no speed.
  EXPECT_LT(std::abs(path.at(5.0).speed), 0.01);
}

TEST(FittedPath, RefusesWhatItCannotFit) {
  std::vector<AntennaFix> few(5);
  for (size_t k = 0; k < few.size(); ++k) few[k].t = static_cast<double>(k);
  EXPECT_THROW(FittedPath(few, Eigen::Vector3d::Zero()), std::invalid_argument);
  std::vector<AntennaFix> gap(20);
  for (size_t k = 0; k < gap.size(); ++k) gap[k].t = static_cast<double>(k) + (k > 10 ? 60.0 : 0.0);
  try {
    FittedPath path(gap, Eigen::Vector3d::Zero());
    ADD_FAILURE() << "expected a refusal";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("a gap of 61"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace giocal::sim
