// Double-difference residuals of a real rover/base pair at a fixed solution: one CSV row per
// phase and code row of every fixed epoch, with both satellites' elevations, for fitting the
// GNSS noise model on real data (bench/gnss_noise_fit.py). The phase residual is taken modulo
// one wavelength: at a fixed position good to centimetres the DD ambiguity is the nearest integer.
// Usage: giocal_gnss_residuals --rover R --base B --nav N [--nav N2] --base-pos x,y,z
//        --pos fixed.pos [--frequencies 2] > residuals.csv
// With --rover and --nav alone (no base): code minus carrier of every signal with both, with its
// elevation, C/N0 and loss-of-lock flag, for the code noise of a receiver without a base (the
// constant ambiguity and the slow ionosphere are taken out per arc by gnss_noise_fit.py --cmc).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "common/gnss/atmosphere.h"
#include "common/gnss/dd_epoch.h"
#include "common/gnss/observation.h"
#include "common/gnss/pos_reader.h"
#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_obs.h"
#include "common/gnss/rtk_job.h"

using namespace giocal;

int main(int argc, char** argv) {
  std::string rover_path, base_path, pos_path;
  std::vector<std::string> nav_paths;
  Eigen::Vector3d base_e = Eigen::Vector3d::Zero();
  DdOptions options;
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
    else if (k == "--frequencies")
      options.frequencies = std::stoi(v);
    else {
      std::cerr << "giocal_gnss_residuals: unknown option " << k << "\n";
      return 2;
    }
  }
  if (!rover_path.empty() && !nav_paths.empty() && base_path.empty()) {
    std::vector<NavData> navs;
    for (const auto& n : nav_paths) navs.push_back(readRinexNav(n));
    const BroadcastOrbits orbits(mergeNav(navs));
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
  std::vector<NavData> navs;
  for (const auto& n : nav_paths) navs.push_back(readRinexNav(n));
  const BroadcastOrbits orbits(mergeNav(navs));
  const ObsData rover = readRinexObs(rover_path);
  const ObsData base = readRinexObs(base_path);
  std::map<long long, Eigen::Vector3d> fixed;  // by rover time in milliseconds
  for (const PositionFix& f : readPosFile(pos_path)) {
    if (f.quality == 1) fixed[std::llround(f.t * 1e3)] = f.p_e;
  }
  options.elevation_mask_deg = 10.0;
  DdEpochBuilder builder(orbits, base_e, options);
  BaseEpochMatcher matcher(base.epochs, 0.5);
  std::printf("t,sys,sat,ref,band,kind,el_sat_deg,el_ref_deg,residual_m,baseline_m\n");
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
      std::printf("%.3f,%c,%s,%s,%c,%s,%.2f,%.2f,%.5f,%.1f\n", r.t, static_cast<char>(o.sat.sys),
                  o.sat.str().c_str(), o.ref.str().c_str(), o.band, o.phase ? "phase" : "code",
                  gs.el * 180.0 / M_PI, gr.el * 180.0 / M_PI, res, (p - base_e).norm());
    }
  }
  return 0;
}
