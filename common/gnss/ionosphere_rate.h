// IonosphereRate: each satellite's ionospheric delay rate, from its geometry-free carrier phase
// over the last tens of seconds, taken out of the time-differenced phase of each of its bands. The
// ionosphere's change over a second is a fraction of a millimetre, but it is slow and differs per
// satellite (through each one's mapping function), so a single receiver's time differences would
// otherwise carry it as a steady displacement, mostly vertical (docs/design.md).
#pragma once

#include <deque>
#include <map>
#include <utility>

#include "common/gnss/satellite.h"

namespace giocal {

struct TdcpPair;

class IonosphereRate {
 public:
  /// window_s: the span the rate is fitted over (0: no correction); min_span_s: the shortest
  /// span of a satellite's unbroken two-band phase that gives it a rate (at most window_s).
  IonosphereRate(double window_s, double min_span_s) : window_s_(window_s), min_span_(min_span_s) {}
  /// Feeds the pair's phase changes of the satellites seen on two bands and corrects each of
  /// their bands by the ionosphere's change over the pair (the fitted rate, scaled by the
  /// band's (f_1/f)^2; its variance added to theirs).
  /// Returns the number of signals corrected.
  int correct(TdcpPair& pair);

 private:
  // Per satellite, (t, the ionosphere on the first band [m] accumulated from the geometry-free
  // phase changes since the track started); a pair without both bands ends the track.
  using Track = std::deque<std::pair<double, double>>;
  double window_s_;
  double min_span_;
  std::map<SatId, Track> tracks_;
};

}  // namespace giocal
