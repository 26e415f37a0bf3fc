// Fix validation: the test of a fixed solution by its DD phase residuals, and the one satellite a
// failed fix may leave out; shared by `giocal rtk` and both calibrators.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "common/gnss/double_difference.h"

namespace giocal {

/// The outcome of checking a fixed solution's DD phase residuals.
struct FixCheck {
  bool ok = false;               // every row within the limit
  std::optional<SatId> exclude;  // when not ok: the satellite to leave out of one more try
};

/// `normalized[k]` is |residual| / sigma of phase row `rows[k]` at the fixed solution. Every row
/// within `limit`: ok. Otherwise the satellite of the row furthest beyond it is named, unless
/// `excluded` already holds one (one bad satellite is tolerated per fix, not a string of them): a
/// correct fix with one wrong row (a signal a quarter cycle off between receivers of two makes,
/// an undetected slip) is then retried without that satellite's ambiguities, and the retry must
/// pass this test on its own rows.
FixCheck checkFixResiduals(const std::vector<DdObservation>& rows,
                           const Eigen::VectorXd& normalized, double limit,
                           const std::vector<SatId>& excluded);

/// Whether `row` involves a satellite of `excluded` as its non-reference satellite.
bool rowExcluded(const DdObservation& row, const std::vector<SatId>& excluded);

}  // namespace giocal
