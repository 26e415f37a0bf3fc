#include "sim/simulator.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <random>
#include <stdexcept>

#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_obs_writer.h"
#include "common/imu/error_free_imu.h"
#include "common/math/rotation.h"
#include "common/time/gps_time.h"
#include "sim/sensor_errors.h"
#include "sim/trajectory.h"

namespace giocal::sim {

double parseGpsTime(const std::string& text) {
  CalendarTime c;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%d-%d-%d %d:%d:%lf%c", &c.year, &c.month, &c.day, &c.hour,
                  &c.minute, &c.second, &tail) != 6 ||
      c.month < 1 || c.month > 12 || c.day < 1 || c.day > 31 || c.hour > 23 || c.minute > 59 ||
      c.second < 0.0 || c.second >= 60.0 || c.year < 1980) {
    throw std::invalid_argument("time '" + text + "' is not 'yyyy-mm-dd hh:mm:ss' (GPST)");
  }
  return gpsSecondsFromCalendar(c);
}

namespace {

// truth.csv row: IMU origin geodetic, velocity and attitude in the local-level ENU frame l at the
// current position.
TruthSample truthRow(const LocalFrame& frame, const NavState& s) {
  const Eigen::Vector3d p_e = frame.ecefFromEnu(s.p_n_b);
  const Geodetic g = geodeticFromEcef(p_e);
  const Eigen::Matrix3d R_l_n = rotationEcefFromEnu(g.lat, g.lon).transpose() * frame.R_e_n();
  TruthSample row;
  row.t = s.t;
  row.lat_deg = g.lat * kRadToDeg;
  row.lon_deg = g.lon * kRadToDeg;
  row.h = g.h;
  row.v_enu = R_l_n * s.v_n_b;
  row.q_n_b = Eigen::Quaterniond(R_l_n * s.q_n_b.toRotationMatrix()).normalized();
  return row;
}

// The IMU state of a rigidly mounted IMU (T_n_b = T_n_m T_m_b) and its acceleration in n.
NavState imuState(const VehicleKinematics& m, const Eigen::Matrix3d& R_m_b,
                  const Eigen::Vector3d& p_m_b, Eigen::Vector3d* a_n_b) {
  const Eigen::Vector3d w_x_p = m.w_m.cross(p_m_b);
  NavState s;
  s.p_n_b = m.p_n_m + m.R_n_m * p_m_b;
  s.v_n_b = m.v_n_m + m.R_n_m * w_x_p;
  s.q_n_b = Eigen::Quaterniond(m.R_n_m * R_m_b).normalized();
  if (a_n_b) *a_n_b = m.a_n_m + m.R_n_m * (m.alpha_m.cross(p_m_b) + m.w_m.cross(w_x_p));
  return s;
}

}  // namespace

