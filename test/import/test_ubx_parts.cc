// The parts of the UBX import: bit fields, frames and their damage, RXM-RAWX decoding with its
// loss-of-lock indicator, the CRC of Galileo pages, the RINEX navigation writer, and a damaged copy
// of the real log.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_nav_writer.h"
#include "common/time/gps_time.h"
#include "import/bit_buffer.h"
#include "import/galileo_inav.h"
#include "import/rawx_decoder.h"
#include "import/ubx_log.h"
#include "import/ubx_stream.h"
#include "temp_dir.h"

namespace giocal::import {
namespace {

const std::string kLog = std::string(GIOCAL_SOURCE_DIR) + "/data/real/ublox-f9p-walk/gnss_1730.ubx";

TEST(BitBuffer, FieldsRoundTripWithSignsAndSplits) {
  BitBuffer b(64);
  b.put(3, 10, 0x2AB);
  b.put(13, 8, static_cast<uint32_t>(-5) & 0xFF);
  b.put(40, 24, 0xABCDEF);
  EXPECT_EQ(b.u(3, 10), 0x2ABu);
  EXPECT_EQ(b.s(13, 8), -5);
  EXPECT_EQ(b.s(3, 10), 0x2AB - 1024);
  EXPECT_EQ(b.u2(13, 8, 40, 24), (0xFBu << 24) | 0xABCDEFu);
  EXPECT_EQ(b.s2(13, 8, 40, 24), static_cast<int32_t>((0xFBu << 24) | 0xABCDEFu));
  EXPECT_THROW(b.u(60, 8), std::out_of_range);
  EXPECT_THROW(b.u(0, 33), std::out_of_range);
}

TEST(GalileoInav, Crc24qOfTheCheckString) {
  const char* text = "123456789";
  BitBuffer b(72);
  for (int k = 0; k < 9; ++k) b.put(8 * k, 8, static_cast<uint8_t>(text[k]));
  EXPECT_EQ(crc24q(b, 72), 0xCDE703u);  // the published check value of CRC-24Q
}

void append(std::vector<uint8_t>& to, const std::vector<uint8_t>& bytes) {
  to.insert(to.end(), bytes.begin(), bytes.end());
}

TEST(UbxStream, SkipsGarbageAndBadChecksumsAndNotesATruncatedEnd) {
  test::TempDir dir;
  std::vector<uint8_t> bytes{'$', 'G', 'P', 0xB5, 0x00};  // NMEA-like noise and a lone sync byte
  append(bytes, ubxFrameBytes(0x01, 0x07, {1, 2, 3}));
  auto bad = ubxFrameBytes(0x02, 0x15, {4, 5, 6, 7});
  bad[7] ^= 0xFF;  // a payload byte changed after the checksum was made
  append(bytes, bad);
  append(bytes, ubxFrameBytes(0x02, 0x13, {8}));
  const auto cut = ubxFrameBytes(0x02, 0x15, std::vector<uint8_t>(40, 9));
  bytes.insert(bytes.end(), cut.begin(), cut.begin() + 20);
  const std::string path = dir.file("log.ubx");
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  UbxStream s(path);
  UbxFrame f;
  ASSERT_TRUE(s.next(f));
  EXPECT_EQ(f.cls, 0x01);
  EXPECT_EQ(f.payload, (std::vector<uint8_t>{1, 2, 3}));
  EXPECT_EQ(f.offset, 5);
  ASSERT_TRUE(s.next(f));
  EXPECT_EQ(f.id, 0x13);
  EXPECT_FALSE(s.next(f));
  EXPECT_EQ(s.counts().frames, 2);
  EXPECT_EQ(s.counts().bad_checksums, 1);
  EXPECT_TRUE(s.counts().truncated_end);
  EXPECT_THROW(UbxStream(dir.file("missing.ubx")), std::runtime_error);
}

// A RAWX payload: header at week/tow, then measurements.
struct Meas {
  int gnss, sv, sig;
  double pr, cp;
  float dop;
  int lock_ms, cno, trk, cp_std = 1;
};

std::vector<uint8_t> rawx(int week, double tow, const std::vector<Meas>& ms) {
  std::vector<uint8_t> p(16 + 32 * ms.size(), 0);
  std::memcpy(&p[0], &tow, 8);
  p[8] = static_cast<uint8_t>(week & 0xFF);
  p[9] = static_cast<uint8_t>(week >> 8);
  p[11] = static_cast<uint8_t>(ms.size());
  p[13] = 1;
  for (std::size_t k = 0; k < ms.size(); ++k) {
    uint8_t* m = &p[16 + 32 * k];
    std::memcpy(m, &ms[k].pr, 8);
    std::memcpy(m + 8, &ms[k].cp, 8);
    std::memcpy(m + 16, &ms[k].dop, 4);
    m[20] = static_cast<uint8_t>(ms[k].gnss);
    m[21] = static_cast<uint8_t>(ms[k].sv);
    m[22] = static_cast<uint8_t>(ms[k].sig);
    m[24] = static_cast<uint8_t>(ms[k].lock_ms & 0xFF);
    m[25] = static_cast<uint8_t>(ms[k].lock_ms >> 8);
    m[26] = static_cast<uint8_t>(ms[k].cno);
    m[28] = static_cast<uint8_t>(ms[k].cp_std);
    m[30] = static_cast<uint8_t>(ms[k].trk);
  }
  return p;
}

TEST(RawxDecoder, ValuesSignalsAndLossOfLock) {
  RawxDecoder d;
  // trkStat: 1 code valid, 2 phase valid, 4 half cycle valid, 8 half cycle subtracted.
  const ObsEpoch e1 = d.decode(rawx(2381, 408657.748,
                                    {{0, 10, 0, 2.0e7, 1.0e8, 1000.5f, 0, 45, 1 | 2 | 4},
                                     {0, 10, 3, 2.0e7 + 3, 8.0e7, 800.f, 500, 40, 1 | 2},
                                     {6, 3, 0, 2.1e7, 1.1e8, 5.f, 900, 40, 1 | 2 | 4},
                                     {2, 7, 0, 2.3e7, 1.2e8, -5.f, 900, 30, 1 | 4, 1}}));
  EXPECT_DOUBLE_EQ(e1.t, gpsSecondsFromWeekTime({2381, 408657.748}));
  ASSERT_EQ(e1.sats.size(), 2u);  // G10 with L1 C/A and L2 CL; GLONASS not written; E07
  EXPECT_EQ(e1.sats[0].sat.str(), "G10");
  ASSERT_EQ(e1.sats[0].signals.size(), 2u);
  const SignalObs& l1 = e1.sats[0].signals[0];
  EXPECT_EQ(l1.band, '1');
  EXPECT_EQ(l1.attr, 'C');
  EXPECT_DOUBLE_EQ(l1.P, 2.0e7);
  EXPECT_DOUBLE_EQ(l1.L, 1.0e8);
  EXPECT_DOUBLE_EQ(l1.D, 1000.5);
  EXPECT_DOUBLE_EQ(l1.S, 45);
  EXPECT_EQ(l1.lli, 1);  // lock time 0: a new lock
  const SignalObs& l2 = e1.sats[0].signals[1];
  EXPECT_EQ(l2.band, '2');
  EXPECT_EQ(l2.attr, 'L');
  EXPECT_EQ(l2.lli, 1 | 2);  // its first phase, and the half cycle not yet resolved
  EXPECT_TRUE(std::isnan(e1.sats[1].signals[0].L));  // phase not valid
  EXPECT_EQ(d.counts().unsupported_system, 1);

  const ObsEpoch e2 = d.decode(rawx(2381, 408658.0,
                                    {{0, 10, 0, 2.0e7, 1.0e8, 1000.5f, 250, 45, 1 | 2 | 4},
                                     {0, 10, 3, 2.0e7, 8.0e7, 800.f, 100, 40, 1 | 2 | 4 | 8}}));
  EXPECT_EQ(e2.sats[0].signals[0].lli, 0);  // lock time grew
  EXPECT_EQ(e2.sats[0].signals[1].lli, 1);  // lock time fell and the half-cycle flag changed
  const ObsEpoch e3 =
      d.decode(rawx(2381, 408658.25, {{0, 10, 0, 2.0e7, 1.0e8, 1000.5f, 500, 45, 1 | 2 | 4, 9}}));
  EXPECT_TRUE(std::isnan(e3.sats[0].signals[0].L));  // phase sigma 0.036 cycles: dropped
  // The slip of an epoch without a valid phase reaches the next phase, although its lock time grew.
  d.decode(rawx(2381, 408658.5, {{0, 10, 0, 2.0e7, 1.0e8, 1000.5f, 0, 45, 1}}));
  const ObsEpoch e4 =
      d.decode(rawx(2381, 408658.75, {{0, 10, 0, 2.0e7, 1.0e8, 1000.5f, 200, 45, 1 | 2 | 4}}));
  EXPECT_EQ(e4.sats[0].signals[0].lli, 1);

  EXPECT_THROW(d.decode(std::vector<uint8_t>(10, 0)), std::runtime_error);
  auto short_one = rawx(2381, 408659.0, {{0, 1, 0, 2e7, 1e8, 0.f, 0, 40, 3}});
  short_one.pop_back();
  EXPECT_THROW(d.decode(short_one), std::runtime_error);
  EXPECT_THROW(d.decode(rawx(0, 1.0, {})), std::runtime_error);
  EXPECT_THROW(d.decode(rawx(2381, NAN, {})), std::runtime_error);
}

Ephemeris sampleEphemeris(GnssSystem sys, int prn, double t) {
  Ephemeris e;
  e.sat = {sys, prn};
  e.toc = e.toe = t;
  e.af0 = -3.4e-4;
  e.af1 = 1.3e-11;
  e.af2 = 0.0;
  e.iode = 83;
  e.iodc = sys == GnssSystem::kGps ? 83 : 0;
  e.crs = -16.78;
  e.delta_n = 4.7e-9;
  e.m0 = 2.73;
  e.cuc = -9.0e-7;
  e.e = 8.6e-3;
  e.cus = 5.6e-6;
  e.sqrt_a = sys == GnssSystem::kBeidou ? 5282.6 : 5153.6;
  e.cic = 1.1e-8;
  e.omega0 = 2.24;
  e.cis = -1.6e-7;
  e.i0 = 0.9658;
  e.crc = 271.7;
  e.omega = -2.06;
  e.omega_dot = -7.96e-9;
  e.idot = 9.7e-11;
  e.tgd = 9.3e-10;
  e.tgd2 = sys == GnssSystem::kGps ? 0.0 : -2.1e-9;
  e.health = 0;
  e.data_source = sys == GnssSystem::kGalileo ? 513 : 0;
  e.accuracy = 2.0;
  return e;
}

TEST(RinexNavWriter, WhatItWritesReadsBackTheSame) {
  test::TempDir dir;
  NavData nav;
  const double t = gpsSecondsFromWeekTime({2381, 410400.0});
  nav.ephemerides = {sampleEphemeris(GnssSystem::kGps, 32, t),
                     sampleEphemeris(GnssSystem::kGalileo, 7, t),
                     sampleEphemeris(GnssSystem::kBeidou, 21, t - 3600.0 + 14.0)};
  nav.gps_iono = {1.1e-8, 2e-8, -6e-8, -1.2e-7, 90112, 0, -196608, -65536};
  nav.has_gps_iono = true;
  writeRinexNav(dir.file("n.rnx"), nav, "test");
  const NavData back = readRinexNav(dir.file("n.rnx"));
  ASSERT_EQ(back.ephemerides.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const Ephemeris &a = nav.ephemerides[k], &b = back.ephemerides[k];
    EXPECT_EQ(a.sat, b.sat);
    EXPECT_NEAR(a.toe, b.toe, 1e-6) << a.sat.str();
    EXPECT_NEAR(a.toc, b.toc, 1e-6) << a.sat.str();
    for (const auto& [x, y] : {std::pair{a.af0, b.af0},
                               {a.sqrt_a, b.sqrt_a},
                               {a.m0, b.m0},
                               {a.tgd, b.tgd},
                               {a.tgd2, b.tgd2},
                               {a.idot, b.idot},
                               {a.iode, b.iode},
                               {a.accuracy, b.accuracy}}) {
      EXPECT_NEAR(x, y, 1e-11 * std::max(1.0, std::abs(x))) << a.sat.str();
    }
    EXPECT_EQ(a.data_source, b.data_source);
  }
  EXPECT_TRUE(back.has_gps_iono);
  EXPECT_NEAR(back.gps_iono[4], 90112, 1e-6);
}

TEST(UbxLog, ADamagedCopyIsReadUpToTheDamageAndSaysWhere) {
  test::TempDir dir;
  std::ifstream in(kLog, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const import::UbxLog whole = readUbxLog(kLog);
  UbxStream frames(kLog);
  UbxFrame f;
  while (frames.next(f) && f.offset < static_cast<long long>(bytes.size() / 2)) {
  }
  bytes[static_cast<std::size_t>(f.offset) + 6] ^= 0x5A;  // the first payload byte of a frame
  bytes.resize(bytes.size() * 3 / 4 + 7);                 // and the log cut mid-frame
  const std::string path = dir.file("damaged.ubx");
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  const import::UbxLog log = readUbxLog(path);
  EXPECT_LT(log.obs.epochs.size(), whole.obs.epochs.size() * 3 / 4 + 2);
  EXPECT_GT(log.obs.epochs.size(), whole.obs.epochs.size() * 3 / 4 - 5);
  EXPECT_EQ(log.stream.bad_checksums, 1);
  EXPECT_TRUE(log.stream.truncated_end);
  ASSERT_EQ(log.warnings.size(), 2u);
  EXPECT_NE(log.warnings[0].find("damaged.ubx: byte "), std::string::npos) << log.warnings[0];
  EXPECT_NE(log.warnings[0].find("bad checksum"), std::string::npos) << log.warnings[0];
  EXPECT_NE(log.warnings[1].find("ends inside a frame"), std::string::npos) << log.warnings[1];

  const std::string empty = dir.write("empty.ubx", "no UBX here\n");
  try {
    readUbxLog(empty);
    FAIL() << "a log without RAWX was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("empty.ubx: no UBX-RXM-RAWX epoch"), std::string::npos);
  }
}

}  // namespace
}  // namespace giocal::import
