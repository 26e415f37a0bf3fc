// Double-difference residuals of a real rover/base pair at a fixed solution: one CSV row per
// phase and code row of every fixed epoch, with both satellites' elevations, for fitting the
// GNSS noise model on real data (bench/gnss_noise_fit.py). The phase residual is taken modulo
// one wavelength: at a fixed position good to centimetres the DD ambiguity is the nearest integer.
// Usage: giocal_gnss_residuals --rover R --base B --nav N [--nav N2] --base-pos x,y,z
//        --pos fixed.pos [--frequencies 2] > residuals.csv
// With --rover and --nav alone (no base): code minus carrier of every signal with both, with its
// elevation, C/N0 and loss-of-lock flag, for the code noise of a receiver without a base (the
// constant ambiguity and the slow ionosphere are taken out per arc by gnss_noise_fit.py --cmc).
// With --rover, --nav and --truth truth.csv --p-b-g x,y,z (a simulated drive): every
// time-differenced phase row (TdcpBuilder, the single-receiver scheme's) against the true antenna
// displacement, for checking the TDCP model against the simulator's phases. With --spp-csv F as
// well, each epoch's single point position against the true antenna (ENU error and stated sigma).
// --ionosphere-window S sets TdcpOptions::ionosphere_window_s (0: the ionosphere's change left in).
// --systems GE and --mask DEG set the time differences' sky, and the single point positions';
// --spp-ionosphere-free 0 makes the latter from the first band with the broadcast ionosphere.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "common/calibration/reference_trajectory.h"
#include "common/geodesy/wgs84.h"
#include "common/gnss/atmosphere.h"
#include "common/gnss/dd_epoch.h"
#include "common/gnss/observation.h"
#include "common/gnss/pos_reader.h"
#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_obs.h"
#include "common/gnss/rtk_job.h"
#include "common/gnss/spp.h"
#include "common/gnss/tdcp_track.h"
#include "common/gnss/time_differenced_phase.h"
#include "common/io/sensor_logs.h"

using namespace giocal;

