#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_obs.h"
#include "common/io/data_error.h"
#include "common/time/gps_time.h"
#include "temp_dir.h"

namespace giocal {
namespace {

const std::string kData = std::string(GIOCAL_SOURCE_DIR) + "/data/real/";
const std::string kGsi = kData + "gsi-static-0759-3040/";
const std::string kMosaic = kData + "mosaic-static-nagoya/";

TEST(RinexObs, Version2GsiFile) {
  const ObsData d = readRinexObs(kGsi + "07590920.05o");
  EXPECT_DOUBLE_EQ(d.header.version, 2.10);
  EXPECT_EQ(d.header.marker, "0759");
  EXPECT_NEAR(d.header.approx_position.x(), -3976219.5082, 1e-9);
  EXPECT_DOUBLE_EQ(d.header.interval, 30.0);
  ASSERT_EQ(d.epochs.size(), 120u);
  const ObsEpoch& e0 = d.epochs.front();
  EXPECT_DOUBLE_EQ(e0.t, gpsSecondsFromCalendar({2005, 4, 2, 0, 0, 0.0}));
  ASSERT_EQ(e0.sats.size(), 8u);
  EXPECT_EQ(e0.sats[0].sat.str(), "G03");
  // First record: L1 55923622.160, C1 24767686.375, L2 43647388.242 (LLI 4 = AS on), P2
  // 24767684.822.
  const SignalObs* l1 = e0.sats[0].bestOnBand('1');
  const SignalObs* l2 = e0.sats[0].bestOnBand('2');
  ASSERT_TRUE(l1 && l2);
  EXPECT_DOUBLE_EQ(l1->L, 55923622.160);
  EXPECT_DOUBLE_EQ(l1->P, 24767686.375);
  EXPECT_DOUBLE_EQ(l2->L, 43647388.242);
  EXPECT_DOUBLE_EQ(l2->P, 24767684.822);
  EXPECT_EQ(l2->attr, 'W');
  EXPECT_EQ(l2->lli, 4);
  EXPECT_DOUBLE_EQ(d.epochs[1].t - e0.t, 30.0);
}

TEST(RinexObs, Version3MosaicFile) {
  const ObsData d = readRinexObs(kMosaic + "rover.obs");
  EXPECT_DOUBLE_EQ(d.header.version, 3.04);
  ASSERT_EQ(d.epochs.size(), 301u);
  EXPECT_EQ(d.header.obs_types.at('G').size(), 17u);
  EXPECT_EQ(d.header.obs_types.at('G')[1], "C1C");
  EXPECT_EQ(d.header.obs_types.at('E').size(), 13u);
  EXPECT_EQ(d.header.phase_shift.count({'G', "L2L"}), 1u);
  // No GLONASS or SBAS satellites are kept; GPS, Galileo, BeiDou and QZSS are.
  int per_sys[128] = {};
  for (const auto& s : d.epochs.front().sats) per_sys[static_cast<int>(s.sat.sys)]++;
  EXPECT_EQ(per_sys['R'], 0);
  EXPECT_GT(per_sys['G'], 5);
  EXPECT_GT(per_sys['E'], 3);
  EXPECT_GT(per_sys['C'], 3);
  for (const auto& s : d.epochs.front().sats) {
    for (const auto& sig : s.signals) {
      if (!std::isnan(sig.P)) {
        EXPECT_GT(sig.P, 1.5e7) << s.sat.str();
        EXPECT_LT(sig.P, 4.5e7) << s.sat.str();
      }
    }
  }
  const SatObs* first_gps = nullptr;
  for (const auto& s : d.epochs.front().sats) {
    if (!first_gps && s.sat.sys == GnssSystem::kGps) first_gps = &s;
  }
  ASSERT_NE(first_gps, nullptr);
  const SatObs& g = *first_gps;
  ASSERT_NE(g.bestOnBand('1'), nullptr);
  EXPECT_EQ(g.bestOnBand('1')->attr, 'C');
  EXPECT_FALSE(std::isnan(g.bestOnBand('1')->D));
  EXPECT_FALSE(std::isnan(g.bestOnBand('1')->S));
}

TEST(RinexNav, Version2AndVersion3) {
  const NavData n2 = readRinexNav(kGsi + "07590920.05n");
  EXPECT_TRUE(n2.has_gps_iono);
  EXPECT_DOUBLE_EQ(n2.gps_iono[0], 1.1180e-08);
  EXPECT_DOUBLE_EQ(n2.gps_iono[4], 8.8060e+04);
  ASSERT_GT(n2.ephemerides.size(), 10u);
  for (const auto& e : n2.ephemerides) {
    EXPECT_EQ(e.sat.sys, GnssSystem::kGps);
    EXPECT_NEAR(e.sqrt_a, 5153.7, 10.0);
    EXPECT_LT(std::abs(e.toe - e.toc), 7200.0);
  }
  const NavData n3 = readRinexNav(kMosaic + "base.nav");
  EXPECT_DOUBLE_EQ(n3.gps_iono[0], 1.8626e-08);
  int g = 0, e = 0, c = 0, j = 0;
  for (const auto& eph : n3.ephemerides) {
    g += eph.sat.sys == GnssSystem::kGps;
    e += eph.sat.sys == GnssSystem::kGalileo;
    c += eph.sat.sys == GnssSystem::kBeidou;
    j += eph.sat.sys == GnssSystem::kQzss;
  }
  EXPECT_EQ(g, 13);
  EXPECT_EQ(e, 67);
  EXPECT_EQ(c, 32);
  EXPECT_EQ(j, 3);
  EXPECT_EQ(n3.skipped_records, 19);  // GLONASS
  // G05's first record: toc 2024-06-24 10:00:00, af0 -1.774230040610E-04, toe 122400 s of week
  // 2320.
  const Ephemeris& g05 = n3.ephemerides.front();
  EXPECT_EQ(g05.sat.str(), "G05");
  EXPECT_DOUBLE_EQ(g05.af0, -1.774230040610E-04);
  EXPECT_DOUBLE_EQ(g05.toe, 2320 * 604800.0 + 122400.0);
  EXPECT_DOUBLE_EQ(g05.toc, gpsSecondsFromCalendar({2024, 6, 24, 10, 0, 0.0}));
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Expects a DataError whose message names the file and a line > 0.
template <typename Fn>
void expectFileLineError(Fn fn, const std::string& path, const std::string& what) {
  try {
    fn();
    FAIL() << "accepted: " << what;
  } catch (const DataError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_GT(e.line(), 0) << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what() << " / " << what;
  }
}

TEST(RinexObs, TruncatedAndMalformedFilesAreReported) {
  test::TempDir dir;
  for (const std::string& src : {kGsi + "07590920.05o", kMosaic + "rover.obs"}) {
    const std::string text = slurp(src);
    // Cut in the middle of an epoch's records (issue 23): the epochs before are read, the cut one
    // is dropped with a warning naming its line.
    const std::string cut = dir.write("cut.obs", text.substr(0, text.size() / 2));
    const ObsData whole = readRinexObs(src);
    const ObsData part = readRinexObs(cut);
    EXPECT_GT(part.epochs.size(), whole.epochs.size() / 3);
    EXPECT_LT(part.epochs.size(), whole.epochs.size() * 2 / 3);
    EXPECT_EQ(part.epochs.back().t, whole.epochs[part.epochs.size() - 1].t);
    ASSERT_EQ(part.warnings.size(), 1u);
    EXPECT_NE(part.warnings[0].find("the file ends inside this epoch"), std::string::npos);
    EXPECT_EQ(part.warnings[0].rfind(cut + ":", 0), 0u) << part.warnings[0];
    // No header end.
    const std::string nohdr =
        dir.write("nohdr.obs", text.substr(0, text.find("END OF HEADER") - 10));
    EXPECT_THROW(readRinexObs(nohdr), DataError);
    // A letter inside a number.
    std::string bad = text;
    const size_t at = bad.find(".", bad.find("END OF HEADER") + 200);
    bad[at - 2] = 'x';
    const std::string badp = dir.write("bad.obs", bad);
    expectFileLineError([&] { readRinexObs(badp); }, badp, "bad");
  }
  // Time going backwards: swap the first two epochs of the GSI file.
  const std::string text = slurp(kGsi + "07590920.05o");
  std::string swapped = text;
  const size_t e1 = swapped.find(" 05  4  2  0  0  0.0000000");
  swapped.replace(e1, 26, " 05  4  2  0  1  0.0000000");
  const std::string sp = dir.write("swap.obs", swapped);
  const ObsData swapped_data = readRinexObs(sp);
  EXPECT_EQ(swapped_data.epochs.size(), readRinexObs(kGsi + "07590920.05o").epochs.size() - 2);
  ASSERT_EQ(swapped_data.warnings.size(), 1u);  // the epochs at 00:00:30 and 00:01:00 again
  EXPECT_NE(swapped_data.warnings[0].find(
                "2 epochs repeating the previous time or going backwards dropped"),
            std::string::npos)
      << swapped_data.warnings[0];
  // Not a RINEX file at all, and an empty one.
  const std::string junk = dir.write("junk.obs", "hello\nworld\n");
  EXPECT_THROW(readRinexObs(junk), DataError);
  EXPECT_THROW(readRinexObs(dir.write("empty.obs", "")), DataError);
}

TEST(RinexNav, TruncatedAndMalformedFilesAreReported) {
  test::TempDir dir;
  const std::string text = slurp(kMosaic + "base.nav");
  const size_t body = text.find("END OF HEADER");
  const std::string cut = dir.write("cut.nav", text.substr(0, text.find("\n", body + 400) + 1));
  expectFileLineError([&] { readRinexNav(cut); }, cut, "truncated");
  std::string bad = text;
  bad[bad.find("E-", body) - 3] = '#';
  const std::string badp = dir.write("bad.nav", bad);
  expectFileLineError([&] { readRinexNav(badp); }, badp, "bad number");
  const std::string obs_as_nav = dir.write("x.nav", slurp(kMosaic + "rover.obs").substr(0, 2000));
  expectFileLineError([&] { readRinexNav(obs_as_nav); }, obs_as_nav, "not a RINEX navigation");
}

/// `text` with the `width` characters at 0-based `pos` replaced by `value` (right-aligned).
std::string withField(std::string text, size_t pos, size_t width, const std::string& value) {
  text.replace(pos, width, std::string(width - value.size(), ' ') + value);
  return text;
}

TEST(RinexNav, OutOfRangeNumbersAreErrorsNotIntegerOverflowsOrHangs) {
  // Values that reached int conversions (undefined behaviour) or made the week fold loop for
  // ever before: a toe of 1e99, a week of 2e24, a health of 1.3e103, a year of 9e99.
  test::TempDir dir;
  const std::string text = slurp(kMosaic + "base.nav");
  const size_t rec = text.find("G05 2024");
  const size_t l3 = text.find('\n', text.find('\n', text.find('\n', rec) + 1) + 1) + 1;  // toe
  const size_t l5 = text.find('\n', text.find('\n', l3) + 1) + 1;                        // week
  const size_t l6 = text.find('\n', l5) + 1;                                             // health
  struct Case {
    std::string text, what;
  } cases[] = {
      {withField(text, l3 + 4, 19, "1.000000000000E+99"), "time of ephemeris"},
      {withField(text, l5 + 4 + 2 * 19, 19, "2.000000000000E+24"), "week"},
      {withField(text, l6 + 4 + 19, 19, "1.30000000000E+103"), "health"},
      {withField(text, rec + 4, 4, "9e99"), "bad year"},
  };
  int k = 0;
  for (const Case& c : cases) {
    const std::string p = dir.write("bad" + std::to_string(k++) + ".nav", c.text);
    expectFileLineError([&] { readRinexNav(p); }, p, c.what);
  }
}

TEST(RinexObs, OutOfRangeCountsAndDatesAreErrors) {
  test::TempDir dir;
  const std::string text = slurp(kMosaic + "rover.obs");
  const size_t epoch = text.find("\n> 2024") + 1;
  const size_t types = text.find("G   17 X1");
  struct Case {
    std::string text, what;
  } cases[] = {
      {withField(text, epoch + 2, 4, "9e99"), "bad epoch year"},
      {withField(text, epoch + 32, 3, "9e9"), "bad number of satellites"},
      {withField(text, types + 3, 3, "9e9"), "bad number of observation types"},
  };
  int k = 0;
  for (const Case& c : cases) {
    const std::string p = dir.write("bad" + std::to_string(k++) + ".obs", c.text);
    expectFileLineError([&] { readRinexObs(p); }, p, c.what);
  }
}

}  // namespace
}  // namespace giocal
