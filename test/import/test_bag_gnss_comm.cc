// Raw GNSS in the gnss_comm convention (GVINS, Ground-Fusion, M2DGR): the first two minutes of a
// real multi-constellation receiver's RINEX written as gnss_comm/GnssMeasMsg epochs and its
// broadcast ephemerides as GnssEphemMsg (each published twice, as drivers do), beside an IMU and
// odometry, imported: every GPS, Galileo and BeiDou observation and ephemeris comes back, and the
// single point positions land on the receiver's surveyed position.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "common/geodesy/wgs84.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_obs.h"
#include "common/gnss/spp.h"
#include "import/bag_dataset.h"
#include "import/gnss_comm_messages.h"
#include "import/ros1_bag_writer.h"
#include "temp_dir.h"

namespace giocal::import {
namespace {

using namespace test_bags;

const std::string kDir = std::string(GIOCAL_SOURCE_DIR) + "/data/real/mosaic-static-nagoya/";
constexpr double kWeek = 604800.0;

const std::string kTimeDef = "MSG: gnss_comm/GnssTimeMsg\nuint32 week\nfloat64 tow\n";
const std::string kMeasDef =
    "GnssObsMsg[] meas\nMSG: gnss_comm/GnssObsMsg\nGnssTimeMsg time\nuint32 sat\n"
    "float64[] freqs\nfloat64[] CN0\nuint8[] LLI\nuint8[] code\nfloat64[] psr\nfloat64[] psr_std\n"
    "float64[] cp\nfloat64[] cp_std\nfloat64[] dopp\nfloat64[] dopp_std\nuint8[] status\n" +
    kTimeDef;
const std::string kEphemDef =
    "uint32 sat\nGnssTimeMsg ttr\nGnssTimeMsg toe\nGnssTimeMsg toc\nfloat64 toe_tow\nuint32 week\n"
    "uint32 iode\nuint32 iodc\nuint32 health\nuint32 code\nfloat64 ura\nfloat64 A\nfloat64 e\n"
    "float64 i0\nfloat64 omg\nfloat64 OMG0\nfloat64 M0\nfloat64 delta_n\nfloat64 OMG_dot\n"
    "float64 i_dot\nfloat64 cuc\nfloat64 cus\nfloat64 crc\nfloat64 crs\nfloat64 cic\nfloat64 cis\n"
    "float64 af0\nfloat64 af1\nfloat64 af2\nfloat64 tgd0\nfloat64 tgd1\nfloat64 A_dot\n"
    "float64 n_dot\n" +
    kTimeDef;

// RTKLIB's code numbers of the signals in this receiver's file (rtklib.h CODE_L1C ...).
const std::map<std::string, int> kCode = {{"1C", 1},  {"2C", 14}, {"2L", 17},
                                          {"2W", 20}, {"5Q", 25}, {"7Q", 28},
                                          {"7I", 27}, {"2I", 40}, {"6I", 42}};

void setTime(RosMessage& m, const std::string& path, double t) {
  m.set(path + ".week", std::floor(t / kWeek));
  m.set(path + ".tow", t - std::floor(t / kWeek) * kWeek);
}

RosMessage measMessage(const ObsEpoch& e) {
  RosMessage m;
  std::size_t n = 0;
  for (const SatObs& s : e.sats) {
    if (gnssCommNumber(s.sat) == 0) continue;
    const std::string p = "meas[" + std::to_string(n++) + "].";
    setTime(m, p + "time", e.t);
    m.set(p + "sat", static_cast<double>(gnssCommNumber(s.sat)));
    const std::size_t k = s.signals.size();
    for (const char* a : {"freqs", "CN0", "LLI", "code", "psr", "psr_std", "cp", "cp_std", "dopp",
                          "dopp_std", "status"})
      m.setLength(p + a, k);
    for (std::size_t i = 0; i < k; ++i) {
      const SignalObs& g = s.signals[i];
      const std::string at = "[" + std::to_string(i) + "]";
      m.set(p + "freqs" + at, carrierFrequency(s.sat.sys, g.band));
      m.set(p + "code" + at, kCode.at(std::string{g.band, g.attr}));
      m.set(p + "psr" + at, std::isnan(g.P) ? 0.0 : g.P);
      m.set(p + "cp" + at, std::isnan(g.L) ? 0.0 : g.L);
      m.set(p + "dopp" + at, std::isnan(g.D) ? 0.0 : g.D);
      m.set(p + "CN0" + at, std::isnan(g.S) ? 0.0 : g.S);
      m.set(p + "LLI" + at, g.lli);
      m.set(p + "status" + at, (std::isnan(g.P) ? 0 : 1) | (std::isnan(g.L) ? 0 : 2));
    }
  }
  // A GLONASS satellite (giocal reads no GLONASS): counted, not written.
  const std::string p = "meas[" + std::to_string(n++) + "].";
  setTime(m, p + "time", e.t);
  m.set(p + "sat", 33 + 7);
  m.setLength(p + "freqs", 1);
  m.set(p + "freqs[0]", 1602e6 + 0.5625e6 * -4);
  m.setLength(p + "psr", 1);
  m.set(p + "psr[0]", 2.1e7);
  m.setLength("meas", n);
  return m;
}

RosMessage ephemMessage(const Ephemeris& e) {
  RosMessage m;
  const bool galileo = e.sat.sys == GnssSystem::kGalileo;
  m.set("sat", static_cast<double>(gnssCommNumber(e.sat)));
  setTime(m, "toe", e.toe);
  setTime(m, "toc", e.toc);
  setTime(m, "ttr", e.toe);
  const std::pair<const char*, double> fields[] = {{"A", e.sqrt_a * e.sqrt_a},
                                                   {"e", e.e},
                                                   {"i0", e.i0},
                                                   {"omg", e.omega},
                                                   {"OMG0", e.omega0},
                                                   {"M0", e.m0},
                                                   {"delta_n", e.delta_n},
                                                   {"OMG_dot", e.omega_dot},
                                                   {"i_dot", e.idot},
                                                   {"cuc", e.cuc},
                                                   {"cus", e.cus},
                                                   {"crc", e.crc},
                                                   {"crs", e.crs},
                                                   {"cic", e.cic},
                                                   {"cis", e.cis},
                                                   {"af0", e.af0},
                                                   {"af1", e.af1},
                                                   {"af2", e.af2},
                                                   {"iode", e.iode},
                                                   {"iodc", e.iodc},
                                                   {"health", e.health},
                                                   {"ura", e.accuracy}};
  for (const auto& [name, v] : fields) m.set(name, v);
  m.set("tgd0", galileo ? e.tgd2 : e.tgd);  // RTKLIB's order: Galileo E1/E5a first
  m.set("tgd1", galileo ? e.tgd : e.tgd2);
  m.set("code", galileo ? e.data_source : 0);
  return m;
}

TEST(BagImport, GnssCommMessagesRoundTripARealReceiversObservations) {
  ObsData rinex = readRinexObs(kDir + "rover.obs");
  rinex.epochs.resize(120);
  NavData nav = readRinexNav(kDir + "base.nav");
  auto& ephs = nav.ephemerides;
  ephs.erase(std::remove_if(ephs.begin(), ephs.end(),
                            [](const Ephemeris& e) { return gnssCommNumber(e.sat) == 0; }),
             ephs.end());
  const double t0_unix = rinex.epochs.front().t + 315964800.0 - 18.0;  // GPS to UTC, 2024
  test::TempDir dir;
  {
    BagWriter w(dir.file("gnss_comm.bag"));
    for (int pass = 0; pass < 2; ++pass) {
      for (const Ephemeris& e : nav.ephemerides) {
        w.write("/ublox_driver/ephem", "gnss_comm/GnssEphemMsg", kEphemDef, ephemMessage(e),
                t0_unix, t0_unix);
      }
    }
    for (const ObsEpoch& e : rinex.epochs) {
      const double t = e.t + 315964800.0 - 18.0;
      w.write("/ublox_driver/range_meas", "gnss_comm/GnssMeasMsg", kMeasDef, measMessage(e), t, t);
    }
    writeStandingRobot(w, t0_unix, 130.0);
  }
  const BagDataset d = readBagDataset(*openBag(dir.file("gnss_comm.bag")), {});
  ASSERT_TRUE(d.raw_gnss.has_value());
  EXPECT_EQ(d.raw_gnss_source, "gnss_comm");
  EXPECT_EQ(d.raw_observation_topic, "/ublox_driver/range_meas");
  EXPECT_EQ(d.raw_ephemeris_topic, "/ublox_driver/ephem");
  const UbxLog& got = *d.raw_gnss;

  ASSERT_EQ(got.obs.epochs.size(), rinex.epochs.size());
  long long compared = 0;
  for (std::size_t k = 0; k < rinex.epochs.size(); ++k) {
    const ObsEpoch &a = got.obs.epochs[k], &b = rinex.epochs[k];
    EXPECT_EQ(a.t, b.t);
    for (const SatObs& s : b.sats) {
      const SatObs* x = a.find(s.sat);
      if (gnssCommNumber(s.sat) == 0) {
        EXPECT_EQ(x, nullptr) << s.sat.str();
        continue;
      }
      ASSERT_NE(x, nullptr) << s.sat.str() << " at epoch " << k;
      ASSERT_EQ(x->signals.size(), s.signals.size()) << s.sat.str();
      for (std::size_t i = 0; i < s.signals.size(); ++i) {
        const SignalObs &p = x->signals[i], &q = s.signals[i];
        EXPECT_EQ(p.band, q.band);
        EXPECT_EQ(p.attr, q.attr);
        EXPECT_TRUE(p.P == q.P || (std::isnan(p.P) && std::isnan(q.P))) << s.sat.str();
        EXPECT_TRUE(p.L == q.L || (std::isnan(p.L) && std::isnan(q.L))) << s.sat.str();
        EXPECT_TRUE(p.D == q.D || (std::isnan(p.D) && std::isnan(q.D))) << s.sat.str();
        EXPECT_EQ(p.lli, q.lli);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 120 * 20);
  EXPECT_EQ(got.rawx.unsupported_system, 120);  // the GLONASS signals are counted, not written
  for (const ObsEpoch& e : got.obs.epochs) EXPECT_EQ(e.find({GnssSystem::kGlonass, 8}), nullptr);

  // Each ephemeris once, with its orbit and clock as the navigation file has them.
  ASSERT_EQ(got.nav.ephemerides.size(), mergeNav({nav}).ephemerides.size());
  for (const Ephemeris& e : got.nav.ephemerides) {
    const auto same = std::find_if(nav.ephemerides.begin(), nav.ephemerides.end(), [&](auto& o) {
      return o.sat == e.sat && o.toe == e.toe && o.data_source == e.data_source;
    });
    ASSERT_NE(same, nav.ephemerides.end()) << e.sat.str();
    EXPECT_EQ(e.toc, same->toc);
    EXPECT_NEAR(e.sqrt_a, same->sqrt_a, 1e-12 * same->sqrt_a);
    EXPECT_EQ(e.m0, same->m0);
    EXPECT_EQ(e.af0, same->af0);
    EXPECT_EQ(e.tgd, same->tgd);
    EXPECT_EQ(e.tgd2, same->tgd2);
  }

  // The imported observations and ephemerides fit: single point positions near the survey.
  const Eigen::Vector3d surveyed =
      ecefFromGeodetic({35.13469901 * M_PI / 180.0, 136.97757549 * M_PI / 180.0, 104.8626});
  const BroadcastOrbits orbits(got.nav);
  int solved = 0;
  for (const ObsEpoch& e : got.obs.epochs) {
    const SppSolution s = solveSpp(e, orbits, SppOptions{});
    if (!s.valid) continue;
    ++solved;
    EXPECT_LT((s.p_e - surveyed).norm(), 15.0);
  }
  EXPECT_GT(solved, 110);
}

TEST(BagImport, GnssCommSatelliteNumbersFollowGnssComm) {
  SatId s;
  ASSERT_TRUE(gnssCommSatellite(1, s));
  EXPECT_EQ(s.str(), "G01");
  ASSERT_TRUE(gnssCommSatellite(33, s));
  EXPECT_EQ(s.str(), "R01");
  ASSERT_TRUE(gnssCommSatellite(60, s));
  EXPECT_EQ(s.str(), "E01");
  ASSERT_TRUE(gnssCommSatellite(98, s));
  EXPECT_EQ(s.str(), "C01");
  ASSERT_TRUE(gnssCommSatellite(160, s));
  EXPECT_EQ(s.str(), "C63");
  EXPECT_FALSE(gnssCommSatellite(161, s));
  EXPECT_FALSE(gnssCommSatellite(0, s));
  EXPECT_EQ(gnssCommNumber({GnssSystem::kGalileo, 11}), 70);
  EXPECT_EQ(gnssCommNumber({GnssSystem::kQzss, 1}), 0);
}

}  // namespace
}  // namespace giocal::import
