#include "ekf/gnss_update.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "common/calibration/code_divergence.h"
#include "common/gnss/doppler.h"
#include "common/gnss/lambda.h"
#include "common/gnss/spp.h"
#include "common/math/median.h"
#include "common/math/row_compression.h"
#include "common/models/ambiguity_fix_model.h"
#include "common/models/dd_gnss_model.h"
#include "common/models/doppler_model.h"
#include "ekf/doppler_update.h"
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

/// The rows that touch no ambiguity state (code rows, phase rows between known ambiguities), read
/// from H (no column beyond the pose's `pose_cols`), less any correlated in R with a row that does:
/// compressRows takes such a closed set only.
std::vector<int> poseOnlyRows(const MeasurementRows& lin, const std::vector<int>& pose_cols) {
  const auto m = static_cast<size_t>(lin.H.rows());
  std::vector<bool> pose(static_cast<size_t>(lin.H.cols()), false), in(m, true);
  for (const int j : pose_cols) pose[static_cast<size_t>(j)] = true;
  for (long j = 0; j < lin.H.cols(); ++j) {
    if (pose[static_cast<size_t>(j)]) continue;
    for (size_t k = 0; k < m; ++k) {
      if (lin.H(long(k), j) != 0.0) in[k] = false;
    }
  }
  for (size_t k = 0; k < m; ++k) {
    if (in[k]) continue;
    for (size_t j = 0; j < m; ++j) {
      if (in[j] && lin.R(long(j), long(k)) != 0.0) in[j] = false;
    }
  }
  std::vector<int> out;
  for (size_t k = 0; k < m; ++k) {
    if (in[k]) out.push_back(static_cast<int>(k));
  }
  return out;
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
  for (const StateKey& n : ambiguities_) {
    if (const int i = s.offset(n); i >= 0) s.covariance()(i, i) += qa;
  }
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
    if (codeRowsDiverged(code_z, options_.divergence_sigma)) {
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
    // The code rows, and the phase rows whose ambiguities are known, touch only the antenna's
    // pose (9 columns): the same information in 9 rows makes the update several times cheaper.
    std::vector<int> pose_cols;
    for (const StateKey& key : nav_keys) {
      for (int k = 0; k < 3; ++k) pose_cols.push_back(s.offset(key) + k);
    }
    rep.used =
        f.updateLinearized(compressRows(lin, poseOnlyRows(lin, pose_cols)), INFINITY).accepted;
    rep.dd_rows = static_cast<int>(rows.size());
  }

  const DopplerRows doppler =
      updateDoppler(f, orbits_, options_, rover, ant_e, ep.rover_satellites, dt);
  rep.rejected_rows += doppler.rejected;
  rep.doppler_rows = doppler.used;

  if (rep.used && options_.ambiguity_resolution) {
    std::vector<DdObservation> phase_rows;
    for (const DdObservation& o : rows) {
      if (o.phase) phase_rows.push_back(o);
    }
    resolveAmbiguities(f, ep, phase_rows, rep);
  }
  return rep;
}

