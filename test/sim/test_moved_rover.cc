// moveStaticRover against the simulator itself: a static receiver's simulated observations moved
// along a path equal what the simulator draws for an antenna driving that path (same clocks,
// ambiguities and draws, no noise), to the size of what the move leaves as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/geodesy/wgs84.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/rinex_nav.h"
#include "common/math/rotation.h"
#include "sim/moved_rover.h"
#include "sim/simulator.h"

namespace giocal {
namespace {

TEST(MovedRover, AStaticReceiverMovedAlongAPathIsWhatThatPathReceives) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  sim::GnssSimSpec spec = cfg.gnss;
  spec.code_sigma = spec.phase_sigma = spec.doppler_sigma = 0.0;
  spec.zenith_wet_sd = 0.0;  // the move's troposphere assumes the simulator's 0.1 m wet delay
  spec.vtec_gradient = 0.0;  // the move leaves the ionosphere as it was
  spec.clock_offset_sd = 5e-3;  // a receiver whose tags run 5 ms off, as the GSI pair's do
  const BroadcastOrbits orbits(readRinexNav(spec.nav_file));
  const Eigen::Vector3d p_static =
      ecefFromGeodetic({cfg.origin_lat_deg * kDegToRad, cfg.origin_lon_deg * kDegToRad, 60.0});
  const LocalFrame frame(p_static);
  const double t0 = sim::parseGpsTime(cfg.start_time), t1 = t0 + 120.0;
  // 2 m/s east, a 40 m swing north and a metre up and down: 240 m from the receiver at the end.
  const auto path = [&](double t, Eigen::Vector3d& p, Eigen::Vector3d& v) {
    const double s = t - t0, w = 2.0 * M_PI / 60.0;
    p = frame.ecefFromEnu({2.0 * s, 40.0 * std::sin(w * s), 1.0 - std::cos(w * s)});
    v = frame.R_e_n() * Eigen::Vector3d(2.0, 40.0 * w * std::cos(w * s), w * std::sin(w * s));
  };
  const auto still = [&](double, Eigen::Vector3d& p, Eigen::Vector3d& v) {
    p = p_static;
    v.setZero();
  };
  const Eigen::Vector3d base = frame.ecefFromEnu({3000.0, 2600.0, 5.0});
  std::mt19937_64 rng_a(7), rng_b(7);
  const sim::SimulatedGnss at_rest = sim::simulateGnss(spec, orbits, still, base, t0, t1, rng_a);
  const sim::SimulatedGnss driven = sim::simulateGnss(spec, orbits, path, base, t0, t1, rng_b);
  const sim::MovedRover moved = sim::moveStaticRover(at_rest.rover, orbits, p_static, path, t0, t1);
  ASSERT_EQ(moved.epochs.size(), driven.rover.size());
  EXPECT_EQ(moved.no_ephemeris, 0);
  EXPECT_EQ(moved.unsupported_signals, 0);
  EXPECT_GT(moved.max_move, 200.0);
  long compared = 0;
  double worst_code = 0, worst_phase = 0, worst_doppler = 0;
  for (size_t k = 0; k < driven.rover.size(); ++k) {
    for (const SatObs& d : driven.rover[k].sats) {
      const SatObs* m = moved.epochs[k].find(d.sat);
      if (!m) continue;  // a satellite at the mask seen by one antenna only
      for (const SignalObs& sd : d.signals) {
        for (const SignalObs& sm : m->signals) {
          if (sm.band != sd.band) continue;
          const double lambda = kSpeedOfLight / carrierFrequency(d.sat.sys, sd.band);
          worst_code = std::max(worst_code, std::abs(sm.P - sd.P));
          worst_phase = std::max(worst_phase, std::abs(sm.L - sd.L) * lambda);
          worst_doppler = std::max(worst_doppler, std::abs(sm.D - sd.D) * lambda);
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 2000);
  // Left as it was: the ionosphere seen from 240 m away (the slant factor of a low satellite at an
  // elevation 4e-5 rad different: 0.5 mm on L2 here, measured; 1.7 mm with the simulator's
  // horizontal gradient as well) and the receiver clock's microsecond in the path's time.
  EXPECT_LT(worst_code, 1e-3);
  EXPECT_LT(worst_phase, 1e-3);
  EXPECT_LT(worst_doppler, 1e-5);  // [m/s] (measured 4e-7)
  EXPECT_GT(worst_phase, 0.0);     // the two are not the same file
}

}  // namespace
}  // namespace giocal
