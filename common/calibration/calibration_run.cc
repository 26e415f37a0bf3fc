#include "common/calibration/calibration_run.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "common/math/rotation.h"

namespace giocal {
namespace {

Eigen::Vector3d rpyDeg(const Eigen::Quaterniond& q) {
  return rpyFromRotation(q.toRotationMatrix()) * kRadToDeg;
}

nlohmann::json vec(const Eigen::VectorXd& v) {
  return nlohmann::json(std::vector<double>(v.data(), v.data() + v.size()));
}

}  // namespace

TruthSample truthRow(const LocalFrame& frame, const NavState& x, double t) {
  TruthSample s;
  s.t = t;
  const Geodetic g = geodeticFromEcef(frame.ecefFromEnu(x.p_n_b));
  s.lat_deg = g.lat * kRadToDeg;
  s.lon_deg = g.lon * kRadToDeg;
  s.h = g.h;
  const Eigen::Matrix3d R_here_n = rotationEcefFromEnu(g.lat, g.lon).transpose() * frame.R_e_n();
  s.v_enu = R_here_n * x.v_n_b;
  s.q_n_b = Eigen::Quaterniond(R_here_n * x.q_n_b.toRotationMatrix()).normalized();
  return s;
}

// Central differences: an output conversion, not an estimator Jacobian.
Eigen::Matrix3d rpyTangentJacobian(const Eigen::Quaterniond& q) {
  Eigen::Matrix3d J;
  const double h = 1e-6;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d d = Eigen::Vector3d::Unit(k) * h;
    const Eigen::Vector3d a = rpyFromRotation(boxPlus(q, d).toRotationMatrix());
    const Eigen::Vector3d b = rpyFromRotation(boxPlus(q, -d).toRotationMatrix());
    for (int r = 0; r < 3; ++r) J(r, k) = std::remainder(a[r] - b[r], 2.0 * M_PI) / (2.0 * h);
  }
  return J;
}

Eigen::Vector3d CalibrationEstimate::rpySigma() const {
  const Eigen::Matrix3d J = rpyTangentJacobian(calib.q_b_m);
  const Eigen::Matrix3d C =
      J * cov.block<3, 3>(calib_index::kTheta, calib_index::kTheta) * J.transpose();
  return C.diagonal().cwiseMax(0.0).cwiseSqrt();
}

Eigen::Matrix<double, 8, 1> CalibrationEstimate::sigma() const {
  Eigen::Matrix<double, 8, 1> sd;
  sd.head<5>() = cov.diagonal().head<5>().cwiseMax(0.0).cwiseSqrt();
  sd.tail<3>() = rpySigma() * kRadToDeg;
  return sd;
}

CalibrationError calibrationError(const CalibrationEstimate& e, const OdometerCalibration& truth) {
  CalibrationError err;
  err.s_v = e.calib.s_v - truth.s_v;
  err.s_w = e.calib.s_w - truth.s_w;
  err.p_b_m = e.calib.p_b_m - truth.p_b_m;
  const Eigen::Vector3d a = rpyFromRotation(e.calib.q_b_m.toRotationMatrix());
  const Eigen::Vector3d b = rpyFromRotation(truth.q_b_m.toRotationMatrix());
  for (int k = 0; k < 3; ++k) err.rpy[k] = std::remainder(a[k] - b[k], 2.0 * M_PI);
  err.tangent << err.s_v, err.s_w, err.p_b_m, boxMinus(e.calib.q_b_m, truth.q_b_m);
  const int idx[7] = {calib_index::kSv,       calib_index::kSw,    calib_index::kP,
                      calib_index::kP + 1,    calib_index::kTheta, calib_index::kTheta + 1,
                      calib_index::kTheta + 2};
  Eigen::Matrix<double, 7, 7> C;
  Eigen::Matrix<double, 7, 1> d;
  for (int r = 0; r < 7; ++r) {
    d[r] = err.tangent[idx[r]];
    for (int c = 0; c < 7; ++c) C(r, c) = e.cov(idx[r], idx[c]);
  }
  const Eigen::LDLT<Eigen::Matrix<double, 7, 7>> ldlt(C);
  err.nees7 = ldlt.info() == Eigen::Success ? d.dot(ldlt.solve(d)) : NAN;
  return err;
}

double calibrationStepChi2(const CalibrationEstimate& before, const CalibrationEstimate& after) {
  CalibrationEstimate moved = after;
  moved.cov = before.cov;
  return calibrationError(moved, before.calib).nees7;
}

std::vector<std::string> calibrationOutputFiles() {
  return {"calibration.csv", "trajectory.csv", "gnss.csv", "summary.json"};
}

