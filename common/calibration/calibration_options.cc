#include "common/calibration/calibration_options.h"

#include "common/gnss/rtk_config.h"
#include "common/io/yaml_fields.h"
#include "common/math/rotation.h"

namespace giocal {

CalibrationOptions readCalibrationOptions(const std::string& path) {
  if (path.empty()) return {};
  return readCalibrationOptions(YamlFields(path));
}

CalibrationOptions readCalibrationOptions(const YamlFields& y) {
  CalibrationOptions o;
  o.models = readModelOptions(y);
  const RtkOptions rtk = readRtkOptions(y);
  o.dd = rtk.dd;
  o.lambda = rtk.lambda;
  o.ambiguity_noise = rtk.ambiguity_noise;
  o.max_base_offset = rtk.max_base_offset;
  o.doppler.elevation_mask_deg = o.dd.elevation_mask_deg;
  o.doppler.systems = o.dd.systems;

  const std::string s = "calibration.";
  auto flag = [&](const std::string& key, bool fallback) {
    return y.numberOr(s + key, fallback ? 1 : 0, 0, 1) != 0.0;
  };
  o.ambiguity_resolution = flag("ambiguity_resolution", o.ambiguity_resolution);
  o.fix_sigma_cycles = y.numberOr(s + "fix_sigma_cycles", o.fix_sigma_cycles, 1e-6, 1.0);
  o.max_fix_residual = y.numberOr(s + "max_fix_residual", o.max_fix_residual, 1.0, 100.0);
  o.innovation_gate = y.numberOr(s + "innovation_gate", o.innovation_gate, 1.0, 1e6);
  o.chi2_probability = y.numberOr(s + "chi2_probability", o.chi2_probability, 0.5, 1.0);
  o.heading_sigma_deg = y.numberOr(s + "heading_sigma_deg", o.heading_sigma_deg, 1e-4, 10.0);
  o.doppler.noise.sigma_zenith =
      y.numberOr(s + "doppler_sigma", o.doppler.noise.sigma_zenith, 1e-4, 100.0);
  o.code_outliers.threshold_m =
      y.numberOr(s + "code_outlier_threshold", o.code_outliers.threshold_m, 0.1, 1e4);
  o.estimate_p_b_g = flag("estimate_p_b_g", o.estimate_p_b_g);
  o.p_b_g_sigma = y.numberOr(s + "p_b_g_sigma", o.p_b_g_sigma, 1e-6, 10.0);
  o.estimate_odometer_delay = flag("estimate_odometer_delay", o.estimate_odometer_delay);
  o.apply_odometer_delay_sigma =
      y.numberOr(s + "apply_odometer_delay_sigma", o.apply_odometer_delay_sigma, 0.0, 1.0);
  o.apply_odometer_delay_min =
      y.numberOr(s + "apply_odometer_delay_min", o.apply_odometer_delay_min, 0.0, 10.0);
  o.odometer_delay_sigma =
      y.numberOr(s + "odometer_delay_sigma", o.odometer_delay_sigma, 1e-4, 1.0);
  o.estimate_gyro_tilt = flag("estimate_gyro_tilt", o.estimate_gyro_tilt);
  o.gyro_tilt_sigma_deg = y.numberOr(s + "gyro_tilt_sigma_deg", o.gyro_tilt_sigma_deg, 1e-4, 10.0);
  o.hold_p_b_m_z = flag("hold_p_b_m_z", o.hold_p_b_m_z);
  o.clock_drift_noise = y.numberOr(s + "clock_drift_noise", o.clock_drift_noise, 0.0, 1e3);
  o.odometer_interval_s = y.numberOr(s + "odometer_interval_s", o.odometer_interval_s, 0.0, 60.0);
  o.odometer_iterations =
      static_cast<int>(y.numberOr(s + "odometer_iterations", o.odometer_iterations, 1, 20));
  o.max_odometer_rejections = static_cast<int>(
      y.numberOr(s + "max_odometer_rejections", o.max_odometer_rejections, 1, 1e6));
  o.max_odometer_gap_s = y.numberOr(s + "max_odometer_gap_s", o.max_odometer_gap_s, 1e-3, 60.0);
  o.gnss_gap_warning_s = y.numberOr(s + "gnss_gap_warning_s", o.gnss_gap_warning_s, 0.1, 1e6);
  o.output_rate_hz = y.numberOr(s + "output_rate_hz", o.output_rate_hz, 0.01, 1e4);
  o.max_imu_gap_s = y.numberOr(s + "max_imu_gap_s", o.max_imu_gap_s, 1e-3, 1e3);
  o.max_imu_bridge_s = y.numberOr(s + "max_imu_bridge_s", o.max_imu_bridge_s, 1e-3, 1e3);
  o.divergence_sigma = y.numberOr(s + "divergence_sigma", o.divergence_sigma, 5.0, 1e6);
  o.lc.sigma_scale = y.numberOr(s + "lc.sigma_scale", o.lc.sigma_scale, 1e-3, 1e3);
  o.lc.use_height = flag("lc.use_height", o.lc.use_height);
  o.lc.learn_heights = flag("lc.learn_heights", o.lc.learn_heights);
  const std::string single = s + "single.";
  TdcpOptions& td = o.single.tdcp;
  td.systems = o.dd.systems;  // rtk.systems, as the Doppler rows take them
  td.max_interval_s = y.numberOr(single + "max_interval_s", td.max_interval_s, 0.01, 60.0);
  td.phase.sigma_zenith = y.numberOr(single + "phase_sigma", td.phase.sigma_zenith, 1e-5, 1.0);
  td.elevation_mask_deg =
      y.numberOr(single + "elevation_mask_deg", td.elevation_mask_deg, 0.0, 60.0);
  td.max_slips_in_a_row =
      static_cast<int>(y.numberOr(single + "max_slips_in_a_row", td.max_slips_in_a_row, 2, 1e6));
  td.ionosphere_window_s =
      y.numberOr(single + "ionosphere_window_s", td.ionosphere_window_s, 0.0, 3600.0);
  td.spp_ionosphere_free = flag("single.spp_ionosphere_free", td.spp_ionosphere_free);
  o.single.position_sigma_min_m =
      y.numberOr(single + "position_sigma_min", o.single.position_sigma_min_m, 0.01, 1e3);
  o.single.tdcp_screen_gate =
      y.numberOr(single + "screen_gate", o.single.tdcp_screen_gate, 1.0, 1e3);
  o.single.tdcp_drift_sigma =
      y.numberOr(single + "tdcp_drift_sigma", o.single.tdcp_drift_sigma, 0.0, 1.0);
  o.single.spp_bias_sigma =
      y.numberOr(single + "spp_bias_sigma", o.single.spp_bias_sigma, 0.0, 1e3);
  o.single.spp_bias_tau_s =
      y.numberOr(single + "spp_bias_tau_s", o.single.spp_bias_tau_s, 1.0, 1e6);
  o.single.tdcp_drift_tau_s =
      y.numberOr(single + "tdcp_drift_tau_s", o.single.tdcp_drift_tau_s, 1.0, 1e5);
  const std::string i = s + "init.";
  o.init.static_speed = y.numberOr(i + "static_speed", o.init.static_speed, 0.0, 1.0);
  o.init.min_static_s = y.numberOr(i + "min_static_s", o.init.min_static_s, 0.1, 1e3);
  o.init.min_distance = y.numberOr(i + "min_distance", o.init.min_distance, 0.05, 1e3);
  o.init.max_heading_sigma_deg =
      y.numberOr(i + "max_heading_sigma_deg", o.init.max_heading_sigma_deg, 0.01, 90.0);
  o.init.max_turn_deg = y.numberOr(i + "max_turn_deg", o.init.max_turn_deg, 0.0, 180.0);
  o.init.velocity_sigma = y.numberOr(i + "velocity_sigma", o.init.velocity_sigma, 1e-4, 10.0);
  o.init.attitude_sigma_deg =
      y.numberOr(i + "attitude_sigma_deg", o.init.attitude_sigma_deg, 1e-3, 90.0);
  const std::string w = s + "warm_start.";
  WarmStartOptions& ws = o.warm_start;
  ws.s_v = y.numberOr(w + "s_v", ws.s_v, 0.0, 1.0);
  ws.s_w = y.numberOr(w + "s_w", ws.s_w, 0.0, 1.0);
  ws.p_b_m = y.numberOr(w + "p_b_m", ws.p_b_m, 0.0, 10.0);
  ws.rpy_deg = y.numberOr(w + "rpy_deg", ws.rpy_deg, 0.0, 90.0);
  const std::string n = "online.";
  OnlineOptions& on = o.online;
  on.reorder_lag_s = y.numberOr(n + "reorder_lag_s", on.reorder_lag_s, 0.0, 60.0);
  on.max_lead_s = y.numberOr(n + "max_lead_s", on.max_lead_s, 0.01, 1e6);
  on.max_imu_wait_s = y.numberOr(n + "max_imu_wait_s", on.max_imu_wait_s, 0.1, 600.0);
  on.max_init_window_s = y.numberOr(n + "max_init_window_s", on.max_init_window_s, 10.0, 1e5);
  on.progress_interval_s = y.numberOr(n + "progress_interval_s", on.progress_interval_s, 1.0, 1e6);
  const std::string c = n + "convergence.";
  ConvergenceOptions& cv = on.convergence;
  cv.sigma_scale = y.numberOr(c + "sigma_scale", cv.sigma_scale, 1e-6, 1.0);
  cv.sigma_lever_m = y.numberOr(c + "sigma_lever_m", cv.sigma_lever_m, 1e-5, 10.0);
  cv.sigma_roll_pitch_deg =
      y.numberOr(c + "sigma_roll_pitch_deg", cv.sigma_roll_pitch_deg, 1e-4, 90.0);
  cv.sigma_yaw_deg = y.numberOr(c + "sigma_yaw_deg", cv.sigma_yaw_deg, 1e-4, 90.0);
  cv.steady_s = y.numberOr(c + "steady_s", cv.steady_s, 0.0, 1e5);
  return o;
}

}  // namespace giocal
