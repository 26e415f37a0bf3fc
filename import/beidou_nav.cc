#include "import/beidou_nav.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/time/gps_time.h"

namespace giocal::import {

namespace {

constexpr uint32_t kBeidouPreamble = 0x712;
constexpr double kBdtWeekInGps = 1356.0;  // BDT week 0 began at GPS week 1356
constexpr double kBdtBehindGps = 14.0;    // GPST - BDT [s]

}  // namespace

BitBuffer beidouSubframe(const SatId& sat, const std::vector<uint32_t>& words) {
  if (words.size() != 10) {
    throw std::runtime_error(sat.str() + " BeiDou subframe of " + std::to_string(words.size()) +
                             " words (10)");
  }
  BitBuffer sf(300);
  for (int w = 0; w < 10; ++w) sf.put(30 * w, 30, words[static_cast<std::size_t>(w)] & 0x3FFFFFFF);
  if (sf.u(0, 11) != kBeidouPreamble) {
    throw std::runtime_error(sat.str() + " subframe without the BeiDou preamble");
  }
  return sf;
}

int beidouSubframeId(const SatId& sat, const BitBuffer& sf, const char* format) {
  const int id = static_cast<int>(sf.u(15, 3));
  if (id < 1 || id > 5) {
    throw std::runtime_error(sat.str() + " " + format + " subframe id " + std::to_string(id));
  }
  return id;
}

bool BeidouIssues::isNew(const Ephemeris& e) {
  const auto key = std::make_pair(e.toe, static_cast<double>(e.iode));
  const auto it = last_.find(e.sat);
  if (it != last_.end() && it->second == key) return false;
  last_[e.sat] = key;
  return true;
}

// 8 MSBs in word 1, 12 LSBs in word 2.
uint32_t beidouSecondsOfWeek(const BitBuffer& sf) { return sf.u2(18, 8, 30, 12); }

double gpsSecondsFromBdt(uint32_t week, double sow, double t_rx) {
  const double t = (kBdtWeekInGps + week) * kSecondsPerWeek + sow + kBdtBehindGps;
  return t + std::round((t_rx - t) / kSecondsPerWeek) * kSecondsPerWeek;
}

double beidouUraMetres(int index) {
  static constexpr double kUra[] = {2.4,  3.4,   4.85,  6.85,  9.65,   13.65,  24.0,  48.0,
                                    96.0, 192.0, 384.0, 768.0, 1536.0, 3072.0, 6144.0};
  return index >= 0 && index < 15 ? kUra[index] : 6144.0;
}

}  // namespace giocal::import
