// An IMU mounted on its side (gravity on its y axis, as on the real Husky bag): the lever arm
// planar motion cannot see is then p_b_m.y, not p_b_m.z. Both estimators hold that component at
// the guess and calibrate the other two, which they cannot do when b's z (here the vehicle's
// forward axis) is the one held; `observability` names that component.
#include <gtest/gtest.h>

#include "calibration_checks.h"
#include "common/calibration/calibration_inputs.h"
#include "common/calibration/weak_directions.h"
#include "common/io/sensor_logs.h"
#include "common/math/rotation.h"
#include "evaluation/observability.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

TEST(ImuOnItsSide, TheVerticalLeverArmIsTheOneHeld) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  // The preset's mounting turned a quarter turn about the vehicle's right axis.
  cfg.truth.q_b_m =
      Eigen::Quaterniond(rotationFromRpy(Eigen::Vector3d(-88.5, -2.0, 3.0) * kDegToRad));
  test::TempDir dir;
  sim::writeDataset(sim::simulate(cfg, 4501), dir.path() + "/data");
  const CalibrationInputs in = loadCalibrationInputs(dir.path() + "/data");
  const CalibrationPrior& prior = in.description.initial_calibration;
  ASSERT_EQ(verticalLeverState(prior), calib_index::kP + 1);
  for (const std::string est : {"ekf", "fgo"}) {
    SCOPED_TRACE(est);
    const CalibrationRun run = replayInputs(in, {est, CalibrationOptions{}, {}}, nullptr);
    ASSERT_TRUE(run.latest);
    EXPECT_EQ(run.final().calib.p_b_m.y(), prior.mean.p_b_m.y());  // held
    EXPECT_NEAR(run.final().sigma()[calib_index::kP + 1], prior.sd_p_b_m.y(), 1e-9);
    // Forward and lateral lever arm, scales and mounting: within 4 sigma, sigma informed.
    test::expectWithinSigmaAndInformed(run.final(), in);
  }
  ObservabilityJob job;
  job.linearize_at = in.truth->calib;
  job.reference = ReferenceTrajectory(readTruthCsv(in.description.pathOf(in.description.truth)));
  CalibrationInputs with_fixes = in;  // antenna positions of 1 cm along the truth, as GNSS
  std::vector<double> times;
  for (const ObsEpoch& e : in.rover.epochs) times.push_back(e.t);
  with_fixes.positions = antennaPositionsAlong(*job.reference, in.truth->p_b_g, times, 0.01);
  const ObservabilityReport r = analyzeObservability(with_fixes, job);
  EXPECT_EQ(r.vertical_state, calib_index::kP + 1);
  EXPECT_FALSE(r.p_b_m_z_observable);
  bool named = false;
  for (const std::string& a : r.advice)
    named = named || a.rfind("p_b_m.y (along the vehicle", 0) == 0;
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace giocal
