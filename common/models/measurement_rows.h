// MeasurementRows: a MeasurementModel linearized into Kalman-filter rows (H, residual, R) over the
// filter's error state.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/models/measurement_model.h"

namespace giocal {

/// Where one model block lives in the filter: its current value and the offset of its error state
/// (-1 for a block the filter holds fixed, which then contributes no H columns).
struct BlockBinding {
  const double* value = nullptr;
  int error_offset = -1;
};

struct MeasurementRows {
  Eigen::VectorXd residual;  // h(x) - z; the innovation is its negative
  Eigen::MatrixXd H;         // d residual / d error state
  Eigen::MatrixXd R;         // measurement noise covariance
};

/// Evaluates `model` at the bound values and scatters its Jacobian blocks into columns of H.
MeasurementRows linearize(const MeasurementModel& model, const std::vector<BlockBinding>& bindings,
                          int error_state_size);

/// What linearize() works in, kept by a caller from one call to the next.
struct LinearizeScratch {
  std::vector<const double*> params;
  std::vector<Eigen::MatrixXd> J;
};

/// The same into `rows`, reusing its storage and `scratch`'s: once they have the sizes, nothing
/// is allocated here (the model's own evaluate() aside).
void linearize(const MeasurementModel& model, const std::vector<BlockBinding>& bindings,
               int error_state_size, MeasurementRows& rows, LinearizeScratch& scratch);

}  // namespace giocal
