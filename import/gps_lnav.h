// GpsLnavAssembler: GPS (and QZSS) L1 C/A LNAV subframes 1-3 to broadcast ephemerides
// (IS-GPS-200 20.3.3.3 and 20.3.3.4; subframes as u-blox UBX-RXM-SFRBX delivers them: ten 30-bit
// words, parity removed by the receiver).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "common/gnss/ephemeris.h"
#include "import/bit_buffer.h"

namespace giocal::import {

class GpsLnavAssembler {
 public:
  /// Adds one subframe (10 words, data in bits 29-6) of `sat` received near GPS time `t_rx`; the
  /// ephemeris when subframes 1-3 of one issue of data are complete (each issue once), else none.
  /// Throws std::runtime_error for a subframe that is not LNAV (preamble, subframe id).
  std::optional<Ephemeris> add(const SatId& sat, const std::vector<uint32_t>& words, double t_rx);
  /// The Klobuchar parameters (alpha0-3, beta0-3) of subframe 4 page 18, once one was received.
  const std::optional<std::array<double, 8>>& ionosphere() const { return iono_; }

 private:
  struct Frames {
    std::array<std::optional<BitBuffer>, 3> sub;
    double last_iodc = -1.0;
  };
  std::map<SatId, Frames> frames_;
  std::optional<std::array<double, 8>> iono_;
};

/// The Klobuchar parameters of a subframe 4 (240 bits) when it is page 18 (SV ID 56).
std::optional<std::array<double, 8>> decodeLnavIonosphere(const BitBuffer& sf4);

/// The ephemeris of three subframes (bit strings of 240 bits: ten 24-bit words); none when their
/// issues of data differ. Weeks (10 bits) and times are resolved next to GPS time t_rx.
std::optional<Ephemeris> decodeLnav(const SatId& sat, const BitBuffer& sf1, const BitBuffer& sf2,
                                    const BitBuffer& sf3, double t_rx);

}  // namespace giocal::import
