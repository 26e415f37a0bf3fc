// The simulated rover alone's satellite clock rate (GnssSimSpec::sat_clock_rate_sd): what it adds
// to the observations is one error per satellite, the same on code and phase of every band, whose
// one-second changes have the asked sigma and correlation time and are in the Doppler too; and it
// leaves every other draw of the rover alone as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "common/geodesy/wgs84.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/rinex_nav.h"
#include "common/math/rotation.h"
#include "sim/simulator.h"

namespace giocal {
namespace {

TEST(SatelliteClockRate, IsOneGaussMarkovRatePerSatelliteOnCodeAndPhaseOfEveryBand) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  sim::GnssSimSpec spec = cfg.gnss;
  spec.base = false;
  sim::setSingleReceiverDefaults(spec);
  ASSERT_GT(spec.sat_clock_rate_sd, 0.0);  // on by default for a rover alone
  spec.code_sigma = spec.phase_sigma = spec.doppler_sigma = 0.0;
  spec.scenes.clear();
  const double sd = spec.sat_clock_rate_sd, tau = spec.sat_clock_rate_tau_s;
  sim::GnssSimSpec without = spec;
  without.sat_clock_rate_sd = 0.0;
  const BroadcastOrbits orbits(readRinexNav(spec.nav_file));
  const Eigen::Vector3d p =
      ecefFromGeodetic({cfg.origin_lat_deg * kDegToRad, cfg.origin_lon_deg * kDegToRad, 60.0});
  const auto still = [&](double, Eigen::Vector3d& p_e, Eigen::Vector3d& v_e) {
    p_e = p;
    v_e.setZero();
  };
  const double t0 = sim::parseGpsTime(cfg.start_time), t1 = t0 + 3600.0;
  std::mt19937_64 rng_a(5), rng_b(5);
  const sim::SimulatedGnss a = sim::simulateGnss(spec, orbits, still, p, t0, t1, rng_a);
  const sim::SimulatedGnss b = sim::simulateGnss(without, orbits, still, p, t0, t1, rng_b);
  ASSERT_EQ(a.rover.size(), b.rover.size());
  EXPECT_EQ(a.clock_steps, b.clock_steps);

  // Per satellite and epoch, the difference of the two files: the same on every signal.
  std::map<SatId, std::vector<double>> added;    // [m], consecutive epochs of one satellite
  std::map<SatId, std::vector<double>> doppler;  // the Doppler's change as a range rate [m/s]
  double worst_spread = 0.0;
  long signals = 0;
  for (size_t k = 0; k < a.rover.size(); ++k) {
    ASSERT_EQ(a.rover[k].sats.size(), b.rover[k].sats.size());
    for (size_t i = 0; i < a.rover[k].sats.size(); ++i) {
      const SatObs &sa = a.rover[k].sats[i], &sb = b.rover[k].sats[i];
      ASSERT_EQ(sa.sat, sb.sat);
      ASSERT_EQ(sa.signals.size(), sb.signals.size());
      const double d0 = sa.signals[0].P - sb.signals[0].P;
      for (size_t j = 0; j < sa.signals.size(); ++j) {
        const double lambda = kSpeedOfLight / carrierFrequency(sa.sat.sys, sa.signals[j].band);
        worst_spread = std::max(worst_spread, std::abs(sa.signals[j].P - sb.signals[j].P - d0));
        worst_spread =
            std::max(worst_spread, std::abs((sa.signals[j].L - sb.signals[j].L) * lambda - d0));
        EXPECT_EQ(sa.signals[j].lli, sb.signals[j].lli);  // the slips drawn alike
        ++signals;
      }
      added[sa.sat].push_back(d0);
      const double lambda = kSpeedOfLight / carrierFrequency(sa.sat.sys, sa.signals[0].band);
      doppler[sa.sat].push_back(-(sa.signals[0].D - sb.signals[0].D) * lambda);
    }
  }
  EXPECT_GT(signals, 50000);
  EXPECT_LT(worst_spread, 1e-6);  // non-dispersive: code and phase of every band alike

  // Its one-second changes: sigma sd, and correlated over tau (exp(-1) at a lag of tau).
  // The Doppler carries the rate of the step that follows its epoch (1 s steps).
  double worst_doppler = 0.0;
  std::vector<std::vector<double>> rates;
  for (const auto& [sat, x] : added) {
    std::vector<double> r;
    for (size_t k = 1; k < x.size(); ++k) {
      r.push_back(x[k] - x[k - 1]);
      worst_doppler = std::max(worst_doppler, std::abs(doppler.at(sat)[k - 1] - r.back()));
    }
    if (r.size() > 10 * static_cast<size_t>(tau)) rates.push_back(r);
  }
  ASSERT_GE(rates.size(), 5u);
  EXPECT_LT(worst_doppler, 1e-6);
  const auto lag = static_cast<size_t>(tau);
  double var = 0.0, cov = 0.0;
  long n = 0, m = 0;
  for (const std::vector<double>& r : rates) {
    for (size_t k = 0; k < r.size(); ++k) {
      var += r[k] * r[k];
      ++n;
      if (k + lag < r.size()) {
        cov += r[k] * r[k + lag];
        ++m;
      }
    }
  }
  var /= static_cast<double>(n);
  cov /= static_cast<double>(m);
  EXPECT_NEAR(std::sqrt(var), sd, 0.2 * sd);
  EXPECT_NEAR(cov / var, std::exp(-1.0), 0.15);
}

}  // namespace
}  // namespace giocal
