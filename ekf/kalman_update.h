// kalmanUpdate: the EKF measurement update (Joseph form) with an innovation chi-square gate.
#pragma once

#include <Eigen/Core>

#include "ekf/measurement_rows.h"

namespace giocal {

struct UpdateResult {
  Eigen::VectorXd dx;  // error-state correction to apply with the state's box-plus
  double nis = 0.0;    // normalized innovation squared
  bool accepted = false;
};

/// Updates P in place and returns the correction; rejects (P unchanged) when the NIS exceeds
/// `chi2_gate` (pass infinity to disable the gate).
UpdateResult kalmanUpdate(Eigen::MatrixXd& P, const MeasurementRows& rows, double chi2_gate);

}  // namespace giocal
