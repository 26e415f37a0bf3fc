// BeidouD2Assembler: the BeiDou D2 navigation message of the GEO satellites (PRN 1-5, 59-63),
// pages 1-10 of subframe 1, to broadcast ephemerides (BDS-SIS-ICD-B1I-3.0 5.3.2; subframes as
// u-blox UBX-RXM-SFRBX delivers them: ten 30-bit words, de-interleaved, parity bits in place).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "common/gnss/ephemeris.h"
#include "import/beidou_nav.h"
#include "import/bit_buffer.h"

namespace giocal::import {

/// Pages 1-10 of one cycle of subframe 1 (page k at index k-1).
using BeidouD2Pages = std::array<BitBuffer, 10>;

class BeidouD2Assembler {
 public:
  /// Adds one subframe (10 words, bits 29-0) of `sat` received near GPS time `t_rx`; the
  /// ephemeris when page 10 completes a cycle of pages 1-10 (each issue once), else none.
  /// Throws std::runtime_error for a subframe that is not BeiDou's (preamble, subframe id, page).
  std::optional<Ephemeris> add(const SatId& sat, const std::vector<uint32_t>& words, double t_rx);

 private:
  std::map<SatId, std::array<std::optional<BitBuffer>, 10>> pages_;
  BeidouIssues issues_;
};

/// The ephemeris of pages 1-10 of subframe 1: their seconds of week 3 s apart (one frame each),
/// else none. Times are converted from BDT to GPS seconds next to GPS time t_rx.
std::optional<Ephemeris> decodeBeidouD2(const SatId& sat, const BeidouD2Pages& pages, double t_rx);

}  // namespace giocal::import