long CalibrationRun::counter(Counter c) const {
  const auto it = counters.find(counterName(c));
  return it == counters.end() ? 0 : it->second;
}

void CalibrationRun::warn(const std::string& w) {
  if (warnings.size() < kMaxWarnings) warnings.push_back(w);
  if (warnings.size() == kMaxWarnings) warnings.push_back("(further warnings omitted)");
}

const CalibrationEstimate& CalibrationRun::final() const {
  if (!latest) throw std::logic_error(estimator + ": the run produced no calibration estimate");
  return *latest;
}

const std::vector<std::string>& calibrationCsvHeader() {
  static const std::vector<std::string> h{
      "t",      "s_v",    "s_w",   "px",    "py",    "pz",      "roll",     "pitch", "yaw",
      "sd_s_v", "sd_s_w", "sd_px", "sd_py", "sd_pz", "sd_roll", "sd_pitch", "sd_yaw"};
  return h;
}

const std::vector<std::string>& gyroTiltCsvHeader() {
  static const std::vector<std::string> h{"t", "tilt_x", "tilt_y", "sd_tilt_x", "sd_tilt_y"};
  return h;
}

const std::vector<std::string>& odometerDelayCsvHeader() {
  static const std::vector<std::string> h{"t", "t_d_odo", "sd_t_d_odo"};
  return h;
}

std::vector<double> calibrationCsvRow(const CalibrationEstimate& e) {
  const Eigen::Vector3d rpy = rpyDeg(e.calib.q_b_m);
  const Eigen::Matrix<double, 8, 1> sd = e.sigma();
  return {e.t,
          e.calib.s_v,
          e.calib.s_w,
          e.calib.p_b_m.x(),
          e.calib.p_b_m.y(),
          e.calib.p_b_m.z(),
          rpy.x(),
          rpy.y(),
          rpy.z(),
          sd[0],
          sd[1],
          sd[2],
          sd[3],
          sd[4],
          sd[5],
          sd[6],
          sd[7]};
}

