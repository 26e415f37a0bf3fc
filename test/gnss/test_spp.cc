#include <gtest/gtest.h>

#include <cmath>

#include "common/geodesy/wgs84.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_obs.h"
#include "common/gnss/spp.h"
#include "common/math/rotation.h"

namespace giocal {
namespace {

const std::string kData = std::string(GIOCAL_SOURCE_DIR) + "/data/real/";

struct Stats {
  int epochs = 0, solved = 0, within5 = 0;
  Eigen::Vector3d mean_enu = Eigen::Vector3d::Zero();
  double vel_sq = 0.0;
  int vel_n = 0;
};

Stats runSpp(const std::string& obs_path, const std::vector<std::string>& nav_paths,
             const Geodetic& truth, const std::vector<GnssSystem>& keep) {
  std::vector<NavData> navs;
  for (const auto& p : nav_paths) navs.push_back(readRinexNav(p));
  const BroadcastOrbits orbits(mergeNav(navs));
  ObsData obs = readRinexObs(obs_path);
  const LocalFrame frame(ecefFromGeodetic(truth));
  Stats st;
  for (ObsEpoch& e : obs.epochs) {
    std::vector<SatObs> sats;
    for (const auto& s : e.sats) {
      if (std::find(keep.begin(), keep.end(), s.sat.sys) != keep.end()) sats.push_back(s);
    }
    e.sats = sats;
    ++st.epochs;
    const SppSolution sol = solveSpp(e, orbits, SppOptions{});
    if (!sol.valid) continue;
    ++st.solved;
    const Eigen::Vector3d enu = frame.enuFromEcef(sol.p_e);
    st.mean_enu += enu;
    st.within5 += enu.head<2>().norm() < 5.0;
    if (sol.velocity_valid) {
      st.vel_sq += (frame.R_e_n().transpose() * sol.v_e).squaredNorm();
      ++st.vel_n;
    }
  }
  if (st.solved) st.mean_enu /= st.solved;
  return st;
}

TEST(Spp, MosaicMultiConstellationWithinFiveMetresAndStaticDoppler) {
  const Geodetic truth{35.13469901 * kDegToRad, 136.97757549 * kDegToRad, 104.8626};
  const Stats st = runSpp(
      kData + "mosaic-static-nagoya/rover.obs", {kData + "mosaic-static-nagoya/base.nav"}, truth,
      {GnssSystem::kGps, GnssSystem::kGalileo, GnssSystem::kBeidou, GnssSystem::kQzss});
  std::cout << "mosaic SPP: " << st.solved << "/" << st.epochs << " solved, mean ENU error "
            << st.mean_enu.transpose() << " m, " << st.within5 << " within 5 m horizontal, static "
            << "velocity RMS " << std::sqrt(st.vel_sq / std::max(st.vel_n, 1)) << " m/s over "
            << st.vel_n << " epochs\n";
  EXPECT_EQ(st.solved, st.epochs);
  EXPECT_LT(st.mean_enu.head<2>().norm(), 5.0);
  EXPECT_GE(st.within5, st.epochs * 95 / 100);
  EXPECT_EQ(st.vel_n, st.epochs);
  EXPECT_LT(std::sqrt(st.vel_sq / st.vel_n), 0.05);
}

// Operating Michibiki satellites broadcast health 1: the last of QZSS LNAV's six signal health
// bits (LEX/L6, or L1C/B), none of the signals giocal uses. Any other bit, or a GPS satellite's
// health 1, still excludes the ephemeris.
TEST(BroadcastOrbitsHealth, QzssLastBitIsMaskedAnyOtherBitExcludes) {
  const NavData nav = readRinexNav(kData + "mosaic-static-nagoya/base.nav");
  const Ephemeris* q = nullptr;
  const Ephemeris* g = nullptr;
  for (const Ephemeris& e : nav.ephemerides) {
    if (e.sat.sys == GnssSystem::kQzss && !q) q = &e;
    if (e.sat.sys == GnssSystem::kGps && e.health == 0 && !g) g = &e;
  }
  ASSERT_TRUE(q && g);
  EXPECT_EQ(q->health, 1);  // as broadcast
  const auto usable = [](Ephemeris e, int health) {
    e.health = health;
    NavData one;
    one.ephemerides.push_back(e);
    return BroadcastOrbits(one).select(e.sat, e.toe) != nullptr;
  };
  EXPECT_TRUE(usable(*q, 0));
  EXPECT_TRUE(usable(*q, 1));
  EXPECT_FALSE(usable(*q, 2));
  EXPECT_FALSE(usable(*q, 32));  // the first of the six bits
  EXPECT_FALSE(usable(*q, 33));
  EXPECT_TRUE(usable(*g, 0));
  EXPECT_FALSE(usable(*g, 1));
}

TEST(Spp, MosaicGpsOnly) {
  const Geodetic truth{35.13469901 * kDegToRad, 136.97757549 * kDegToRad, 104.8626};
  const Stats st = runSpp(kData + "mosaic-static-nagoya/rover.obs",
                          {kData + "mosaic-static-nagoya/base.nav"}, truth, {GnssSystem::kGps});
  std::cout << "mosaic GPS-only SPP: mean ENU error " << st.mean_enu.transpose() << " m\n";
  EXPECT_EQ(st.solved, st.epochs);
  EXPECT_LT(st.mean_enu.head<2>().norm(), 5.0);
}

TEST(Spp, GsiRinex2WithinFiveMetres) {
  // Reference: mean of RTKLIB's fixed RTK solution (rtklib_reference.pos).
  const Geodetic truth{35.160865960 * kDegToRad, 139.613843021 * kDegToRad, 68.3822};
  const std::string dir = kData + "gsi-static-0759-3040/";
  const Stats st = runSpp(dir + "07590920.05o", {dir + "07590920.05n", dir + "30400920.05n"}, truth,
                          {GnssSystem::kGps});
  std::cout << "GSI SPP: " << st.solved << "/" << st.epochs << " solved, mean ENU error "
            << st.mean_enu.transpose() << " m, " << st.within5 << " within 5 m horizontal\n";
  EXPECT_GE(st.solved, 110);  // 2005: the last epochs have only ~5 satellites above the mask
  EXPECT_LT(st.mean_enu.head<2>().norm(), 5.0);
  EXPECT_GE(st.within5, st.solved * 90 / 100);
}

// SppOptions::systems and the mask: the real mosaic rover's epochs solved on GPS above 24 degrees
// use only those satellites, and solve as the same epochs with the others taken out of the file.
TEST(Spp, TheSystemsAndMaskAskedForAreTheOnlyOnesUsed) {
  const BroadcastOrbits orbits(readRinexNav(kData + "mosaic-static-nagoya/base.nav"));
  const ObsData obs = readRinexObs(kData + "mosaic-static-nagoya/rover.obs");
  SppOptions gps;
  gps.systems = {GnssSystem::kGps};
  gps.elevation_mask_deg = 24.0;
  int solved = 0;
  for (size_t k = 0; k < obs.epochs.size(); k += 30) {
    const ObsEpoch& e = obs.epochs[k];
    const SppSolution all = solveSpp(e, orbits, SppOptions{});
    const SppSolution g = solveSpp(e, orbits, gps);
    ObsEpoch only = e;
    only.sats.clear();
    for (const SatObs& s : e.sats) {
      if (s.sat.sys == GnssSystem::kGps) only.sats.push_back(s);
    }
    SppOptions masked;
    masked.elevation_mask_deg = 24.0;
    const SppSolution from_file = solveSpp(only, orbits, masked);
    ASSERT_TRUE(all.valid && g.valid && from_file.valid);
    ++solved;
    EXPECT_GT(all.used.size(), 2 * g.used.size());
    for (const SatId& s : g.used) EXPECT_EQ(s.sys, GnssSystem::kGps);
    EXPECT_EQ(g.used, from_file.used);
    EXPECT_LT((g.p_e - from_file.p_e).norm(), 1e-6);
  }
  EXPECT_GE(solved, 10);
}

// SppOptions::ionosphere_free on the real mosaic rover (static, surveyed): the broadcast
// (Klobuchar) model leaves its single point positions about 3 m off on average, the same in every
// epoch; the ionosphere-free code removes most of that bias (`giocal_gnss_residuals
// --spp-csv` on the rover moved along the field laps: 3.1 m against 0.4 m, full sky). A file
// with the second band taken out solves as before, the option on or off.
TEST(Spp, IonosphereFreeCodeRemovesTheBroadcastIonosphereModelsBias) {
  const BroadcastOrbits orbits(readRinexNav(kData + "mosaic-static-nagoya/base.nav"));
  const ObsData obs = readRinexObs(kData + "mosaic-static-nagoya/rover.obs");
  const Geodetic truth{35.13469901 * M_PI / 180.0, 136.97757549 * M_PI / 180.0, 104.8626};
  const LocalFrame frame(ecefFromGeodetic(truth));
  SppOptions one_band;  // the single-receiver scheme's mask
  one_band.elevation_mask_deg = 15.0;
  SppOptions two_bands = one_band;
  two_bands.ionosphere_free = true;
  Eigen::Vector3d mean1 = Eigen::Vector3d::Zero(), mean2 = Eigen::Vector3d::Zero();
  int n = 0;
  for (size_t k = 0; k < obs.epochs.size(); k += 10) {
    const ObsEpoch& e = obs.epochs[k];
    const SppSolution a = solveSpp(e, orbits, one_band), b = solveSpp(e, orbits, two_bands);
    ASSERT_TRUE(a.valid && b.valid) << e.t;
    mean1 += frame.enuFromEcef(a.p_e);
    mean2 += frame.enuFromEcef(b.p_e);
    ++n;
    ObsEpoch primary_only = e;
    for (SatObs& so : primary_only.sats) {
      std::vector<SignalObs> keep;
      for (const SignalObs& sig : so.signals) {
        if (sig.band == primaryBand(so.sat.sys)) keep.push_back(sig);
      }
      so.signals = keep;
    }
    const SppSolution c = solveSpp(primary_only, orbits, one_band);
    const SppSolution d = solveSpp(primary_only, orbits, two_bands);
    ASSERT_TRUE(c.valid && d.valid);
    EXPECT_EQ(c.p_e, d.p_e);
  }
  ASSERT_GE(n, 25);
  mean1 /= n;
  mean2 /= n;
  EXPECT_GT(mean1.norm(), 2.0) << mean1.transpose();
  EXPECT_LT(mean2.norm(), 1.0) << mean2.transpose() << " against " << mean1.transpose();
}

// SppSolution::range_error_cov_p against the solutions themselves: each used satellite's code
// moved by 0.3 m in turn (the real mosaic rover, GPS above 24 degrees: a narrow sky), the
// position's moves per metre summed as outer products equal it.
TEST(Spp, RangeErrorCovarianceIsTheSumOfEachSatellitesPull) {
  const BroadcastOrbits orbits(readRinexNav(kData + "mosaic-static-nagoya/base.nav"));
  const ObsData obs = readRinexObs(kData + "mosaic-static-nagoya/rover.obs");
  SppOptions gps;
  gps.systems = {GnssSystem::kGps};
  gps.elevation_mask_deg = 24.0;
  for (size_t k = 0; k < obs.epochs.size(); k += 100) {
    const ObsEpoch& e = obs.epochs[k];
    const SppSolution s0 = solveSpp(e, orbits, gps);
    ASSERT_TRUE(s0.valid);
    ASSERT_GE(s0.used.size(), 5u);
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for (const SatId& sat : s0.used) {
      ObsEpoch moved = e;
      for (SatObs& so : moved.sats) {
        if (so.sat != sat) continue;
        for (SignalObs& sig : so.signals) {
          if (sig.band == primaryBand(sat.sys)) sig.P += 0.3;
        }
      }
      const SppSolution s1 = solveSpp(moved, orbits, gps);
      ASSERT_TRUE(s1.valid);
      ASSERT_EQ(s1.used, s0.used);
      const Eigen::Vector3d d = (s1.p_e - s0.p_e) / 0.3;
      C += d * d.transpose();
    }
    EXPECT_LT((C - s0.range_error_cov_p).norm(), 2e-3 * s0.range_error_cov_p.norm())
        << C << "\n"
        << s0.range_error_cov_p;
    EXPECT_GT(std::sqrt(s0.range_error_cov_p.trace()), 1.5);  // a narrow sky: PDOP above 1.5
    const LocalFrame frame(s0.p_e);
    const Eigen::Matrix3d Q = sppBiasCovariance(frame, s0, 2.0);
    const Eigen::Matrix3d C_n = frame.R_e_n().transpose() * C * frame.R_e_n();
    EXPECT_LT((Q - 4.0 * C_n).norm(), 1e-2 * Q.norm());
  }
}

TEST(Spp, Chi2Quantile) {
  // Tabulated 99.9 % and 95 % points: exact for 1 and 2 degrees of freedom, Wilson-Hilferty (within
  // 1.5 %, enough for an outlier gate) above.
  EXPECT_NEAR(chi2Quantile(0.999, 1), 10.828, 0.01);
  EXPECT_NEAR(chi2Quantile(0.95, 1), 3.841, 0.01);
  for (const auto& [dof, q999] :
       std::vector<std::pair<int, double>>{{2, 13.816}, {5, 20.515}, {20, 45.315}}) {
    EXPECT_NEAR(chi2Quantile(0.999, dof) / q999, 1.0, 0.015) << dof;
  }
  EXPECT_NEAR(chi2Quantile(0.95, 10) / 18.307, 1.0, 0.015);
}

}  // namespace
}  // namespace giocal
