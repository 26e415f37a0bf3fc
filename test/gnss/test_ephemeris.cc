#include <gtest/gtest.h>

#include <map>

#include "common/gnss/ephemeris.h"
#include "common/gnss/rinex_nav.h"

namespace giocal {
namespace {

// The satellite velocity and clock drift are the analytic time derivatives of the ICD position
// and clock equations: checked against central differences of the position and the clock on every
// broadcast record of a real multi-constellation navigation file (GPS, Galileo, QZSS, BeiDou MEO,
// IGSO and GEO), at the reference time and up to two hours either side.
TEST(Ephemeris, VelocityAndClockDriftAreTheDerivativesOfPositionAndClock) {
  const NavData nav =
      readRinexNav(std::string(GIOCAL_SOURCE_DIR) + "/data/real/mosaic-static-nagoya/base.nav");
  std::map<char, int> checked;
  int geo = 0;
  double worst_v = 0.0, worst_drift = 0.0;
  for (const Ephemeris& eph : nav.ephemerides) {
    for (const double dt : {-7200.0, -600.0, 0.0, 900.0, 7200.0}) {
      const double t = eph.toe + dt, t0 = t - 1e-3, t1 = t + 1e-3;
      // The step as the doubles hold it: at 1.4e9 GPS seconds, t +- 1 ms is rounded by up to
      // 1.2e-7 s, and dividing by the nominal 2 ms put a 7e-5 scale error on the velocity (the
      // central difference this analytic velocity replaced had exactly that error, 0.2 m/s).
      const double step = t1 - t0;
      const SatelliteState s = satelliteState(eph, t);
      const SatelliteState a = satelliteState(eph, t0), b = satelliteState(eph, t1);
      const Eigen::Vector3d v_numeric = (b.p_e - a.p_e) / step;
      worst_v = std::max(worst_v, (s.v_e - v_numeric).norm());
      worst_drift = std::max(worst_drift, std::abs(s.clock_drift - (b.clock - a.clock) / step));
      EXPECT_GT(s.v_e.norm(), 0.1) << eph.sat.str();
    }
    ++checked[static_cast<char>(eph.sat.sys)];
    geo += isBeidouGeo(eph.sat);
  }
  // A central difference over +-1 ms is good to about 1e-7 m/s (jerk h^2 / 6) and its rounding
  // (4e-9 m of position / 2e-3 s) to a few 1e-6 m/s.
  EXPECT_LT(worst_v, 1e-4);
  EXPECT_LT(worst_drift, 1e-12);
  EXPECT_GT(checked['G'], 0);
  EXPECT_GT(checked['E'], 0);
  EXPECT_GT(checked['C'], 0);
  EXPECT_GT(geo, 0);
}

}  // namespace
}  // namespace giocal
