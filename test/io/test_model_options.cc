#include <gtest/gtest.h>

#include "common/calibration/calibration_options.h"
#include "common/gnss/rtk_config.h"
#include "common/gnss/tdcp_track.h"
#include "common/io/data_error.h"
#include "common/io/model_options.h"
#include "options/fgo_options.h"
#include "temp_dir.h"

namespace giocal {
namespace {

TEST(ModelOptions, ShippedConfigEqualsTheDefaults) {
  const ModelOptions shipped =
      readModelOptions(std::string(GIOCAL_SOURCE_DIR) + "/config/giocal.yaml");
  const ModelOptions defaults;
  EXPECT_DOUBLE_EQ(shipped.motion.window_s, defaults.motion.window_s);
  EXPECT_NEAR(shipped.motion.zupt_max_gyro, defaults.motion.zupt_max_gyro, 1e-15);
  EXPECT_NEAR(shipped.motion.nhc_max_gyro, defaults.motion.nhc_max_gyro, 1e-15);
  EXPECT_DOUBLE_EQ(shipped.motion.zupt_max_speed, defaults.motion.zupt_max_speed);
  EXPECT_DOUBLE_EQ(shipped.motion.nhc_min_speed, defaults.motion.nhc_min_speed);
  EXPECT_DOUBLE_EQ(shipped.zupt_sigma, defaults.zupt_sigma);
  EXPECT_DOUBLE_EQ(shipped.nhc_sigma, defaults.nhc_sigma);
  EXPECT_DOUBLE_EQ(shipped.lateral_speed_density, defaults.lateral_speed_density);
  EXPECT_DOUBLE_EQ(shipped.tilt_rate_density, defaults.tilt_rate_density);
}

TEST(RtkOptions, ShippedConfigEqualsTheDefaults) {
  const RtkOptions shipped = readRtkOptions(std::string(GIOCAL_SOURCE_DIR) + "/config/giocal.yaml");
  const RtkOptions d;
  EXPECT_DOUBLE_EQ(shipped.dd.elevation_mask_deg, d.dd.elevation_mask_deg);
  EXPECT_EQ(shipped.dd.frequencies, d.dd.frequencies);
  EXPECT_EQ(shipped.dd.systems, d.dd.systems);
  EXPECT_DOUBLE_EQ(shipped.dd.code.sigma_zenith, d.dd.code.sigma_zenith);
  EXPECT_DOUBLE_EQ(shipped.dd.phase.sigma_zenith, d.dd.phase.sigma_zenith);
  EXPECT_DOUBLE_EQ(shipped.accel_noise, d.accel_noise);
  EXPECT_DOUBLE_EQ(shipped.ambiguity_noise, d.ambiguity_noise);
  EXPECT_DOUBLE_EQ(shipped.innovation_gate, d.innovation_gate);
  EXPECT_DOUBLE_EQ(shipped.lambda.ratio_threshold, d.lambda.ratio_threshold);
  EXPECT_EQ(shipped.lambda.min_fixed, d.lambda.min_fixed);
  EXPECT_EQ(shipped.fix_and_hold, d.fix_and_hold);
  EXPECT_DOUBLE_EQ(shipped.hold_sigma_cycles, d.hold_sigma_cycles);
  EXPECT_DOUBLE_EQ(shipped.max_base_offset, d.max_base_offset);
  EXPECT_DOUBLE_EQ(shipped.max_outage, d.max_outage);
  EXPECT_DOUBLE_EQ(shipped.divergence_sigma, d.divergence_sigma);
  EXPECT_DOUBLE_EQ(shipped.max_fix_residual, d.max_fix_residual);
  EXPECT_DOUBLE_EQ(shipped.max_fix_sigma, d.max_fix_sigma);
  test::TempDir dir;
  EXPECT_DOUBLE_EQ(
      readRtkOptions(dir.write("s.yaml", "rtk:\n  max_fix_sigma: 0.05\n")).max_fix_sigma, 0.05);
  EXPECT_EQ(readRtkOptions(dir.write("g.yaml", "rtk:\n  systems: G\n")).dd.systems,
            std::vector<GnssSystem>{GnssSystem::kGps});
  EXPECT_THROW(readRtkOptions(dir.write("r.yaml", "rtk:\n  systems: GR\n")), DataError);
}

TEST(CalibrationOptions, ShippedConfigEqualsTheDefaults) {
  const CalibrationOptions c =
      readCalibrationOptions(std::string(GIOCAL_SOURCE_DIR) + "/config/giocal.yaml");
  const CalibrationOptions d;
  EXPECT_EQ(c.ambiguity_resolution, d.ambiguity_resolution);
  EXPECT_DOUBLE_EQ(c.fix_sigma_cycles, d.fix_sigma_cycles);
  EXPECT_DOUBLE_EQ(c.max_fix_residual, d.max_fix_residual);
  EXPECT_DOUBLE_EQ(c.innovation_gate, d.innovation_gate);
  EXPECT_DOUBLE_EQ(c.chi2_probability, d.chi2_probability);
  EXPECT_DOUBLE_EQ(c.heading_sigma_deg, d.heading_sigma_deg);
  EXPECT_DOUBLE_EQ(c.doppler.noise.sigma_zenith, d.doppler.noise.sigma_zenith);
  EXPECT_DOUBLE_EQ(c.code_outliers.threshold_m, d.code_outliers.threshold_m);
  EXPECT_EQ(c.estimate_p_b_g, d.estimate_p_b_g);
  EXPECT_DOUBLE_EQ(c.p_b_g_sigma, d.p_b_g_sigma);
  EXPECT_EQ(c.hold_p_b_m_z, d.hold_p_b_m_z);
  EXPECT_DOUBLE_EQ(c.clock_drift_noise, d.clock_drift_noise);
  EXPECT_DOUBLE_EQ(c.odometer_interval_s, d.odometer_interval_s);
  EXPECT_EQ(c.odometer_iterations, d.odometer_iterations);
  EXPECT_DOUBLE_EQ(c.max_odometer_gap_s, d.max_odometer_gap_s);
  EXPECT_DOUBLE_EQ(c.output_rate_hz, d.output_rate_hz);
  EXPECT_DOUBLE_EQ(c.max_imu_gap_s, d.max_imu_gap_s);
  EXPECT_DOUBLE_EQ(c.divergence_sigma, d.divergence_sigma);
  EXPECT_DOUBLE_EQ(c.init.static_speed, d.init.static_speed);
  EXPECT_DOUBLE_EQ(c.init.min_static_s, d.init.min_static_s);
  EXPECT_DOUBLE_EQ(c.init.min_distance, d.init.min_distance);
  EXPECT_DOUBLE_EQ(c.init.max_heading_sigma_deg, d.init.max_heading_sigma_deg);
  EXPECT_DOUBLE_EQ(c.init.max_turn_deg, d.init.max_turn_deg);
  EXPECT_DOUBLE_EQ(c.init.velocity_sigma, d.init.velocity_sigma);
  EXPECT_DOUBLE_EQ(c.init.attitude_sigma_deg, d.init.attitude_sigma_deg);
  EXPECT_DOUBLE_EQ(c.single.tdcp.ionosphere_window_s, d.single.tdcp.ionosphere_window_s);
  EXPECT_EQ(c.single.tdcp.systems, d.single.tdcp.systems);
  EXPECT_DOUBLE_EQ(c.single.tdcp_drift_sigma, d.single.tdcp_drift_sigma);
  EXPECT_DOUBLE_EQ(c.single.tdcp_drift_tau_s, d.single.tdcp_drift_tau_s);
  // The rtk section's DD options reach the calibrators; its systems the single-receiver
  // scheme's time differences too.
  test::TempDir dir;
  const CalibrationOptions g = readCalibrationOptions(
      dir.write("g.yaml",
                "rtk:\n  systems: G\ncalibration:\n  ambiguity_resolution: 0\n  single:\n"
                "    ionosphere_window_s: 0\n    tdcp_drift_sigma: 0\n"));
  EXPECT_EQ(g.dd.systems, std::vector<GnssSystem>{GnssSystem::kGps});
  EXPECT_EQ(g.single.tdcp.systems, std::vector<GnssSystem>{GnssSystem::kGps});
  EXPECT_EQ(g.single.tdcp.ionosphere_window_s, 0.0);
  EXPECT_EQ(g.single.tdcp_drift_sigma, 0.0);
  // The single point positions take the time differences' sky.
  const SppOptions spp = sppOnSkyOf(g.single.tdcp);
  EXPECT_EQ(spp.systems, std::vector<GnssSystem>{GnssSystem::kGps});
  EXPECT_DOUBLE_EQ(spp.elevation_mask_deg, g.single.tdcp.elevation_mask_deg);
  EXPECT_FALSE(g.ambiguity_resolution);
  EXPECT_THROW(readCalibrationOptions(dir.write("b.yaml", "calibration:\n  innovation_gate: 0\n")),
               DataError);
}

TEST(FgoOptions, ShippedConfigEqualsTheDefaults) {
  const FgoOptions c = readFgoOptions(std::string(GIOCAL_SOURCE_DIR) + "/config/giocal.yaml");
  const FgoOptions d;
  EXPECT_EQ(c.window, d.window);
  EXPECT_EQ(c.max_iterations, d.max_iterations);
  EXPECT_DOUBLE_EQ(c.code_huber, d.code_huber);
  EXPECT_DOUBLE_EQ(c.rejection_sigma, d.rejection_sigma);
  EXPECT_EQ(c.max_rejections, d.max_rejections);
  EXPECT_DOUBLE_EQ(c.stop_step_sigma, d.stop_step_sigma);
  test::TempDir dir;
  EXPECT_EQ(readFgoOptions(dir.write("w.yaml", "fgo:\n  window: 7\n")).window, 7);
  EXPECT_DOUBLE_EQ(
      readFgoOptions(dir.write("s.yaml", "fgo:\n  stop_step_sigma: 0\n")).stop_step_sigma, 0.0);
  EXPECT_THROW(readFgoOptions(dir.write("n.yaml", "fgo:\n  stop_step_sigma: -1\n")), DataError);
  EXPECT_THROW(readFgoOptions(dir.write("b.yaml", "fgo:\n  window: 1\n")), DataError);
  EXPECT_EQ(c.solver, WindowSolver::kGaussNewton);
  EXPECT_EQ(readFgoOptions(dir.write("c.yaml", "fgo:\n  solver: ceres\n")).solver,
            WindowSolver::kCeres);
  try {
    readFgoOptions(dir.write("s.yaml", "fgo:\n  solver: lm\n"));
    FAIL() << "unknown solver accepted";
  } catch (const DataError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("'lm' is neither gauss_newton nor ceres"),
              std::string::npos)
        << e.what();
  }
}

TEST(ModelOptions, OverridesAndBadValues) {
  test::TempDir dir;
  const auto p = dir.write("c.yaml", "models:\n  nhc_min_speed: 0.2\n");
  EXPECT_DOUBLE_EQ(readModelOptions(p).motion.nhc_min_speed, 0.2);
  EXPECT_DOUBLE_EQ(readModelOptions(p).zupt_sigma, ModelOptions().zupt_sigma);
  const auto bad = dir.write("b.yaml", "models:\n  zupt_sigma: -1\n");
  try {
    readModelOptions(bad);
    FAIL();
  } catch (const DataError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("models.zupt_sigma"), std::string::npos);
  }
}

}  // namespace
}  // namespace giocal
