// updateWithModel(): one EKF measurement update from a shared MeasurementModel whose blocks are
// bound to registry variables by name: linearize, gate, update the covariance, correct the state.
#pragma once

#include <string>
#include <vector>

#include "ekf/kalman_update.h"
#include "ekf/state_registry.h"

namespace giocal {

/// `names[k]` is the registry variable of model block k. Rejected updates (NIS above chi2_gate)
/// leave the state untouched.
UpdateResult updateWithModel(StateRegistry& s, const MeasurementModel& model,
                             const std::vector<std::string>& names, double chi2_gate);

}  // namespace giocal
