// BeiDou D2 (the GEO satellites' navigation message): pages 1-10 of subframe 1 written from an
// ephemeris by the ICD's bit layout (BDS-SIS-ICD-B1I-3.0 5.3.2), read back by giocal, and, as the
// independent check of that layout, decoded by RTKLIB's convbin from a real u-blox log into which
// the pages are inserted as UBX-RXM-SFRBX messages.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <iterator>

#include "import/beidou_d2.h"
#include "import/ubx_reference.h"
#include "import/ubx_stream.h"
#include "temp_dir.h"

namespace giocal {
namespace {

using import::BitBuffer;

const std::string kLog = std::string(GIOCAL_SOURCE_DIR) + "/data/real/ublox-f9p-walk/gnss_1730.ubx";
constexpr double kPi = 3.1415926535898;
constexpr double kBdtWeekInGps = 1356.0;

// Part of a parameter: `len` bits at `pos` (from 0, the ICD's bit 1) of page `page` (1-10).
struct Part {
  int page, pos, len;
};

// Writes `value` (two's complement where negative) MSBs first over the parts.
void put(std::vector<BitBuffer>& pages, std::initializer_list<Part> parts, double value) {
  int total = 0;
  for (const Part& p : parts) total += p.len;
  const auto v = static_cast<uint64_t>(std::llround(value)) & ((uint64_t{1} << total) - 1);
  for (const Part& p : parts) {
    total -= p.len;
    pages[static_cast<std::size_t>(p.page - 1)].put(
        p.pos, p.len, static_cast<uint32_t>((v >> total) & ((uint64_t{1} << p.len) - 1)));
  }
}

// The ten 30-bit words of each of pages 1-10 of one subframe-1 cycle carrying `e`, broadcast from
// BDT week `week`, seconds of week `sow1` (page k 3(k-1) s later). The layout is written out here
// from the ICD's figures of the D2 pages, not shared with the decoder.
std::vector<std::vector<uint32_t>> d2Pages(const Ephemeris& e, int week, int sow1) {
  std::vector<BitBuffer> p(10, BitBuffer(300));
  for (int k = 1; k <= 10; ++k) {
    put(p, {{k, 0, 11}}, 0x712);  // preamble
    put(p, {{k, 15, 3}}, 1);      // subframe 1
    put(p, {{k, 18, 8}, {k, 30, 12}}, sow1 + 3 * (k - 1));
    put(p, {{k, 42, 4}}, k);  // page number
  }
  const auto sowOf = [&](double t) {  // GPS seconds to seconds of the BDT week
    return t - 14.0 - (kBdtWeekInGps + week) * 604800.0;
  };
  put(p, {{1, 46, 1}}, e.health);
  put(p, {{1, 47, 5}}, e.iodc);
  put(p, {{1, 60, 4}}, 2);  // URA index: 4.85 m
  put(p, {{1, 64, 13}}, week);
  put(p, {{1, 77, 5}, {1, 90, 12}}, sowOf(e.toc) / 8);
  put(p, {{1, 102, 10}}, e.tgd / 1e-10);
  put(p, {{1, 120, 10}}, e.tgd2 / 1e-10);
  put(p, {{3, 100, 12}, {3, 120, 12}}, std::ldexp(e.af0, 33));
  put(p, {{3, 132, 4}, {4, 46, 6}, {4, 60, 12}}, std::ldexp(e.af1, 50));
  put(p, {{4, 72, 10}, {4, 90, 1}}, std::ldexp(e.af2, 66));
  put(p, {{4, 91, 5}}, e.iode);
  put(p, {{4, 96, 16}}, std::ldexp(e.delta_n / kPi, 43));
  put(p, {{4, 120, 14}, {5, 46, 4}}, std::ldexp(e.cuc, 31));
  put(p, {{5, 50, 2}, {5, 60, 22}, {5, 90, 8}}, std::ldexp(e.m0 / kPi, 31));
  put(p, {{5, 98, 14}, {5, 120, 4}}, std::ldexp(e.cus, 31));
  put(p, {{5, 124, 10}, {6, 46, 6}, {6, 60, 16}}, std::ldexp(e.e, 33));
  put(p, {{6, 76, 6}, {6, 90, 22}, {6, 120, 4}}, std::ldexp(e.sqrt_a, 19));
  put(p, {{6, 124, 10}, {7, 46, 6}, {7, 60, 2}}, std::ldexp(e.cic, 31));
  put(p, {{7, 62, 18}}, std::ldexp(e.cis, 31));
  put(p, {{7, 80, 2}, {7, 90, 15}}, sowOf(e.toe) / 8);
  put(p, {{7, 105, 7}, {7, 120, 14}, {8, 46, 6}, {8, 60, 5}}, std::ldexp(e.i0 / kPi, 31));
  put(p, {{8, 65, 17}, {8, 90, 1}}, std::ldexp(e.crc, 6));
  put(p, {{8, 91, 18}}, std::ldexp(e.crs, 6));
  put(p, {{8, 109, 3}, {8, 120, 16}, {9, 46, 5}}, std::ldexp(e.omega_dot / kPi, 43));
  put(p, {{9, 51, 1}, {9, 60, 22}, {9, 90, 9}}, std::ldexp(e.omega0 / kPi, 31));
  put(p, {{9, 99, 13}, {9, 120, 14}, {10, 46, 5}}, std::ldexp(e.omega / kPi, 31));
  put(p, {{10, 51, 1}, {10, 60, 13}}, std::ldexp(e.idot / kPi, 43));
  std::vector<std::vector<uint32_t>> words;
  for (const BitBuffer& page : p) {
    words.emplace_back();
    for (int w = 0; w < 10; ++w) words.back().push_back(page.u(30 * w, 30));
  }
  return words;
}

// A geostationary satellite's broadcast ephemeris (values on the message's grid), toe and toc at
// BDT week 900, 259200 s (GPS seconds).
Ephemeris geoEphemeris(int prn) {
  Ephemeris e;
  e.sat = {GnssSystem::kBeidou, prn};
  e.iodc = 17;
  e.iode = 9;
  e.toe = e.toc = (kBdtWeekInGps + 900) * 604800.0 + 259200.0 + 14.0;
  e.tgd = -23e-10;
  e.tgd2 = 41e-10;
  e.af0 = std::ldexp(-1234567.0, -33);
  e.af1 = std::ldexp(-98765.0, -50);
  e.af2 = std::ldexp(-3.0, -66);
  e.delta_n = std::ldexp(-2345.0, -43) * kPi;
  e.cuc = std::ldexp(-54321.0, -31);
  e.m0 = std::ldexp(-1987654321.0, -31) * kPi;
  e.cus = std::ldexp(43210.0, -31);
  e.e = std::ldexp(2345678.0, -33);
  e.sqrt_a = std::ldexp(3374516224.0, -19);  // 6493.5 m^0.5: the GEO radius
  e.cic = std::ldexp(-12345.0, -31);
  e.cis = std::ldexp(23456.0, -31);
  e.i0 = std::ldexp(45678901.0, -31) * kPi;
  e.crc = std::ldexp(-76543.0, -6);
  e.crs = std::ldexp(65432.0, -6);
  e.omega_dot = std::ldexp(-1234567.0, -43) * kPi;
  e.omega0 = std::ldexp(-2109876543.0, -31) * kPi;
  e.omega = std::ldexp(1876543210.0, -31) * kPi;
  e.idot = std::ldexp(-4321.0, -43) * kPi;
  return e;
}

void expectSameEphemeris(const Ephemeris& a, const Ephemeris& b) {
  const double fields[][2] = {{a.toe, b.toe},
                              {a.toc, b.toc},
                              {a.af0, b.af0},
                              {a.af1, b.af1},
                              {a.af2, b.af2},
                              {a.crs, b.crs},
                              {a.crc, b.crc},
                              {a.cus, b.cus},
                              {a.cuc, b.cuc},
                              {a.cis, b.cis},
                              {a.cic, b.cic},
                              {a.delta_n, b.delta_n},
                              {a.m0, b.m0},
                              {a.e, b.e},
                              {a.sqrt_a, b.sqrt_a},
                              {a.omega0, b.omega0},
                              {a.i0, b.i0},
                              {a.omega, b.omega},
                              {a.omega_dot, b.omega_dot},
                              {a.idot, b.idot},
                              {a.tgd, b.tgd},
                              {a.tgd2, b.tgd2},
                              {a.iodc, b.iodc},
                              {a.iode, b.iode},
                              {a.health * 1.0, b.health * 1.0}};
  for (std::size_t k = 0; k < std::size(fields); ++k) {
    EXPECT_EQ(fields[k][0], fields[k][1]) << "field " << k;
  }
}

TEST(BeidouD2, PagesOneToTenOfOneCycleGiveTheEphemerisOnce) {
  const Ephemeris e = geoEphemeris(3);
  const auto pages = d2Pages(e, 900, 259190);
  const double t_rx = e.toe;
  import::BeidouD2Assembler d2;
  // A cycle joined in the middle: pages 6-10 alone give nothing.
  for (int k = 5; k < 10; ++k) EXPECT_FALSE(d2.add(e.sat, pages[k], t_rx));
  // Pages of two cycles (pages 1-5 of the next, 6-10 of this one) are not joined.
  const auto next = d2Pages(e, 900, 259190 + 30);
  for (int k = 0; k < 5; ++k) EXPECT_FALSE(d2.add(e.sat, next[k], t_rx));
  EXPECT_FALSE(d2.add(e.sat, pages[9], t_rx));
  std::optional<Ephemeris> got;
  for (int k = 5; k < 10; ++k) got = d2.add(e.sat, next[k], t_rx);
  ASSERT_TRUE(got);
  expectSameEphemeris(*got, e);
  // The same issue again: not given twice.
  for (int k = 0; k < 10; ++k) EXPECT_FALSE(d2.add(e.sat, pages[k], t_rx));
  // A page number outside 1-10 is not D2's.
  auto bad = pages[0];
  bad[1] = (bad[1] & ~(0xFu << 14)) | (12u << 14);  // page number: word 2, bits 43-46
  EXPECT_THROW(d2.add(e.sat, bad, t_rx), std::runtime_error);
}

// The UBX-RXM-SFRBX payload of one BeiDou subframe (u-blox interface description: gnssId,
// svId, sigId, freqId, numWords, chn, version 2, reserved, then the words little-endian).
std::vector<uint8_t> sfrbx(int prn, const std::vector<uint32_t>& words) {
  std::vector<uint8_t> p = {3, static_cast<uint8_t>(prn), 1, 0, 10, 0, 2, 0};  // B1I D2
  for (uint32_t w : words) {
    for (int b = 0; b < 4; ++b) p.push_back(static_cast<uint8_t>(w >> (8 * b)));
  }
  return import::ubxFrameBytes(0x02, 0x13, p);
}

TEST(UbxRealLog, BeidouD2EphemerisAgreesWithConvbin) {
  // The real log's time: BDT week and seconds of week of its first epoch.
  import::UbxStream stream(kLog);
  import::UbxFrame f;
  while (stream.next(f) && !(f.cls == 0x02 && f.id == 0x15)) {
  }
  ASSERT_EQ(f.id, 0x15);
  const long long after_first_epoch = f.offset + 8 + static_cast<long long>(f.payload.size());
  const import::UbxLog log = import::readUbxLog(kLog);
  const double t0 = log.obs.epochs.front().t;
  const double bdt = t0 - 14.0 - kBdtWeekInGps * 604800.0;
  const int week = static_cast<int>(bdt / 604800.0);
  const int sow = static_cast<int>(std::floor(bdt - week * 604800.0)) + 1;
  // Two GEO satellites' ephemerides, toe and toc at the week's last whole hour.
  std::vector<Ephemeris> sent;
  std::vector<uint8_t> inserted;
  for (int prn : {3, 60}) {
    Ephemeris e = geoEphemeris(prn);
    e.toe = e.toc = (kBdtWeekInGps + week) * 604800.0 + std::floor(sow / 3600.0) * 3600.0 + 14.0;
    sent.push_back(e);
    for (const auto& words : d2Pages(e, week, sow)) {
      const auto frame = sfrbx(prn, words);
      inserted.insert(inserted.end(), frame.begin(), frame.end());
    }
  }
  std::ifstream in(kLog, std::ios::binary);
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  bytes.insert(bytes.begin() + after_first_epoch, inserted.begin(), inserted.end());
  test::TempDir dir;
  const std::string path = dir.file("with_geo.ubx");
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));

