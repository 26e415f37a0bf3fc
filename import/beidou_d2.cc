#include "import/beidou_d2.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "import/beidou_nav.h"

namespace giocal::import {
namespace {

constexpr uint32_t kFrameSeconds = 3;  // a D2 frame; subframe 1 carries one page per frame

int pageNumber(const BitBuffer& sf) { return static_cast<int>(sf.u(42, 4)); }

// A parameter whose high bits end one page and whose low bits (`lsb_len` of them) start the next.
uint32_t joined(uint32_t msb, uint32_t lsb, int lsb_len) { return (msb << lsb_len) | lsb; }

}  // namespace

std::optional<Ephemeris> decodeBeidouD2(const SatId& sat, const BeidouD2Pages& p, double t_rx) {
  const uint32_t sow1 = beidouSecondsOfWeek(p[0]);
  for (uint32_t k = 1; k < 10; ++k) {
    if (beidouSecondsOfWeek(p[k]) != sow1 + kFrameSeconds * k) return std::nullopt;
  }
  // Bit positions count from 0 at the first bit of the 300-bit subframe (the ICD's bit 1).
  Ephemeris e;
  e.sat = sat;
  const BitBuffer& p1 = p[0];
  e.health = static_cast<int>(p1.u(46, 1));
  e.iodc = p1.u(47, 5);  // AODC
  e.accuracy = beidouUraMetres(static_cast<int>(p1.u(60, 4)));
  const uint32_t week = p1.u(64, 13);
  e.toc = gpsSecondsFromBdt(week, p1.u2(77, 5, 90, 12) * 8.0, t_rx);
  e.tgd = p1.s(102, 10) * 1e-10;   // TGD1: B1I/B3I
  e.tgd2 = p1.s(120, 10) * 1e-10;  // TGD2: B2I/B3I

  const BitBuffer &p3 = p[2], &p4 = p[3], &p5 = p[4], &p6 = p[5], &p7 = p[6], &p8 = p[7],
                  &p9 = p[8], &p10 = p[9];
  e.af0 = scaled(p3.s2(100, 12, 120, 12), -33);
  e.af1 = scaled(twosComplement(joined(p3.u(132, 4), p4.u2(46, 6, 60, 12), 18), 22), -50);
  e.af2 = scaled(p4.s2(72, 10, 90, 1), -66);
  e.iode = p4.u(91, 5);  // AODE
  e.delta_n = scaled(p4.s(96, 16), -43) * kBeidouPi;
  e.cuc = scaled(twosComplement(joined(p4.u(120, 14), p5.u(46, 4), 4), 18), -31);
  const uint32_t m0 = (p5.u(50, 2) << 30) | (p5.u(60, 22) << 8) | p5.u(90, 8);
  e.m0 = scaled(static_cast<int32_t>(m0), -31) * kBeidouPi;
  e.cus = scaled(p5.s2(98, 14, 120, 4), -31);
  e.e = scaled(joined(p5.u(124, 10), p6.u2(46, 6, 60, 16), 22), -33);
  const uint32_t sqrt_a = (p6.u(76, 6) << 26) | (p6.u(90, 22) << 4) | p6.u(120, 4);
  e.sqrt_a = scaled(sqrt_a, -19);
  e.cic = scaled(twosComplement(joined(p6.u(124, 10), p7.u2(46, 6, 60, 2), 8), 18), -31);
  e.cis = scaled(p7.s(62, 18), -31);
  e.toe = gpsSecondsFromBdt(week, p7.u2(80, 2, 90, 15) * 8.0, t_rx);
  const uint32_t i0 = joined(p7.u2(105, 7, 120, 14), p8.u2(46, 6, 60, 5), 11);
  e.i0 = scaled(static_cast<int32_t>(i0), -31) * kBeidouPi;
  e.crc = scaled(p8.s2(65, 17, 90, 1), -6);
  e.crs = scaled(p8.s(91, 18), -6);
  const uint32_t omega_dot = joined(p8.u2(109, 3, 120, 16), p9.u(46, 5), 5);
  e.omega_dot = scaled(twosComplement(omega_dot, 24), -43) * kBeidouPi;
  const uint32_t omega0 = (p9.u(51, 1) << 31) | (p9.u(60, 22) << 9) | p9.u(90, 9);
  e.omega0 = scaled(static_cast<int32_t>(omega0), -31) * kBeidouPi;
  const uint32_t omega = joined(p9.u2(99, 13, 120, 14), p10.u(46, 5), 5);
  e.omega = scaled(static_cast<int32_t>(omega), -31) * kBeidouPi;
  e.idot = scaled(p10.s2(51, 1, 60, 13), -43) * kBeidouPi;
  return e;
}

std::optional<Ephemeris> BeidouD2Assembler::add(const SatId& sat,
                                                const std::vector<uint32_t>& words, double t_rx) {
  const BitBuffer sf = beidouSubframe(sat, words);
  const int id = beidouSubframeId(sat, sf, "D2");
  if (id != 1) return std::nullopt;  // integrity, differential corrections, almanac: not read
  const int page = pageNumber(sf);
  if (page < 1 || page > 10)
    throw std::runtime_error(sat.str() + " D2 subframe 1 page " + std::to_string(page));
  auto& held = pages_[sat];
  held[static_cast<std::size_t>(page - 1)] = sf;
  if (page != 10) return std::nullopt;
  for (const auto& h : held) {
    if (!h) return std::nullopt;
  }
  const BeidouD2Pages pages{*held[0], *held[1], *held[2], *held[3], *held[4],
                            *held[5], *held[6], *held[7], *held[8], *held[9]};
  auto eph = decodeBeidouD2(sat, pages, t_rx);
  if (!eph || !issues_.isNew(*eph)) return std::nullopt;
  return eph;
}

}  // namespace giocal::import
