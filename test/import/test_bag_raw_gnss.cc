// Raw GNSS in a bag: the real u-blox log's RXM-RAWX and RXM-SFRBX frames written as
// ublox_msgs/RxmRAWX and RxmSFRBX messages (ROS 1 definitions of the u-blox ROS driver) beside an
// IMU and odometry, imported: the same observations and ephemerides as the UBX log itself.
#include <gtest/gtest.h>

#include "common/time/gps_time.h"
#include "import/bag_dataset.h"
#include "import/payload_reader.h"
#include "import/ros1_bag_writer.h"
#include "import/ubx_log.h"
#include "temp_dir.h"

namespace giocal::import {
namespace {

using namespace test_bags;

const std::string kLog = std::string(GIOCAL_SOURCE_DIR) + "/data/real/ublox-f9p-walk/gnss_1730.ubx";

const std::string kRawxDef =
    "float64 rcvTOW\nuint16 week\nint8 leapS\nuint8 numMeas\nuint8 recStat\nuint8 version\n"
    "uint8[2] reserved1\nRxmRAWX_Meas[] meas\n"
    "MSG: ublox_msgs/RxmRAWX_Meas\nfloat64 prMes\nfloat64 cpMes\nfloat32 doMes\nuint8 gnssId\n"
    "uint8 svId\nuint8 sigId\nuint8 freqId\nuint16 locktime\nint8 cno\nuint8 prStdev\n"
    "uint8 cpStdev\nuint8 doStdev\nuint8 trkStat\nuint8 reserved3\n";
const std::string kSfrbxDef =
    "uint8 gnssId\nuint8 svId\nuint8 reserved0\nuint8 freqId\nuint8 numWords\nuint8 chn\n"
    "uint8 version\nuint8 reserved1\nuint32[] dwrd\n";

RosMessage rawxMessage(const UbxFrame& f) {
  const PayloadReader p(f.payload);
  RosMessage m;
  m.set("rcvTOW", p.r8(0));
  m.set("week", p.u2(8));
  m.set("leapS", p.i1(10));
  m.set("recStat", p.u1(12));
  m.set("version", p.u1(13));
  const std::size_t n = p.u1(11);
  m.setLength("meas", n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::string e = "meas[" + std::to_string(k) + "].";
    const std::size_t o = 16 + 32 * k;
    m.set(e + "prMes", p.r8(o));
    m.set(e + "cpMes", p.r8(o + 8));
    m.set(e + "doMes", p.r4(o + 16));
    const char* bytes[] = {"gnssId", "svId", "sigId", "freqId"};
    for (std::size_t b = 0; b < 4; ++b) m.set(e + bytes[b], p.u1(o + 20 + b));
    m.set(e + "locktime", p.u2(o + 24));
    m.set(e + "cno", p.u1(o + 26));
    m.set(e + "prStdev", p.u1(o + 27));
    m.set(e + "cpStdev", p.u1(o + 28));
    m.set(e + "doStdev", p.u1(o + 29));
    m.set(e + "trkStat", p.u1(o + 30));
  }
  return m;
}

RosMessage sfrbxMessage(const UbxFrame& f) {
  const PayloadReader p(f.payload);
  RosMessage m;
  m.set("gnssId", p.u1(0));
  m.set("svId", p.u1(1));
  m.set("reserved0", p.u1(2));
  m.set("freqId", p.u1(3));
  m.set("version", p.u1(6));
  const std::size_t n = p.u1(4);
  m.setLength("dwrd", n);
  for (std::size_t k = 0; k < n; ++k) m.set("dwrd[" + std::to_string(k) + "]", p.u4(8 + 4 * k));
  return m;
}

TEST(BagImport, UbloxRawGnssReadsAsTheUbxLogDoes) {
  test::TempDir dir;
  const UbxLog direct = readUbxLog(kLog);
  const double t0_unix = direct.obs.epochs.front().t + 315964800.0 - 18.0;  // GPS to UTC, 2025
  {
    BagWriter w(dir.file("raw.bag"));
    UbxStream s(kLog);
    UbxFrame f;
    double t = t0_unix;
    while (s.next(f)) {
      if (f.cls != 0x02 || (f.id != 0x15 && f.id != 0x13)) continue;
      t += 0.001;
      if (f.id == 0x15)
        w.write("/ublox/rxmraw", "ublox_msgs/RxmRAWX", kRawxDef, rawxMessage(f), t, t);
      if (f.id == 0x13)
        w.write("/ublox/rxmsfrb", "ublox_msgs/RxmSFRBX", kSfrbxDef, sfrbxMessage(f), t, t);
    }
    writeStandingRobot(w, t0_unix, 100.0);
  }
  const BagDataset d = readBagDataset(*openBag(dir.file("raw.bag")), {});
  ASSERT_TRUE(d.raw_gnss.has_value());
  EXPECT_EQ(d.raw_gnss_source, "ublox_msgs");
  EXPECT_EQ(d.raw_observation_topic, "/ublox/rxmraw");
  EXPECT_EQ(d.raw_ephemeris_topic, "/ublox/rxmsfrb");
  const UbxLog& bag = *d.raw_gnss;
  ASSERT_EQ(bag.obs.epochs.size(), direct.obs.epochs.size());
  for (std::size_t k = 0; k < bag.obs.epochs.size(); k += 50) {
    const ObsEpoch &a = bag.obs.epochs[k], &b = direct.obs.epochs[k];
    EXPECT_EQ(a.t, b.t);
    ASSERT_EQ(a.sats.size(), b.sats.size());
    for (std::size_t s = 0; s < a.sats.size(); ++s) {
      ASSERT_EQ(a.sats[s].signals.size(), b.sats[s].signals.size());
      for (std::size_t g = 0; g < a.sats[s].signals.size(); ++g) {
        const SignalObs &x = a.sats[s].signals[g], &y = b.sats[s].signals[g];
        EXPECT_TRUE(x.P == y.P || (std::isnan(x.P) && std::isnan(y.P)));
        EXPECT_TRUE(x.L == y.L || (std::isnan(x.L) && std::isnan(y.L)));
        EXPECT_EQ(x.D, y.D);
        EXPECT_EQ(x.lli, y.lli);
      }
    }
  }
  ASSERT_EQ(bag.nav.ephemerides.size(), direct.nav.ephemerides.size());
  for (std::size_t k = 0; k < bag.nav.ephemerides.size(); ++k) {
    EXPECT_EQ(bag.nav.ephemerides[k].sat, direct.nav.ephemerides[k].sat);
    EXPECT_EQ(bag.nav.ephemerides[k].m0, direct.nav.ephemerides[k].m0);
  }
}

}  // namespace
}  // namespace giocal::import
