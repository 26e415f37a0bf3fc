#include <gtest/gtest.h>

#include <random>

#include "common/geodesy/wgs84.h"
#include "common/math/rotation.h"

namespace giocal {
namespace {

TEST(Wgs84, KnownPoints) {
  EXPECT_LT((ecefFromGeodetic({0, 0, 0}) - Eigen::Vector3d(wgs84::kA, 0, 0)).norm(), 1e-9);
  const double b = wgs84::kA * (1.0 - wgs84::kF);
  EXPECT_LT((ecefFromGeodetic({M_PI / 2, 0, 100}) - Eigen::Vector3d(0, 0, b + 100)).norm(), 1e-6);
  // The GSI base (RTKLIB reference conf): ECEF -3978241.958 3382840.234 3649900.853.
  const Geodetic g = geodeticFromEcef({-3978241.958, 3382840.234, 3649900.853});
  EXPECT_NEAR(g.lat * kRadToDeg, 35.1, 0.5);
  EXPECT_NEAR(g.lon * kRadToDeg, 139.6, 0.5);
}

TEST(Wgs84, GeodeticRoundTrip) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> lat(-M_PI / 2, M_PI / 2), lon(-M_PI, M_PI),
      h(-500.0, 25e6);
  for (int k = 0; k < 2000; ++k) {
    const Geodetic g{lat(rng), lon(rng), h(rng)};
    const Geodetic back = geodeticFromEcef(ecefFromGeodetic(g));
    EXPECT_NEAR(back.lat, g.lat, 1e-11);
    if (std::abs(g.lat) < M_PI / 2 - 1e-9) {
      EXPECT_NEAR(std::remainder(back.lon - g.lon, 2 * M_PI), 0.0, 1e-11);
    }
    EXPECT_NEAR(back.h, g.h, 1e-5);
  }
}

TEST(Wgs84, EnuFrame) {
  const LocalFrame frame(ecefFromGeodetic({0.6, 2.4, 50.0}));
  const Eigen::Matrix3d R = frame.R_e_n();
  EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_NEAR(R.determinant(), 1.0, 1e-14);
  // Up is the ellipsoid normal: 1 m up changes only the height.
  const Geodetic up = geodeticFromEcef(frame.ecefFromEnu({0, 0, 1}));
  EXPECT_NEAR(up.h, 51.0, 1e-8);
  EXPECT_NEAR(up.lat, 0.6, 1e-12);
  // North increases latitude, east increases longitude.
  EXPECT_GT(geodeticFromEcef(frame.ecefFromEnu({0, 10, 0})).lat, 0.6);
  EXPECT_GT(geodeticFromEcef(frame.ecefFromEnu({10, 0, 0})).lon, 2.4);
  const Eigen::Vector3d p(123.4, -56.7, 8.9);
  EXPECT_LT((frame.enuFromEcef(frame.ecefFromEnu(p)) - p).norm(), 1e-8);
  // Earth rotation in n: no east component, north = w cos(lat), up = w sin(lat).
  const Eigen::Vector3d w = frame.omega_ie_n();
  EXPECT_NEAR(w.x(), 0.0, 1e-18);
  EXPECT_NEAR(w.y(), wgs84::kOmegaEarth * std::cos(frame.originGeodetic().lat), 1e-15);
}

TEST(Wgs84, GravityVectorFollowsThePosition) {
  const LocalFrame frame(ecefFromGeodetic({0.6, 2.4, 50.0}));
  EXPECT_LT((frame.gravity_n(Eigen::Vector3d::Zero()) - frame.gravity_n()).norm(), 1e-12);
  // 1 km east the local up leans east by 1000 m / N (prime vertical radius), so gravity gains a
  // westward component of that ratio.
  const double s = std::sin(0.6), N = wgs84::kA / std::sqrt(1 - wgs84::kE2 * s * s);
  const Eigen::Vector3d g = frame.gravity_n({1000.0, 0.0, 0.0});
  EXPECT_NEAR(g.x() / -g.z(), -1000.0 / N, 1e-8);
}

TEST(Wgs84, NormalGravity) {
  EXPECT_NEAR(normalGravity(0.0, 0.0), 9.7803253359, 1e-9);
  EXPECT_NEAR(normalGravity(M_PI / 2, 0.0), 9.8321849379, 1e-8);
  // Free-air gradient about -3.086e-6 s^-2.
  EXPECT_NEAR((normalGravity(0.8, 1000.0) - normalGravity(0.8, 0.0)) / 1000.0, -3.086e-6, 2e-8);
}

}  // namespace
}  // namespace giocal
