// GalileoInavAssembler: Galileo I/NAV nominal pages (E1-B or E5b-I) to broadcast ephemerides
// (Galileo OS SIS ICD 4.3.5, words 1-5; pages as u-blox UBX-RXM-SFRBX delivers them: eight
// 32-bit words holding the even and the odd page part, CRC-24Q checked here).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "common/gnss/ephemeris.h"
#include "import/bit_buffer.h"

namespace giocal::import {

class GalileoInavAssembler {
 public:
  /// Adds one page pair of `sat` received near GPS time `t_rx`; the ephemeris when words 1-5 of
  /// one issue of data are complete (each issue once), else none. Alert pages and words other than
  /// 1-5 are ignored; throws std::runtime_error for a page with a bad CRC or part order.
  std::optional<Ephemeris> add(const SatId& sat, const std::vector<uint32_t>& words, double t_rx);

 private:
  struct Words {
    std::array<std::optional<BitBuffer>, 5> word;  // the 128-bit data of words 1-5
    double last_iod = -1.0;
  };
  std::map<SatId, Words> words_;
};

/// CRC-24Q (RTCM / Galileo polynomial 0x1864CFB) of the first `bits` bits of a buffer.
uint32_t crc24q(const BitBuffer& buf, int bits);

/// The ephemeris of words 1-5 (128-bit data each); none when their issues of data differ.
std::optional<Ephemeris> decodeInav(const SatId& sat, const std::array<BitBuffer, 5>& w,
                                    double t_rx);

}  // namespace giocal::import
