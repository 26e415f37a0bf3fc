// RawxDecoder: UBX-RXM-RAWX (0x02 0x15) payloads to observation epochs: code, carrier phase,
// Doppler and C/N0 per signal, with the loss-of-lock indicator made from the lock time and the
// half-cycle flags (u-blox F9 interface description, RXM-RAWX).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "common/gnss/observation.h"

namespace giocal::import {

struct RawxCounts {
  long long epochs = 0;
  long long measurements = 0;
  long long unsupported_system = 0;  // GLONASS, NavIC and unknown gnssId (not written)
  long long unknown_signal = 0;      // sigId giocal has no RINEX code for
  long long invalid_code = 0;        // pseudo-range not valid (trkStat) or not finite
  long long invalid_phase = 0;       // phase not valid, or its sigma above 0.02 cycles
  long long clock_resets = 0;        // epochs with the receiver's clock-reset flag
};

class RawxDecoder {
 public:
  /// The epoch of one payload; throws std::runtime_error naming what is wrong with a payload that
  /// is not a RAWX message (too short, length not matching numMeas, week 0, time not finite).
  ObsEpoch decode(const std::vector<uint8_t>& payload);
  const RawxCounts& counts() const { return counts_; }

 private:
  struct Lock {
    int locktime_ms = -1;
    bool half_subtracted = false;
    bool slip_pending = false;  // a slip seen while the phase was not valid, for the next phase
  };
  std::map<std::tuple<SatId, char, char>, Lock> locks_;
  RawxCounts counts_;
};

}  // namespace giocal::import
