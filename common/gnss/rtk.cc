#include "common/gnss/rtk.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <set>

#include "common/geodesy/wgs84.h"
#include "common/gnss/double_difference.h"
#include "common/math/kalman_update.h"
#include "common/math/median.h"
#include "common/math/row_compression.h"

namespace giocal {

RtkFilter::RtkFilter(const BroadcastOrbits& orbits, const Eigen::Vector3d& base_e,
                     const RtkOptions& options)
    : orbits_(orbits),
      base_e_(base_e),
      options_(options),
      dd_builder_(orbits, base_e, options.dd) {}

int RtkFilter::ambiguityIndex(const AmbKey& key) const {
  const auto it = std::find(amb_keys_.begin(), amb_keys_.end(), key);
  return it == amb_keys_.end() ? -1 : 6 + static_cast<int>(it - amb_keys_.begin());
}

void RtkFilter::addAmbiguity(const AmbKey& key, double value, double variance) {
  const long n = x_.size();
  x_.conservativeResize(n + 1);
  x_[n] = value;
  P_.conservativeResize(n + 1, n + 1);
  P_.row(n).setZero();
  P_.col(n).setZero();
  P_(n, n) = variance;
  amb_keys_.push_back(key);
}

void RtkFilter::removeAmbiguity(const AmbKey& key) {
  const int i = ambiguityIndex(key);
  if (i < 0) return;
  const long n = x_.size();
  std::vector<int> keep;
  for (int k = 0; k < n; ++k) {
    if (k != i) keep.push_back(k);
  }
  Eigen::VectorXd x(n - 1);
  Eigen::MatrixXd P(n - 1, n - 1);
  for (size_t a = 0; a < keep.size(); ++a) {
    x[static_cast<long>(a)] = x_[keep[a]];
    for (size_t b = 0; b < keep.size(); ++b)
      P(static_cast<long>(a), static_cast<long>(b)) = P_(keep[a], keep[b]);
  }
  x_ = x;
  P_ = P;
  amb_keys_.erase(amb_keys_.begin() + (i - 6));
}

bool RtkFilter::diverged(const std::vector<DdObservation>& rows,
                         const Eigen::VectorXd& normalized) const {
  std::vector<double> z[2];
  for (size_t a = 0; a < rows.size(); ++a) {
    z[rows[a].phase ? 1 : 0].push_back(normalized[static_cast<long>(a)]);
  }
  const double limit = options_.divergence_sigma;
  return z[0].size() >= 4 && median(z[0]) > limit && (z[1].empty() || median(z[1]) > limit);
}

FixCheck RtkFilter::checkFix(const DdEpoch& ep, const std::vector<bool>& active,
                             const std::vector<SatId>& excluded,
                             const Eigen::VectorXd& x_fix) const {
  std::vector<DdObservation> phase;
  for (size_t k = 0; k < ep.obs.size(); ++k) {
    if (active[k] && ep.obs[k].phase && !rowExcluded(ep.obs[k], excluded))
      phase.push_back(ep.obs[k]);
  }
  const Eigen::MatrixXd R = ddCovariance(phase, ep.undiff_variance);
  Eigen::VectorXd z(static_cast<long>(phase.size()));
  for (size_t k = 0; k < phase.size(); ++k) {
    const DdObservation& o = phase[k];
    const double pred =
        ddPredict(o, ep.geometry, x_fix.head<3>(), x_fix[ambiguityIndex({o.sat, o.band})],
                  x_fix[ambiguityIndex({o.ref, o.band})], nullptr);
    const long i = static_cast<long>(k);
    z[i] = std::abs(o.value - pred) / std::sqrt(R(i, i));
  }
  return checkFixResiduals(phase, z, options_.max_fix_residual, excluded);
}

RtkSolution RtkFilter::process(const ObsEpoch& rover, const ObsEpoch* base) {
  RtkSolution sol;
  sol.t = rover.t;
  SppOptions spp_opt;
  const SppSolution spp = solveSpp(rover, orbits_, spp_opt);
  if (!spp.valid) return sol;
  sol.quality = 5;
  sol.p_e = spp.p_e;
  sol.cov_e = spp.cov_p;
  sol.satellites = static_cast<int>(spp.used.size());
  if (!base) return sol;
  sol.age = rover.t - base->t;

  // Time update.
  const double dt = initialized_ ? rover.t - t_last_ : 0.0;
  if (!initialized_ || dt <= 0.0 || dt > 300.0) {
    x_ = Eigen::VectorXd::Zero(6);
    x_.head<3>() = spp.p_e;
    if (spp.velocity_valid) x_.segment<3>(3) = spp.v_e;
    P_ = Eigen::MatrixXd::Zero(6, 6);
    P_.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() * 100.0;
    P_.block<3, 3>(3, 3) = Eigen::Matrix3d::Identity() * 10.0;
    amb_keys_.clear();
    last_seen_.clear();
    initialized_ = true;
  } else {
    const long n = x_.size();
    // F = I except dp/dv = dt I: F P F^T by its two rows and columns that change (a dense
    // product of the whole state with ambiguities was a tenth of the filter's time).
    x_.head<3>() += dt * x_.segment<3>(3);
    P_.topRows<3>() += dt * P_.middleRows<3>(3);
    P_.leftCols<3>() += dt * P_.middleCols<3>(3);
    const double q = options_.accel_noise * options_.accel_noise;
    P_.topLeftCorner<3, 3>() += Eigen::Matrix3d::Identity() * q * dt * dt * dt / 3.0;
    P_.block<3, 3>(0, 3) += Eigen::Matrix3d::Identity() * q * dt * dt / 2.0;
    P_.block<3, 3>(3, 0) += Eigen::Matrix3d::Identity() * q * dt * dt / 2.0;
    P_.block<3, 3>(3, 3) += Eigen::Matrix3d::Identity() * q * dt;
    for (long k = 6; k < n; ++k)
      P_(k, k) += options_.ambiguity_noise * options_.ambiguity_noise * dt;
  }
  t_last_ = rover.t;

  // This epoch's double differences; slipped or new ambiguities (re)start from code. Those not
  // observed are kept for max_outage: under trees a satellite blocked for an epoch or two comes
  // back on the same ambiguity (the slip detector bridges the gap), and restarting it from code
  // each time leaves too few converged ambiguities to fix.
  const DdEpoch ep = dd_builder_.build(rover, *base, x_.head<3>());
  const std::vector<SdGeometry>& geometry = ep.geometry;
  const std::vector<DdObservation>& obs = ep.obs;
  for (const SdAmbiguity& a : ep.ambiguities) {
    const AmbKey key{a.sat, a.band};
    if (a.slipped) removeAmbiguity(key);
    if (ambiguityIndex(key) < 0) addAmbiguity(key, a.code_value, ambiguityStartVariance(a.lambda));
    last_seen_[key] = rover.t;
  }
  for (const AmbKey& k : std::vector<AmbKey>(amb_keys_)) {
    if (rover.t - last_seen_[k] > options_.max_outage) {
      removeAmbiguity(k);
      last_seen_.erase(k);
    }
  }
  if (obs.empty()) return sol;

  // Measurement update, linearized at the prediction, with an innovation gate.
  std::vector<bool> active(obs.size(), true);
  const auto& undiff_var = ep.undiff_variance;
  for (int attempt = 0; attempt < 8; ++attempt) {
    std::vector<int> rows;
    std::vector<DdObservation> used_obs;
    for (size_t k = 0; k < obs.size(); ++k) {
      if (active[k]) {
        rows.push_back(static_cast<int>(k));
        used_obs.push_back(obs[k]);
      }
    }
    const long m = static_cast<long>(rows.size()), n = x_.size();
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m, n);
    const Eigen::MatrixXd R = ddCovariance(used_obs, undiff_var);
    Eigen::VectorXd v(m);
    for (long a = 0; a < m; ++a) {
      const DdObservation& o = used_obs[static_cast<size_t>(a)];
      Eigen::RowVector3d J;
      const int ia = o.phase ? ambiguityIndex({o.sat, o.band}) : -1;
      const int ir = o.phase ? ambiguityIndex({o.ref, o.band}) : -1;
      const double pred =
          ddPredict(o, geometry, x_.head<3>(), o.phase ? x_[ia] : 0.0, o.phase ? x_[ir] : 0.0, &J);
      H.block(a, 0, 1, 3) = J;
      if (o.phase) {
        H(a, ia) = o.lambda;
        H(a, ir) = -o.lambda;
      }
      v[a] = o.value - pred;
    }
    const MeasurementRows lin{-v, H, R};
    const Eigen::VectorXd z = normalizedInnovations(P_, lin);
    // Lost track: the code rows as a whole far outside their predicted spread, and the phase rows
    // too (a reference satellite's NLOS error shifts every code row, while the phase rows still
    // agree). The filter starts again from the single point solution; comparing with that
    // solution directly restarted it on every large NLOS error of the solution itself.
    if (attempt == 0 && !restarting_ && diverged(used_obs, z)) {
      initialized_ = false;
      restarting_ = true;
      const RtkSolution again = process(rover, base);
      restarting_ = false;
      return again;
    }
    // Gate: the worst normalized innovation above the threshold is removed and the update redone.
    long worst = -1;
    double worst_z = options_.innovation_gate;
    for (long a = 0; a < m; ++a) {
      if (z[a] > worst_z) {
        worst_z = z[a];
        worst = a;
      }
    }
    if (worst >= 0 && attempt < 7) {
      const DdObservation& o = obs[static_cast<size_t>(rows[static_cast<size_t>(worst)])];
      active[static_cast<size_t>(rows[static_cast<size_t>(worst)])] = false;
      if (o.phase) {
        // A phase outlier is most likely an undetected slip: restart that ambiguity from code.
        const int ia = ambiguityIndex({o.sat, o.band});
        P_.row(ia).setZero();
        P_.col(ia).setZero();
        P_(ia, ia) = ambiguityStartVariance(o.lambda);
      }
      continue;
    }
    // The Joseph-form update with the optimal gain, which the shared update forms without the
    // gain matrix (a third of the dense products' work; the initialization runs this), with the
    // code rows compressed into the three rows of information they carry on the position.
    std::vector<int> code;
    for (long k = 0; k < m; ++k) {
      if (!used_obs[static_cast<size_t>(k)].phase) code.push_back(static_cast<int>(k));
    }
    const UpdateResult u = kalmanUpdate(P_, compressRows(lin, code), INFINITY, {}, &workspace_);
    if (u.accepted) x_ += u.dx;
    break;
  }
  sol.quality = 2;
  sol.p_e = x_.head<3>();
  sol.cov_e = P_.topLeftCorner<3, 3>();
  sol.v_e = x_.segment<3>(3);

