// CycleSlipDetector: flags carrier-phase cycle slips of one receiver from the loss-of-lock
// indicator, the geometry-free combination, the Melbourne-Wuebbena combination and the Doppler
// prediction of the phase change.
#pragma once

#include <utility>
#include <vector>

#include "common/gnss/observation.h"

namespace giocal {

struct CycleSlipOptions {
  double gf_threshold = 0.05;      // jump of the geometry-free combination [m], plus...
  double gf_rate = 0.003;          // ...this much per second between epochs (ionosphere) [m/s]
  double mw_threshold = 4.0;       // jump of Melbourne-Wuebbena [wide-lane cycles]; decides only
                                   // where the geometry-free or the Doppler test is missing
  double doppler_threshold = 5.0;  // phase change against Doppler, common part removed [cycles]
  double max_gap = 60.0;           // a longer gap in tracking counts as a slip [s]
  double doppler_max_gap = 2.0;    // the Doppler test bridges gaps up to this long [s]
};

class CycleSlipDetector {
 public:
  explicit CycleSlipDetector(const CycleSlipOptions& options = {}) : options_(options) {}

  /// Updates with one epoch; afterwards slipped(sat, band) tells whether that phase slipped
  /// since the previous epoch (a new satellite or signal counts as slipped, and so does a band
  /// whose best signal changed attribute, e.g. L2W to L2L: another tracking loop, with its own
  /// integer). Every band with a phase is tracked; the geometry-free and Melbourne-Wuebbena
  /// tests pair it with the satellite's primary band (for the primary band, with its first other
  /// band), and are skipped for an epoch in which that partner changed attribute.
  void update(const ObsEpoch& epoch);
  bool slipped(const SatId& sat, char band) const;

 private:
  struct Track {
    double t = 0, gf = 0, mw = 0, L = 0;
    bool has_gf = false, has_mw = false;
    double D = 0;
    char attr = 0, partner_attr = 0;  // the signal's attribute and its partner's
  };
  using Key = std::pair<SatId, char>;
  CycleSlipOptions options_;
  // Sorted by key: flat vectors rebuilt each epoch (maps cost an allocation per signal).
  std::vector<std::pair<Key, Track>> tracks_, next_;
  std::vector<std::pair<Key, bool>> slip_;
};

}  // namespace giocal
