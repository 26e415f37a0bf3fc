#include "common/gnss/spp.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>

#include "common/gnss/atmosphere.h"
#include "common/gnss/dd_epoch.h"

namespace giocal {

namespace {

struct Candidate {
  SatId sat;
  const SignalObs* sig;  // the primary band's: its range places the satellite, its Doppler
  // The code range solved for: the primary band's, or with a second band the ionosphere-free
  // combination (IF), whose noise is `noise_factor` times one band's and whose satellite clock
  // is referenced to that pair of bands (`clock_shift` [s] added to the primary band's).
  double P = 0.0;
  bool iono_free = false;
  double noise_factor = 1.0, clock_shift = 0.0;
  // The satellite at transmission, which the iterations do not change: found on the first.
  const Ephemeris* eph = nullptr;
  std::optional<SatelliteState> sent;
  SatelliteAtReception s;
  double el = 0, az = 0, var = 0, residual = 0;
  Eigen::Vector3d u;  // unit vector receiver -> satellite
};

/// The ionosphere-free range of the primary band and the first other band with a code range
/// (as ddBands lists them), if the satellite has one: P_IF = (f1^2 P1 - f2^2 P2) / (f1^2 - f2^2),
/// its satellite clock shifted from the primary band's group delay to the pair's.
void ionosphereFree(const SatObs& so, const Ephemeris& eph, Candidate& c) {
  for (const char band : ddBands(so.sat.sys, 3)) {
    if (band == c.sig->band) continue;
    const SignalObs* s2 = so.bestOnBand(band);
    if (!s2 || !(s2->P > 1e7) || !(s2->P < 6e7)) continue;
    const double f1 = carrierFrequency(so.sat.sys, c.sig->band);
    const double f2 = carrierFrequency(so.sat.sys, band);
    if (!(f1 > 0.0) || !(f2 > 0.0) || f1 == f2) continue;
    const double g1 = f1 * f1, g2 = f2 * f2;
    c.P = (g1 * c.sig->P - g2 * s2->P) / (g1 - g2);
    const double gd1 = groupDelay(eph, c.sig->band), gd2 = groupDelay(eph, band);
    c.clock_shift = gd1 - (g1 * gd1 - g2 * gd2) / (g1 - g2);
    c.noise_factor = std::sqrt(g1 * g1 + g2 * g2) / std::abs(g1 - g2);
    c.iono_free = true;
    return;
  }
}

double normalQuantile(double p) {
  // Acklam's rational approximation of the inverse normal CDF (|error| < 1.2e-9).
  static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                             1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                             6.680131188771972e+01, -1.328068155288572e+01};
  static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                             -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                             3.754408661907416e+00};
  const double pl = 0.02425;
  if (p < pl) {
    const double q = std::sqrt(-2 * std::log(p));
    return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
           ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
  }
  if (p > 1 - pl) return -normalQuantile(1 - p);
  const double q = p - 0.5, r = q * q;
  return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
         (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
}

}  // namespace

double chi2Quantile(double probability, int dof) {
  const double z = normalQuantile(probability);
  if (dof == 1) {
    const double z1 = normalQuantile(0.5 + probability / 2.0);  // chi2(1) is a squared normal
    return z1 * z1;
  }
  if (dof == 2) return -2.0 * std::log(1.0 - probability);  // chi2(2) is exponential
  const double k = dof;
  const double t = 1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k));
  return k * t * t * t;
}

