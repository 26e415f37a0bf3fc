// TUM export: positions in ENU metres about the origin, orientation q_n_b re-expressed in the
// origin's ENU frame, one "t x y z qx qy qz qw" line per pose.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "common/geodesy/wgs84.h"
#include "common/io/tum_trajectory.h"
#include "temp_dir.h"

namespace giocal {
namespace {

TEST(TumTrajectory, PositionsAndOrientationsInTheOriginsFrame) {
  test::TempDir dir;
  const Geodetic origin{48.0 * M_PI / 180.0, 11.0 * M_PI / 180.0, 500.0};
  const Eigen::Vector3d origin_e = ecefFromGeodetic(origin);
  const LocalFrame frame(origin_e);
  std::vector<TruthSample> samples;
  const Eigen::Quaterniond yaw90(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  for (const Eigen::Vector3d& enu : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(30, 2000, -1)}) {
    const Geodetic g = geodeticFromEcef(frame.ecefFromEnu(enu));
    TruthSample s;
    s.t = 1e9 + enu.y();
    s.lat_deg = g.lat * 180.0 / M_PI;
    s.lon_deg = g.lon * 180.0 / M_PI;
    s.h = g.h;
    s.q_n_b = yaw90;
    samples.push_back(s);
  }
  writeTumTrajectory(dir.file("t.txt"), samples, origin_e);
  std::ifstream in(dir.file("t.txt"));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line[0], '#');
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    std::vector<double> r(8);
    for (double& v : r) ss >> v;
    rows.push_back(r);
  }
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NEAR(rows[0][0], 1e9, 1e-6);
  for (int k = 1; k <= 3; ++k) EXPECT_NEAR(rows[0][k], 0.0, 1e-4);
  EXPECT_NEAR(rows[1][1], 30.0, 1e-3);
  EXPECT_NEAR(rows[1][2], 2000.0, 1e-3);
  EXPECT_NEAR(rows[1][3], -1.0, 1e-3);
  // At the origin the orientation is q_n_b itself; 2 km north the local level frame has turned
  // by 2000 m / R (3e-4 rad) about east, which the exported orientation carries.
  const Eigen::Quaterniond q0(rows[0][7], rows[0][4], rows[0][5], rows[0][6]);
  const Eigen::Quaterniond q1(rows[1][7], rows[1][4], rows[1][5], rows[1][6]);
  EXPECT_LT(q0.angularDistance(yaw90), 1e-8);
  EXPECT_NEAR(q1.angularDistance(yaw90), 2000.0 / 6.37e6, 2e-5);
}

}  // namespace
}  // namespace giocal