namespace {

NavData readNavs(const std::vector<std::string>& paths) {
  std::vector<NavData> navs;
  for (const auto& n : paths) navs.push_back(readRinexNav(n));
  return mergeNav(navs);
}

// The TDCP rows of a simulated drive against its truth: t, sat, ref, band, elevations, the
// residual (observed minus the true displacement's prediction) and the row's stated sigma.
int tdcpAtTruth(const std::string& rover_path, const std::vector<std::string>& nav_paths,
                const std::string& truth_path, const Eigen::Vector3d& p_b_g,
                const std::string& spp_path, const TdcpOptions& tdcp) {
  const BroadcastOrbits orbits(readNavs(nav_paths));
  const ObsData rover = readRinexObs(rover_path);
  const std::vector<TruthSample> truth = readTruthCsv(truth_path);
  size_t k = 0;
  // The antenna (ECEF) at the truth row nearest t.
  const auto antenna = [&](double t, Eigen::Vector3d& p_e) {
    while (k + 1 < truth.size() && std::abs(truth[k + 1].t - t) <= std::abs(truth[k].t - t)) ++k;
    if (std::abs(truth[k].t - t) > 1e-3) return false;
    p_e = antennaOfRow(truth[k], p_b_g);
    return true;
  };
  TdcpBuilder builder(orbits, tdcp);
  std::map<double, Eigen::Vector3d> at;  // antenna by epoch time
  std::printf("t,sat,ref,band,el_sat_deg,el_ref_deg,residual_m,sigma_m\n");
  FILE* spp_out = spp_path.empty() ? nullptr : std::fopen(spp_path.c_str(), "w");
  if (spp_out) std::fprintf(spp_out, "t,e_m,n_m,u_m,sd_e_m,sd_n_m,sd_u_m,satellites\n");
  for (const ObsEpoch& r : rover.epochs) {
    Eigen::Vector3d p_e;
    if (!antenna(r.t, p_e)) continue;
    at[r.t] = p_e;
    if (spp_out) {
      const SppSolution spp = solveSpp(r, orbits, sppOnSkyOf(tdcp));
      if (spp.valid) {
        const Geodetic g = geodeticFromEcef(p_e);
        const Eigen::Matrix3d R = rotationEcefFromEnu(g.lat, g.lon);
        const Eigen::Vector3d d = R.transpose() * (spp.p_e - p_e);
        const Eigen::Matrix3d C = R.transpose() * spp.cov_p * R;
        std::fprintf(spp_out, "%.3f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%zu\n", r.t, d.x(), d.y(), d.z(),
                     std::sqrt(C(0, 0)), std::sqrt(C(1, 1)), std::sqrt(C(2, 2)), spp.used.size());
      }
    }
    const TdcpPair pair = builder.add(r, p_e);
    const auto a0 = at.find(pair.t0), a1 = at.find(pair.t1);
    if (pair.rows.empty() || a0 == at.end() || a1 == at.end()) continue;
    const Eigen::MatrixXd C = tdcpCovariance(pair);
    for (size_t i = 0; i < pair.rows.size(); ++i) {
      const TdcpRow& row = pair.rows[i];
      const TdcpSignal& s = pair.signals[static_cast<size_t>(row.signal)];
      const TdcpSignal& ref = pair.signals[static_cast<size_t>(row.ref)];
      const double res = tdcpObserved(pair, row) -
                         tdcpPredict(pair, row, a0->second, a1->second, nullptr, nullptr);
      std::printf("%.3f,%s,%s,%c,%.2f,%.2f,%.5f,%.5f\n", pair.t1, s.sat.str().c_str(),
                  ref.sat.str().c_str(), s.band, s.el * 180.0 / M_PI, ref.el * 180.0 / M_PI, res,
                  std::sqrt(C(static_cast<long>(i), static_cast<long>(i))));
    }
  }
  if (spp_out) std::fclose(spp_out);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string rover_path, base_path, pos_path, truth_path, spp_path;
  Eigen::Vector3d p_b_g = Eigen::Vector3d::Zero();
  std::vector<std::string> nav_paths;
  Eigen::Vector3d base_e = Eigen::Vector3d::Zero();
  DdOptions options;
  TdcpOptions tdcp;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--rover")
      rover_path = v;
    else if (k == "--base")
      base_path = v;
    else if (k == "--nav")
      nav_paths.push_back(v);
    else if (k == "--pos")
      pos_path = v;
    else if (k == "--base-pos")
      base_e = parseBasePosition(v);
    else if (k == "--truth")
      truth_path = v;
    else if (k == "--spp-csv")
      spp_path = v;
    else if (k == "--p-b-g") {
      if (std::sscanf(v.c_str(), "%lf,%lf,%lf", &p_b_g.x(), &p_b_g.y(), &p_b_g.z()) != 3) {
        std::cerr << "giocal_gnss_residuals: --p-b-g takes x,y,z [m]\n";
        return 2;
      }
    } else if (k == "--systems") {
      tdcp.systems.clear();
      for (const char c : v) tdcp.systems.push_back(static_cast<GnssSystem>(c));
    } else if (k == "--mask")
      tdcp.elevation_mask_deg = std::stod(v);
    else if (k == "--ionosphere-window")
      tdcp.ionosphere_window_s = std::stod(v);
    else if (k == "--spp-ionosphere-free")
      tdcp.spp_ionosphere_free = std::stoi(v) != 0;
    else if (k == "--frequencies")
      options.frequencies = std::stoi(v);
    else {
      std::cerr << "giocal_gnss_residuals: unknown option " << k << "\n";
      return 2;
    }
  }
  if (!truth_path.empty())
    return tdcpAtTruth(rover_path, nav_paths, truth_path, p_b_g, spp_path, tdcp);
  if (!rover_path.empty() && !nav_paths.empty() && base_path.empty()) {
    const BroadcastOrbits orbits(readNavs(nav_paths));
    const ObsData rover = readRinexObs(rover_path);
    const Eigen::Vector3d p = rover.header.approx_position;
    const Topocentric sky(p);
    std::printf("t,sat,band,el_deg,cn0,lli,cmc_m\n");
    for (const ObsEpoch& r : rover.epochs) {
      for (const SatObs& so : r.sats) {
        for (const SignalObs& sig : so.signals) {
          if (std::isnan(sig.P) || std::isnan(sig.L)) continue;
          const auto at = orbits.atReception(so.sat, r.t, sig.P, sig.band, p);
          const double f = carrierFrequency(so.sat.sys, sig.band);
          if (!at || f <= 0.0) continue;
          double el = 0.0, az = 0.0;
          sky.elevationAzimuth(at->p_e, el, az);
          std::printf("%.3f,%s,%c,%.2f,%.1f,%d,%.4f\n", r.t, so.sat.str().c_str(), sig.band,
                      el * 180.0 / M_PI, sig.S, sig.lli, sig.P - sig.L * kSpeedOfLight / f);
        }
      }
    }
    return 0;
  }
  if (rover_path.empty() || base_path.empty() || nav_paths.empty() || pos_path.empty() ||
      base_e.isZero()) {
    std::cerr << "usage: giocal_gnss_residuals --rover R --base B --nav N --base-pos x,y,z "
                 "--pos fixed.pos\n";
    return 2;
  }
  const BroadcastOrbits orbits(readNavs(nav_paths));
  const ObsData rover = readRinexObs(rover_path);
  const ObsData base = readRinexObs(base_path);
  std::map<long long, Eigen::Vector3d> fixed;  // by rover time in milliseconds
  for (const PositionFix& f : readPosFile(pos_path)) {
    if (f.quality == 1) fixed[std::llround(f.t * 1e3)] = f.p_e;
  }
  options.elevation_mask_deg = 10.0;
  DdEpochBuilder builder(orbits, base_e, options);
  BaseEpochMatcher matcher(base.epochs, 0.5);
  std::printf(
      "t,sys,sat,ref,band,kind,el_sat_deg,el_ref_deg,residual_m,baseline_m,cn0_sat_rover,"
      "cn0_sat_base,cn0_ref_rover,cn0_ref_base\n");
  // The C/N0 of a satellite's best signal on a band (NaN when the file has none).
  const auto cn0 = [](const ObsEpoch& e, const SatId& sat, char band) {
    const SatObs* so = e.find(sat);
    const SignalObs* sig = so ? so->bestOnBand(band) : nullptr;
    return sig ? sig->S : std::nan("");
  };
  for (const ObsEpoch& r : rover.epochs) {
    const ObsEpoch* b = matcher.nearest(r.t);
    // Fixed solutions carry the rover's time tag to the millisecond in the .pos.
    auto it = fixed.lower_bound(std::llround(r.t * 1e3) - 10);
    const bool have = it != fixed.end() && std::abs(it->first - std::llround(r.t * 1e3)) <= 10;
    if (!b) continue;
    const Eigen::Vector3d p = have ? it->second : rover.header.approx_position;
    const DdEpoch ep = builder.build(r, *b, p);  // every epoch: the slip detectors need them
    if (!have) continue;
    for (const DdObservation& o : ep.obs) {
      const SdGeometry& gs = ep.geometry[static_cast<size_t>(o.sat_index)];
      const SdGeometry& gr = ep.geometry[static_cast<size_t>(o.ref_index)];
      double res = o.value - ddRange(p, gs, gr, nullptr);
      if (o.phase) res -= o.lambda * std::round(res / o.lambda);
      std::printf("%.3f,%c,%s,%s,%c,%s,%.2f,%.2f,%.5f,%.1f,%.1f,%.1f,%.1f,%.1f\n", r.t,
                  static_cast<char>(o.sat.sys), o.sat.str().c_str(), o.ref.str().c_str(), o.band,
                  o.phase ? "phase" : "code", gs.el * 180.0 / M_PI, gr.el * 180.0 / M_PI, res,
                  (p - base_e).norm(), cn0(r, o.sat, o.band), cn0(*b, o.sat, o.band),
                  cn0(r, o.ref, o.band), cn0(*b, o.ref, o.band));
    }
  }
  return 0;
}
