// codeRowsDiverged(): the divergence test both estimators apply to a GNSS epoch's DD code rows.
#pragma once

#include <vector>

#include "common/math/median.h"

namespace giocal {

/// Whether the code rows as a whole lie far outside their spread: at least four rows, and the
/// median of their normalized absolute residuals beyond `limit` (calibration.divergence_sigma).
/// The median, so that a few NLOS rows never call it; each estimator normalizes as it can (the
/// EKF by the innovation covariance, the factor graph by the code noise).
inline bool codeRowsDiverged(const std::vector<double>& z, double limit) {
  return z.size() >= 4 && median(z) > limit;
}

}  // namespace giocal