  std::set<SatId> used;
  for (size_t k = 0; k < obs.size(); ++k) {
    if (active[k]) {
      used.insert(obs[k].sat);
      used.insert(obs[k].ref);
    }
  }
  sol.satellites = static_cast<int>(used.size());

  // Ambiguity resolution on the DD ambiguities of this epoch's phase rows. A fix that fails its
  // residual check is tried once more without the satellite of its worst row (fix_validation.h).
  std::vector<SatId> excluded;
  Eigen::VectorXd x_fix, d;
  Eigen::MatrixXd PAt, Qf;
  Eigen::LDLT<Eigen::MatrixXd> qf;
  for (;;) {
    std::vector<std::pair<int, int>> dd;  // (sat state index, ref state index)
    std::vector<double> dd_el;
    for (size_t k = 0; k < obs.size(); ++k) {
      if (!active[k] || !obs[k].phase || rowExcluded(obs[k], excluded)) continue;
      dd.push_back(
          {ambiguityIndex({obs[k].sat, obs[k].band}), ambiguityIndex({obs[k].ref, obs[k].band})});
      dd_el.push_back(geometry[static_cast<size_t>(obs[k].sat_index)].el);
    }
    const long na = static_cast<long>(dd.size());
    if (na < options_.lambda.min_fixed) return sol;
    Eigen::VectorXd a(na);
    for (long k = 0; k < na; ++k) {
      a[k] = x_[dd[static_cast<size_t>(k)].first] - x_[dd[static_cast<size_t>(k)].second];
    }
    const Eigen::MatrixXd Qa = ddAmbiguityCovariance(P_, dd);
    const std::vector<int> drop = lowestElevationFirst(dd_el);
    AmbiguityFix fix;
    try {
      fix = resolveAmbiguities(a, Qa, drop, options_.lambda);
    } catch (const std::invalid_argument&) {
      return sol;
    }
    sol.ratio = fix.ratio;
    if (!fix.fixed) return sol;
    // The fixed solution conditioned on the fixed DD ambiguities. Their rows of A are e_s - e_r:
    // A P A^T and P A^T are read off P, and of the fixed covariance only the position's block is
    // needed (dense products with A were most of the filter's time when it fixes every epoch).
    const long nf = static_cast<long>(fix.indices.size()), n = x_.size();
    std::vector<std::pair<int, int>> fixed_dd;
    for (int i : fix.indices) fixed_dd.push_back(dd[static_cast<size_t>(i)]);
    Qf = ddAmbiguityCovariance(P_, fixed_dd);
    PAt.resize(n, nf);
    d.resize(nf);
    for (long k = 0; k < nf; ++k) {
      const auto [i, j] = fixed_dd[static_cast<size_t>(k)];
      PAt.col(k) = P_.col(i) - P_.col(j);
      d[k] = x_[i] - x_[j] - fix.values[k];
    }
    qf.compute(Qf);
    x_fix = x_ - PAt * qf.solve(d);
    const FixCheck check = checkFix(ep, active, excluded, x_fix);
    if (check.ok) break;
    if (!check.exclude) return sol;
    excluded.push_back(*check.exclude);
  }
  sol.p_e = x_fix.head<3>();
  sol.cov_e = P_.topLeftCorner<3, 3>() -
              PAt.topRows<3>() * qf.solve(Eigen::MatrixXd(PAt.topRows<3>().transpose()));
  // "Fixed" promises centimetres: a partial fix of too few ambiguities, under trees, can pass the
  // ratio test and still leave the horizontal position decimetres uncertain (its covariance says
  // so); it is reported as float, with the partially fixed position and that covariance.
  const Geodetic g = geodeticFromEcef(sol.p_e);
  const Eigen::Matrix3d R_e_n = rotationEcefFromEnu(g.lat, g.lon);
  const Eigen::Matrix2d cov_h = (R_e_n.transpose() * sol.cov_e * R_e_n).topLeftCorner<2, 2>();
  if (std::sqrt(cov_h.trace()) > options_.max_fix_sigma) return sol;
  sol.quality = 1;
  if (options_.fix_and_hold) {
    // Held as measurements of sigma hold_sigma_cycles: S = A P A^T + R, and the update
    // P - P A^T S^-1 A P as W^T W with W = L^-1 (P A^T)^T.
    Eigen::MatrixXd S = Qf;
    S.diagonal().array() += std::pow(options_.hold_sigma_cycles, 2);
    const Eigen::LLT<Eigen::MatrixXd> llt(S);
    x_ -= PAt * llt.solve(d);
    Eigen::MatrixXd W = PAt.transpose();
    llt.matrixL().solveInPlace(W);
    P_.selfadjointView<Eigen::Lower>().rankUpdate(W.transpose(), -1.0);
    P_.triangularView<Eigen::StrictlyUpper>() = P_.transpose();
  }
  return sol;
}

}  // namespace giocal
