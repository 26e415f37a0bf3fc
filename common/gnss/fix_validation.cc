#include "common/gnss/fix_validation.h"

#include <algorithm>
#include <cmath>

namespace giocal {

FixCheck checkFixResiduals(const std::vector<DdObservation>& rows,
                           const Eigen::VectorXd& normalized, double limit,
                           const std::vector<SatId>& excluded) {
  FixCheck c;
  long worst = -1;
  double worst_z = limit;
  for (long k = 0; k < normalized.size(); ++k) {
    // A NaN residual fails the check too (it would pass every comparison).
    if (!(normalized[k] <= worst_z)) {
      worst_z = normalized[k];
      worst = k;
      if (std::isnan(worst_z)) break;
    }
  }
  if (worst < 0) {
    c.ok = true;
    return c;
  }
  if (!excluded.empty() || std::isnan(worst_z)) return c;
  c.exclude = rows[static_cast<size_t>(worst)].sat;
  return c;
}

bool rowExcluded(const DdObservation& row, const std::vector<SatId>& excluded) {
  return std::find(excluded.begin(), excluded.end(), row.sat) != excluded.end();
}

}  // namespace giocal
