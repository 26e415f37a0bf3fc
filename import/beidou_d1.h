// BeidouD1Assembler: BeiDou D1 navigation message subframes 1-3 of the MEO and IGSO satellites to
// broadcast ephemerides (BDS-SIS-ICD-B1I-3.0 5.2.4; subframes as u-blox UBX-RXM-SFRBX delivers
// them: ten 30-bit words, de-interleaved, data bits first). The GEO satellites' D2: beidou_d2.h.
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

class BeidouD1Assembler {
 public:
  /// Adds one subframe (10 words, bits 29-0) of `sat` received near GPS time `t_rx`; the
  /// ephemeris when subframes 1-3 of one frame are complete (each issue once), else none.
  /// Throws std::runtime_error for a subframe that is not D1 (preamble, subframe id).
  std::optional<Ephemeris> add(const SatId& sat, const std::vector<uint32_t>& words, double t_rx);

 private:
  std::map<SatId, std::array<std::optional<BitBuffer>, 3>> frames_;
  BeidouIssues issues_;
};

/// The ephemeris of subframes 1-3 (300-bit strings, parity bits in place) of one frame: their
/// seconds of week 6 s apart, else none. Times are converted from BDT to GPS seconds next to
/// GPS time t_rx.
std::optional<Ephemeris> decodeBeidouD1(const SatId& sat, const BitBuffer& sf1,
                                        const BitBuffer& sf2, const BitBuffer& sf3, double t_rx);

}  // namespace giocal::import
