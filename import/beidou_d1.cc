#include "import/beidou_d1.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "import/beidou_nav.h"

namespace giocal::import {

std::optional<Ephemeris> decodeBeidouD1(const SatId& sat, const BitBuffer& sf1,
                                        const BitBuffer& sf2, const BitBuffer& sf3, double t_rx) {
  const uint32_t sow1 = beidouSecondsOfWeek(sf1);
  if (beidouSecondsOfWeek(sf2) != sow1 + 6 || beidouSecondsOfWeek(sf3) != sow1 + 12)
    return std::nullopt;

  Ephemeris e;
  e.sat = sat;
  e.health = static_cast<int>(sf1.u(42, 1));
  e.iodc = sf1.u(43, 5);  // AODC
  e.accuracy = beidouUraMetres(static_cast<int>(sf1.u(48, 4)));
  const uint32_t week = sf1.u(60, 13);
  e.toc = gpsSecondsFromBdt(week, sf1.u2(73, 9, 90, 8) * 8.0, t_rx);
  e.tgd = sf1.s(98, 10) * 1e-10;            // TGD1: B1I/B3I
  e.tgd2 = sf1.s2(108, 4, 120, 6) * 1e-10;  // TGD2: B2I/B3I
  e.af2 = scaled(sf1.s(214, 11), -66);
  e.af0 = scaled(sf1.s2(225, 7, 240, 17), -33);
  e.af1 = scaled(sf1.s2(257, 5, 270, 17), -50);
  e.iode = sf1.u(287, 5);  // AODE

  e.delta_n = scaled(sf2.s2(42, 10, 60, 6), -43) * kBeidouPi;
  e.cuc = scaled(sf2.s2(66, 16, 90, 2), -31);
  e.m0 = scaled(sf2.s2(92, 20, 120, 12), -31) * kBeidouPi;
  e.e = scaled(sf2.u2(132, 10, 150, 22), -33);
  e.cus = scaled(sf2.s(180, 18), -31);
  e.crc = scaled(sf2.s2(198, 4, 210, 14), -6);
  e.crs = scaled(sf2.s2(224, 8, 240, 10), -6);
  e.sqrt_a = scaled(sf2.u2(250, 12, 270, 20), -19);
  const uint32_t toe = (sf2.u(290, 2) << 15) | sf3.u2(42, 10, 60, 5);
  e.toe = gpsSecondsFromBdt(week, toe * 8.0, t_rx);

  e.i0 = scaled(sf3.s2(65, 17, 90, 15), -31) * kBeidouPi;
  e.cic = scaled(sf3.s2(105, 7, 120, 11), -31);
  e.omega_dot = scaled(sf3.s2(131, 11, 150, 13), -43) * kBeidouPi;
  e.cis = scaled(sf3.s2(163, 9, 180, 9), -31);
  e.idot = scaled(sf3.s2(189, 13, 210, 1), -43) * kBeidouPi;
  e.omega0 = scaled(sf3.s2(211, 21, 240, 11), -31) * kBeidouPi;
  e.omega = scaled(sf3.s2(251, 11, 270, 21), -31) * kBeidouPi;
  return e;
}

std::optional<Ephemeris> BeidouD1Assembler::add(const SatId& sat,
                                                const std::vector<uint32_t>& words, double t_rx) {
  const BitBuffer sf = beidouSubframe(sat, words);
  const int id = beidouSubframeId(sat, sf, "D1");
  if (id > 3) return std::nullopt;  // almanac and time offsets: not read
  auto& f = frames_[sat];
  f[static_cast<std::size_t>(id - 1)] = sf;
  if (id != 3 || !f[0] || !f[1]) return std::nullopt;
  auto eph = decodeBeidouD1(sat, *f[0], *f[1], *f[2], t_rx);
  if (!eph || !issues_.isNew(*eph)) return std::nullopt;
  return eph;
}

}  // namespace giocal::import