void GnssUpdate::resolveAmbiguities(CalibrationFilter& f, const DdEpoch& ep,
                                    const std::vector<DdObservation>& phase_rows,
                                    GnssEpochReport& rep, const std::vector<SatId>& excluded) {
  StateRegistry& s = f.state();
  const long na = static_cast<long>(phase_rows.size());
  if (na < options_.lambda.min_fixed) return;
  // DD ambiguity k = N(sat) - N(ref): its mean and covariance from the states' entries. Where a
  // row's reference is not known but another SD ambiguity of its group is, the pair is taken
  // against that one (the same DD space): against an estimated reference, every DD of a group
  // whose other SD ambiguities are known carries the reference's variance alone, and their
  // covariance is singular.
  std::map<std::pair<SatId, char>, SatId> known_ref;  // (reference, band) -> a known satellite
  for (const DdObservation& o : phase_rows) {
    const auto group = std::make_pair(o.ref, o.band);
    if (!known_ref.count(group) && !s.isKnown(ambiguityKey(o.ref, o.band)) &&
        s.isKnown(ambiguityKey(o.sat, o.band))) {
      known_ref[group] = o.sat;
    }
  }
  std::vector<std::pair<StateKey, StateKey>> keys_k;
  std::vector<std::pair<int, int>> pairs;
  Eigen::VectorXd a(na);
  std::vector<double> el;
  for (long k = 0; k < na; ++k) {
    const DdObservation& o = phase_rows[static_cast<size_t>(k)];
    SatId sat = o.sat, ref = o.ref;
    int sat_index = o.sat_index;
    if (const auto it = known_ref.find({o.ref, o.band}); it != known_ref.end()) {
      ref = it->second;
      if (sat == ref) {  // this row's satellite is the new reference: the old one takes its place
        sat = o.ref;
        sat_index = o.ref_index;
      }
    }
    keys_k.push_back({ambiguityKey(sat, o.band), ambiguityKey(ref, o.band)});
    const std::vector<BlockBinding> b = s.bind({keys_k.back().first, keys_k.back().second});
    pairs.push_back({b[0].error_offset, b[1].error_offset});
    a[k] = *b[0].value - *b[1].value;
    el.push_back(ep.geometry[static_cast<size_t>(sat_index)].el);
  }
  const Eigen::MatrixXd Qa = ddAmbiguityCovariance(s.covariance(), pairs);
  // A DD ambiguity already held at its integer (its variance at the hold's level or zero, where
  // both SD ambiguities are known) is fixed: LAMBDA searches the others, as it would have found
  // the held ones' integers among them; a known pair's zero variance would make the search's
  // covariance singular. When all are held (most epochs of a drive) no search is run.
  const double held_variance = 4.0 * options_.fix_sigma_cycles * options_.fix_sigma_cycles;
  std::vector<int> floating, held_pairs;
  for (long k = 0; k < na; ++k) {
    const bool held =
        Qa(k, k) < held_variance && std::abs(a[k] - std::round(a[k])) < kHeldOffsetCycles;
    (held ? held_pairs : floating).push_back(static_cast<int>(k));
  }
  const auto n_held = static_cast<int>(held_pairs.size());
  if (floating.empty()) {
    rep.fixed = true;
    rep.fixed_ambiguities = n_held;
    rep.ratio = INFINITY;
    return;
  }
  const auto nf = static_cast<long>(floating.size());
  Eigen::VectorXd a_f(nf);
  Eigen::MatrixXd Q_f(nf, nf);
  std::vector<double> el_f;
  for (long i = 0; i < nf; ++i) {
    a_f[i] = a[floating[size_t(i)]];
    el_f.push_back(el[size_t(floating[size_t(i)])]);
    for (long j = 0; j < nf; ++j) Q_f(i, j) = Qa(floating[size_t(i)], floating[size_t(j)]);
  }
  LambdaOptions lambda = options_.lambda;
  lambda.min_fixed = std::max(1, lambda.min_fixed - n_held);  // the held count towards it
  AmbiguityFix fix;
  try {
    fix = giocal::resolveAmbiguities(a_f, Q_f, lowestElevationFirst(el_f), lambda);
  } catch (const std::invalid_argument&) {
    fix = {};  // float covariance not positive definite: none of these fixed this epoch
    f.countNumericalFailure();
  }
  rep.ratio = fix.ratio;
  if (!fix.fixed) {
    // Partial fixing ends with the held ones alone, as it did when they were searched too.
    if (n_held >= options_.lambda.min_fixed) {
      rep.fixed = true;
      rep.fixed_ambiguities = n_held;
      rep.ratio = INFINITY;
    }
    return;
  }

  std::vector<DdAmbiguityFix> fixes;
  std::vector<int> fixed_pairs = held_pairs;
  for (size_t k = 0; k < fix.indices.size(); ++k) {
    const int i = floating[static_cast<size_t>(fix.indices[k])];
    fixed_pairs.push_back(i);
    fixes.push_back(
        {keys_k[size_t(i)].first, keys_k[size_t(i)].second, fix.values[static_cast<long>(k)]});
  }
  rep.fixed_ambiguities = static_cast<int>(fixed_pairs.size());
  // Held fixes are known from then on: the state is conditioned on their SD ambiguities, which
  // leave the covariance (with a group's reference this also pins the SD common mode, which no
  // DD row sees). Later DD rows between known ambiguities touch the pose only.
  std::vector<StateKey> held;
  for (const int i : fixed_pairs) {
    held.push_back(keys_k[size_t(i)].first);
    held.push_back(keys_k[size_t(i)].second);
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
  // A failed fix is tried once more without the satellite of its worst row (fix_validation.h).
  const Eigen::VectorXd z = lin.residual.cwiseAbs().cwiseQuotient(lin.R.diagonal().cwiseSqrt());
  const FixCheck check = checkFixResiduals(phase_rows, z, options_.max_fix_residual, excluded);
  if (!check.ok) {
    s = saved;
    ++rep.fixes_rejected;
    if (!check.exclude) return;
    ++rep.fix_exclusions;
    const std::vector<SatId> left_out{*check.exclude};
    std::vector<DdObservation> rest;
    for (const DdObservation& o : phase_rows) {
      if (!rowExcluded(o, left_out)) rest.push_back(o);
    }
    resolveAmbiguities(f, ep, rest, rep, left_out);
    return;
  }
  s.condition(held);
  rep.fixed = true;
}

}  // namespace giocal
