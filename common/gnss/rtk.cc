#include "common/gnss/rtk.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include "common/gnss/atmosphere.h"
#include "common/gnss/double_difference.h"

namespace giocal {

std::vector<char> rtkBands(GnssSystem sys, int frequencies) {
  std::vector<char> b;
  switch (sys) {
    case GnssSystem::kBeidou:
      b = {'2', '7'};
      break;
    case GnssSystem::kGalileo:
      b = {'1', '7'};
      break;
    default:
      b = {'1', '2'};
      break;
  }
  b.resize(static_cast<size_t>(std::clamp(frequencies, 1, 2)));
  return b;
}

RtkFilter::RtkFilter(const BroadcastOrbits& orbits, const Eigen::Vector3d& base_e,
                     const RtkOptions& options)
    : orbits_(orbits),
      base_e_(base_e),
      options_(options),
      rover_slips_(options.slips),
      base_slips_(options.slips) {}

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
    refs_.clear();
    initialized_ = true;
  } else {
    const long n = x_.size();
    Eigen::MatrixXd F = Eigen::MatrixXd::Identity(n, n);
    F.block<3, 3>(0, 3) = Eigen::Matrix3d::Identity() * dt;
    x_ = F * x_;
    P_ = F * P_ * F.transpose();
    const double q = options_.accel_noise * options_.accel_noise;
    P_.topLeftCorner<3, 3>() += Eigen::Matrix3d::Identity() * q * dt * dt * dt / 3.0;
    P_.block<3, 3>(0, 3) += Eigen::Matrix3d::Identity() * q * dt * dt / 2.0;
    P_.block<3, 3>(3, 0) += Eigen::Matrix3d::Identity() * q * dt * dt / 2.0;
    P_.block<3, 3>(3, 3) += Eigen::Matrix3d::Identity() * q * dt;
    for (long k = 6; k < n; ++k)
      P_(k, k) += options_.ambiguity_noise * options_.ambiguity_noise * dt;
    // A position far from the single point solution means the filter lost track: restart it.
    if ((x_.head<3>() - spp.p_e).norm() > 30.0) {
      x_.head<3>() = spp.p_e;
      P_.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() * 100.0;
    }
  }
  t_last_ = rover.t;

  // Cycle slips reset the ambiguities of either receiver's slipped phases.
  rover_slips_.update(rover);
  base_slips_.update(*base);

  // The satellites as each receiver saw them (the time tags and pseudo-ranges carry the same
  // receiver clock error, so tag minus range is the transmission time for both).
  const double mask = options_.elevation_mask_deg * M_PI / 180.0;
  struct SatRow {
    SdGeometry geo;
    const SatObs* r;
    const SatObs* b;
  };
  std::vector<SatRow> sats;
  for (const SatObs& ro : rover.sats) {
    if (std::find(options_.systems.begin(), options_.systems.end(), ro.sat.sys) ==
        options_.systems.end())
      continue;
    const SatObs* bo = base->find(ro.sat);
    if (!bo) continue;
    const SignalObs* rp = ro.bestOnBand(primaryBand(ro.sat.sys));
    const SignalObs* bp = bo->bestOnBand(primaryBand(ro.sat.sys));
    if (!rp || !bp) continue;
    const auto sr = orbits_.atReception(ro.sat, rover.t, rp->P, rp->band, x_.head<3>());
    const auto sb = orbits_.atReception(ro.sat, base->t, bp->P, bp->band, base_e_);
    if (!sr || !sb) continue;
    SdGeometry g;
    g.sat = ro.sat;
    g.sat_at_rover_e = sr->p_e;
    g.base_range = (sb->p_e - base_e_).norm();
    double az = 0.0;
    elevationAzimuth(x_.head<3>(), sr->p_e, g.el, az);
    if (g.el < mask) continue;
    sats.push_back({g, &ro, bo});
  }
  std::vector<SdGeometry> geometry;
  for (const auto& s : sats) geometry.push_back(s.geo);

  // Single differences per band; new or slipped ambiguities (re)initialized from code.
  std::vector<DdObservation> obs;
  std::map<AmbKey, bool> seen;
  for (GnssSystem sys : options_.systems) {
    for (char band : rtkBands(sys, options_.frequencies)) {
      std::vector<int> cand;
      std::map<int, std::pair<double, double>> sd;  // index -> (SD code, SD phase [m])
      const double lambda = kSpeedOfLight / carrierFrequency(sys, band);
      for (size_t i = 0; i < sats.size(); ++i) {
        if (sats[i].geo.sat.sys != sys) continue;
        const SignalObs* r = sats[i].r->bestOnBand(band);
        const SignalObs* b = sats[i].b->bestOnBand(band);
        if (!r || !b || std::isnan(r->L) || std::isnan(b->L)) continue;
        const AmbKey key{sats[i].geo.sat, band};
        const double sd_p = r->P - b->P, sd_l = (r->L - b->L) * lambda;
        if (rover_slips_.slipped(key.first, band) || base_slips_.slipped(key.first, band)) {
          removeAmbiguity(key);
        }
        if (ambiguityIndex(key) < 0)
          addAmbiguity(key, (sd_l - sd_p) / lambda, std::pow(10.0 / lambda, 2));
        seen[key] = true;
        cand.push_back(static_cast<int>(i));
        sd[static_cast<int>(i)] = {sd_p, sd_l};
      }
      if (cand.size() < 2) continue;
      const auto prev = refs_.find({sys, band});
      int prev_idx = -1;
      for (int i : cand) {
        if (prev != refs_.end() && geometry[static_cast<size_t>(i)].sat == prev->second)
          prev_idx = i;
      }
      const int ref = chooseReference(geometry, cand, prev_idx, 30.0 * M_PI / 180.0);
      refs_[{sys, band}] = geometry[static_cast<size_t>(ref)].sat;
      for (int i : cand) {
        if (i == ref) continue;
        for (bool phase : {true, false}) {
          DdObservation o;
          o.sat = geometry[static_cast<size_t>(i)].sat;
          o.ref = geometry[static_cast<size_t>(ref)].sat;
          o.band = band;
          o.phase = phase;
          o.lambda = lambda;
          o.sat_index = i;
          o.ref_index = ref;
          o.value = phase ? sd[i].second - sd[ref].second : sd[i].first - sd[ref].first;
          obs.push_back(o);
        }
      }
    }
  }
  // Ambiguities of satellites no longer observed are dropped.
  for (const AmbKey& k : std::vector<AmbKey>(amb_keys_)) {
    if (!seen.count(k)) removeAmbiguity(k);
  }
  if (obs.empty()) return sol;

  // Measurement update, linearized at the prediction, with an innovation gate.
  std::vector<bool> active(obs.size(), true);
  // Undifferenced variances (rover plus base) of each satellite's code and phase.
  std::vector<std::pair<double, double>> undiff_var;
  for (const SdGeometry& g : geometry) {
    undiff_var.push_back({2.0 * options_.code.variance(g.el), 2.0 * options_.phase.variance(g.el)});
  }
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
      double pred = ddRange(x_.head<3>(), geometry[static_cast<size_t>(o.sat_index)],
                            geometry[static_cast<size_t>(o.ref_index)], &J);
      H.block(a, 0, 1, 3) = J;
      if (o.phase) {
        const int ia = ambiguityIndex({o.sat, o.band}), ir = ambiguityIndex({o.ref, o.band});
        pred += o.lambda * (x_[ia] - x_[ir]);
        H(a, ia) = o.lambda;
        H(a, ir) = -o.lambda;
      }
      v[a] = o.value - pred;
    }
    const Eigen::MatrixXd S = H * P_ * H.transpose() + R;
    // Gate: the worst normalized innovation above the threshold is removed and the update redone.
    long worst = -1;
    double worst_z = options_.innovation_gate;
    for (long a = 0; a < m; ++a) {
      const double z = std::abs(v[a]) / std::sqrt(S(a, a));
      if (z > worst_z) {
        worst_z = z;
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
        P_(ia, ia) = std::pow(10.0 / o.lambda, 2);
      }
      continue;
    }
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(S);
    const Eigen::MatrixXd K = ldlt.solve(H * P_).transpose();
    x_ += K * v;
    const Eigen::MatrixXd IKH = Eigen::MatrixXd::Identity(n, n) - K * H;
    P_ = IKH * P_ * IKH.transpose() + K * R * K.transpose();
    break;
  }
  sol.quality = 2;
  sol.p_e = x_.head<3>();
  sol.cov_e = P_.topLeftCorner<3, 3>();
  sol.v_e = x_.segment<3>(3);

  // Ambiguity resolution on the DD ambiguities of this epoch's phase rows.
  std::vector<std::pair<int, int>> dd;  // (sat state index, ref state index)
  std::vector<double> dd_el;
  for (size_t k = 0; k < obs.size(); ++k) {
    if (!active[k] || !obs[k].phase) continue;
    dd.push_back(
        {ambiguityIndex({obs[k].sat, obs[k].band}), ambiguityIndex({obs[k].ref, obs[k].band})});
    dd_el.push_back(geometry[static_cast<size_t>(obs[k].sat_index)].el);
  }
  std::set<SatId> used;
  for (size_t k = 0; k < obs.size(); ++k) {
    if (active[k]) {
      used.insert(obs[k].sat);
      used.insert(obs[k].ref);
    }
  }
  sol.satellites = static_cast<int>(used.size());
  const long na = static_cast<long>(dd.size());
  if (na < options_.lambda.min_fixed) return sol;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(na, x_.size());
  for (long k = 0; k < na; ++k) {
    A(k, dd[static_cast<size_t>(k)].first) = 1.0;
    A(k, dd[static_cast<size_t>(k)].second) = -1.0;
  }
  const Eigen::VectorXd a = A * x_;
  const Eigen::MatrixXd Qa = A * P_ * A.transpose();
  std::vector<int> drop(static_cast<size_t>(na));
  std::iota(drop.begin(), drop.end(), 0);
  std::sort(drop.begin(), drop.end(), [&](int i, int j) {
    return dd_el[static_cast<size_t>(i)] < dd_el[static_cast<size_t>(j)];
  });
  AmbiguityFix fix;
  try {
    fix = resolveAmbiguities(a, Qa, drop, options_.lambda);
  } catch (const std::invalid_argument&) {
    return sol;
  }
  sol.ratio = fix.ratio;
  if (!fix.fixed) return sol;
  const long nf = static_cast<long>(fix.indices.size());
  Eigen::MatrixXd Af(nf, x_.size());
  for (long k = 0; k < nf; ++k) Af.row(k) = A.row(fix.indices[static_cast<size_t>(k)]);
  const Eigen::MatrixXd Qf = Af * P_ * Af.transpose();
  const Eigen::MatrixXd PAt = P_ * Af.transpose();
  const Eigen::LDLT<Eigen::MatrixXd> qf(Qf);
  const Eigen::VectorXd x_fix = x_ - PAt * qf.solve(Af * x_ - fix.values);
  const Eigen::MatrixXd P_fix = P_ - PAt * qf.solve(PAt.transpose());
  sol.quality = 1;
  sol.p_e = x_fix.head<3>();
  sol.cov_e = P_fix.topLeftCorner<3, 3>();
  if (options_.fix_and_hold) {
    const Eigen::MatrixXd R =
        Eigen::MatrixXd::Identity(nf, nf) * std::pow(options_.hold_sigma_cycles, 2);
    const Eigen::MatrixXd S = Af * P_ * Af.transpose() + R;
    const Eigen::MatrixXd K = S.ldlt().solve(Af * P_).transpose();
    x_ += K * (fix.values - Af * x_);
    P_ = (Eigen::MatrixXd::Identity(x_.size(), x_.size()) - K * Af) * P_;
  }
  return sol;
}

}  // namespace giocal
