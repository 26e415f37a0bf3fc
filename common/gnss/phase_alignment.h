// The check that one receiver's carrier phases of a band are aligned to one reference signal, as
// RINEX 3.01 and later require, and the repair of a signal whose phases sit a quarter or half
// cycle off: measured on the satellite-epochs that track two signals of one band, over a whole
// file (the RINEX reader) or on a stream of epochs (the live Calibrator).
#pragma once

#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "common/gnss/observation.h"

namespace giocal {

/// What the check found for one signal against its band's reference signal.
struct SignalOffset {
  char sys = 'G', band = '1', attr = 'C', ref = 'C';
  double cycles = 0.0;       // circular mean of attr's phase minus ref's, modulo a cycle
  double consistency = 0.0;  // mean resultant length of those differences (1: all alike)
  int pairs = 0;             // satellite-epochs that tracked both
  double applied = 0.0;      // subtracted from attr's phases [cycles]; 0 when left as they are
};

class PhaseAlignment {
 public:
  /// Satellite-epochs tracking both signals needed before a signal is judged.
  static constexpr int kMinPairs = 20;
  /// How far the mean may sit from a quarter cycle, and the least consistency, for a repair.
  static constexpr double kQuarterTolerance = 0.05, kMinConsistency = 0.9;

  /// Accumulates the epoch's phase differences between signals of one band; true when a signal's
  /// pairs with a reference reached kMinPairs with it.
  bool add(const ObsEpoch& e);
  /// Judges every signal seen with its reference; `path` names the file in the warnings.
  void decide(const std::string& path);
  /// Subtracts the repairs from the epoch's phases (a whole file: from its first epoch).
  void apply(ObsEpoch& e) const;
  /// A stream of one receiver's epochs in arrival order: adds the epoch, judges each signal once,
  /// when its pairs with a reference reach kMinPairs, and subtracts the repairs known so far.
  /// The epochs before a repair went out as they came, so the first repaired phase of each
  /// satellite and signal is marked a loss of lock (LLI bit 0): its ambiguity starts again.
  /// Only repairs are named in the warnings (`source` names the receiver).
  void stream(ObsEpoch& e, const std::string& source);
  const std::vector<SignalOffset>& offsets() const { return offsets_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  struct Sum {
    double c = 0.0, s = 0.0;
    int n = 0;
  };
  /// Judges the signals not judged yet whose pairs with some reference reached kMinPairs.
  void judge(const std::string& path, bool name_unrepaired);

  std::map<std::tuple<char, char, char, char>, Sum> sums_;  // (sys, band, attr, ref)
  std::map<std::tuple<char, char, char>, double> shift_;    // (sys, band, attr) -> cycles
  std::set<std::tuple<char, char, char>> judged_;           // (sys, band, attr)
  // Streams: (sys, prn, band, attr) whose repaired phases have gone out (LLI marked once).
  std::set<std::tuple<char, int, char, char>> repaired_out_;
  std::vector<SignalOffset> offsets_;
  std::vector<std::string> warnings_;
};

/// True when the header lists two or more phase signals on one band of a system: only then can
/// the phases of a band disagree between signals.
bool hasSeveralPhasesOnABand(const ObsHeader& h);

}  // namespace giocal