std::string summaryJson(const CalibrationRun& run, const OdometerCalibration* truth,
                        const std::map<std::string, std::uintmax_t>& files) {
  nlohmann::ordered_json j;
  j["estimator"] = run.estimator;
  j["status"] = run.status;
  if (!files.empty()) j["files"] = files;
  if (run.latest) {
    const CalibrationEstimate& e = *run.latest;
    const Eigen::Quaterniond& q = e.calib.q_b_m;
    j["final"] = {{"s_v", e.calib.s_v},
                  {"s_w", e.calib.s_w},
                  {"p_b_m", vec(e.calib.p_b_m)},
                  {"q_b_m", {q.w(), q.x(), q.y(), q.z()}},
                  {"rpy_b_m_deg", vec(rpyDeg(q))}};
    j["t_final"] = e.t;  // GPS time of the final estimate (a later drive's --prior counts from it)
    const Eigen::Matrix<double, 8, 1> sd = e.sigma();
    j["sd"] = {{"s_v", sd[0]},
               {"s_w", sd[1]},
               {"p_b_m", vec(sd.segment<3>(2))},
               {"rpy_b_m_deg", vec(sd.tail<3>())}};
    if (e.gyro_tilt.allFinite()) {  // estimated (calibration.estimate_gyro_tilt)
      j["final"]["gyro_tilt_deg"] = {e.gyro_tilt.x() * kRadToDeg, e.gyro_tilt.y() * kRadToDeg};
      j["sd"]["gyro_tilt_deg"] = {e.gyro_tilt_sd.x() * kRadToDeg, e.gyro_tilt_sd.y() * kRadToDeg};
    }
    if (std::isfinite(e.odometer_delay_s)) {  // estimated (calibration.estimate_odometer_delay)
      j["final"]["t_d_odo"] = e.odometer_delay_s;
      j["sd"]["t_d_odo"] = e.odometer_delay_sd_s;
    }
  } else {
    j["final"] = nullptr;
    j["sd"] = nullptr;
  }
  j["data_duration_s"] = run.data_duration_s;
  if (std::isfinite(run.t_first_rover_epoch)) j["t_first_rover_epoch"] = run.t_first_rover_epoch;
  j["wall_time_s"] = run.wall_time_s;
  j["gnss_epochs"] = run.gnss_epochs;
  j["fix_rate"] = run.fixRate();
  j["load_time_s"] = run.load_time_s;
  j["real_time_factor"] = run.wall_time_s > 0 ? run.data_duration_s / run.wall_time_s : 0.0;
  j["t_initialized"] = run.t_initialized;
  j["p_b_m_z"] = run.p_b_m_z;
  if (run.latest) {
    // Full tangent covariance [s_v, s_w, p_b_m, theta_b_m] for consistency checks (NEES).
    const auto& C = run.latest->cov;
    std::vector<std::vector<double>> cov(8);
    for (int r = 0; r < 8; ++r)
      for (int c = 0; c < 8; ++c) cov[static_cast<size_t>(r)].push_back(C(r, c));
    j["covariance_tangent"] = cov;
  }
  j["initialization"] = run.initialization;
  j["converged_at"] = run.converged_at;
  if (run.odometer_delay.samples > 0) {
    const OdometerDelay& d = run.odometer_delay;
    j["odometer_delay"] = {{"valid", d.valid},
                           {"delay_s", d.delay_s},
                           {"sigma_s", d.sigma_s},
                           {"blocks", d.samples},
                           {"yaw_rate_rms", d.yaw_rate_rms}};
  }
  if (run.odometer_delay_applied_s != 0.0)
    j["odometer_delay"]["applied_s"] = run.odometer_delay_applied_s;
  if (run.lc_heights) {
    const FixHeights& h = *run.lc_heights;
    j["lc_heights"] = {{"decided", h.decided},
                       {"fixes", h.fixes},
                       {"distance_m", h.distance_m},
                       {"spread_m", h.spread_m},
                       {"reported_sigma_m", h.reported_sigma_m},
                       {"scale", h.scale()},
                       {"applied_scale", run.lc_height_scale_applied}};
    if (!h.decided) j["lc_heights"]["why_not"] = h.why_not;
  }
  if (run.lc_residuals) {
    const PositionResiduals& r = *run.lc_residuals;
    j["lc_residuals"] = {{"fixes", r.fixes},
                         {"interval_s", r.interval_s},
                         {"sigma_ratio", r.sigma_ratio},
                         {"correlation_s", r.correlation_s},
                         {"fixes_per_independent", r.inflation},
                         {"sigmas_understated_by", r.understatedBy()}};
    // The calibration's sigmas as far as these fixes support them: the run's own times the
    // factor it measured (its sigmas take every fix as independent; the fixes' errors are not).
    if (j["sd"].is_object() && r.understatedBy() > 1.0) {
      auto& supported = j["sd_supported"];
      supported = j["sd"];
      for (auto& [key, value] : supported.items()) {
        if (value.is_number()) value = value.get<double>() * r.understatedBy();
        if (value.is_array()) {
          for (auto& x : value) x = x.get<double>() * r.understatedBy();
        }
      }
    }
  }
  if (!run.robot.empty()) j["robot"] = run.robot;
  if (run.validation) {
    const RunValidation& v = *run.validation;
    if (v.verdict.empty()) {
      j["validation"] = {{"why_not", v.why_not}};
    } else {
      j["validation"] = {{"verdict", v.verdict},
                         {"calibrated", v.calibrated_m},
                         {"guess", v.guess_m},
                         {"ratio", v.ratio},
                         {"better_windows", v.better_windows},
                         {"windows", v.windows},
                         {"confidence", v.confidence},
                         {"reference", v.reference}};
      j["validation"]["per_window"] = validationWindowsJson(v.per_window);
    }
  }
  j["counters"] = run.counters;
  j["timing_s"] = run.timing;
  j["warnings"] = run.warnings;
  if (!run.options.empty()) {
    // Numbers as numbers, so that readers compare them as the configuration file's values.
    nlohmann::json o = nlohmann::json::object();
    for (const auto& [key, value] : run.options) {
      char* end = nullptr;
      const double v = std::strtod(value.c_str(), &end);
      if (!value.empty() && end && *end == '\0')
        o[key] = v;
      else
        o[key] = value;
    }
    j["options"] = o;
  }
  if (truth && run.latest) {
    const CalibrationError err = calibrationError(*run.latest, *truth);
    j["error"] = {{"s_v", err.s_v},
                  {"s_w", err.s_w},
                  {"p_b_m", vec(err.p_b_m)},
                  {"rpy_b_m_deg", vec(err.rpy * kRadToDeg)},
                  {"nees7", err.nees7}};
  }
  std::ostringstream out;
  out << std::setprecision(12) << j.dump(2) << "\n";
  return out.str();
}

nlohmann::ordered_json validationWindowsJson(const std::vector<ValidationWindow>& windows) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const ValidationWindow& w : windows) {
    out.push_back({{"start_s", w.start_s},
                   {"duration_s", w.duration_s},
                   {"distance_m", w.distance_m},
                   {"calibrated_m", w.calibrated_m},
                   {"guess_m", w.guess_m}});
  }
  return out;
}

}  // namespace giocal
