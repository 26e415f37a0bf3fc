// CodeOutlierCheck: the first stage of the reference paper's outlier mitigation (Song et al.
// 2025): each pseudo-range is predicted from the previous accepted one plus the Doppler-integrated
// range change; a pseudo-range whose jump from that prediction stands out from the common
// (receiver clock) jump of all satellites is an outlier.
#pragma once

#include <set>
#include <utility>
#include <vector>

#include "common/gnss/observation.h"

namespace giocal {

struct CodeOutlierOptions {
  double threshold_m = 3.0;  // largest accepted departure from the Doppler prediction [m]
  double max_gap_s = 5.0;    // a longer gap restarts a satellite's track
  int min_satellites = 4;    // fewer tracked signals: no decision (all accepted)
  int max_consecutive = 3;   // after this many rejections in a row the track restarts
};

class CodeOutlierCheck {
 public:
  using Key = std::pair<SatId, char>;  // satellite and band
  explicit CodeOutlierCheck(const CodeOutlierOptions& options = {}) : options_(options) {}

  /// The signals of this epoch whose pseudo-range is an outlier. Epochs must come in time order.
  std::set<Key> check(const ObsEpoch& epoch);

 private:
  struct Track {
    double t = 0.0;
    double P = 0.0;  // last accepted (or predicted) pseudo-range [m]
    double range_rate = 0.0;
    int rejected_in_row = 0;
  };
  struct Candidate {
    Key key;
    double P, range_rate, jump;
    bool tracked;
  };
  CodeOutlierOptions options_;
  std::vector<std::pair<Key, Track>> tracks_, next_;  // sorted by key
  // One epoch's signals and their jumps: kept, so that an epoch allocates nothing.
  std::vector<Candidate> cands_;
  std::vector<double> jumps_;
};

}  // namespace giocal
