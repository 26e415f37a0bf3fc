#include "import/rawx_decoder.h"

#include <cmath>
#include <stdexcept>

#include "common/time/gps_time.h"
#include "import/payload_reader.h"
#include "import/ubx_signals.h"

namespace giocal::import {

namespace {

// cpStdev is 0.004 cycles per count; a phase the receiver reports with a sigma above 0.02 cycles
// is not one to resolve an ambiguity with (RTKLIB's convbin applies the same bound).
constexpr int kMaxPhaseStdevIndex = 5;

}  // namespace

ObsEpoch RawxDecoder::decode(const std::vector<uint8_t>& payload) {
  const PayloadReader p(payload);
  if (p.size() < 16) {
    throw std::runtime_error("RXM-RAWX of " + std::to_string(p.size()) + " bytes (at least 16)");
  }
  const double tow = p.r8(0);
  const int week = p.u2(8);
  const int n = p.u1(11);
  if (p.size() != 16 + 32 * static_cast<std::size_t>(n)) {
    throw std::runtime_error("RXM-RAWX of " + std::to_string(p.size()) + " bytes for " +
                             std::to_string(n) + " measurements");
  }
  if (week == 0) throw std::runtime_error("RXM-RAWX without a week number (receiver time unset)");
  if (!std::isfinite(tow) || tow < 0.0 || tow > kSecondsPerWeek) {
    throw std::runtime_error("RXM-RAWX time of week not within 0-604800 s");
  }
  if (p.u1(12) & 2) ++counts_.clock_resets;

  ObsEpoch epoch;
  epoch.t = gpsSecondsFromWeekTime({week, tow});
  for (int i = 0; i < n; ++i) {
    const std::size_t o = 16 + 32 * static_cast<std::size_t>(i);
    ++counts_.measurements;
    SatId sat;
    if (!ubxSatellite(p.u1(o + 20), p.u1(o + 21), sat)) {
      ++counts_.unsupported_system;
      continue;
    }
    SignalObs sig;
    if (!ubxSignal(sat.sys, p.u1(o + 22), sig.band, sig.attr)) {
      ++counts_.unknown_signal;
      continue;
    }
    const int trk = p.u1(o + 30);
    const double pr = p.r8(o);
    const double cp = p.r8(o + 8);
    const double dop = p.r4(o + 16);
    if ((trk & 1) && std::isfinite(pr)) {
      sig.P = pr;
    } else {
      ++counts_.invalid_code;
    }
    const bool phase_ok =
        (trk & 2) && (p.u1(o + 28) & 15) <= kMaxPhaseStdevIndex && std::isfinite(cp) && cp != 0.0;
    if (phase_ok) {
      sig.L = cp;
    } else {
      ++counts_.invalid_phase;
    }
    if (std::isfinite(dop)) sig.D = dop;
    sig.S = p.u1(o + 26);
    // The first phase of a signal, a lock time that restarted or fell, or a change of the
    // half-cycle correction is a slip, carried to the next valid phase when this one is not; a
    // phase whose half-cycle ambiguity is not yet resolved carries bit 1.
    const int locktime = p.u2(o + 24);
    const bool half_valid = trk & 4;
    const bool half_subtracted = trk & 8;
    Lock& lock = locks_[{sat, sig.band, sig.attr}];
    const bool slip = lock.slip_pending || lock.locktime_ms < 0 || locktime == 0 ||
                      locktime < lock.locktime_ms || half_subtracted != lock.half_subtracted;
    lock = {locktime, half_subtracted, slip && !phase_ok};
    if (phase_ok) sig.lli = (slip ? 1 : 0) | (half_valid ? 0 : 2);

    SatObs* so = nullptr;
    for (auto& s : epoch.sats) {
      if (s.sat == sat) so = &s;
    }
    if (!so) {
      epoch.sats.push_back({sat, {}});
      so = &epoch.sats.back();
    }
    so->signals.push_back(sig);
  }
  ++counts_.epochs;
  return epoch;
}

}  // namespace giocal::import
