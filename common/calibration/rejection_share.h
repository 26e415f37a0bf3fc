// Rejection share: whether the estimate still fits its data at the end of a run, from the share
// of odometer intervals and GNSS rows its gates turned away; said in the run's warnings.
#pragma once

#include <string>
#include <vector>

#include "common/calibration/calibration_run.h"

namespace giocal {

/// One message per kind of measurement (odometer intervals, GNSS rows: DD rows, or with
/// `positions_only` (the LC scheme) three rows per position fix) of which more than
/// `fraction` were rejected by the gates. Why: a run whose estimate has left the data rejects
/// almost everything it is given and then drifts unchecked (docs/results.md, "The factor graph's
/// own solver with a near-perfect IMU": 1102 of 1237 odometer intervals); healthy runs reject
/// under 3 % of either, the fault-injection bench's NLOS outliers about a tenth of the code rows.
std::vector<std::string> rejectionShareWarnings(const CalibrationRun& run, bool positions_only,
                                                double fraction = 0.5);

/// Why a run's estimate has left its data, in a few words, or empty: more than half of its
/// odometer intervals or GNSS rows rejected by the gates (`positions_only` as above), or with
/// `loosely_coupled` more than half of its position fixes updating nothing. The run's status then
/// says `suspect: <why>`.
std::string suspectReason(const CalibrationRun& run, bool positions_only, bool loosely_coupled);

}  // namespace giocal