SimulatedLogs simulateMotionSensors(const SimConfig& config, const VehiclePath& traj,
                                    const LocalFrame& frame, double t0, std::uint64_t seed) {
  SimulatedLogs out{frame, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};

  // Independent streams for each sensor keep one sensor's draws from shifting another's.
  std::mt19937_64 rng_imu(seed * 4 + 1), rng_odo(seed * 4 + 2), rng_guess(seed * 4 + 3);
  ImuErrors imu_errors(config.imu, rng_imu);
  // The IMU frame b written out (truth.csv, truth_calib.yaml, dataset.yaml's p_b_g) is the
  // accelerometer's measuring axes: the ideal axes' misalignment is not observable by any
  // estimator, which calibrates against the axes it measures in (docs/design.md).
  const Eigen::Matrix3d R_a_b = imu_errors.measuringAxes();  // ideal axes b to measuring a
  const Eigen::Quaterniond q_b_a(R_a_b.transpose());
  OdometerCalibration truth_a = config.truth;
  truth_a.q_b_m = Eigen::Quaterniond(R_a_b * config.truth.q_b_m.toRotationMatrix()).normalized();
  truth_a.p_b_m = R_a_b * config.truth.p_b_m;
  const Eigen::Vector3d p_a_g = R_a_b * config.p_b_g;
  const OdometerCalibration& truth = config.truth;
  OdometerErrors odo_errors(config.odometer, truth.s_v, truth.s_w, seed * 4 + 2 + (1ull << 62));
  const Eigen::Matrix3d R_b_m = truth.q_b_m.toRotationMatrix();
  const Eigen::Matrix3d R_m_b = R_b_m.transpose();
  const Eigen::Vector3d p_m_b = -R_m_b * truth.p_b_m;

  const double dt_imu = 1.0 / config.imu.rate_hz;
  const long n_imu = static_cast<long>(std::floor(traj.duration() * config.imu.rate_hz + 1e-9));
  for (long k = 0; k <= n_imu; ++k) {
    const double tau = static_cast<double>(k) * dt_imu;
    const VehicleKinematics m = traj.at(tau);
    Eigen::Vector3d a_n_b;
    NavState s = imuState(m, R_m_b, p_m_b, &a_n_b);
    s.t = t0 + tau;
    const ImuSample ideal = errorFreeImu(frame, s, a_n_b, R_b_m * m.w_m);
    s.b_g = imu_errors.gyroBias();
    s.b_a = imu_errors.accelBias();
    out.imu.push_back(imu_errors.measure(s.t, ideal.gyro, ideal.acc, dt_imu, rng_imu));
    s.q_n_b = (s.q_n_b * q_b_a).normalized();
    out.truth_n.push_back(s);
    out.truth.push_back(truthRow(frame, s));
  }

  const double dt_odo = 1.0 / config.odometer.rate_hz;
  const long n_odo =
      static_cast<long>(std::floor(traj.duration() * config.odometer.rate_hz + 1e-9));
  for (long k = 0; k <= n_odo; ++k) {
    const double tau = static_cast<double>(k) * dt_odo;
    const VehicleKinematics m = traj.at(tau);
    out.true_speed.push_back(m.speed);
    out.true_yaw_rate.push_back(m.w_m.z());
    out.odom.push_back(odo_errors.measure(t0 + tau, m.speed, m.w_m.z(), dt_odo, rng_odo));
    out.odom.back().t += config.odometer.delay_s;
  }

  out.truth_calib.calib = truth_a;
  out.truth_calib.p_b_g = p_a_g;
  out.truth_calib.gyro_tilt_deg = imu_errors.gyroTilt() * kRadToDeg;

  DatasetDescription& d = out.description;
  d.truth = "truth.csv";
  const double arw = config.imu.arw_deg_sqrt_h * kDegToRad / 60.0;
  d.imu_noise.gyro_noise_density = arw;
  d.imu_noise.accel_noise_density = config.imu.vrw_m_s_sqrt_h / 60.0;
  d.imu_noise.gyro_bias_random_walk =
      std::max(config.imu.gyro_bias_rw_deg_h_sqrt_h * kDegToRad / 3600.0 / 60.0, 1e-7);
  d.imu_noise.accel_bias_random_walk = std::max(config.imu.accel_bias_rw_mgal_sqrt_s * 1e-5, 1e-6);
  d.imu_noise.gyro_bias_sigma = std::max(config.imu.gyro_bias_deg_h * kDegToRad / 3600.0, 1e-6);
  d.imu_noise.accel_bias_sigma = std::max(config.imu.accel_bias_mgal * 1e-5, 1e-5);
  d.odom_noise.speed_sigma = config.odometer.speed_sigma;
  d.odom_noise.yaw_rate_sigma = config.odometer.yaw_rate_sigma_deg_s * kDegToRad;
  d.odom_noise.scale_random_walk = config.odometer.scale_drift_per_sqrt_s;
  d.p_b_g = p_a_g;

  // The initial guess: the truth plus one draw of the configured sigma.
  std::normal_distribution<double> n01(0.0, 1.0);
  CalibrationPrior& prior = d.initial_calibration;
  prior.sd_s_v = config.guess_sd_s_v;
  prior.sd_s_w = config.guess_sd_s_w;
  prior.sd_p_b_m = Eigen::Vector3d::Constant(config.guess_sd_p_b_m);
  prior.sd_rpy_b_m = Eigen::Vector3d::Constant(config.guess_sd_rpy_deg * kDegToRad);
  prior.mean.s_v = truth_a.s_v + config.guess_sd_s_v * n01(rng_guess);
  prior.mean.s_w = truth_a.s_w + config.guess_sd_s_w * n01(rng_guess);
  for (int i = 0; i < 3; ++i)
    prior.mean.p_b_m[i] = truth_a.p_b_m[i] + config.guess_sd_p_b_m * n01(rng_guess);
  Eigen::Vector3d rot_err;
  for (int i = 0; i < 3; ++i) rot_err[i] = config.guess_sd_rpy_deg * kDegToRad * n01(rng_guess);
  prior.mean.q_b_m = Eigen::Quaterniond(truth_a.q_b_m * expSO3(rot_err)).normalized();
  return out;
}

AntennaTruth antennaPath(const SimConfig& config, const VehiclePath& path, const LocalFrame& frame,
                         double t0) {
  const Eigen::Matrix3d R_b_m = config.truth.q_b_m.toRotationMatrix();
  const Eigen::Matrix3d R_m_b = R_b_m.transpose();
  const Eigen::Vector3d p_m_b = -R_m_b * config.truth.p_b_m;
  // Antenna at the lever arm p_b_g: p_g = p_b + R_n_b p_b_g, v_g = v_b + R_n_b (w_b x p_b_g).
  return [&path, frame, t0, R_b_m, R_m_b, p_m_b, p_b_g = config.p_b_g](
             double t, Eigen::Vector3d& p_e, Eigen::Vector3d& v_e) {
    const VehicleKinematics m = path.at(t - t0);
    const NavState s = imuState(m, R_m_b, p_m_b, nullptr);
    const Eigen::Matrix3d R_n_b = s.q_n_b.toRotationMatrix();
    const Eigen::Vector3d w_b = R_b_m * m.w_m;
    p_e = frame.ecefFromEnu(s.p_n_b + R_n_b * p_b_g);
    v_e = frame.R_e_n() * (s.v_n_b + R_n_b * w_b.cross(p_b_g));
  };
}

