// PositionResidualCheck: LC solutions against a trajectory. White errors at their stated sigma
// support the run's sigmas; errors twice their sigma, or errors that wander (first-order
// Gauss-Markov, 10 s), are measured as such and warned about.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "common/calibration/position_residuals.h"
#include "common/geodesy/wgs84.h"
#include "common/math/rotation.h"
#include "common/online/position_residual_sink.h"

namespace giocal {
namespace {

// A drive east at 1 m/s for 1000 s, sampled at 10 Hz, with fixes at 2 Hz whose errors have
// `scale` times the stated 0.5 m and correlation time tau_s (0: white).
PositionResiduals check(double scale, double tau_s, std::uint32_t seed) {
  const LocalFrame frame(ecefFromGeodetic({0.6, 2.1, 50.0}));
  const double stated = 0.5, dt_fix = 0.5;
  std::mt19937 rng(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  const double a = tau_s > 0.0 ? std::exp(-dt_fix / tau_s) : 0.0;
  Eigen::Vector2d err(scale * stated * unit(rng), scale * stated * unit(rng));
  std::vector<PositionFix> fixes;
  for (double t = 0.25; t < 1000.0; t += dt_fix) {
    err = a * err + std::sqrt(1.0 - a * a) * scale * stated * Eigen::Vector2d(unit(rng), unit(rng));
    PositionFix f;
    f.t = t;
    // The antenna: the IMU on the line plus the lever arm (level, axes along ENU).
    f.p_e = frame.ecefFromEnu(Eigen::Vector3d(t + 0.1 + err.x(), 0.2 + err.y(), 0.3));
    f.cov_enu = Eigen::Vector3d(stated * stated, stated * stated, 1.0).asDiagonal();
    fixes.push_back(f);
  }
  PositionResidualCheck c(fixes, Eigen::Vector3d(0.1, 0.2, 0.3));
  for (int k = 0; k <= 10000; ++k) {
    const double t = 0.1 * k;
    const Geodetic g = geodeticFromEcef(frame.ecefFromEnu(Eigen::Vector3d(t, 0.0, 0.0)));
    TruthSample s;
    s.t = t;
    s.lat_deg = g.lat * kRadToDeg;
    s.lon_deg = g.lon * kRadToDeg;
    s.h = g.h;
    s.q_n_b = Eigen::Quaterniond::Identity();
    c.add(s);
  }
  const PositionResiduals r = c.result();
  std::printf("ratio %.3f inflation %.1f correlation %.2f s\n", r.sigma_ratio, r.inflation,
              r.correlation_s);
  return r;
}

TEST(PositionResiduals, WhiteErrorsAtTheirSigmaSupportTheRun) {
  const PositionResiduals r = check(1.0, 0.0, 1);
  EXPECT_EQ(r.fixes, 2000);
  EXPECT_NEAR(r.interval_s, 0.5, 1e-6);
  EXPECT_NEAR(r.sigma_ratio, 1.0, 0.12);
  EXPECT_LT(r.inflation, 1.2);
  EXPECT_LT(r.understatedBy(), 1.2);
  EXPECT_EQ(understatedSigmaWarning(r), "");
}

TEST(PositionResiduals, ErrorsTwiceTheirSigmaAreMeasuredTwice) {
  const PositionResiduals r = check(2.0, 0.0, 2);
  EXPECT_NEAR(r.sigma_ratio, 2.0, 0.15);
  EXPECT_LT(r.inflation, 1.2);
  EXPECT_EQ(understatedSigmaWarning(r), "");  // 2 < 3: not worth a warning
}

TEST(PositionResiduals, WanderingErrorsCountAsFewerFixes) {
  // Gauss-Markov with tau 10 s at 2 Hz: rho_k = exp(-k / 20); the sum while rho >= 0.05 is about
  // 18.5, so 1 + 2 * 18.5 = 38 fixes count as one.
  const PositionResiduals r = check(1.0, 10.0, 3);
  EXPECT_NEAR(r.sigma_ratio, 1.0, 0.25);
  EXPECT_NEAR(r.inflation, 38.0, 12.0);
  EXPECT_NEAR(r.correlation_s, 9.3, 3.0);
  EXPECT_GT(r.understatedBy(), 4.0);
  EXPECT_NE(understatedSigmaWarning(r).find("too small"), std::string::npos);
}

}  // namespace
}  // namespace giocal
