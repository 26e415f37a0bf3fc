// kalmanUpdate: the EKF measurement update (the optimal-gain covariance downdate P - K S K^T,
// equal to the Joseph form at that gain, checked) with an innovation chi-square gate.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/math/kalman_workspace.h"
#include "common/models/measurement_rows.h"

namespace giocal {

struct UpdateResult {
  Eigen::VectorXd dx;  // error-state correction to apply with the state's box-plus
  double nis = 0.0;    // normalized innovation squared
  bool accepted = false;
  // Not a gate's rejection: S was not positive definite, or the downdate left P with a negative
  // or non-finite variance (P is then restored). Counted apart (numerical_failures).
  bool numerical_failure = false;
};

/// Updates P in place and returns the correction; rejects (P unchanged) when the NIS exceeds
/// `chi2_gate` (pass infinity to disable the gate), or fails (P unchanged, numerical_failure).
/// Error-state indices in `held` are consider states (Schmidt): their gain rows are zero, so
/// neither they nor their variance change, while their uncertainty still enters the update of the
/// others. `workspace` (optional) keeps the temporaries' storage between updates.
UpdateResult kalmanUpdate(Eigen::MatrixXd& P, const MeasurementRows& rows, double chi2_gate,
                          const std::vector<int>& held = {}, KalmanWorkspace* workspace = nullptr);
/// The same into `out`, whose dx keeps its storage from one update to the next (a filter that
/// must not allocate per sample keeps one); out.dx is the correction only when out.accepted.
void kalmanUpdateInto(Eigen::MatrixXd& P, const MeasurementRows& rows, double chi2_gate,
                      const std::vector<int>& held, KalmanWorkspace& workspace, UpdateResult& out);

/// The update in two halves, for an iterated update whose intermediate covariances are not
/// kept: kalmanGainInto() leaves P as it is and gives the correction and NIS (out.accepted when
/// it passes the gate and S is positive definite); kalmanDowndate() then applies the covariance
/// downdate of that same gain, from what the gain left in `workspace` (nothing else may use the
/// workspace in between). Together they are kalmanUpdateInto(), to the bit.
void kalmanGainInto(const Eigen::MatrixXd& P, const MeasurementRows& rows, double chi2_gate,
                    const std::vector<int>& held, KalmanWorkspace& workspace, UpdateResult& out);
void kalmanDowndate(Eigen::MatrixXd& P, const std::vector<int>& held, KalmanWorkspace& workspace,
                    UpdateResult& out);

/// |innovation| / sqrt(S_ii) of every row, S = H P H^T + R: the per-row outlier test.
Eigen::VectorXd normalizedInnovations(const Eigen::MatrixXd& P, const MeasurementRows& rows);

}  // namespace giocal