SimulatedLogs simulate(const SimConfig& config, std::uint64_t seed) {
  const double t0 = parseGpsTime(config.start_time);
  const Eigen::Vector3d origin_e = ecefFromGeodetic(
      {config.origin_lat_deg * kDegToRad, config.origin_lon_deg * kDegToRad, config.origin_h});
  const LocalFrame frame(origin_e);
  const Trajectory traj(MotionProfile(config.segments), config.terrain, Eigen::Vector3d::Zero(),
                        config.initial_heading_deg * kDegToRad);
  SimulatedLogs out = simulateMotionSensors(config, traj, frame, t0, seed);
  if (config.gnss.enabled) {
    const AntennaTruth antenna = antennaPath(config, traj, frame, t0);
    const BroadcastOrbits orbits(readRinexNav(config.gnss.nav_file));
    const Eigen::Vector3d base_e = frame.ecefFromEnu(config.gnss.base_offset_enu);
    std::mt19937_64 rng_gnss(seed * 4 + 4);
    out.gnss =
        simulateGnss(config.gnss, orbits, antenna, base_e, t0, t0 + traj.duration(), rng_gnss);
    for (const SceneSpec& sc : config.gnss.scenes) {
      const double end = std::min(sc.end, traj.duration());
      if (end > sc.start) out.scenes.push_back({t0 + sc.start, t0 + end, sc.type});
    }
    out.nav_file = config.gnss.nav_file;
    for (const ObsEpoch& e : out.gnss.rover) {
      Eigen::Vector3d p, v;
      antenna(e.t, p, v);
      out.antenna_e.push_back(p);
    }
    if (config.gnss.base) {
      out.description.base_position_ecef = base_e;
    } else {
      out.description.base_obs.clear();  // a rover alone
    }
  }

  return out;
}

void writeDataset(const SimulatedLogs& logs, const std::string& folder) {
  std::filesystem::create_directories(folder);
  DatasetDescription d = logs.description;
  d.folder = folder;
  writeImuCsv(d.pathOf(d.imu), logs.imu);
  writeOdomCsv(d.pathOf(d.odom), logs.odom);
  writeTruthCsv(d.pathOf(d.truth), logs.truth);
  writeTruthCalibration(folder + "/truth_calib.yaml", logs.truth_calib);
  if (!logs.scenes.empty()) writeScenesCsv(folder + "/scenes.csv", logs.scenes);
  if (!logs.gnss.rover.empty()) {
    // Each receiver's file lists the signals it tracks; the base's records the phase-shift
    // corrections it applied (a base of another make, gnss.base_signals).
    const auto headerOf = [&](int receiver) {
      RinexObsHeader h;
      for (const SignalSpec& s : logs.gnss.signals[receiver]) {
        const char sys = static_cast<char>(s.sys);
        for (char type : {'C', 'L', 'D', 'S'}) h.obs_types[sys].push_back({type, s.band, s.attr});
        if (receiver == 1 && logs.gnss.base_phase_aligned && s.shift_cycles != 0.0)
          h.phase_shift[{sys, std::string{'L', s.band, s.attr}}] = s.shift_cycles;
      }
      return h;
    };
    RinexObsHeader h = headerOf(0);
    h.interval = logs.gnss.rover.size() > 1 ? logs.gnss.rover[1].t - logs.gnss.rover[0].t : 1.0;
    h.marker = "ROVER";
    // A receiver's own approximate position: the first antenna position, metres off.
    h.approx_position = logs.antenna_e.front() + Eigen::Vector3d(2.0, -3.0, 1.5);
    writeRinexObs(d.pathOf(d.rover_obs), h, logs.gnss.rover);
    if (!d.base_obs.empty()) {
      const double interval = h.interval;
      h = headerOf(1);
      h.interval = interval;
      h.marker = "BASE";
      h.approx_position = logs.gnss.base_e;
      writeRinexObs(d.pathOf(d.base_obs), h, logs.gnss.base);
    }
    std::filesystem::copy_file(logs.nav_file, d.pathOf(d.nav.front()),
                               std::filesystem::copy_options::overwrite_existing);
    // The source may be read-only (shipped data); the dataset's copy belongs to the user.
    std::filesystem::permissions(d.pathOf(d.nav.front()), std::filesystem::perms::owner_read |
                                                              std::filesystem::perms::owner_write |
                                                              std::filesystem::perms::group_read |
                                                              std::filesystem::perms::others_read);
  }
  writeDatasetDescription(d);
}

}  // namespace giocal::sim
