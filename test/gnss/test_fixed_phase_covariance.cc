#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "common/gnss/fixed_phase_covariance.h"

namespace giocal {
namespace {

struct Sky {
  DdEpoch epoch;
  Eigen::Vector3d rover_e{-3818600.0, 3559600.0, 3652260.0};
  std::vector<Eigen::Vector3d> los;  // unit vectors rover -> satellite
  std::vector<double> phase_var;     // SD phase variance per satellite [m^2]
};

// Satellites at the given (azimuth, elevation) [deg] in the rover's ENU frame; the first is the
// reference of every DD phase row, on one band.
Sky skyOf(const std::vector<std::pair<double, double>>& az_el) {
  Sky s;
  const Eigen::Vector3d up = s.rover_e.normalized();
  const Eigen::Vector3d east = Eigen::Vector3d::UnitZ().cross(up).normalized();
  const Eigen::Vector3d north = up.cross(east);
  for (size_t k = 0; k < az_el.size(); ++k) {
    const double az = az_el[k].first * M_PI / 180.0, el = az_el[k].second * M_PI / 180.0;
    const Eigen::Vector3d u =
        std::cos(el) * (std::sin(az) * east + std::cos(az) * north) + std::sin(el) * up;
    s.los.push_back(u);
    SdGeometry g;
    g.sat.prn = static_cast<int>(k) + 1;
    g.sat_at_rover_e = s.rover_e + 2.2e7 * u;
    g.base_range = 2.2e7;
    g.el = el;
    s.epoch.geometry.push_back(g);
    s.phase_var.push_back(std::pow(0.003, 2) * (1.0 + 1.0 / std::pow(std::sin(el), 2)));
    s.epoch.undiff_variance.push_back({1.0, s.phase_var.back()});
    if (k == 0) continue;
    for (bool phase : {true, false}) {  // code rows must not count
      DdObservation o;
      o.sat = g.sat;
      o.ref.prn = 1;
      o.phase = phase;
      o.lambda = 0.19;
      o.sat_index = static_cast<int>(k);
      o.ref_index = 0;
      s.epoch.obs.push_back(o);
    }
  }
  return s;
}

TEST(FixedPhaseCovariance, EqualsSingleDifferencesWithACommonTermEstimated) {
  // Double differencing against a reference removes one common term per epoch; the same
  // information is the single differences' with that term as an unknown, uncorrelated rows.
  const Sky s = skyOf({{0, 80}, {40, 30}, {130, 55}, {200, 20}, {290, 45}, {330, 70}});
  const std::optional<Eigen::Matrix3d> cov = fixedPhasePositionCovariance(s.epoch, s.rover_e);
  ASSERT_TRUE(cov);
  const long n = static_cast<long>(s.los.size());
  Eigen::MatrixXd A(n, 4), W = Eigen::MatrixXd::Zero(n, n);
  for (long k = 0; k < n; ++k) {
    A.row(k) << -s.los[static_cast<size_t>(k)].transpose(), 1.0;
    W(k, k) = 1.0 / s.phase_var[static_cast<size_t>(k)];
  }
  const Eigen::Matrix3d expected = (A.transpose() * W * A).inverse().topLeftCorner<3, 3>();
  EXPECT_LT((*cov - expected).norm(), 1e-6 * expected.norm()) << *cov << "\n\n" << expected;
  // Millimetres horizontally, more vertically: a sanity scale for six satellites.
  EXPECT_LT(std::sqrt(cov->trace()), 0.02);
}

TEST(FixedPhaseCovariance, ThreeSatellitesLeaveAnAxisOpen) {
  EXPECT_FALSE(fixedPhasePositionCovariance(skyOf({{0, 80}, {40, 30}, {130, 55}}).epoch,
                                            skyOf({{0, 80}}).rover_e));
  EXPECT_TRUE(fixedPhasePositionCovariance(skyOf({{0, 80}, {40, 30}, {130, 55}, {250, 40}}).epoch,
                                           skyOf({{0, 80}}).rover_e));
}

}  // namespace
}  // namespace giocal
