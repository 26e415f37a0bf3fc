#include "sim/sim_config.h"

#include <cctype>
#include <filesystem>

#include "common/io/data_error.h"
#include "common/io/yaml_fields.h"
#include "common/math/rotation.h"

namespace giocal::sim {

namespace {

// gnss.base_signals: [{signal: G2X, shift_cycles: -0.25, min_elevation_deg: 0}, ...].
std::vector<SignalSpec> readBaseSignals(const std::string& path, const YamlFields& y,
                                        const std::string& systems) {
  const YAML::Node list = y.root()["gnss"]["base_signals"];
  if (!list.IsSequence()) y.fail("gnss.base_signals", "needs a list of {signal: G2X, ...}");
  std::vector<SignalSpec> out;
  for (size_t i = 0; i < list.size(); ++i) {
    // Each entry read on its own, under its place in the file, so messages name it so.
    const std::string at = "base_signals[" + std::to_string(i) + "]", k = "gnss." + at;
    YAML::Node wrapper;
    wrapper["gnss"][at] = list[i];
    const YamlFields f(path, wrapper);
    const std::string code = f.text(k + ".signal");
    SignalSpec sig;
    if (code.size() != 3 || systems.find(code[0]) == std::string::npos ||
        carrierFrequency(static_cast<GnssSystem>(code[0]), code[1]) == 0.0 ||
        !std::isupper(static_cast<unsigned char>(code[2]))) {
      f.fail(k + ".signal", "'" + code +
                                "' is not a system of gnss.systems, a band and an attribute"
                                " (G2X, J1C, ...)");
    }
    sig.sys = static_cast<GnssSystem>(code[0]);
    sig.band = code[1];
    sig.attr = code[2];
    for (const SignalSpec& o : out) {
      if (o.sys == sig.sys && o.band == sig.band && o.attr == sig.attr)
        f.fail(k + ".signal", "'" + code + "' is listed twice");
    }
    sig.shift_cycles = f.numberOr(k + ".shift_cycles", 0.0, -0.5, 0.5);
    sig.min_elevation_deg = f.numberOr(k + ".min_elevation_deg", 0.0, 0.0, 90.0);
    f.rejectUnknownKeys();
    out.push_back(sig);
  }
  return out;
}

}  // namespace

SimConfig readSimConfig(const std::string& path) {
  const YamlFields y(path);
  SimConfig c;
  c.name = y.textOr("name", c.name);
  c.start_time = y.textOr("start_time", c.start_time);
  c.origin_lat_deg = y.numberOr("origin.lat_deg", c.origin_lat_deg, -89.0, 89.0);
  c.origin_lon_deg = y.numberOr("origin.lon_deg", c.origin_lon_deg, -180.0, 180.0);
  c.origin_h = y.numberOr("origin.h", c.origin_h, -500.0, 9000.0);
  c.initial_heading_deg =
      y.numberOr("trajectory.initial_heading_deg", c.initial_heading_deg, -360, 360);
  c.terrain.amplitude = y.numberOr("trajectory.terrain.amplitude", c.terrain.amplitude, 0.0, 100.0);
  c.terrain.wavelength =
      y.numberOr("trajectory.terrain.wavelength", c.terrain.wavelength, 1.0, 1e5);

  // trajectory.segments, then trajectory.loop repeated trajectory.laps times.
  auto readSegments = [&](const std::string& key, int repeat) {
    if (!y.root()["trajectory"][key].IsSequence())
      y.fail("trajectory." + key, "needs a list of segments");
    const YAML::Node segs = y.root()["trajectory"][key];
    // Each segment is read once and repeated: reading the YAML again per lap made a preset of
    // 1000 laps take 3 s to read (9 minutes under the fuzzer's sanitizers).
    std::vector<SegmentSpec> once;
    for (size_t i = 0; i < segs.size(); ++i) {
      YAML::Node wrapper;
      wrapper["s"] = segs[i];
      const YamlFields s(path, wrapper);
      SegmentSpec spec;
      spec.type = s.text("s.type");
      spec.duration = s.numberOr("s.duration", 0.0, 0.0, 1e6);
      spec.speed = s.numberOr("s.speed", -1.0, 0.0, 30.0);
      spec.radius = s.numberOr("s.radius", 0.0, 0.0, 1e5);
      spec.direction = s.textOr("s.direction", "left");
      spec.angle_deg = s.numberOr("s.angle_deg", 0.0, 0.0, 1e5);
      spec.rate_deg_s = s.numberOr("s.rate_deg_s", 0.0, -360.0, 360.0);
      spec.transition = s.numberOr("s.transition", 1.0, 0.0, 100.0);
      s.rejectUnknownKeys();
      once.push_back(spec);
    }
    for (int lap = 0; lap < repeat; ++lap)
      c.segments.insert(c.segments.end(), once.begin(), once.end());
  };
  if (!y.has("trajectory.segments"))
    y.fail("trajectory", "needs 'segments', a list of motion segments");
  readSegments("segments", 1);
  if (y.has("trajectory.loop")) {
    readSegments("loop", static_cast<int>(y.number("trajectory.laps", 1, 1000)));
  }
  try {
    MotionProfile check(c.segments);
  } catch (const std::invalid_argument& e) {
    y.fail("trajectory.segments", e.what());
  }

  ImuErrorSpec& m = c.imu;
  m.rate_hz = y.numberOr("imu.rate_hz", m.rate_hz, 1.0, 2000.0);
  m.gyro_bias_deg_h = y.numberOr("imu.gyro_bias_deg_h", m.gyro_bias_deg_h, 0.0, 1e5);
  m.accel_bias_mgal = y.numberOr("imu.accel_bias_mgal", m.accel_bias_mgal, 0.0, 1e7);
  m.arw_deg_sqrt_h = y.numberOr("imu.arw_deg_sqrt_h", m.arw_deg_sqrt_h, 0.0, 1e3);
  m.vrw_m_s_sqrt_h = y.numberOr("imu.vrw_m_s_sqrt_h", m.vrw_m_s_sqrt_h, 0.0, 1e3);
  m.gyro_bias_rw_deg_h_sqrt_h =
      y.numberOr("imu.gyro_bias_rw_deg_h_sqrt_h", m.gyro_bias_rw_deg_h_sqrt_h, 0.0, 1e5);
  m.accel_bias_rw_mgal_sqrt_s =
      y.numberOr("imu.accel_bias_rw_mgal_sqrt_s", m.accel_bias_rw_mgal_sqrt_s, 0.0, 1e5);
  m.scale_ppm = y.numberOr("imu.scale_ppm", m.scale_ppm, 0.0, 1e5);
  m.misalignment_deg = y.numberOr("imu.misalignment_deg", m.misalignment_deg, 0.0, 10.0);

  OdometerErrorSpec& o = c.odometer;
  o.rate_hz = y.numberOr("odometer.rate_hz", o.rate_hz, 1.0, 1000.0);
  o.speed_sigma = y.numberOr("odometer.speed_sigma", o.speed_sigma, 0.0, 10.0);
  o.yaw_rate_sigma_deg_s =
      y.numberOr("odometer.yaw_rate_sigma_deg_s", o.yaw_rate_sigma_deg_s, 0.0, 100.0);
  o.scale_drift_per_sqrt_s =
      y.numberOr("odometer.scale_drift_per_sqrt_s", o.scale_drift_per_sqrt_s, 0.0, 1.0);
  o.speed_quantum = y.numberOr("odometer.speed_quantum", o.speed_quantum, 0.0, 1.0);
  o.delay_s = y.numberOr("odometer.delay_s", o.delay_s, 0.0, 1.0);
  o.slip_rate_per_min = y.numberOr("odometer.slip_rate_per_min", o.slip_rate_per_min, 0.0, 600.0);
  o.slip_duration_s = y.numberOr("odometer.slip_duration_s", o.slip_duration_s, 0.0, 60.0);
  o.slip_speed_factor = y.numberOr("odometer.slip_speed_factor", o.slip_speed_factor, 0.0, 10.0);
  o.yaw_rate_quantum_deg_s =
      y.numberOr("odometer.yaw_rate_quantum_deg_s", o.yaw_rate_quantum_deg_s, 0.0, 10.0);

  c.truth.s_v = y.number("calibration.s_v", -0.5, 0.5);
  c.truth.s_w = y.number("calibration.s_w", -0.5, 0.5);
  c.truth.p_b_m = y.vector3("calibration.p_b_m", -10.0, 10.0);
  c.truth.q_b_m = Eigen::Quaterniond(
      rotationFromRpy(y.vector3("calibration.rpy_b_m_deg", -180.0, 180.0) * kDegToRad));
  c.p_b_g = y.vector3("calibration.p_b_g", -10.0, 10.0);

  GnssSimSpec& g = c.gnss;
  g.enabled = y.has("gnss");
  if (g.enabled) {
    // The nav file is relative to the config file's folder.
    const std::filesystem::path nav = y.text("gnss.nav_file");
    g.nav_file =
        nav.is_absolute()
            ? nav.string()
            : (std::filesystem::path(path).parent_path() / nav).lexically_normal().string();
    if (!std::filesystem::exists(g.nav_file)) y.fail("gnss.nav_file", "no file " + g.nav_file);
    g.systems = y.textOr("gnss.systems", g.systems);
    for (char sys : g.systems) {
      if (sys != 'G' && sys != 'E' && sys != 'C' && sys != 'J')
        y.fail("gnss.systems", "letters must be among G, E, C, J");
    }
    g.beidou_meo_only = y.numberOr("gnss.beidou_meo_only", g.beidou_meo_only ? 1 : 0, 0, 1) != 0.0;
    g.rate_hz = y.numberOr("gnss.rate_hz", g.rate_hz, 0.01, 100.0);
    g.elevation_mask_deg = y.numberOr("gnss.elevation_mask_deg", g.elevation_mask_deg, 0.0, 60.0);
    g.code_sigma = y.numberOr("gnss.code_sigma", g.code_sigma, 0.0, 100.0);
    g.phase_sigma = y.numberOr("gnss.phase_sigma", g.phase_sigma, 0.0, 1.0);
    g.doppler_sigma = y.numberOr("gnss.doppler_sigma", g.doppler_sigma, 0.0, 10.0);
    g.multipath.code_sigma =
        y.numberOr("gnss.multipath_code_sigma", g.multipath.code_sigma, 0.0, 100.0);
    g.multipath.phase_sigma =
        y.numberOr("gnss.multipath_phase_sigma", g.multipath.phase_sigma, 0.0, 1.0);
    g.multipath.tau_s = y.numberOr("gnss.multipath_tau_s", g.multipath.tau_s, 0.01, 1e5);
    if (y.has("gnss.base_offset_enu"))
      g.base_offset_enu = y.vector3("gnss.base_offset_enu", -1e5, 1e5);
    if (y.has("gnss.base")) {
      const std::string base = y.text("gnss.base");
      if (base != "none") y.fail("gnss.base", "is 'none' (a rover alone) or left out");
      g.base = false;
      setSingleReceiverDefaults(g);
    }
    g.orbit_error_m = y.numberOr("gnss.orbit_error_m", g.orbit_error_m, 0.0, 100.0);
    g.orbit_error_rate = y.numberOr("gnss.orbit_error_rate", g.orbit_error_rate, 0.0, 0.1);
    g.sat_clock_error_m = y.numberOr("gnss.sat_clock_error_m", g.sat_clock_error_m, 0.0, 100.0);
    g.sat_clock_random_walk =
        y.numberOr("gnss.sat_clock_random_walk", g.sat_clock_random_walk, 0.0, 0.1);
    g.sat_clock_rate_sd = y.numberOr("gnss.sat_clock_rate_sd", g.sat_clock_rate_sd, 0.0, 0.1);
    g.sat_clock_rate_tau_s =
        y.numberOr("gnss.sat_clock_rate_tau_s", g.sat_clock_rate_tau_s, 0.1, 1e5);
    g.vtec_random_walk = y.numberOr("gnss.vtec_random_walk", g.vtec_random_walk, 0.0, 1.0);
    g.zenith_wet_random_walk =
        y.numberOr("gnss.zenith_wet_random_walk", g.zenith_wet_random_walk, 0.0, 0.01);
    g.clock_step_s = y.numberOr("gnss.clock_step_s", g.clock_step_s, 0.0, 0.01);
    g.half_cycle_share = y.numberOr("gnss.half_cycle_share", g.half_cycle_share, 0.0, 1.0);
    g.clock_offset_sd = y.numberOr("gnss.clock_offset_sd", g.clock_offset_sd, 0.0, 1e-3);
    g.clock_drift_sd = y.numberOr("gnss.clock_drift_sd", g.clock_drift_sd, 0.0, 1e-5);
    g.zenith_wet_sd = y.numberOr("gnss.zenith_wet_sd", g.zenith_wet_sd, 0.0, 1.0);
    g.vtec_tecu = y.numberOr("gnss.vtec_tecu", g.vtec_tecu, 0.0, 300.0);
    g.vtec_gradient = y.numberOr("gnss.vtec_gradient", g.vtec_gradient, 0.0, 1e-4);
    if (y.has("gnss.base_signals")) g.base_signals = readBaseSignals(path, y, g.systems);
    g.base_phase_aligned =
        y.numberOr("gnss.base_phase_aligned", g.base_phase_aligned ? 1 : 0, 0, 1) != 0.0;
    if (y.has("gnss.scenes")) {
      const YAML::Node scenes = y.root()["gnss"]["scenes"];
      if (!scenes.IsSequence()) y.fail("gnss.scenes", "needs a list of scenes");
      for (size_t i = 0; i < scenes.size(); ++i) {
        YAML::Node wrapper;
        wrapper["s"] = scenes[i];
        const YamlFields f(path, wrapper);
        SceneSpec sc;
        try {
          sc = sceneDefaults(f.text("s.type"));
        } catch (const std::invalid_argument& e) {
          f.fail("s.type", e.what());
        }
        sc.start = f.number("s.start", 0.0, 1e7);
        sc.end = f.number("s.end", sc.start, 1e7);
        sc.block_probability = f.numberOr("s.block_probability", sc.block_probability, 0.0, 1.0);
        sc.building_side = f.textOr("s.side", sc.building_side);
        if (!sc.building_side.empty() && sc.building_side != "left" &&
            sc.building_side != "right") {
          f.fail("s.side", "must be left or right");
        }
        sc.building_elevation_deg =
            f.numberOr("s.building_elevation_deg", sc.building_elevation_deg, 0.0, 90.0);
        sc.outlier_probability =
            f.numberOr("s.outlier_probability", sc.outlier_probability, 0.0, 1.0);
        sc.outlier_m = f.numberOr("s.outlier_m", sc.outlier_m, 0.0, 1000.0);
        sc.extra_phase_sigma = f.numberOr("s.extra_phase_sigma", sc.extra_phase_sigma, 0.0, 1.0);
        sc.slip_probability = f.numberOr("s.slip_probability", sc.slip_probability, 0.0, 1.0);
        f.rejectUnknownKeys();
        g.scenes.push_back(sc);
      }
    }
  }

  c.guess_sd_s_v = y.numberOr("initial_guess_sigma.s_v", c.guess_sd_s_v, 1e-9, 0.5);
  c.guess_sd_s_w = y.numberOr("initial_guess_sigma.s_w", c.guess_sd_s_w, 1e-9, 0.5);
  c.guess_sd_p_b_m = y.numberOr("initial_guess_sigma.p_b_m", c.guess_sd_p_b_m, 1e-9, 10.0);
  c.guess_sd_rpy_deg = y.numberOr("initial_guess_sigma.rpy_deg", c.guess_sd_rpy_deg, 1e-9, 90.0);
  // A misspelled key would otherwise simulate something else than the file says, silently (the
  // field preset's wheel-slip lines were ignored until 2026-11-26).
  y.rejectUnknownKeys();
  return c;
}

}  // namespace giocal::sim
