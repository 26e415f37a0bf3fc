// GNSS observations of one receiver: per epoch, per satellite, per signal (band and attribute)
// pseudo-range, carrier phase, Doppler, C/N0 and loss-of-lock flags.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/gnss/satellite.h"

namespace giocal {

struct SignalObs {
  char band = '1';                                      // RINEX 3 frequency band digit
  char attr = 'C';                                      // RINEX 3 tracking attribute
  double P = std::numeric_limits<double>::quiet_NaN();  // pseudo-range [m]
  double L = std::numeric_limits<double>::quiet_NaN();  // carrier phase [cycles]
  double D = std::numeric_limits<double>::quiet_NaN();  // Doppler [Hz]
  double S = std::numeric_limits<double>::quiet_NaN();  // C/N0 [dB-Hz]
  int lli = 0;  // loss of lock indicator of the phase: bit 0 slip, bit 1 half-cycle ambiguity
};

/// A tracking attribute's place in the order of preference of one band's signals (lower first):
/// civil and open codes, then semi-codeless, then the rest.
int attributeRank(char attr);

struct SatObs {
  SatId sat;
  std::vector<SignalObs> signals;
  /// The signal of `band` that has code and phase, preferring the better-known attributes;
  /// falls back to one with code only; nullptr when the band is absent.
  const SignalObs* bestOnBand(char band) const;
};

struct ObsEpoch {
  double t = 0.0;              // GPS seconds (receiver time tag)
  int flag = 0;                // RINEX epoch flag (0 ok, 1 power failure before this epoch)
  double rx_clock_offset = 0;  // receiver clock offset reported in the file [s], 0 if absent
  std::vector<SatObs> sats;
  const SatObs* find(const SatId& sat) const;
};

struct ObsHeader {
  double version = 0.0;
  std::string marker;
  Eigen::Vector3d approx_position = Eigen::Vector3d::Zero();    // ECEF [m]; zero if not given
  Eigen::Vector3d antenna_delta_hen = Eigen::Vector3d::Zero();  // [m]
  double interval = 0.0;
  std::map<char, std::vector<std::string>> obs_types;  // system -> RINEX 3 codes ("C1C", ...)
  // SYS / PHASE SHIFT: (system, code) -> shift applied to the phases in the file [cycles].
  std::map<std::pair<char, std::string>, double> phase_shift;
};

struct ObsData {
  ObsHeader header;
  std::vector<ObsEpoch> epochs;
  int skipped_special_records = 0;    // event-flag records (2-6) skipped
  std::vector<std::string> warnings;  // recoverable damage dropped (RinexObsReader::warnings)
};

/// Pairs rover epochs, in time order, with the base epoch nearest in time.
class BaseEpochMatcher {
 public:
  BaseEpochMatcher(const std::vector<ObsEpoch>& base, double max_offset)
      : base_(base), max_offset_(max_offset) {}
  /// The base epoch nearest t if within max_offset, else nullptr. Calls must come with t rising.
  const ObsEpoch* nearest(double t);

 private:
  const std::vector<ObsEpoch>& base_;
  double max_offset_;
  size_t k_ = 0;
};

}  // namespace giocal
