// What BeiDou's D1 and D2 navigation messages share (BDS-SIS-ICD-B1I-3.0 5.2, 5.3): the subframe
// as u-blox delivers it, its id and seconds of week, BDT to GPS time, and the URA table.
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "common/gnss/ephemeris.h"
#include "common/gnss/satellite.h"
#include "import/bit_buffer.h"

namespace giocal::import {

/// The value the ICD defines for the semicircle.
constexpr double kBeidouPi = 3.1415926535898;

/// The 300-bit subframe of ten 30-bit words (bits 29-0 of each, de-interleaved, parity bits in
/// place); throws std::runtime_error naming `sat` for another word count or without the preamble.
BitBuffer beidouSubframe(const SatId& sat, const std::vector<uint32_t>& words);

/// The subframe id (FraID); throws std::runtime_error naming `sat` and `format` ("D1", "D2")
/// outside 1-5.
int beidouSubframeId(const SatId& sat, const BitBuffer& sf, const char* format);

/// Passes each issue of a satellite's ephemeris (toe, AODE) once: the message repeats it.
class BeidouIssues {
 public:
  bool isNew(const Ephemeris& e);

 private:
  std::map<SatId, std::pair<double, double>> last_;
};

/// The subframe's seconds of BDT week.
uint32_t beidouSecondsOfWeek(const BitBuffer& sf);

/// GPS seconds of a BDT week and seconds of week, in the week nearest GPS time t_rx.
double gpsSecondsFromBdt(uint32_t week, double sow, double t_rx);

/// URA index to metres (the GPS table, which the ICD takes over).
double beidouUraMetres(int index);

}  // namespace giocal::import
