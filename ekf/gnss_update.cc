#include "ekf/gnss_update.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "common/gnss/doppler.h"
#include "common/gnss/lambda.h"
#include "common/gnss/spp.h"
#include "common/math/median.h"
#include "common/math/row_compression.h"
#include "common/models/ambiguity_fix_model.h"
#include "common/models/dd_gnss_model.h"
#include "common/models/doppler_model.h"
#include "ekf/imu_propagation.h"

namespace giocal {

namespace {

/// A held DD ambiguity within this of its integer counts as fixed without a search [cycles]: a
/// hold leaves it within a few fix sigmas (1e-3 cycles); one further off is searched again.
constexpr double kHeldOffsetCycles = 0.05;

/// `first` for the model's first blocks, then the model's own keys (its ambiguities).
std::vector<StateKey> modelKeys(const MeasurementModel& m, const std::vector<StateKey>& first) {
  std::vector<StateKey> keys = first;
  for (size_t k = first.size(); k < m.blocks().size(); ++k) keys.push_back(m.blocks()[k].key);
  return keys;
}

}  // namespace

GnssUpdate::GnssUpdate(const BroadcastOrbits& orbits, const Eigen::Vector3d& base_e,
                       const CalibrationOptions& options)
    : orbits_(orbits),
      options_(options),
      builder_(orbits, base_e, options.dd),
      rover_check_(options.code_outliers),
      base_check_(options.code_outliers) {}

void GnssUpdate::resetAmbiguity(StateRegistry& s, const StateKey& key, double value,
                                double lambda) {
  if (s.has(key)) s.remove(key);
  s.add(vectorBlock(key, 1), Eigen::VectorXd::Constant(1, value),
        Eigen::MatrixXd::Constant(1, 1, ambiguityStartVariance(lambda)));
  ambiguities_.insert(key);
}

GnssEpochReport GnssUpdate::process(CalibrationFilter& f, const ObsEpoch& rover,
                                    const ObsEpoch& base) {
  GnssEpochReport rep;
  f.propagateTo(rover.t);
  StateRegistry& s = f.state();
  const double dt = std::isnan(t_last_) ? 0.0 : rover.t - t_last_;
  t_last_ = rover.t;

  // Stage 1: pseudo-ranges that disagree with their Doppler-predicted change.
  const std::set<CodeOutlierCheck::Key> bad_rover = rover_check_.check(rover);
  const std::set<CodeOutlierCheck::Key> bad_base = base_check_.check(base);

  const NavState x = f.nav();
  const Eigen::Vector3d ant_e = f.frame().ecefFromEnu(x.p_n_b + x.q_n_b * s.value(state::kPbg));
  const DdEpoch ep = builder_.build(rover, base, ant_e);

  // SD ambiguities: random walk, restart after slips, add new, drop unseen.
  const double qa = options_.ambiguity_noise * options_.ambiguity_noise * dt;
  for (const StateKey& n : ambiguities_) s.covariance()(s.offset(n), s.offset(n)) += qa;
  std::set<StateKey> seen;
  std::map<StateKey, const SdAmbiguity*> by_key;
  for (const SdAmbiguity& a : ep.ambiguities) {
    const StateKey n = ambiguityKey(a.sat, a.band);
    seen.insert(n);
    by_key[n] = &a;
    if (a.slipped || !s.has(n)) {
      rep.ambiguity_resets += a.slipped && s.has(n);
      resetAmbiguity(s, n, a.code_value, a.lambda);
    }
  }
  for (const StateKey& n : std::vector<StateKey>(ambiguities_.begin(), ambiguities_.end())) {
    if (!seen.count(n)) {
      s.remove(n);
      ambiguities_.erase(n);
    }
  }

  // Rows: phase always, code unless stage 1 flagged either satellite at either receiver.
  std::vector<DdObservation> rows;
  for (const DdObservation& o : ep.obs) {
    if (!o.phase) {
      const auto flagged = [&](const SatId& sat) {
        return bad_rover.count({sat, o.band}) || bad_base.count({sat, o.band});
      };
      if (flagged(o.sat) || flagged(o.ref)) {
        ++rep.code_outliers;
        continue;
      }
    }
    rows.push_back(o);
  }

  // Stage 2: the worst row beyond the innovation gate goes, until none is left; a phase row's
  // ambiguity restarts from code (most likely an undetected slip).
  const std::vector<StateKey> nav_keys{state::kP, state::kQ, state::kPbg};
  MeasurementRows lin;  // the rows that passed, linearized at the state the update starts from
  while (!rows.empty()) {
    const DdGnssModel model(f.frame(), ep.geometry, rows, ep.undiff_variance);
    lin = linearize(model, s.bind(modelKeys(model, nav_keys)), s.dim());
    const Eigen::VectorXd z = normalizedInnovations(s.covariance(), lin);
    // Divergence: the code rows as a whole far outside their predicted spread.
    std::vector<double> code_z;
    for (size_t k = 0; k < rows.size(); ++k) {
      if (!rows[k].phase) code_z.push_back(z[static_cast<long>(k)]);
    }
    if (code_z.size() >= 4 && median(code_z) > options_.divergence_sigma) {
      rep.diverged = true;
      return rep;
    }
    long worst = 0;
    const double zmax = z.maxCoeff(&worst);
    if (zmax <= options_.innovation_gate) break;
    const DdObservation bad = rows[static_cast<size_t>(worst)];
    rows.erase(rows.begin() + worst);
    ++rep.rejected_rows;
    if (bad.phase) {
      const StateKey n = ambiguityKey(bad.sat, bad.band);
      resetAmbiguity(s, n, by_key.at(n)->code_value, bad.lambda);
      ++rep.ambiguity_resets;
    }
  }
  if (!rows.empty()) {
    // The code rows touch only the antenna's pose (9 columns): the same information in 9 rows
    // makes the update of a state with tens of ambiguities about 40 % cheaper.
    std::vector<int> code;
    for (size_t k = 0; k < rows.size(); ++k) {
      if (!rows[k].phase) code.push_back(static_cast<int>(k));
    }
    rep.used = f.updateLinearized(compressRows(lin, code), INFINITY).accepted;
    rep.dd_rows = static_cast<int>(rows.size());
  }

  updateDoppler(f, rover, ant_e, dt, rep);

  if (rep.used && options_.ambiguity_resolution) {
    std::vector<DdObservation> phase_rows;
    for (const DdObservation& o : rows) {
      if (o.phase) phase_rows.push_back(o);
    }
    resolveAmbiguities(f, ep, phase_rows, rep);
  }
  return rep;
}

void GnssUpdate::updateDoppler(CalibrationFilter& f, const ObsEpoch& rover,
                               const Eigen::Vector3d& ant_e, double dt, GnssEpochReport& rep) {
  std::vector<DopplerObservation> obs =
      dopplerObservations(rover, orbits_, ant_e, options_.doppler);
  if (obs.size() < 4) return;
  StateRegistry& s = f.state();
  const CalibrationFilter::Gyro gyro = f.gyroAt(rover.t);
  const std::vector<StateKey> keys{state::kV, state::kQ, state::kBg, state::kPbg,
                                   state::kClockDrift};
  if (!s.has(state::kClockDrift) || dt > 30.0) {
    // Start the clock drift from the median residual at zero drift.
    if (s.has(state::kClockDrift)) s.remove(state::kClockDrift);
    s.add(vectorBlock(state::kClockDrift, 1), Eigen::VectorXd::Zero(1),
          Eigen::MatrixXd::Constant(1, 1, 1.0));
    const DopplerModel m(f.frame().R_e_n(), gyro.rate, obs);
    const MeasurementRows lin = linearize(m, s.bind(keys), s.dim());
    s.value(state::kClockDrift)[0] = -median(
        std::vector<double>(lin.residual.data(), lin.residual.data() + lin.residual.size()));
  } else {
    const int i = s.offset(state::kClockDrift);
    s.covariance()(i, i) += options_.clock_drift_noise * options_.clock_drift_noise * dt;
  }
  while (obs.size() >= 4) {
    const DopplerModel m(f.frame().R_e_n(), gyro.rate, obs);
    const Eigen::VectorXd z =
        normalizedInnovations(s.covariance(), linearize(m, s.bind(keys), s.dim()));
    long worst = 0;
    if (z.maxCoeff(&worst) <= options_.innovation_gate) {
      // A row per satellite, on 13 state columns (velocity, attitude, gyro bias, lever arm,
      // clock drift): compressed to those, as the DD code rows.
      std::vector<int> all(obs.size());
      std::iota(all.begin(), all.end(), 0);
      f.updateLinearized(compressRows(f.rows(m, keys, gyro.variance), all), INFINITY);
      return;
    }
    obs.erase(obs.begin() + worst);
    ++rep.rejected_rows;
  }
}

void GnssUpdate::resolveAmbiguities(CalibrationFilter& f, const DdEpoch& ep,
                                    const std::vector<DdObservation>& phase_rows,
                                    GnssEpochReport& rep) {
  StateRegistry& s = f.state();
  const long na = static_cast<long>(phase_rows.size());
  if (na < options_.lambda.min_fixed) return;
  // DD ambiguity k = N(sat) - N(ref): its mean and covariance from the states' entries.
  std::vector<std::pair<int, int>> pairs;
  Eigen::VectorXd a(na);
  std::vector<double> el;
  for (long k = 0; k < na; ++k) {
    const DdObservation& o = phase_rows[static_cast<size_t>(k)];
    const StateKey ns = ambiguityKey(o.sat, o.band), nr = ambiguityKey(o.ref, o.band);
    pairs.push_back({s.offset(ns), s.offset(nr)});
    a[k] = s.value(ns)[0] - s.value(nr)[0];
    el.push_back(ep.geometry[static_cast<size_t>(o.sat_index)].el);
  }
  const Eigen::MatrixXd Qa = ddAmbiguityCovariance(s.covariance(), pairs);
  // Every DD ambiguity already held at its integer: LAMBDA would return those integers and the
  // filter would not move (below), so the search is not run. Most epochs of a drive are such.
  const double held_variance = 4.0 * options_.fix_sigma_cycles * options_.fix_sigma_cycles;
  bool all_held = true;
  for (long k = 0; k < na && all_held; ++k) {
    all_held = Qa(k, k) < held_variance && std::abs(a[k] - std::round(a[k])) < kHeldOffsetCycles;
  }
  if (all_held) {
    rep.fixed = true;
    rep.fixed_ambiguities = static_cast<int>(na);
    rep.ratio = INFINITY;
    return;
  }
  const std::vector<int> drop = lowestElevationFirst(el);
  AmbiguityFix fix;
  try {
    fix = giocal::resolveAmbiguities(a, Qa, drop, options_.lambda);
  } catch (const std::invalid_argument&) {
    return;  // float covariance not positive definite: no fix this epoch
  }
  rep.ratio = fix.ratio;
  if (!fix.fixed) return;

  // Fixes already held (their DD variance is at the constraint's level) need no new update.
  std::vector<DdAmbiguityFix> fixes;
  for (size_t k = 0; k < fix.indices.size(); ++k) {
    const int i = fix.indices[k];
    if (Qa(i, i) < held_variance) continue;
    const DdObservation& o = phase_rows[static_cast<size_t>(i)];
    fixes.push_back({ambiguityKey(o.sat, o.band), ambiguityKey(o.ref, o.band),
                     fix.values[static_cast<long>(k)]});
  }
  rep.fixed_ambiguities = static_cast<int>(fix.indices.size());
  if (fixes.empty()) {
    rep.fixed = true;
    return;
  }
  // Apply the fixes, then keep them only if the fixed solution fits every DD phase row.
  const StateRegistry saved = s;
  const AmbiguityFixModel constraint(fixes, options_.fix_sigma_cycles);
  std::vector<StateKey> keys;
  for (const StateBlock& b : constraint.blocks()) keys.push_back(b.key);
  f.update(constraint, keys, INFINITY);
  const DdGnssModel model(f.frame(), ep.geometry, phase_rows, ep.undiff_variance);
  const MeasurementRows lin =
      linearize(model, s.bind(modelKeys(model, {state::kP, state::kQ, state::kPbg})), s.dim());
  const Eigen::VectorXd sd = lin.R.diagonal().cwiseSqrt();
  if ((lin.residual.cwiseAbs().array() / sd.array()).maxCoeff() > options_.max_fix_residual) {
    s = saved;
    ++rep.rejected_rows;
    return;
  }
  rep.fixed = true;
}

}  // namespace giocal
