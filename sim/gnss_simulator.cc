#include "sim/gnss_simulator.h"

#include <cmath>
#include <map>
#include <stdexcept>

#include "common/geodesy/wgs84.h"
#include "sim/sky_geometry.h"

namespace giocal::sim {

namespace {

constexpr double kEarthRadius = 6371e3, kIonoHeight = 350e3;

double gauss(std::mt19937_64& rng, double sd) {
  std::normal_distribution<double> n(0.0, 1.0);
  return n(rng) * sd;
}

// Simulator ionosphere: single layer at 350 km, delay on L1 for a vertical TEC [TECU].
double ionosphereL1(double vtec, double el) {
  const double f1 = 1575.42e6;
  const double s = kEarthRadius * std::cos(el) / (kEarthRadius + kIonoHeight);
  return 40.3e16 * vtec / (f1 * f1) / std::sqrt(1.0 - s * s);
}

struct Receiver {
  double clock, drift;  // [s], [s/s]
  double zwd;           // zenith wet delay [m]
};

// A satellite's broadcast errors: where and when it truly is against its ephemeris.
struct BroadcastError {
  Eigen::Vector3d orbit = Eigen::Vector3d::Zero(), orbit_rate = Eigen::Vector3d::Zero();
  double clock_m = 0.0;
  double clock_rate = 0.0;  // the clock error's short-term rate, a Gauss-Markov process [m/s]
};

// BeiDou MEO satellites by PRN (BDS-2 C11, C12, C14; BDS-3 C19-C30, C32-C37, C41-C46).
bool isBeidouMeo(const SatId& sat) {
  const int p = sat.prn;
  return p == 11 || p == 12 || p == 14 || (p >= 19 && p <= 30) || (p >= 32 && p <= 37) ||
         (p >= 41 && p <= 46) || (p >= 47 && p <= 55);
}

}  // namespace

SceneSpec sceneDefaults(const std::string& type) {
  SceneSpec s;
  s.type = type;
  if (type == "few_trees") {
    s.block_probability = 0.15;
    s.outlier_probability = 0.02;
    s.outlier_m = 5.0;
    s.extra_phase_sigma = 0.003;
    s.slip_probability = 0.002;
  } else if (type == "more_trees") {
    s.block_probability = 0.35;
    s.outlier_probability = 0.05;
    s.outlier_m = 10.0;
    s.extra_phase_sigma = 0.006;
    s.slip_probability = 0.01;
  } else if (type == "building") {
    s.building_side = "left";
    s.outlier_probability = 0.08;
    s.outlier_m = 15.0;
    s.extra_phase_sigma = 0.004;
    s.slip_probability = 0.005;
  } else if (type != "open_sky") {
    throw std::invalid_argument("unknown scene type '" + type +
                                "' (open_sky, few_trees, more_trees, building)");
  }
  return s;
}

void setSingleReceiverDefaults(GnssSimSpec& spec) {
  spec.orbit_error_m = 0.5;      // broadcast SISRE of GPS and Galileo: decimetres to 1 m
  spec.orbit_error_rate = 2e-4;  // about 0.7 m per hour
  spec.sat_clock_error_m = 0.5;
  spec.sat_clock_random_walk = 1e-4;  // 0.1 mm in 1 s, 0.5 mm in 30 s
  // The time differences' slow part on a real receiver (the mosaic rover, GPS above 24 degrees,
  // bench/tdcp_slow_errors.py): 1 s pairs averaged over 20, 60 and 120 s are off by 1.17, 0.73
  // and 0.60 mm/s, the same on L1 and L2, larger for GPS than for Galileo; the sum of the above
  // made 0.66, 0.26 and 0.22. A rate per satellite correlated over a minute makes up the rest.
  spec.sat_clock_rate_sd = 7e-4;
  spec.sat_clock_rate_tau_s = 60.0;
  spec.vtec_random_walk = 0.002;         // 0.3 mm on L1 in 1 s, 0.12 TECU in an hour
  spec.zenith_wet_random_walk = 1.7e-4;  // 1 cm per sqrt(hour)
  spec.clock_step_s = 1e-3;
  spec.clock_offset_sd = 2e-4;
  spec.clock_drift_sd = 5e-7;  // a TCXO: the clock walks off and steps every few minutes
  spec.half_cycle_share = 0.2;
}

std::vector<std::pair<char, char>> simulatedSignals(GnssSystem sys) {
  switch (sys) {
    case GnssSystem::kGps:
      return {{'1', 'C'}, {'2', 'W'}};
    case GnssSystem::kGalileo:
      return {{'1', 'C'}, {'7', 'Q'}};
    case GnssSystem::kBeidou:
      return {{'2', 'I'}, {'7', 'I'}};
    case GnssSystem::kQzss:
      return {{'1', 'C'}, {'2', 'L'}};
    default:
      return {};
  }
}

std::vector<SignalSpec> receiverSignals(const GnssSimSpec& spec, int receiver, GnssSystem sys) {
  std::vector<SignalSpec> out;
  if (receiver == 1) {
    for (const SignalSpec& s : spec.base_signals) {
      if (s.sys == sys) out.push_back(s);
    }
    if (!out.empty()) return out;
  }
  for (const auto& [band, attr] : simulatedSignals(sys)) out.push_back({sys, band, attr});
  return out;
}

SimulatedGnss simulateGnss(const GnssSimSpec& spec, const BroadcastOrbits& orbits,
                           const AntennaTruth& rover, const Eigen::Vector3d& base_e, double t0,
                           double t1, std::mt19937_64& rng) {
  SimulatedGnss out;
  out.base_e = base_e;
  out.base_phase_aligned = spec.base_phase_aligned;
  std::map<GnssSystem, std::vector<SignalSpec>> tracked[2];  // per receiver and system
  for (int r = 0; r < 2; ++r) {
    for (const char sys : spec.systems) {
      const auto gs = static_cast<GnssSystem>(sys);
      tracked[r][gs] = receiverSignals(spec, r, gs);
      out.signals[r].insert(out.signals[r].end(), tracked[r][gs].begin(), tracked[r][gs].end());
    }
  }
  std::vector<SatId> sats;
  for (const Ephemeris& e : orbits.nav().ephemerides) {
    if (spec.systems.find(static_cast<char>(e.sat.sys)) == std::string::npos) continue;
    if (spec.beidou_meo_only && e.sat.sys == GnssSystem::kBeidou && !isBeidouMeo(e.sat)) continue;
    if (std::find(sats.begin(), sats.end(), e.sat) == sats.end()) sats.push_back(e.sat);
  }
  std::sort(sats.begin(), sats.end());
  Receiver rx[2];
  for (Receiver& r : rx) {
    r.clock = gauss(rng, spec.clock_offset_sd);
    r.drift = gauss(rng, spec.clock_drift_sd);
    r.zwd = std::max(0.0, 0.1 + gauss(rng, spec.zenith_wet_sd));
  }
  // The single receiver's errors draw from their own generator, so that datasets with a base
  // are the same as before they existed.
  const bool rover_alone_errors = spec.orbit_error_m > 0 || spec.orbit_error_rate > 0 ||
                                  spec.sat_clock_error_m > 0 || spec.sat_clock_random_walk > 0 ||
                                  spec.vtec_random_walk > 0 || spec.zenith_wet_random_walk > 0 ||
                                  spec.sat_clock_rate_sd > 0 || spec.half_cycle_share > 0;
  std::mt19937_64 rng_alone(rover_alone_errors ? rng() : 0);
  // The satellite clocks' short-term rate draws from a generator of its own, seeded from a copy
  // of rng_alone, so that the other errors of a rover alone are the same with or without it.
  std::mt19937_64 rng_rate(std::mt19937_64(rng_alone)() ^ 0x9e3779b97f4a7c15ULL);
  const double rate_decay = spec.sat_clock_rate_tau_s > 0
                                ? std::exp(-1.0 / (spec.rate_hz * spec.sat_clock_rate_tau_s))
                                : 0.0;
  Multipath multipath(spec.multipath, spec.multipath.enabled() ? rng() : 0);
  std::map<SatId, BroadcastError> broadcast;
  for (const SatId& sat : sats) {
    BroadcastError& b = broadcast[sat];
    if (!rover_alone_errors) continue;
    for (int k = 0; k < 3; ++k) {
      b.orbit[k] = gauss(rng_alone, spec.orbit_error_m);
      b.orbit_rate[k] = gauss(rng_alone, spec.orbit_error_rate);
    }
    b.clock_m = gauss(rng_alone, spec.sat_clock_error_m);
    b.clock_rate = gauss(rng_rate, spec.sat_clock_rate_sd);
  }
  double vtec_walk = 0.0;
  const double mask = spec.elevation_mask_deg * M_PI / 180.0;
  const LocalFrame frame(base_e);  // the ionosphere gradient is measured from the base
  const double dt = 1.0 / spec.rate_hz;
  const long n = static_cast<long>(std::floor((t1 - t0) * spec.rate_hz + 1e-9));
  std::uniform_int_distribution<int> amb(-100000, 100000), slip_size(1, 10);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  double heading = 0.0;  // direction of travel (azimuth from north), kept while standing
  for (long k = 0; k <= n; ++k) {
    const double tag = t0 + static_cast<double>(k) * dt;
    for (int r = 0; r < (spec.base ? 2 : 1); ++r) {
      Receiver& rc = rx[r];
      ObsEpoch ep;
      ep.t = tag;
      const double t_true = tag - rc.clock;
      Eigen::Vector3d p, v = Eigen::Vector3d::Zero();
      if (r == 0) {
        rover(t_true, p, v);
      } else {
        p = base_e;
      }
      const Geodetic geo = geodeticFromEcef(p);
      const SceneSpec* scene = nullptr;
      if (r == 0) {
        for (const SceneSpec& sc : spec.scenes) {
          if (tag - t0 >= sc.start && tag - t0 < sc.end) scene = &sc;
        }
        const Eigen::Vector3d v_enu = rotationEcefFromEnu(geo.lat, geo.lon).transpose() * v;
        if (v_enu.head<2>().norm() > 0.05) heading = std::atan2(v_enu.x(), v_enu.y());
      }
      // VTEC varies slowly in time and space (a plane gradient across the area).
      const Eigen::Vector3d d_enu = frame.enuFromEcef(p);
      const double vtec =
          (spec.vtec_tecu * (1.0 + 0.1 * std::sin(2 * M_PI * (tag - t0) / 3600.0)) + vtec_walk) *
          (1.0 + spec.vtec_gradient * (d_enu.x() + d_enu.y()));
      for (const SatId& sat : sats) {
        SatObs so;
        so.sat = sat;
        // Scene effects drawn once per satellite and epoch (shadowing and NLOS hit every band).
        bool blocked = false;
        double nlos = 0.0;
        if (scene) {
          Geometry g0;
          if (geometry(orbits, sat, t_true, p, v, simulatedSignals(sat.sys).front().first, g0)) {
            double rel = std::remainder(g0.az - heading, 2 * M_PI);  // > 0: right of travel
            const bool on_side = scene->building_side == "left" ? rel < 0 : rel > 0;
            if (!scene->building_side.empty() && on_side &&
                g0.el < scene->building_elevation_deg * M_PI / 180.0) {
              blocked = true;
            }
            if (u01(rng) < scene->block_probability * (1.0 - g0.el / (M_PI / 2))) blocked = true;
            if (u01(rng) < scene->outlier_probability)
              nlos = scene->outlier_m * (0.3 + 0.7 * u01(rng));
          }
        }
        if (blocked) continue;
        for (const SignalSpec& sig : tracked[r][sat.sys]) {
          const char band = sig.band;
          Geometry g;
          if (!geometry(orbits, sat, t_true, p, v, band, g) || g.el < mask ||
              g.el < sig.min_elevation_deg * M_PI / 180.0) {
            continue;
          }
          const double f = carrierFrequency(sat.sys, band);
          const double lambda = kSpeedOfLight / f;
          const double iono = ionosphereL1(vtec, g.el) * std::pow(1575.42e6 / f, 2);
          const double trop = troposphere(geo.h, g.el, rc.zwd);
          const double sin_el = std::max(std::sin(g.el), 0.05);
          const double factor = std::sqrt(1.0 + 1.0 / sin_el);
          const BroadcastError& be = broadcast[sat];
          const double since = t_true - t0;
          const double broadcast_m = g.u.dot(be.orbit + be.orbit_rate * since) + be.clock_m;
          const double common = g.range + broadcast_m + kSpeedOfLight * (rc.clock - g.clock) + trop;
          const auto key = std::make_tuple(r, sat, band);
          if (!out.ambiguity.count(key)) out.ambiguity[key] = amb(rng);
          SignalObs s;
          s.band = band;
          s.attr = sig.attr;
          if (scene && u01(rng) < scene->slip_probability) {
            if (spec.half_cycle_share > 0 && u01(rng_alone) < spec.half_cycle_share) {
              out.ambiguity[key] += 0.5;  // a half cycle, flagged while unresolved
              s.lli = 2;
              ++out.half_cycles;
            } else {
              out.ambiguity[key] += (u01(rng) < 0.5 ? -1 : 1) * slip_size(rng);
              if (u01(rng) < 0.5) s.lli = 1;  // half of the slips are flagged by the receiver
            }
            ++out.slips;
          }
          const double extra = scene ? gauss(rng, scene->extra_phase_sigma) : 0.0;
          const MultipathError mp = multipath.at(r, sat, band, tag, factor);
          s.P = common + iono + nlos + mp.code + gauss(rng, spec.code_sigma * factor);
          s.L =
              (common - iono + extra + mp.phase + gauss(rng, spec.phase_sigma * factor)) / lambda +
              out.ambiguity[key];
          // The raw phase sits its correction short of the band's reference; a file that aligns
          // adds it back (and records it), one that does not keeps the raw phase.
          if (!spec.base_phase_aligned) s.L -= sig.shift_cycles;
          s.D = -(g.range_rate + g.u.dot(be.orbit_rate) + be.clock_rate +
                  kSpeedOfLight * (rc.drift - g.clock_drift)) /
                    lambda +
                gauss(rng, spec.doppler_sigma * factor) / lambda;
          s.S = std::round((35.0 + 15.0 * sin_el) * 4.0) / 4.0;
          so.signals.push_back(s);
        }
        if (!so.signals.empty()) ep.sats.push_back(so);
      }
      (r == 0 ? out.rover : out.base).push_back(ep);
      // Clock: drift plus a random walk, advanced to the next epoch; a receiver that keeps its
      // clock within half a step of GPS time steps it (time tag, code and phase alike).
      rc.clock += rc.drift * dt + gauss(rng, spec.clock_random_walk * std::sqrt(dt));
      if (spec.clock_step_s > 0 && std::abs(rc.clock) > 0.5 * spec.clock_step_s) {
        rc.clock -= std::copysign(spec.clock_step_s, rc.clock);
        out.clock_steps += r == 0;
      }
      if (spec.zenith_wet_random_walk > 0)
        rc.zwd += gauss(rng_alone, spec.zenith_wet_random_walk * std::sqrt(dt));
    }
    if (rover_alone_errors) {
      vtec_walk += gauss(rng_alone, spec.vtec_random_walk * std::sqrt(dt));
      for (auto& [sat, b] : broadcast) {
        b.clock_m += gauss(rng_alone, spec.sat_clock_random_walk * std::sqrt(dt));
        if (spec.sat_clock_rate_sd > 0) {
          b.clock_m += b.clock_rate * dt;
          b.clock_rate =
              rate_decay * b.clock_rate +
              gauss(rng_rate, spec.sat_clock_rate_sd * std::sqrt(1.0 - rate_decay * rate_decay));
        }
      }
    }
  }
  return out;
}

}  // namespace giocal::sim
