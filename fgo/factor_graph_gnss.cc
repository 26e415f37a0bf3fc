// The factor graph's GNSS factors: DD code (after the shared stage-1 check and a prediction
// gate), DD phase with versioned SD ambiguities, Doppler, post-solve row rejection, and LAMBDA
// fixes validated by the fixed solution's phase residuals.
#include <algorithm>
#include <cmath>

#include "common/calibration/code_divergence.h"
#include "common/gnss/fix_validation.h"
#include "common/gnss/lambda.h"
#include "common/imu/gyro_mean.h"
#include "common/math/median.h"
#include "common/models/ambiguity_fix_model.h"
#include "common/models/doppler_model.h"
#include "common/models/prior_model.h"
#include "fgo/factor_graph_core.h"
#include "fgo/factor_tag.h"

namespace giocal {

using fgo_tag::tagged;
using state::kPbg;

std::optional<StateKey> FactorGraphCore::ambiguityVar(const SatId& sat, char band) const {
  const auto it = amb_version_.find({sat, band});
  if (it == amb_version_.end()) return std::nullopt;
  return ambiguityKey(sat, band, it->second);
}

void FactorGraphCore::newAmbiguity(const SatId& sat, char band, double value, double lambda) {
  const StateKey name = ambiguityKey(sat, band, ++amb_version_[{sat, band}]);
  w_.addVariable(vectorBlock(name, 1), Eigen::VectorXd::Constant(1, value));
  w_.addFactor(
      {std::make_shared<PriorModel>(
           std::vector<StateBlock>{vectorBlock(name, 1)}, Eigen::VectorXd::Constant(1, value),
           Eigen::MatrixXd::Constant(1, 1, ambiguityStartVariance(lambda))),
       {name},
       0.0,
       "ambiguity_prior"});
}

std::vector<StateKey> FactorGraphCore::phaseVars(const DdGnssModel& model,
                                                 const std::vector<DdObservation>& rows) const {
  // The model's ambiguity blocks (version 0) -> the current version of each ambiguity; the
  // epoch's position and attitude are the caller's.
  std::vector<StateKey> vars(model.blocks().size());
  vars[2] = kPbg;
  for (const DdObservation& o : rows) {
    for (const SatId& sat : {o.sat, o.ref}) {
      const int b = model.ambiguityBlock(sat, o.band);
      if (b >= 0) vars[static_cast<size_t>(b)] = ambiguityVar(sat, o.band).value();
    }
  }
  return vars;
}

void FactorGraphCore::gnssFactors(FgoEpoch& e, const ObsEpoch& rover, const ObsEpoch& base) {
  // Stage 1: pseudo-ranges that disagree with their Doppler-predicted change (shared with the EKF).
  const auto bad_rover = rover_check_.check(rover);
  const auto bad_base = base_check_.check(base);
  const NavState x = nav(e);
  const Eigen::Vector3d ant_e = frame_.ecefFromEnu(x.p_n_b + x.q_n_b * w_.value(kPbg));
  e.dd = builder_.build(rover, base, ant_e);
  for (const SdAmbiguity& a : e.dd.ambiguities) {
    const std::optional<StateKey> cur = ambiguityVar(a.sat, a.band);
    if (a.slipped || !cur || !w_.has(*cur)) {
      run_->count(Counter::kAmbiguityResets, a.slipped && cur);
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
      run_->count(Counter::kCodeOutliers);
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
    // Divergence, as the EKF's test: the code rows as a whole far outside their spread. The
    // prediction's own uncertainty is left out, so this fires only where the gate below would
    // reject most rows anyway, and only after a short interval: across an outage the
    // prediction is the IMU's alone, metres off (the EKF's covariance knows that).
    const Eigen::VectorXd z = r.cwiseAbs().cwiseQuotient(sd);
    if (e.t - epochs_.back().t <= o_.gnss_gap_warning_s &&
        codeRowsDiverged(std::vector<double>(z.data(), z.data() + z.size()), o_.divergence_sigma)) {
      e.diverged = true;
      return;
    }
    std::vector<DdObservation> kept;
    for (long i = 0; i < r.size(); ++i) {
      if (std::abs(r[i]) <= o_.innovation_gate * sd[i]) {
        kept.push_back(e.code_rows[static_cast<size_t>(i)]);
      } else {
        run_->count(Counter::kGnssRowsRejected);
      }
    }
    e.code_rows = kept;
  }
  const GyroMean g = meanGyro(in_.imu, e.t, 0.5 * o_.models.motion.window_s,
                              in_.description.imu_noise.gyro_noise_density);
  e.gyro = g.rate;
  e.doppler = dopplerObservations(rover, orbits_, ant_e, o_.doppler, e.dd.rover_satellites);
  startClockDrift(e);
  addGnssRowFactors(e);
}

void FactorGraphCore::startClockDrift(const FgoEpoch& e) {
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
}

void FactorGraphCore::addGnssRowFactors(const FgoEpoch& e) {
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
    std::vector<StateKey> vars = phaseVars(*model, e.phase_rows);
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

Eigen::VectorXd FactorGraphCore::normalizedRowResiduals(const FgoEpoch& e, bool phase) const {
  const std::vector<DdObservation>& rows = phase ? e.phase_rows : e.code_rows;
  if (rows.empty()) return Eigen::VectorXd::Zero(1);
  const DdGnssModel m(frame_, e.dd.geometry, rows, e.dd.undiff_variance);
  std::vector<StateKey> vars = phase ? phaseVars(m, rows) : std::vector<StateKey>{e.p, e.q, kPbg};
  vars[0] = e.p;
  vars[1] = e.q;
  std::vector<const double*> params;
  for (const StateKey& v : vars) params.push_back(w_.value(v).data());
  Eigen::VectorXd r;
  m.evaluate(params.data(), r, nullptr);
  return r.cwiseAbs().cwiseQuotient(m.covariance().diagonal().cwiseSqrt());
}

bool FactorGraphCore::rejectWorstRow(FgoEpoch& e) {
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
  run_->count(Counter::kGnssRowsRejected);
  std::vector<DdObservation>& rows = phase ? e.phase_rows : e.code_rows;
  const DdObservation bad = rows[static_cast<size_t>(which)];
  rows.erase(rows.begin() + which);
  if (phase) {
    for (const SdAmbiguity& a : e.dd.ambiguities) {
      if (a.sat == bad.sat && a.band == bad.band)
        newAmbiguity(a.sat, a.band, a.code_value, a.lambda);
    }
    run_->count(Counter::kAmbiguityResets);
  }
  addGnssRowFactors(e);
  return true;
}

bool FactorGraphCore::resolve(FgoEpoch& e, const std::vector<SatId>& excluded) {
  std::vector<const DdObservation*> rows;  // the phase rows this fix is tried on
  for (const DdObservation& o : e.phase_rows) {
    if (!rowExcluded(o, excluded)) rows.push_back(&o);
  }
  const long na = static_cast<long>(rows.size());
  if (na < o_.lambda.min_fixed) return false;
  std::vector<StateKey> amb;
  auto index = [&](const StateKey& n) {
    const auto it = std::find(amb.begin(), amb.end(), n);
    if (it != amb.end()) return static_cast<long>(it - amb.begin());
    amb.push_back(n);
    return static_cast<long>(amb.size()) - 1;
  };
  std::vector<std::pair<int, int>> pairs;
  std::vector<double> el;
  for (const DdObservation* o : rows) {
    pairs.push_back({static_cast<int>(index(ambiguityVar(o->sat, o->band).value())),
                     static_cast<int>(index(ambiguityVar(o->ref, o->band).value()))});
    el.push_back(e.dd.geometry[static_cast<size_t>(o->sat_index)].el);
  }
  // Float DD ambiguities and their covariance from the window.
  Eigen::VectorXd a(na);
  for (long k = 0; k < na; ++k) {
    const auto [i, j] = pairs[static_cast<size_t>(k)];
    const SlidingWindow& window = w_;  // reading only: keeps the factorization cached
    a[k] =
        window.value(amb[static_cast<size_t>(i)])[0] - window.value(amb[static_cast<size_t>(j)])[0];
  }
  const Eigen::MatrixXd Qa = ddAmbiguityCovariance(w_.covariance(amb), pairs);
  const std::vector<int> drop = lowestElevationFirst(el);
  AmbiguityFix fix;
  try {
    fix = resolveAmbiguities(a, Qa, drop, o_.lambda);
  } catch (const std::invalid_argument&) {
    run_->count(Counter::kNumericalFailures);  // the float covariance is not positive definite
    return false;
  }
  if (!fix.fixed) return false;
  std::vector<DdAmbiguityFix> fresh;
  for (size_t k = 0; k < fix.indices.size(); ++k) {
    const auto [i, j] = pairs[static_cast<size_t>(fix.indices[k])];
    const std::pair<StateKey, StateKey> key{amb[static_cast<size_t>(i)],
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
  solveWindow();
  // Validate by the fixed solution's DD phase residuals, not by the cost (the IMU and odometer
  // factors make any fix raise it); a failed fix is tried once more without the satellite of its
  // worst row (fix_validation.h).
  const Eigen::VectorXd z_all = normalizedRowResiduals(e, true);
  std::vector<DdObservation> checked;
  Eigen::VectorXd z(na);
  for (size_t k = 0; k < e.phase_rows.size(); ++k) {
    if (rowExcluded(e.phase_rows[k], excluded)) continue;
    z[static_cast<long>(checked.size())] = z_all[static_cast<long>(k)];
    checked.push_back(e.phase_rows[k]);
  }
  const FixCheck check = checkFixResiduals(checked, z, o_.max_fix_residual, excluded);
  if (!check.ok) {
    w_.removeFactors(tag);
    solveWindow();
    run_->count(Counter::kFixesRejected);
    if (!check.exclude) return false;
    run_->count(Counter::kFixExclusions);
    return resolve(e, {*check.exclude});
  }
  for (const DdAmbiguityFix& f : fresh) held_fixes_.insert({f.sat_block, f.ref_block});
  return true;
}

}  // namespace giocal
