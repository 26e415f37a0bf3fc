#include "fgo/fgo_calibrator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <numeric>
#include <set>
#include <stdexcept>

#include "common/calibration/initial_state.h"
#include "common/calibration/weak_directions.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/code_outlier_check.h"
#include "common/gnss/dd_epoch.h"
#include "common/gnss/doppler.h"
#include "common/gnss/lambda.h"
#include "common/imu/gyro_mean.h"
#include "common/imu/imu_preintegration.h"
#include "common/math/rotation.h"
#include "common/models/ambiguity_fix_model.h"
#include "common/models/dd_gnss_model.h"
#include "common/models/doppler_model.h"
#include "common/models/heading_change_model.h"
#include "common/models/imu_preintegration_model.h"
#include "common/models/nhc_model.h"
#include "common/models/odometer_preintegration_model.h"
#include "common/models/planar_motion_projection.h"
#include "common/models/prior_model.h"
#include "common/models/random_walk_model.h"
#include "common/models/standstill_projection.h"
#include "common/models/zupt_model.h"
#include "common/motion/motion_detector.h"
#include "common/odometer/odometer_preintegration.h"
#include "fgo/sliding_window.h"

namespace giocal {
namespace {

constexpr const char* kPbm = "p_b_m";
constexpr const char* kQbm = "q_b_m";
constexpr const char* kPbg = "p_b_g";

/// The variables of one GNSS epoch.
struct Epoch {
  double t = 0.0;
  int k = 0;
  bool still = false;
  std::string p, q, v, ba, bg, sv, sw, cd;
  DdEpoch dd;
  std::vector<DdObservation> code_rows, phase_rows;
  std::vector<DopplerObservation> doppler;
  Eigen::Vector3d gyro = Eigen::Vector3d::Zero();

  std::vector<std::string> all() const { return {p, q, v, ba, bg, sv, sw, cd}; }
};

std::string tagged(const char* what, int k) { return std::string(what) + "#" + std::to_string(k); }

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

class FactorGraphCalibrator {
 public:
  FactorGraphCalibrator(const CalibrationInputs& in, const CalibrationOptions& o,
                        const FgoOptions& fo, const InitialState& init, CalibrationRun& run)
      : in_(in),
        o_(o),
        fo_(fo),
        run_(run),
        frame_(init.origin_e),
        orbits_(in.nav),
        builder_(orbits_, in.base_e, o.dd),
        rover_check_(o.code_outliers),
        base_check_(o.code_outliers),
        motion_([&] {
          MotionDetectorOptions m = o.models.motion;
          m.gyro_noise_density = in.description.imu_noise.gyro_noise_density;
          return m;
        }()) {
    start(init);
  }

  /// One GNSS epoch; returns whether validated fixes hold in it.
  bool addEpoch(const ObsEpoch& rover, const ObsEpoch& base);
  const std::deque<Epoch>& epochs() const { return epochs_; }

 private:
  Epoch newEpoch(double t);
  void addNavVariables(const Epoch& e, const NavState& x, double s_v, double s_w, double cd);
  NavState nav(const Epoch& e) const;
  void feedMotion(double t, const Eigen::Vector3d& b_g);
  void gnssFactors(Epoch& e, const ObsEpoch& rover, const ObsEpoch& base);
  void addGnssRowFactors(const Epoch& e);
  std::string ambiguityVar(const SatId& sat, char band) const;
  void newAmbiguity(const SatId& sat, char band, double value, double lambda);
  std::vector<std::string> phaseVars(const DdGnssModel& model,
                                     const std::vector<DdObservation>& rows) const;
  void start(const InitialState& init);
  /// |residual| / sigma of each of the epoch's code or phase rows at the current values.
  Eigen::VectorXd normalizedRowResiduals(const Epoch& e, bool phase) const;
  bool rejectWorstRow(Epoch& e);
  bool resolve(Epoch& e);
  void record(const Epoch& e);
  void outputTrajectory(const Epoch& from, const Epoch& to);
  void marginalizeOldest();
  /// With p_b_m.z held (planar motion), vehicle-motion factors are blind to p_b_m along the
  /// vehicle's vertical axis (common/models/planar_motion_projection.h).
  std::shared_ptr<const MeasurementModel> planar(std::shared_ptr<const MeasurementModel> m) const {
    if (!o_.hold_p_b_m_z) return m;
    return std::make_shared<PlanarMotionProjection>(std::move(m));
  }

