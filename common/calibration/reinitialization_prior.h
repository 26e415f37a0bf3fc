// Reinitialization prior: the calibration a re-initialization after a divergence starts from.
#pragma once

#include "common/calibration/calibration_run.h"
#include "common/io/dataset_description.h"

namespace giocal {

/// The dataset with its calibration prior's mean replaced by the estimate, the scales' sigmas
/// kept at least the prior's (a diverged estimator is not trusted). An estimate beyond 3 sigmas
/// of the guess (the rotation by its angle against the largest angle sigma) leaves the dataset as
/// it was: a diverged estimator's calibration can be anything (docs/results.md, "The factor
/// graph's own solver with a near-perfect IMU": re-initialized from it, the factor graph diverged
/// 29 times; from the guess, 4 times, ending with NEES7 0.9).
DatasetDescription reinitializationPrior(DatasetDescription d, const CalibrationEstimate& e);

}  // namespace giocal
