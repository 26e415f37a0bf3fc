// tdcpDriftCovariance against an independent route: the displacement solveTdcpDisplacement finds
// (undifferenced rows with a clock change per system and band) when one satellite's phase runs
// off at 0.1 mm/s on every band, one satellite at a time, gives the drift's sensitivity to each
// satellite's rate; sigma^2 S S^T must be the covariance it states.
#include <gtest/gtest.h>

#include <cmath>

#include "common/geodesy/wgs84.h"
#include "common/gnss/tdcp_displacement.h"
#include "common/math/rotation.h"
#include "common/models/tdcp_model.h"

namespace giocal {
namespace {

TdcpPair skyOf(const Eigen::Vector3d& p_e, const LocalFrame& frame, int satellites) {
  TdcpPair pair;
  pair.t0 = 10.0;
  pair.t1 = 11.0;
  for (int k = 0; k < satellites; ++k) {
    const double az = 2.0 * M_PI * k / satellites + 0.3, el = (20.0 + 9.0 * k) * kDegToRad;
    const Eigen::Vector3d u(std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el));
    const Eigen::Vector3d sat_e = p_e + 2.2e7 * (frame.R_e_n() * u);
    for (const char band : {'1', '2'}) {
      TdcpSignal s;
      s.sat = SatId{GnssSystem::kGps, 3 + k};
      s.band = band;
      s.lambda = band == '1' ? 0.1903 : 0.2442;
      s.sat0_e = s.sat1_e = sat_e;
      s.variance = 1e-5 * (1.0 + 1.0 / std::sin(el));
      s.el = el;
      pair.signals.push_back(s);
    }
  }
  // Each band's rows against its first satellite's signal.
  for (int i = 2; i < static_cast<int>(pair.signals.size()); ++i) pair.rows.push_back({i, i % 2});
  return pair;
}

TEST(TdcpDrift, ItsCovarianceIsTheDisplacementSolversForRatesPerSatellite) {
  const Eigen::Vector3d p_e = ecefFromGeodetic({35.0 * kDegToRad, 137.0 * kDegToRad, 50.0});
  const LocalFrame frame(p_e);
  const int n = 7;
  const TdcpPair pair = skyOf(p_e, frame, n);
  const double sigma = 7e-4;
  const Eigen::Matrix3d Q = tdcpDriftCovariance(frame, pair, p_e, sigma);
  ASSERT_TRUE(Q.allFinite());
  // One satellite at a time running off by 0.1 mm/s (well inside the noise, so the solver keeps
  // every signal): its displacement, in ENU, per unit rate is that satellite's column.
  const double rate = 1e-4;
  Eigen::MatrixXd S(3, n);
  for (int k = 0; k < n; ++k) {
    TdcpPair p = pair;
    for (TdcpSignal& s : p.signals) {
      if (s.sat.prn == 3 + k) s.phase_change_m += rate * (p.t1 - p.t0);
    }
    const TdcpDisplacement d = solveTdcpDisplacement(p, p_e);
    ASSERT_TRUE(d.valid);
    ASSERT_TRUE(d.rejected.empty());
    // The drift is the antenna motion the rates mimic (TdcpModel moves the antenna by it).
    S.col(k) = frame.R_e_n().transpose() * d.d_e / (rate * (p.t1 - p.t0));
  }
  const Eigen::Matrix3d expected = sigma * sigma * S * S.transpose();
  EXPECT_LT((Q - expected).norm(),
            1e-4 * expected.norm());  // measured 1.5e-5: the solve's rounding
  // The vertical is the least fixed direction of a sky above the horizon.
  EXPECT_GT(Q(2, 2), Q(0, 0));
  EXPECT_GT(Q(2, 2), Q(1, 1));
}

TEST(TdcpDrift, ASkyOfThreeSatellitesFixesNone) {
  const Eigen::Vector3d p_e = ecefFromGeodetic({35.0 * kDegToRad, 137.0 * kDegToRad, 50.0});
  const LocalFrame frame(p_e);
  EXPECT_FALSE(tdcpDriftCovariance(frame, skyOf(p_e, frame, 3), p_e, 7e-4).allFinite());
}

}  // namespace
}  // namespace giocal