  const CalibrationInputs& in_;
  CalibrationOptions o_;
  FgoOptions fo_;
  CalibrationRun& run_;
  LocalFrame frame_;
  BroadcastOrbits orbits_;
  DdEpochBuilder builder_;
  CodeOutlierCheck rover_check_, base_check_;
  MotionDetector motion_;
  SlidingWindow w_;
  std::deque<Epoch> epochs_;
  int next_k_ = 0;
  std::map<std::pair<SatId, char>, int> amb_version_;
  std::set<std::pair<std::string, std::string>> held_fixes_;
  double motion_fed_t_ = -INFINITY;
  double next_output_ = 0.0;
  bool clock_drift_started_ = false;
};

Epoch FactorGraphCalibrator::newEpoch(double t) {
  Epoch e;
  e.t = t;
  e.k = next_k_++;
  e.p = tagged("p_n_b", e.k);
  e.q = tagged("q_n_b", e.k);
  e.v = tagged("v_n_b", e.k);
  e.ba = tagged("b_a", e.k);
  e.bg = tagged("b_g", e.k);
  e.sv = tagged("s_v", e.k);
  e.sw = tagged("s_w", e.k);
  e.cd = tagged("cdt_dot", e.k);
  return e;
}

void FactorGraphCalibrator::addNavVariables(const Epoch& e, const NavState& x, double s_v,
                                            double s_w, double cd) {
  Eigen::VectorXd q(4);
  quatToWxyz(x.q_n_b, q.data());
  w_.addVariable(vectorBlock(e.p), x.p_n_b);
  w_.addVariable(rotationBlock(e.q), q);
  w_.addVariable(vectorBlock(e.v), x.v_n_b);
  w_.addVariable(vectorBlock(e.ba), x.b_a);
  w_.addVariable(vectorBlock(e.bg), x.b_g);
  w_.addVariable(vectorBlock(e.sv, 1), Eigen::VectorXd::Constant(1, s_v));
  w_.addVariable(vectorBlock(e.sw, 1), Eigen::VectorXd::Constant(1, s_w));
  w_.addVariable(vectorBlock(e.cd, 1), Eigen::VectorXd::Constant(1, cd));
}

NavState FactorGraphCalibrator::nav(const Epoch& e) const {
  NavState x;
  x.t = e.t;
  x.p_n_b = w_.value(e.p);
  x.q_n_b = quatFromWxyz(w_.value(e.q).data());
  x.v_n_b = w_.value(e.v);
  x.b_a = w_.value(e.ba);
  x.b_g = w_.value(e.bg);
  return x;
}

void FactorGraphCalibrator::feedMotion(double t, const Eigen::Vector3d& b_g) {
  for (const ImuSample& s : in_.imu) {
    if (s.t <= motion_fed_t_) continue;
    if (s.t > t) break;
    motion_.addImu(s.t, s.gyro - b_g);
  }
  for (const OdomSample& s : in_.odom) {
    if (s.t <= motion_fed_t_) continue;
    if (s.t > t) break;
    motion_.addOdometer(s.t, s.v);
  }
  motion_fed_t_ = t;
}

std::string FactorGraphCalibrator::ambiguityVar(const SatId& sat, char band) const {
  const auto it = amb_version_.find({sat, band});
  if (it == amb_version_.end()) return "";
  return "N:" + sat.str() + ":" + std::string(1, band) + "#" + std::to_string(it->second);
}

void FactorGraphCalibrator::newAmbiguity(const SatId& sat, char band, double value, double lambda) {
  ++amb_version_[{sat, band}];
  const std::string name = ambiguityVar(sat, band);
  w_.addVariable(vectorBlock(name, 1), Eigen::VectorXd::Constant(1, value));
  // Start from code, as the filter does: 10 m of uncertainty.
  w_.addFactor(
      {std::make_shared<PriorModel>(std::vector<StateBlock>{vectorBlock(name, 1)},
                                    Eigen::VectorXd::Constant(1, value),
                                    Eigen::MatrixXd::Constant(1, 1, std::pow(10.0 / lambda, 2))),
       {name},
       0.0,
       "ambiguity_prior"});
}

std::vector<std::string> FactorGraphCalibrator::phaseVars(
    const DdGnssModel& model, const std::vector<DdObservation>& rows) const {
  // Model block "N:<sat>:<band>" -> the current version of that ambiguity.
  std::vector<std::string> vars(model.blocks().size());
  vars[2] = kPbg;
  for (const DdObservation& o : rows) {
    for (const SatId& sat : {o.sat, o.ref}) {
      const int b = model.ambiguityBlock(sat, o.band);
      if (b >= 0) vars[static_cast<size_t>(b)] = ambiguityVar(sat, o.band);
    }
  }
  return vars;
}

void FactorGraphCalibrator::start(const InitialState& init) {
  Epoch e = newEpoch(init.x.t);
  const CalibrationPrior& prior = in_.description.initial_calibration;
  addNavVariables(e, init.x, prior.mean.s_v, prior.mean.s_w, 0.0);
  Eigen::VectorXd q_bm(4);
  quatToWxyz(prior.mean.q_b_m, q_bm.data());
  w_.addVariable(vectorBlock(kPbm), prior.mean.p_b_m);
  w_.addVariable(rotationBlock(kQbm), q_bm);
  w_.addVariable(vectorBlock(kPbg), in_.description.p_b_g);
  if (o_.hold_p_b_m_z) w_.holdComponents(kPbm, {2});
  // The initial state and the calibration prior, with their cross-covariance (heading).
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(23, 23);
  P.topLeftCorner(15, 15) = init.P_nav;
  P.block(15, 15, 8, 8) = priorCalibrationCovariance(prior);
  P.block(0, 15, 15, 8) = init.P_nav_calib;
  P.block(15, 0, 8, 15) = init.P_nav_calib.transpose();
  std::vector<StateBlock> blocks{vectorBlock(e.p),     rotationBlock(e.q), vectorBlock(e.v),
                                 vectorBlock(e.ba),    vectorBlock(e.bg),  vectorBlock(e.sv, 1),
                                 vectorBlock(e.sw, 1), vectorBlock(kPbm),  rotationBlock(kQbm)};
  Eigen::VectorXd mean(0);
  std::vector<std::string> names;
  for (const StateBlock& b : blocks) {
    const Eigen::VectorXd& x = w_.value(b.name);
    mean.conservativeResize(mean.size() + x.size());
    mean.tail(x.size()) = x;
    names.push_back(b.name);
  }
  w_.addFactor({std::make_shared<PriorModel>(blocks, mean, P), names, 0.0, "initial_prior"});
  w_.addFactor(
      {std::make_shared<PriorModel>(std::vector<StateBlock>{vectorBlock(e.cd, 1)},
                                    Eigen::VectorXd::Zero(1), Eigen::MatrixXd::Constant(1, 1, 1e6)),
       {e.cd},
       0.0,
       "clock_drift_prior"});
  if (o_.estimate_p_b_g) {
    w_.addFactor({std::make_shared<PriorModel>(
                      std::vector<StateBlock>{vectorBlock(kPbg)}, in_.description.p_b_g,
                      Eigen::Matrix3d::Identity() * o_.p_b_g_sigma * o_.p_b_g_sigma),
                  {kPbg},
                  0.0,
                  "lever_prior"});
  } else {
    w_.setConstant(kPbg, true);
  }
  feedMotion(e.t, init.x.b_g);
  e.still = motion_.isStatic();
  next_output_ = e.t;
  epochs_.push_back(e);
}

void FactorGraphCalibrator::gnssFactors(Epoch& e, const ObsEpoch& rover, const ObsEpoch& base) {
  // Stage 1: pseudo-ranges that disagree with their Doppler-predicted change (shared with the EKF).
  const auto bad_rover = rover_check_.check(rover);
  const auto bad_base = base_check_.check(base);
  const NavState x = nav(e);
  const Eigen::Vector3d ant_e = frame_.ecefFromEnu(x.p_n_b + x.q_n_b * w_.value(kPbg));
  e.dd = builder_.build(rover, base, ant_e);
  for (const SdAmbiguity& a : e.dd.ambiguities) {
    const std::string cur = ambiguityVar(a.sat, a.band);
    if (a.slipped || cur.empty() || !w_.has(cur)) {
      run_.counters["ambiguity_resets"] += a.slipped && !cur.empty();
      newAmbiguity(a.sat, a.band, a.code_value, a.lambda);
    }
  }
  for (const DdObservation& o : e.dd.obs) {
    if (o.phase) {
      e.phase_rows.push_back(o);
      continue;
    }
    const auto flagged = [&](const SatId& s) {
      return bad_rover.count({s, o.band}) || bad_base.count({s, o.band});
    };
    if (flagged(o.sat) || flagged(o.ref)) {
      ++run_.counters["code_outliers"];
      continue;
    }
    e.code_rows.push_back(o);
  }
  // Stage 2: code rows far from the IMU/odometer prediction (the prediction's own uncertainty,
  // centimetres over one epoch, is small against code noise).
  if (!e.code_rows.empty()) {
    const DdGnssModel code(frame_, e.dd.geometry, e.code_rows, e.dd.undiff_variance);
    const double* params[3] = {w_.value(e.p).data(), w_.value(e.q).data(), w_.value(kPbg).data()};
    Eigen::VectorXd r;
    code.evaluate(params, r, nullptr);
    const Eigen::VectorXd sd = code.covariance().diagonal().cwiseSqrt();
    std::vector<DdObservation> kept;
    for (long i = 0; i < r.size(); ++i) {
      if (std::abs(r[i]) <= o_.innovation_gate * sd[i]) {
        kept.push_back(e.code_rows[static_cast<size_t>(i)]);
      } else {
        ++run_.counters["gnss_rows_rejected"];
      }
    }
    e.code_rows = kept;
  }
  const GyroMean g = meanGyro(in_.imu, e.t, 0.5 * o_.models.motion.window_s,
                              in_.description.imu_noise.gyro_noise_density);
  e.gyro = g.rate;
  e.doppler = dopplerObservations(rover, orbits_, ant_e, o_.doppler);
  if (e.doppler.size() >= 4 && !clock_drift_started_) {
    // Start the clock drift from the median residual at zero drift.
    const DopplerModel m(frame_.R_e_n(), e.gyro, e.doppler);
    const double* params[5] = {w_.value(e.v).data(), w_.value(e.q).data(), w_.value(e.bg).data(),
                               w_.value(kPbg).data(), w_.value(e.cd).data()};
    w_.value(e.cd)[0] = 0.0;
    Eigen::VectorXd r;
    m.evaluate(params, r, nullptr);
    w_.value(e.cd)[0] = -median(std::vector<double>(r.data(), r.data() + r.size()));
    clock_drift_started_ = true;
  }
  addGnssRowFactors(e);
}

void FactorGraphCalibrator::addGnssRowFactors(const Epoch& e) {
  for (const char* t : {"dd_code", "dd_phase", "doppler"}) w_.removeFactors(tagged(t, e.k));
  if (!e.code_rows.empty()) {
    w_.addFactor(
        {std::make_shared<DdGnssModel>(frame_, e.dd.geometry, e.code_rows, e.dd.undiff_variance),
         {e.p, e.q, kPbg},
         fo_.code_huber,
         tagged("dd_code", e.k)});
  }
  if (!e.phase_rows.empty()) {
    auto model =
        std::make_shared<DdGnssModel>(frame_, e.dd.geometry, e.phase_rows, e.dd.undiff_variance);
    std::vector<std::string> vars = phaseVars(*model, e.phase_rows);
    vars[0] = e.p;
    vars[1] = e.q;
    w_.addFactor({model, vars, 0.0, tagged("dd_phase", e.k)});
  }
  if (e.doppler.size() >= 4) {
    w_.addFactor({std::make_shared<DopplerModel>(frame_.R_e_n(), e.gyro, e.doppler),
                  {e.v, e.q, e.bg, kPbg, e.cd},
                  fo_.code_huber,
                  tagged("doppler", e.k)});
  }
}

Eigen::VectorXd FactorGraphCalibrator::normalizedRowResiduals(const Epoch& e, bool phase) const {
  const std::vector<DdObservation>& rows = phase ? e.phase_rows : e.code_rows;
  if (rows.empty()) return Eigen::VectorXd::Zero(1);
  const DdGnssModel m(frame_, e.dd.geometry, rows, e.dd.undiff_variance);
  std::vector<std::string> vars =
      phase ? phaseVars(m, rows) : std::vector<std::string>{"", "", kPbg};
  vars[0] = e.p;
  vars[1] = e.q;
  std::vector<const double*> params;
  for (const std::string& v : vars) params.push_back(w_.value(v).data());
  Eigen::VectorXd r;
  m.evaluate(params.data(), r, nullptr);
  return r.cwiseAbs().cwiseQuotient(m.covariance().diagonal().cwiseSqrt());
}

bool FactorGraphCalibrator::rejectWorstRow(Epoch& e) {
  // Residual-based rejection after a solve: the worst DD row beyond rejection_sigma goes; a
  // phase row's ambiguity restarts (most likely an undetected slip).
  double worst = fo_.rejection_sigma;
  int which = -1;
  bool phase = false;
  for (bool ph : {false, true}) {
    const Eigen::VectorXd z = normalizedRowResiduals(e, ph);
    for (long i = 0; i < z.size(); ++i) {
      if (z[i] > worst) {
        worst = z[i];
        which = static_cast<int>(i);
        phase = ph;
      }
    }
  }
  if (which < 0) return false;
  ++run_.counters["gnss_rows_rejected"];
  std::vector<DdObservation>& rows = phase ? e.phase_rows : e.code_rows;
  const DdObservation bad = rows[static_cast<size_t>(which)];
  rows.erase(rows.begin() + which);
  if (phase) {
    for (const SdAmbiguity& a : e.dd.ambiguities) {
      if (a.sat == bad.sat && a.band == bad.band)
        newAmbiguity(a.sat, a.band, a.code_value, a.lambda);
    }
    ++run_.counters["ambiguity_resets"];
  }
  addGnssRowFactors(e);
  return true;
}

bool FactorGraphCalibrator::resolve(Epoch& e) {
  const long na = static_cast<long>(e.phase_rows.size());
  if (na < o_.lambda.min_fixed) return false;
  std::vector<std::string> amb;
  auto index = [&](const std::string& n) {
    const auto it = std::find(amb.begin(), amb.end(), n);
    if (it != amb.end()) return static_cast<long>(it - amb.begin());
    amb.push_back(n);
    return static_cast<long>(amb.size()) - 1;
  };
  std::vector<std::pair<long, long>> pairs;
  std::vector<double> el;
  for (const DdObservation& o : e.phase_rows) {
    pairs.push_back({index(ambiguityVar(o.sat, o.band)), index(ambiguityVar(o.ref, o.band))});
    el.push_back(e.dd.geometry[static_cast<size_t>(o.sat_index)].el);
  }
  // Float DD ambiguities and their covariance from the window.
  const Eigen::MatrixXd C = w_.covariance(amb);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(na, static_cast<long>(amb.size()));
  Eigen::VectorXd a(na);
  for (long k = 0; k < na; ++k) {
    const auto [i, j] = pairs[static_cast<size_t>(k)];
    A(k, i) = 1.0;
    A(k, j) = -1.0;
    a[k] = w_.value(amb[static_cast<size_t>(i)])[0] - w_.value(amb[static_cast<size_t>(j)])[0];
  }
  const Eigen::MatrixXd Qa = A * C * A.transpose();
  std::vector<int> drop(static_cast<size_t>(na));
  std::iota(drop.begin(), drop.end(), 0);
  std::sort(drop.begin(), drop.end(),
            [&](int x, int y) { return el[static_cast<size_t>(x)] < el[static_cast<size_t>(y)]; });
  AmbiguityFix fix;
  try {
    fix = resolveAmbiguities(a, 0.5 * (Qa + Qa.transpose()), drop, o_.lambda);
  } catch (const std::invalid_argument&) {
    return false;
  }
  if (!fix.fixed) return false;
  std::vector<DdAmbiguityFix> fresh;
  for (size_t k = 0; k < fix.indices.size(); ++k) {
    const auto [i, j] = pairs[static_cast<size_t>(fix.indices[k])];
    const std::pair<std::string, std::string> key{amb[static_cast<size_t>(i)],
                                                  amb[static_cast<size_t>(j)]};
    if (held_fixes_.count(key)) continue;
    fresh.push_back({key.first, key.second, fix.values[static_cast<long>(k)]});
  }
  if (fresh.empty()) return true;
  const std::string tag = tagged("fix", e.k);
  for (const DdAmbiguityFix& f : fresh) {
    w_.addFactor(
        {std::make_shared<AmbiguityFixModel>(std::vector<DdAmbiguityFix>{f}, o_.fix_sigma_cycles),
         {f.sat_block, f.ref_block},
         0.0,
         tag});
  }
  w_.solve(fo_.max_iterations);
  // Validate by the fixed solution's DD phase residuals, not by the cost (the IMU and odometer
  // factors make any fix raise it).
  if (normalizedRowResiduals(e, true).maxCoeff() > o_.max_fix_residual) {
    w_.removeFactors(tag);
    w_.solve(fo_.max_iterations);
    ++run_.counters["fixes_rejected"];
    return false;
  }
  for (const DdAmbiguityFix& f : fresh) held_fixes_.insert({f.sat_block, f.ref_block});
  return true;
}

void FactorGraphCalibrator::record(const Epoch& e) {
  CalibrationEstimate est;
  est.t = e.t;
  est.calib.s_v = w_.value(e.sv)[0];
  est.calib.s_w = w_.value(e.sw)[0];
  est.calib.p_b_m = w_.value(kPbm);
  est.calib.q_b_m = quatFromWxyz(w_.value(kQbm).data());
  est.cov = w_.covariance({e.sv, e.sw, kPbm, kQbm});
  if (o_.hold_p_b_m_z) {
    // Held at the prior: its sigma is the prior's, and nothing correlates with it.
    const int z = calib_index::kP + 2;
    est.cov.row(z).setZero();
    est.cov.col(z).setZero();
    est.cov(z, z) = std::pow(in_.description.initial_calibration.sd_p_b_m.z(), 2);
  }
  run_.history.push_back(est);
}

void FactorGraphCalibrator::outputTrajectory(const Epoch& from, const Epoch& to) {
  const NavState x0 = nav(from);
  while (next_output_ <= to.t + 1e-9) {
    NavState x = x0;
    if (next_output_ > from.t) {
      ImuPreintegration pre(in_.description.imu_noise, frame_.gravity_n(x0.p_n_b),
                            frame_.omega_ie_n(), x0.b_a, x0.b_g);
      pre.integrateSamples(in_.imu, from.t, next_output_);
      x = pre.predict(x0);
    }
    run_.trajectory.push_back(truthRow(frame_, x, std::max(next_output_, from.t)));
    next_output_ += 1.0 / o_.output_rate_hz;
  }
}

void FactorGraphCalibrator::marginalizeOldest() {
  const Epoch old = epochs_.front();
  epochs_.pop_front();
  const std::vector<std::string> mine = old.all();
  const std::set<std::string> mine_set(mine.begin(), mine.end());
  // Ambiguities seen only by the oldest epoch's factors leave with it.
  std::set<std::string> epoch_vars;
  for (const Epoch& e : epochs_) {
    for (const std::string& v : e.all()) epoch_vars.insert(v);
  }
  std::map<std::string, bool> still_used;
  for (const Factor& f : w_.factors()) {
    const bool touches_old = std::any_of(f.vars.begin(), f.vars.end(),
                                         [&](const std::string& v) { return mine_set.count(v); });
    const bool touches_epoch = std::any_of(
        f.vars.begin(), f.vars.end(), [&](const std::string& v) { return epoch_vars.count(v); });
    for (const std::string& v : f.vars) {
      if (v.rfind("N:", 0) != 0) continue;
      still_used[v] = still_used[v] || (touches_epoch && !touches_old);
    }
  }
  std::vector<std::string> drop = mine;
  for (const auto& [v, used] : still_used) {
    if (!used) drop.push_back(v);
  }
  for (auto it = held_fixes_.begin(); it != held_fixes_.end();) {
    const bool gone = std::find(drop.begin(), drop.end(), it->first) != drop.end() ||
                      std::find(drop.begin(), drop.end(), it->second) != drop.end();
    it = gone ? held_fixes_.erase(it) : std::next(it);
  }
  w_.marginalize(drop);
}

bool FactorGraphCalibrator::addEpoch(const ObsEpoch& rover, const ObsEpoch& base) {
  const Epoch prev = epochs_.back();
  Epoch e = newEpoch(rover.t);
  const double dt = e.t - prev.t;
  const NavState x_prev = nav(prev);
  auto imu =
      std::make_shared<ImuPreintegration>(in_.description.imu_noise, frame_.gravity_n(x_prev.p_n_b),
                                          frame_.omega_ie_n(), x_prev.b_a, x_prev.b_g);
  imu->integrateSamples(in_.imu, prev.t, e.t);
  addNavVariables(e, imu->predict(x_prev), w_.value(prev.sv)[0], w_.value(prev.sw)[0],
                  w_.value(prev.cd)[0]);
  w_.addFactor({std::make_shared<ImuPreintegrationModel>(imu),
                {prev.p, prev.q, prev.v, prev.ba, prev.bg, e.p, e.q, e.v, e.ba, e.bg},
                0.0,
                tagged("imu", e.k)});
  OdometerPreintegrationNoise on;
  on.speed_sigma = in_.description.odom_noise.speed_sigma;
  on.yaw_rate_sigma = in_.description.odom_noise.yaw_rate_sigma;
  on.lateral_speed_density = o_.models.lateral_speed_density;
  on.tilt_rate_density = o_.models.tilt_rate_density;
  auto odo =
      std::make_shared<OdometerPreintegration>(on, w_.value(prev.sv)[0], w_.value(prev.sw)[0]);
  // Motion constraints and whether the robot stood still over the interval.
  feedMotion(e.t, x_prev.b_g);
  e.still = motion_.isStatic();
  if (in_.odom.front().t <= prev.t) {
    odo->integrateSamples(in_.odom, prev.t, e.t);
    std::shared_ptr<const MeasurementModel> model =
        planar(std::make_shared<OdometerPreintegrationModel>(odo));
    if (e.still && prev.still) model = std::make_shared<StandstillProjection>(model);
    w_.addFactor({model,
                  {prev.p, prev.q, e.p, e.q, prev.sv, prev.sw, kPbm, kQbm},
                  0.0,
                  tagged("odometer", e.k)});
  }
  // Scales and clock drift as random walks (a floor keeps a zero density well posed).
  const double q_s = std::max(in_.description.odom_noise.scale_random_walk, 1e-5) * std::sqrt(dt);
  w_.addFactor({std::make_shared<RandomWalkModel>("s_v", 1, q_s), {prev.sv, e.sv}, 0.0, "rw"});
  w_.addFactor({std::make_shared<RandomWalkModel>("s_w", 1, q_s), {prev.sw, e.sw}, 0.0, "rw"});
  w_.addFactor({std::make_shared<RandomWalkModel>(
                    "cdt_dot", 1, std::max(o_.clock_drift_noise, 1e-6) * std::sqrt(dt)),
                {prev.cd, e.cd},
                0.0,
                "rw"});
  if (e.still) {
    w_.addFactor({std::make_shared<ZuptModel>(o_.models.zupt_sigma), {e.v}, 0.0, "zupt"});
    if (prev.still) {
      w_.addFactor({std::make_shared<HeadingChangeModel>(o_.heading_sigma_deg * kDegToRad),
                    {prev.q, e.q},
                    0.0,
                    "heading"});
    }
  }
  if (motion_.nhcApplies()) {
    const GyroMean g = meanGyro(in_.imu, e.t, 0.5 * o_.models.motion.window_s,
                                in_.description.imu_noise.gyro_noise_density);
    w_.addFactor({planar(std::make_shared<NhcModel>(g.rate, o_.models.nhc_sigma)),
                  {e.v, e.q, e.bg, kPbm, kQbm},
                  0.0,
                  "nhc"});
  }
  gnssFactors(e, rover, base);
  epochs_.push_back(e);
  Epoch& cur = epochs_.back();
  w_.solve(fo_.max_iterations);
  for (int r = 0; r < fo_.max_rejections && rejectWorstRow(cur); ++r) w_.solve(fo_.max_iterations);
  const bool fixed = o_.ambiguity_resolution && resolve(cur);
  run_.counters["dd_rows"] += static_cast<long>(cur.code_rows.size() + cur.phase_rows.size());
  record(cur);
  outputTrajectory(epochs_[epochs_.size() - 2], cur);
  if (static_cast<int>(epochs_.size()) > fo_.window) marginalizeOldest();
  return fixed;
}

}  // namespace

CalibrationRun runFgoCalibration(const CalibrationInputs& in, const CalibrationOptions& options,
                                 const FgoOptions& fgo_options) {
  const auto start = std::chrono::steady_clock::now();
  CalibrationRun run;
  run.estimator = "fgo";
  run.data_duration_s = in.dataDuration();
  run.p_b_m_z = options.hold_p_b_m_z
                    ? "held at the prior (constant in the graph): planar motion leaves it "
                      "unobservable"
                    : "estimated; unobservable under planar motion, its sigma stays near the prior";
  for (const char* c : {"dd_rows", "gnss_rows_rejected", "code_outliers", "ambiguity_resets",
                        "fixes_rejected", "gnss_without_base"}) {
    run.counters[c] = 0;
  }
  std::string why;
  const auto init =
      findInitialState(in, options, in.description.initial_calibration, in.imu.front().t, &why);
  if (!init) throw std::runtime_error("could not initialize: " + why);
  run.t_initialized = init->x.t;
  run.initialization = {{"static_window_s", init->static_window_s},
                        {"heading_baseline_m", init->heading_baseline_m},
                        {"heading_sigma_deg", init->heading_sigma * kRadToDeg}};
  FactorGraphCalibrator graph(in, options, fgo_options, *init, run);
  BaseEpochMatcher matcher(in.base.epochs, options.max_base_offset);
  double epoch_time = 0.0;
  int solved = 0;
  for (const ObsEpoch& rover : in.rover.epochs) {
    if (rover.t <= graph.epochs().back().t + 1e-6 || rover.t > in.imu.back().t) continue;
    const ObsEpoch* base = matcher.nearest(rover.t);
    if (!base) {
      ++run.counters["gnss_without_base"];
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const bool fixed = graph.addEpoch(rover, *base);
    epoch_time += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++solved;
    ++run.gnss_epochs;
    run.fixed_epochs += fixed;
  }
  run.timing["mean_epoch_s"] = solved ? epoch_time / solved : 0.0;
  if (!run.history.empty()) {
    for (const std::string& w :
         weakDirections(run.history.back(), in.description.initial_calibration))
      run.warnings.push_back(w);
  }
  run.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace giocal
