#include "import/gps_lnav.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/time/gps_time.h"

namespace giocal::import {

namespace {

constexpr uint32_t kLnavPreamble = 0x8B;

// Word w (1-10), bit b (1-24) of IS-GPS-200's numbering, in the packed 24-bit-per-word string.
constexpr int at(int w, int b) { return 24 * (w - 1) + (b - 1); }

// URA index to metres (IS-GPS-200 20.3.3.3.1.3, the upper bound of each range).
double uraMetres(int index) {
  static constexpr double kUra[] = {2.4,  3.4,   4.85,  6.85,  9.65,   13.65,  24.0,  48.0,
                                    96.0, 192.0, 384.0, 768.0, 1536.0, 3072.0, 6144.0};
  return index >= 0 && index < 15 ? kUra[index] : 6144.0;
}

}  // namespace

std::optional<Ephemeris> decodeLnav(const SatId& sat, const BitBuffer& sf1, const BitBuffer& sf2,
                                    const BitBuffer& sf3, double t_rx) {
  const uint32_t iodc = sf1.u2(at(3, 23), 2, at(8, 1), 8);
  const uint32_t iode2 = sf2.u(at(3, 1), 8);
  const uint32_t iode3 = sf3.u(at(10, 1), 8);
  if (iode2 != iode3 || (iodc & 0xFF) != iode2) return std::nullopt;

  Ephemeris e;
  e.sat = sat;
  e.iodc = iodc;
  e.iode = iode2;
  e.accuracy = uraMetres(static_cast<int>(sf1.u(at(3, 13), 4)));
  e.health = static_cast<int>(sf1.u(at(3, 17), 6));
  e.tgd = scaled(sf1.s(at(7, 17), 8), -31);
  e.toc = gpsSecondsNear(scaled(sf1.u(at(8, 9), 16), 4), t_rx);
  e.af2 = scaled(sf1.s(at(9, 1), 8), -55);
  e.af1 = scaled(sf1.s(at(9, 9), 16), -43);
  e.af0 = scaled(sf1.s(at(10, 1), 22), -31);

  e.crs = scaled(sf2.s(at(3, 9), 16), -5);
  e.delta_n = scaled(sf2.s(at(4, 1), 16), -43) * kIcdPi;
  e.m0 = scaled(sf2.s2(at(4, 17), 8, at(5, 1), 24), -31) * kIcdPi;
  e.cuc = scaled(sf2.s(at(6, 1), 16), -29);
  e.e = scaled(sf2.u2(at(6, 17), 8, at(7, 1), 24), -33);
  e.cus = scaled(sf2.s(at(8, 1), 16), -29);
  e.sqrt_a = scaled(sf2.u2(at(8, 17), 8, at(9, 1), 24), -19);
  e.toe = gpsSecondsNear(scaled(sf2.u(at(10, 1), 16), 4), t_rx);

  e.cic = scaled(sf3.s(at(3, 1), 16), -29);
  e.omega0 = scaled(sf3.s2(at(3, 17), 8, at(4, 1), 24), -31) * kIcdPi;
  e.cis = scaled(sf3.s(at(5, 1), 16), -29);
  e.i0 = scaled(sf3.s2(at(5, 17), 8, at(6, 1), 24), -31) * kIcdPi;
  e.crc = scaled(sf3.s(at(7, 1), 16), -5);
  e.omega = scaled(sf3.s2(at(7, 17), 8, at(8, 1), 24), -31) * kIcdPi;
  e.omega_dot = scaled(sf3.s(at(9, 1), 24), -43) * kIcdPi;
  e.idot = scaled(sf3.s(at(10, 9), 14), -43) * kIcdPi;
  return e;
}

std::optional<std::array<double, 8>> decodeLnavIonosphere(const BitBuffer& sf4) {
  if (sf4.u(at(3, 3), 6) != 56) return std::nullopt;  // not page 18
  return std::array<double, 8>{scaled(sf4.s(at(3, 9), 8), -30), scaled(sf4.s(at(4, 1), 8), -27),
                               scaled(sf4.s(at(4, 9), 8), -24), scaled(sf4.s(at(4, 17), 8), -24),
                               scaled(sf4.s(at(5, 1), 8), 11),  scaled(sf4.s(at(5, 9), 8), 14),
                               scaled(sf4.s(at(5, 17), 8), 16), scaled(sf4.s(at(6, 1), 8), 16)};
}

std::optional<Ephemeris> GpsLnavAssembler::add(const SatId& sat, const std::vector<uint32_t>& words,
                                               double t_rx) {
  if (words.size() != 10) {
    throw std::runtime_error(sat.str() + " LNAV subframe of " + std::to_string(words.size()) +
                             " words (10)");
  }
  BitBuffer sf(240);
  for (int w = 0; w < 10; ++w)
    sf.put(24 * w, 24, (words[static_cast<std::size_t>(w)] >> 6) & 0xFFFFFF);
  if (sf.u(0, 8) != kLnavPreamble) {
    throw std::runtime_error(sat.str() + " subframe without the LNAV preamble (CNAV or damage)");
  }
  const int id = static_cast<int>(sf.u(at(2, 20), 3));
  if (id < 1 || id > 5)
    throw std::runtime_error(sat.str() + " LNAV subframe id " + std::to_string(id));
  if (id == 4 && sat.sys == GnssSystem::kGps) {
    if (auto iono = decodeLnavIonosphere(sf)) iono_ = iono;
  }
  if (id > 3) return std::nullopt;  // almanac pages: not read
  Frames& f = frames_[sat];
  f.sub[static_cast<std::size_t>(id - 1)] = sf;
  if (id != 3 || !f.sub[0] || !f.sub[1]) return std::nullopt;
  auto eph = decodeLnav(sat, *f.sub[0], *f.sub[1], *f.sub[2], t_rx);
  if (!eph || eph->iodc == f.last_iodc) return std::nullopt;
  f.last_iodc = eph->iodc;
  return eph;
}

}  // namespace giocal::import