  import::UbxLog ours_log;
  const test::Converted ours = test::giocalImport(dir, path, ours_log);
  const test::Converted ref = test::convbin(dir, path);
  int geo = 0;
  for (const Ephemeris& r : ref.nav.ephemerides) geo += isBeidouGeo(r.sat);
  EXPECT_EQ(geo, 2) << "convbin decodes both GEO satellites' pages";
  // Both decoders agree in every field (the MEO/IGSO D1 ones of the log included) ...
  EXPECT_GE(test::compareEphemerides(ours, ref, GnssSystem::kBeidou), 2 + 4);
  // ... and give what was sent (through RINEX's 12 significant digits).
  for (const Ephemeris& s : sent) {
    const Ephemeris* o = nullptr;
    for (const Ephemeris& x : ours.nav.ephemerides) o = x.sat == s.sat ? &x : o;
    ASSERT_NE(o, nullptr) << s.sat.str();
    EXPECT_EQ(o->toe, s.toe);
    EXPECT_NEAR(o->sqrt_a, s.sqrt_a, 1e-9);
    EXPECT_NEAR(o->omega0, s.omega0, 1e-11);
    EXPECT_NEAR(o->af0, s.af0, 1e-16);
  }
  std::cout << "BeiDou D2: convbin decoded " << geo << " GEO ephemerides from the inserted pages\n";
}

}  // namespace
}  // namespace giocal
