#include "import/galileo_inav.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/time/gps_time.h"

namespace giocal::import {

namespace {

// RINEX 3 data source of an I/NAV record: bit 0 (I/NAV E1-B) and bit 9 (clock for E5b/E1).
constexpr int kInavSource = (1 << 0) | (1 << 9);

// SISA index to metres (Galileo OS SIS ICD 5.1.12); 255 (no prediction) is kept as -1.
double sisaMetres(int n) {
  if (n <= 49) return 0.01 * n;
  if (n <= 74) return 0.5 + 0.02 * (n - 50);
  if (n <= 99) return 1.0 + 0.04 * (n - 75);
  if (n <= 125) return 2.0 + 0.16 * (n - 100);
  return -1.0;
}

}  // namespace

uint32_t crc24q(const BitBuffer& buf, int bits) {
  uint32_t crc = 0;
  for (int k = 0; k < bits; ++k) {
    const uint32_t in = buf.u(k, 1);
    const uint32_t top = (crc >> 23) & 1u;
    crc = (crc << 1) & 0xFFFFFF;
    if (top ^ in) crc ^= 0x864CFB;
  }
  return crc;
}

std::optional<Ephemeris> decodeInav(const SatId& sat, const std::array<BitBuffer, 5>& w,
                                    double t_rx) {
  const uint32_t iod = w[0].u(6, 10);
  for (int k = 1; k < 4; ++k) {
    if (w[static_cast<std::size_t>(k)].u(6, 10) != iod) return std::nullopt;
  }
  Ephemeris e;
  e.sat = sat;
  e.iode = iod;
  e.data_source = kInavSource;
  e.toe = gpsSecondsNear(w[0].u(16, 14) * 60.0, t_rx);
  e.m0 = scaled(w[0].s(30, 32), -31) * kIcdPi;
  e.e = scaled(w[0].u(62, 32), -33);
  e.sqrt_a = scaled(w[0].u(94, 32), -19);

  e.omega0 = scaled(w[1].s(16, 32), -31) * kIcdPi;
  e.i0 = scaled(w[1].s(48, 32), -31) * kIcdPi;
  e.omega = scaled(w[1].s(80, 32), -31) * kIcdPi;
  e.idot = scaled(w[1].s(112, 14), -43) * kIcdPi;

  e.omega_dot = scaled(w[2].s(16, 24), -43) * kIcdPi;
  e.delta_n = scaled(w[2].s(40, 16), -43) * kIcdPi;
  e.cuc = scaled(w[2].s(56, 16), -29);
  e.cus = scaled(w[2].s(72, 16), -29);
  e.crc = scaled(w[2].s(88, 16), -5);
  e.crs = scaled(w[2].s(104, 16), -5);
  e.accuracy = sisaMetres(static_cast<int>(w[2].u(120, 8)));

  e.cic = scaled(w[3].s(22, 16), -29);
  e.cis = scaled(w[3].s(38, 16), -29);
  e.toc = gpsSecondsNear(w[3].u(54, 14) * 60.0, t_rx);
  e.af0 = scaled(w[3].s(68, 31), -34);
  e.af1 = scaled(w[3].s(99, 21), -46);
  e.af2 = scaled(w[3].s(120, 6), -59);

  e.tgd2 = scaled(w[4].s(47, 10), -32);  // BGD E1/E5a
  e.tgd = scaled(w[4].s(57, 10), -32);   // BGD E1/E5b
  const uint32_t e5b_hs = w[4].u(67, 2), e1b_hs = w[4].u(69, 2);
  const uint32_t e5b_dvs = w[4].u(71, 1), e1b_dvs = w[4].u(72, 1);
  e.health = static_cast<int>(e1b_dvs | e1b_hs << 1 | e5b_dvs << 6 | e5b_hs << 7);
  return e;
}

std::optional<Ephemeris> GalileoInavAssembler::add(const SatId& sat,
                                                   const std::vector<uint32_t>& words,
                                                   double t_rx) {
  if (words.size() < 8) {
    throw std::runtime_error(sat.str() + " I/NAV page of " + std::to_string(words.size()) +
                             " words (8)");
  }
  BitBuffer page(256);
  for (int k = 0; k < 8; ++k) page.put(32 * k, 32, words[static_cast<std::size_t>(k)]);
  if (page.u(1, 1) == 1 || page.u(129, 1) == 1) return std::nullopt;  // alert page
  if (page.u(0, 1) != 0 || page.u(128, 1) != 1) {
    throw std::runtime_error(sat.str() + " I/NAV page parts out of order (even/odd)");
  }
  // CRC over the even part's 114 bits and the odd part's first 82, behind 4 zero bits.
  BitBuffer crc_in(200);
  for (int k = 0; k < 114; ++k) crc_in.put(4 + k, 1, page.u(k, 1));
  for (int k = 0; k < 82; ++k) crc_in.put(118 + k, 1, page.u(128 + k, 1));
  if (crc24q(crc_in, 200) != page.u(128 + 82, 24)) {
    throw std::runtime_error(sat.str() + " I/NAV page with a bad CRC");
  }
  BitBuffer data(128);
  for (int k = 0; k < 112; ++k) data.put(k, 1, page.u(2 + k, 1));
  for (int k = 0; k < 16; ++k) data.put(112 + k, 1, page.u(130 + k, 1));
  const int type = static_cast<int>(data.u(0, 6));
  if (type < 1 || type > 5) return std::nullopt;
  Words& ws = words_[sat];
  ws.word[static_cast<std::size_t>(type - 1)] = data;
  for (const auto& w : ws.word) {
    if (!w) return std::nullopt;
  }
  auto eph =
      decodeInav(sat, {*ws.word[0], *ws.word[1], *ws.word[2], *ws.word[3], *ws.word[4]}, t_rx);
  if (!eph || eph->iode == ws.last_iod) return std::nullopt;
  ws.last_iod = eph->iode;
  return eph;
}

}  // namespace giocal::import
