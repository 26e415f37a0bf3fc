// TdcpModel: one receiver's time-differenced carrier phase predicted from the poses at the pair's
// two epochs through the GNSS lever arm (antenna p_e = origin + R_e_n (p_n_b + R_n_b p_b_g) at
// each), one row per satellite-minus-reference difference; the receiver clock's change cancels.
// The EKF gives it a clone of the pose at the first epoch, the factor graph two epochs' states.
#pragma once

#include <vector>

#include "common/geodesy/wgs84.h"
#include "common/gnss/time_differenced_phase.h"
#include "common/models/measurement_model.h"

namespace giocal {

class TdcpModel : public MeasurementModel {
 public:
  TdcpModel(const LocalFrame& frame, TdcpPair pair);
  std::string name() const override { return "tdcp"; }
  /// p_n_b@i, q_n_b@i (the first epoch), p_n_b@j, q_n_b@j (the second), p_b_g.
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return static_cast<int>(pair_.rows.size()); }
  /// residual = predicted - observed phase change difference [m]
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override { return covariance_; }

 private:
  LocalFrame frame_;
  TdcpPair pair_;
  Eigen::MatrixXd covariance_;
};

}  // namespace giocal
