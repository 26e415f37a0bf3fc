// compressRows: measurement rows replaced by fewer rows that carry the same information.
#pragma once

#include <vector>

#include "common/models/measurement_rows.h"

namespace giocal {

/// The rows `subset` of `rows` (uncorrelated in R with the others) replaced by at most as many
/// whitened rows (R = I) as the state columns they touch, with the same H^T R^-1 H and
/// H^T R^-1 r: a Kalman update with the result gives the same correction and covariance, Schmidt
/// (held) states included, for fewer rows. The innovation's part no state explains is dropped,
/// so the update's NIS is smaller. Returns `rows` unchanged where nothing is gained or the subset
/// is correlated with the other rows or its R is not positive definite.
MeasurementRows compressRows(const MeasurementRows& rows, const std::vector<int>& subset);

}  // namespace giocal
