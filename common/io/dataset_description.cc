#include "common/io/dataset_description.h"

#include <yaml-cpp/yaml.h>

#include "common/io/atomic_file.h"
#include "common/io/data_error.h"
#include "common/io/yaml_fields.h"
#include "common/math/rotation.h"

namespace giocal {

namespace {

constexpr double kMaxNoise = 1e3;    // any noise figure above this is a unit mistake
constexpr double kMaxLever = 100.0;  // [m] between sensors on one robot
constexpr double kMaxScale = 0.9;    // |s| beyond this is no longer a scale error

// Reads q_b_m from "<key>.q_b_m" [w,x,y,z] or "<key>.rpy_b_m_deg"; both present must agree.
Eigen::Quaterniond readRotation(const YamlFields& y, const std::string& key) {
  const bool has_q = y.has(key + ".q_b_m"), has_rpy = y.has(key + ".rpy_b_m_deg");
  if (!has_q && !has_rpy) y.fail(key, "needs q_b_m or rpy_b_m_deg");
  Eigen::Quaterniond q_rpy = Eigen::Quaterniond::Identity();
  if (has_rpy) {
    q_rpy =
        Eigen::Quaterniond(rotationFromRpy(y.vector3(key + ".rpy_b_m_deg", -360, 360) * kDegToRad));
  }
  if (!has_q) return q_rpy;
  const Eigen::Vector4d v = y.vector4(key + ".q_b_m");
  if (std::abs(v.norm() - 1.0) > 1e-3) y.fail(key + ".q_b_m", "quaternion is not of unit norm");
  const Eigen::Quaterniond q = quatFromWxyz(v.data());
  if (has_rpy && q.angularDistance(q_rpy) > 1e-6) {
    y.fail(key + ".q_b_m", "disagrees with rpy_b_m_deg");
  }
  return q;
}

void emitVector(YAML::Emitter& out, const Eigen::Ref<const Eigen::VectorXd>& v) {
  out << YAML::Flow << YAML::BeginSeq;
  for (int i = 0; i < v.size(); ++i) out << v[i];
  out << YAML::EndSeq;
}

void emitRotation(YAML::Emitter& out, const Eigen::Quaterniond& q) {
  Eigen::Vector4d wxyz;
  quatToWxyz(q, wxyz.data());
  out << YAML::Key << "q_b_m" << YAML::Value;
  emitVector(out, wxyz);
  out << YAML::Key << "rpy_b_m_deg" << YAML::Value;
  emitVector(out, rpyFromRotation(q.toRotationMatrix()) * kRadToDeg);
}

void writeYaml(const std::string& path, const YAML::Emitter& out, const std::string& title) {
  AtomicFile file(path);
  file.stream() << "# " << title << "\n" << out.c_str() << "\n";
  file.commit();
}

}  // namespace

void requireRawGnss(const DatasetDescription& d) {
  if (d.rover_obs.empty()) {
    throw DataError(d.pathOf("dataset.yaml"), 0,
                    "no raw GNSS (files.rover_obs is empty): give a position solution instead "
                    "(the LC scheme: --gnss lc --pos gnss.pos; observability: --pos gnss.pos)");
  }
  if (d.base_obs.empty()) {
    throw DataError(d.pathOf("dataset.yaml"), 0,
                    "no base station (files.base_obs is empty): calibrate needs a base's "
                    "observations of the same time; name a RINEX file of one in dataset.yaml");
  }
}

DatasetDescription readDatasetDescription(const std::string& folder) {
  const YamlFields y(folder + "/dataset.yaml");
  DatasetDescription d;
  d.folder = folder;
  d.rover_obs = y.text("files.rover_obs");
  d.base_obs = y.text("files.base_obs");
  d.nav = y.textList("files.nav", d.rover_obs.empty());  // no raw GNSS, no ephemerides needed
  d.imu = y.text("files.imu");
  d.odom = y.text("files.odom");
  d.truth = y.textOr("files.truth", "");

  ImuNoise& n = d.imu_noise;
  n.gyro_noise_density = y.number("imu.gyro_noise_density", 0.0, kMaxNoise);
  n.accel_noise_density = y.number("imu.accel_noise_density", 0.0, kMaxNoise);
  n.gyro_bias_random_walk = y.number("imu.gyro_bias_random_walk", 0.0, kMaxNoise);
  n.accel_bias_random_walk = y.number("imu.accel_bias_random_walk", 0.0, kMaxNoise);
  n.gyro_bias_sigma = y.number("imu.gyro_bias_sigma", 0.0, kMaxNoise);
  n.accel_bias_sigma = y.number("imu.accel_bias_sigma", 0.0, kMaxNoise);

  d.odom_noise.speed_sigma = y.number("odometer.speed_sigma", 0.0, kMaxNoise);
  d.odom_noise.yaw_rate_sigma = y.number("odometer.yaw_rate_sigma", 0.0, kMaxNoise);
  d.odom_noise.scale_random_walk = y.numberOr("odometer.scale_random_walk", 0.0, 0.0, kMaxNoise);
  d.odom_noise.measures_yaw_rate = y.flagOr("odometer.measures_yaw_rate", true);

  d.p_b_g = y.vector3("gnss.p_b_g", -kMaxLever, kMaxLever);
  if (y.has("gnss.base_position_ecef")) {
    const Eigen::Vector3d p = y.vector3("gnss.base_position_ecef");
    if (p.norm() < 6.0e6 || p.norm() > 6.5e6) {
      y.fail("gnss.base_position_ecef", "not an ECEF position near the Earth's surface");
    }
    d.base_position_ecef = p;
  }

  constexpr double kMaxOffset = 10.0;  // [s]; more is a wrong clock, not a latency
  d.time_offsets.imu = y.numberOr("time_offsets.imu", 0.0, -kMaxOffset, kMaxOffset);
  d.time_offsets.odometer = y.numberOr("time_offsets.odometer", 0.0, -kMaxOffset, kMaxOffset);
  d.time_offsets.positions = y.numberOr("time_offsets.positions", 0.0, -kMaxOffset, kMaxOffset);

  CalibrationPrior& c = d.initial_calibration;
  c.mean.s_v = y.number("initial_calibration.s_v", -kMaxScale, kMaxScale);
  c.mean.s_w = y.number("initial_calibration.s_w", -kMaxScale, kMaxScale);
  c.mean.p_b_m = y.vector3("initial_calibration.p_b_m", -kMaxLever, kMaxLever);
  c.mean.q_b_m = readRotation(y, "initial_calibration");
  c.sd_s_v = y.number("initial_calibration.sigma.s_v", 1e-9, 1.0);
  c.sd_s_w = y.number("initial_calibration.sigma.s_w", 1e-9, 1.0);
  c.sd_p_b_m = y.vector3("initial_calibration.sigma.p_b_m", 1e-9, kMaxLever);
  c.sd_rpy_b_m = y.vector3("initial_calibration.sigma.rpy_b_m_deg", 1e-9, 180.0) * kDegToRad;
  // An optional key misspelt (time_offsets.odometr) would otherwise be its default, silently.
  y.rejectUnknownKeys();
  return d;
}

void writeDatasetDescription(const DatasetDescription& d) {
  using YAML::Key, YAML::Value, YAML::BeginMap, YAML::EndMap, YAML::Comment;
  YAML::Emitter out;
  out.SetDoublePrecision(12);
  out << BeginMap;
  out << Key << "files" << Value << BeginMap;
  out << Key << "rover_obs" << Value << d.rover_obs << Key << "base_obs" << Value << d.base_obs;
  out << Key << "nav" << Value << YAML::Flow << d.nav;
  out << Key << "imu" << Value << d.imu << Key << "odom" << Value << d.odom;
  if (!d.truth.empty()) out << Key << "truth" << Value << d.truth;
  out << EndMap;

  const ImuNoise& n = d.imu_noise;
  out << Key << "imu" << Value << BeginMap;
  out << Key << "gyro_noise_density" << Value << n.gyro_noise_density << Comment("rad/s/sqrt(Hz)");
  out << Key << "accel_noise_density" << Value << n.accel_noise_density
      << Comment("m/s^2/sqrt(Hz)");
  out << Key << "gyro_bias_random_walk" << Value << n.gyro_bias_random_walk
      << Comment("rad/s^2/sqrt(Hz)");
  out << Key << "accel_bias_random_walk" << Value << n.accel_bias_random_walk
      << Comment("m/s^3/sqrt(Hz)");
  out << Key << "gyro_bias_sigma" << Value << n.gyro_bias_sigma << Comment("rad/s");
  out << Key << "accel_bias_sigma" << Value << n.accel_bias_sigma << Comment("m/s^2");
  out << EndMap;

  out << Key << "odometer" << Value << BeginMap;
  out << Key << "speed_sigma" << Value << d.odom_noise.speed_sigma << Comment("m/s");
  out << Key << "yaw_rate_sigma" << Value << d.odom_noise.yaw_rate_sigma << Comment("rad/s");
  out << Key << "scale_random_walk" << Value << d.odom_noise.scale_random_walk
      << Comment("1/sqrt(s)");
  if (!d.odom_noise.measures_yaw_rate) {
    out << Key << "measures_yaw_rate" << Value << false
        << Comment("speed only: odom.csv's w is not read, s_w is not calibrated");
  }
  out << EndMap;

  out << Key << "gnss" << Value << BeginMap;
  out << Key << "p_b_g" << Value;
  emitVector(out, d.p_b_g);
  out << Comment("m, antenna phase centre in b");
  if (d.base_position_ecef) {
    out << Key << "base_position_ecef" << Value;
    emitVector(out, *d.base_position_ecef);
    out << Comment("m");
  }
  out << EndMap;

  if (d.time_offsets.any()) {
    out << Key << "time_offsets" << Value << BeginMap;
    out << Key << "imu" << Value << d.time_offsets.imu << Key << "odometer" << Value
        << d.time_offsets.odometer << Key << "positions" << Value << d.time_offsets.positions;
    out << EndMap << Comment("s, added to each sensor's stamps");
  }

  const CalibrationPrior& c = d.initial_calibration;
  out << Key << "initial_calibration" << Value << BeginMap;
  out << Key << "s_v" << Value << c.mean.s_v << Key << "s_w" << Value << c.mean.s_w;
  out << Key << "p_b_m" << Value;
  emitVector(out, c.mean.p_b_m);
  out << Comment("m");
  emitRotation(out, c.mean.q_b_m);
  out << Key << "sigma" << Value << BeginMap;
  out << Key << "s_v" << Value << c.sd_s_v << Key << "s_w" << Value << c.sd_s_w;
  out << Key << "p_b_m" << Value;
  emitVector(out, c.sd_p_b_m);
  out << Key << "rpy_b_m_deg" << Value;
  emitVector(out, c.sd_rpy_b_m * kRadToDeg);
  out << EndMap << EndMap << EndMap;
  writeYaml(d.folder + "/dataset.yaml", out, "giocal dataset description");
}

TruthCalibration readTruthCalibration(const std::string& path) {
  const YamlFields y(path);
  TruthCalibration t;
  t.calib.s_v = y.number("s_v", -kMaxScale, kMaxScale);
  t.calib.s_w = y.number("s_w", -kMaxScale, kMaxScale);
  t.calib.p_b_m = y.vector3("p_b_m", -kMaxLever, kMaxLever);
  // The rotation keys sit at the top level of this file; reuse the checked reader on a wrapper.
  YAML::Node wrapper;
  wrapper["calib"] = y.root();
  t.calib.q_b_m = readRotation(YamlFields(path, wrapper), "calib");
  t.p_b_g = y.vector3("p_b_g", -kMaxLever, kMaxLever);
  if (y.has("gyro_tilt_deg")) t.gyro_tilt_deg = y.numberList("gyro_tilt_deg", 2);
  return t;
}

void writeTruthCalibration(const std::string& path, const TruthCalibration& t) {
  YAML::Emitter out;
  out.SetDoublePrecision(15);
  out << YAML::BeginMap;
  out << YAML::Key << "s_v" << YAML::Value << t.calib.s_v;
  out << YAML::Key << "s_w" << YAML::Value << t.calib.s_w;
  out << YAML::Key << "p_b_m" << YAML::Value;
  emitVector(out, t.calib.p_b_m);
  emitRotation(out, t.calib.q_b_m);
  out << YAML::Key << "p_b_g" << YAML::Value;
  emitVector(out, t.p_b_g);
  if (t.gyro_tilt_deg.allFinite()) {
    out << YAML::Key << "gyro_tilt_deg" << YAML::Value;
    emitVector(out, t.gyro_tilt_deg);
  }
  out << YAML::EndMap;
  writeYaml(path, out, "giocal true calibration (m, degrees; q_b_m is [w, x, y, z])");
}

}  // namespace giocal
