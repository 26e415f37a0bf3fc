// GnssUpdate: one GNSS epoch in the EKF: Doppler-aided code outlier check (stage 1), DD epoch,
// SD ambiguity states (added, reset on slips, removed when unseen), gated DD code and phase update
// (stage 2), gated Doppler update with clock drift, then LAMBDA partial fixing validated by ratio
// and fixed-solution residuals and applied as tight constraints.
#pragma once

#include <set>

#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/code_outlier_check.h"
#include "common/gnss/dd_epoch.h"
#include "common/gnss/fix_validation.h"
#include "ekf/calibration_filter.h"

namespace giocal {

struct GnssEpochReport {
  bool used = false;      // a DD update was made
  bool fixed = false;     // validated ambiguity fixes were applied
  bool diverged = false;  // DD code innovations far outside their covariance
  int dd_rows = 0, rejected_rows = 0, code_outliers = 0, ambiguity_resets = 0;
  int fixed_ambiguities = 0;
  int fixes_rejected = 0, fix_exclusions = 0;  // fixes that failed validation; of those, retried
  int tdcp_rows = 0, tdcp_slips = 0, tdcp_screened = 0;  // the single-receiver scheme
  int doppler_rows = 0;
  double ratio = 0.0;
};

class GnssUpdate {
 public:
  GnssUpdate(const BroadcastOrbits& orbits, const Eigen::Vector3d& base_e,
             const CalibrationOptions& options);
  /// Propagates `filter` to the rover epoch and updates it.
  GnssEpochReport process(CalibrationFilter& filter, const ObsEpoch& rover, const ObsEpoch& base);

 private:
  void resetAmbiguity(StateRegistry& s, const StateKey& key, double value, double lambda);
  void resolveAmbiguities(CalibrationFilter& f, const DdEpoch& ep,
                          const std::vector<DdObservation>& phase_rows, GnssEpochReport& rep,
                          const std::vector<SatId>& excluded = {});

  const BroadcastOrbits& orbits_;
  CalibrationOptions options_;
  DdEpochBuilder builder_;
  CodeOutlierCheck rover_check_, base_check_;
  std::set<StateKey> ambiguities_;  // the SD ambiguity states in the registry
  double t_last_ = NAN;
};

}  // namespace giocal