SppSolution solveSpp(const ObsEpoch& epoch, const BroadcastOrbits& orbits,
                     const SppOptions& options) {
  SppSolution sol;
  std::vector<Candidate> cands;
  for (const SatObs& so : epoch.sats) {
    if (!options.systems.empty() && std::find(options.systems.begin(), options.systems.end(),
                                              so.sat.sys) == options.systems.end())
      continue;
    const SignalObs* sig = so.bestOnBand(primaryBand(so.sat.sys));
    if (!sig || !(sig->P > 1e7) || !(sig->P < 6e7)) continue;
    if (options.cn0_mask_dbhz > 0 && !(sig->S >= options.cn0_mask_dbhz)) continue;
    Candidate c;
    c.sat = so.sat;
    c.sig = sig;
    c.P = sig->P;
    c.eph = orbits.select(so.sat, epoch.t);
    c.u.setZero();
    if (options.ionosphere_free && c.eph) ionosphereFree(so, *c.eph, c);
    cands.push_back(c);
  }
  std::vector<bool> excluded(cands.size(), false);
  const double mask = options.elevation_mask_deg * M_PI / 180.0;

  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  std::map<GnssSystem, double> clk;
  for (int attempt = 0; attempt <= options.max_rejections; ++attempt) {
    std::vector<int> rows;
    std::vector<GnssSystem> systems;
    Eigen::MatrixXd H;
    Eigen::VectorXd v, w;
    bool converged = false;
    for (int it = 0; it < 15 && !converged; ++it) {
      const bool near_surface = x.norm() > 6.0e6;
      const Geodetic g = near_surface ? geodeticFromEcef(x) : Geodetic{};
      const std::optional<Topocentric> sky =
          near_surface ? std::optional<Topocentric>(x) : std::nullopt;
      rows.clear();
      systems.clear();
      for (size_t k = 0; k < cands.size(); ++k) {
        if (excluded[k]) continue;
        Candidate& c = cands[k];
        if (!c.eph) continue;
        if (!c.sent) c.sent = BroadcastOrbits::atTransmission(*c.eph, epoch.t, c.sig->P);
        c.s = BroadcastOrbits::inReceptionFrame(*c.eph, *c.sent, c.sig->P, c.sig->band, x);
        const Eigen::Vector3d d = c.s.p_e - x;
        c.u = d.normalized();
        double trop = 0, iono = 0;
        c.el = M_PI / 2;
        c.az = 0;
        if (near_surface) {
          sky->elevationAzimuth(c.s.p_e, c.el, c.az);
          if (c.el < mask) continue;
          trop = tropoSaastamoinen(g, c.el);
          if (orbits.nav().has_gps_iono) {
            const double f1 = carrierFrequency(GnssSystem::kGps, '1');
            const double f = carrierFrequency(c.sat.sys, c.sig->band);
            iono =
                ionoKlobuchar(orbits.nav().gps_iono, epoch.t, g, c.el, c.az) * (f1 / f) * (f1 / f);
          }
        }
        if (c.iono_free) iono = 0.0;
        c.residual = c.P - (d.norm() + (clk.count(c.sat.sys) ? clk[c.sat.sys] : 0.0) -
                            kSpeedOfLight * (c.s.clock + c.clock_shift) + trop + iono);
        c.var = options.code.variance(c.el) * c.noise_factor * c.noise_factor + c.s.variance +
                std::pow(0.5 * iono, 2) + std::pow(0.1 * trop, 2);
        rows.push_back(static_cast<int>(k));
        if (std::find(systems.begin(), systems.end(), c.sat.sys) == systems.end()) {
          systems.push_back(c.sat.sys);
        }
      }
      const int n = static_cast<int>(rows.size()), m = 3 + static_cast<int>(systems.size());
      if (n < m) return sol;
      H = Eigen::MatrixXd::Zero(n, m);
      v.resize(n);
      w.resize(n);
      for (int i = 0; i < n; ++i) {
        const Candidate& c = cands[static_cast<size_t>(rows[static_cast<size_t>(i)])];
        H.block(i, 0, 1, 3) = -c.u.transpose();
        const auto si = std::find(systems.begin(), systems.end(), c.sat.sys) - systems.begin();
        H(i, 3 + si) = 1.0;
        v[i] = c.residual;
        w[i] = 1.0 / c.var;
      }
      const Eigen::MatrixXd N = H.transpose() * w.asDiagonal() * H;
      const Eigen::VectorXd dx = N.ldlt().solve(H.transpose() * w.asDiagonal() * v);
      x += dx.head<3>();
      for (size_t s = 0; s < systems.size(); ++s) clk[systems[s]] += dx[3 + static_cast<long>(s)];
      converged = dx.head<3>().norm() < 1e-4;
      if (converged) {
        const Eigen::MatrixXd Q = N.inverse();
        sol.cov_p = Q.topLeftCorner<3, 3>();
        Eigen::MatrixXd Hg = H;  // GDOP with unit weights
        sol.gdop = std::sqrt((Hg.transpose() * Hg).inverse().trace());
        const Eigen::MatrixXd A = Q.topRows<3>() * H.transpose() * w.asDiagonal();
        sol.range_error_cov_p = A * A.transpose();
      }
    }
    if (!converged) return sol;
    // Residuals of the last linearization (the update that followed was below 0.1 mm).
    double chi2 = 0.0, worst = 0.0;
    int worst_k = -1;
    for (size_t i = 0; i < rows.size(); ++i) {
      const Candidate& c = cands[static_cast<size_t>(rows[i])];
      const double nr = c.residual * c.residual / c.var;
      chi2 += nr;
      if (nr > worst) {
        worst = nr;
        worst_k = rows[i];
      }
    }
    const int dof = static_cast<int>(rows.size()) - 3 - static_cast<int>(systems.size());
    if (dof > 0 && chi2 > chi2Quantile(options.chi2_probability, dof) &&
        attempt < options.max_rejections && dof > 1) {
      excluded[static_cast<size_t>(worst_k)] = true;
      sol.rejected.push_back(cands[static_cast<size_t>(worst_k)].sat);
      continue;
    }
    if (sol.gdop > options.max_gdop) return sol;
    sol.valid = true;
    sol.p_e = x;
    sol.clock_m = clk;
    for (int k : rows) sol.used.push_back(cands[static_cast<size_t>(k)].sat);
    break;
  }
  if (!sol.valid) return sol;

  // Doppler velocity: observed range rate -lambda D = u.(v_s - v_r) + c (dtr_dot - dts_dot).
  std::vector<const Candidate*> dop;
  for (size_t k = 0; k < cands.size(); ++k) {
    if (!excluded[k] &&
        std::find(sol.used.begin(), sol.used.end(), cands[k].sat) != sol.used.end() &&
        !std::isnan(cands[k].sig->D)) {
      dop.push_back(&cands[k]);
    }
  }
  std::vector<bool> dop_out(dop.size(), false);
  Eigen::Vector4d y = Eigen::Vector4d::Zero();
  for (int attempt = 0; attempt <= options.max_rejections; ++attempt) {
    std::vector<int> idx;
    for (size_t i = 0; i < dop.size(); ++i) {
      if (!dop_out[i]) idx.push_back(static_cast<int>(i));
    }
    if (idx.size() < 5) return sol;
    const int n = static_cast<int>(idx.size());
    Eigen::MatrixXd H(n, 4);
    Eigen::VectorXd v(n), w(n);
    for (int gn = 0; gn < 2; ++gn) {  // linear problem: a second pass only refreshes residuals
      for (int i = 0; i < n; ++i) {
        const Candidate& c = *dop[static_cast<size_t>(idx[static_cast<size_t>(i)])];
        const double lambda = kSpeedOfLight / carrierFrequency(c.sat.sys, c.sig->band);
        // Sagnac rate: d/dt of omega/c (x_s y_r - y_s x_r).
        const double we = wgs84::kOmegaEarth;
        const Eigen::Vector3d& ps = c.s.p_e;
        const Eigen::Vector3d& vs = c.s.v_e;
        const double sagnac_rate =
            we / kSpeedOfLight *
            (vs.y() * x.x() + ps.y() * y.x() - vs.x() * x.y() - ps.x() * y.y());
        const double predicted =
            c.u.dot(vs - y.head<3>()) + y[3] - kSpeedOfLight * c.s.clock_drift + sagnac_rate;
        v[i] = -lambda * c.sig->D - predicted;
        H.row(i) << -c.u.transpose(), 1.0;
        w[i] = 1.0 / options.doppler.variance(c.el);
      }
      const Eigen::Matrix4d N = H.transpose() * w.asDiagonal() * H;
      if (gn == 0) y += N.ldlt().solve(H.transpose() * w.asDiagonal() * v);
    }
    double chi2 = 0, worst = 0;
    int worst_i = -1;
    for (int i = 0; i < n; ++i) {
      const double nr = v[i] * v[i] * w[i];
      chi2 += nr;
      if (nr > worst) {
        worst = nr;
        worst_i = idx[static_cast<size_t>(i)];
      }
    }
    if (chi2 > chi2Quantile(options.chi2_probability, n - 4) && attempt < options.max_rejections) {
      dop_out[static_cast<size_t>(worst_i)] = true;
      sol.doppler_rejected.push_back(dop[static_cast<size_t>(worst_i)]->sat);
      y.setZero();
      continue;
    }
    sol.velocity_valid = true;
    sol.v_e = y.head<3>();
    sol.clock_drift_m_s = y[3];
    break;
  }
  return sol;
}

Eigen::Matrix3d sppBiasCovariance(const LocalFrame& frame, const SppSolution& spp, double sigma) {
  const Eigen::Matrix3d& R_e_n = frame.R_e_n();
  return sigma * sigma * R_e_n.transpose() * spp.range_error_cov_p * R_e_n;
}

PositionFix sppFix(const SppSolution& spp, double t, double sigma_min) {
  PositionFix fix;
  fix.t = t;
  fix.p_e = spp.p_e;
  fix.quality = 5;
  fix.satellites = static_cast<int>(spp.used.size());
  const Geodetic g = geodeticFromEcef(spp.p_e);
  const Eigen::Matrix3d R_e_enu = rotationEcefFromEnu(g.lat, g.lon);
  fix.cov_enu = R_e_enu.transpose() * spp.cov_p * R_e_enu;
  for (int k = 0; k < 3; ++k) {
    const double sd = std::sqrt(std::max(fix.cov_enu(k, k), 0.0));
    if (sd >= sigma_min) continue;
    // Raise the standard deviation, keeping the correlations.
    const double f = sigma_min / std::max(sd, 1e-9);
    fix.cov_enu.row(k) *= f;
    fix.cov_enu.col(k) *= f;
  }
  return fix;
}

}  // namespace giocal
