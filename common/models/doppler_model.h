// DopplerModel: the rover's Doppler range rates predicted from the IMU velocity, the antenna's
// lever-arm velocity (gyro rate x p_b_g) and the receiver clock drift.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/gnss/doppler.h"
#include "common/models/measurement_model.h"

namespace giocal {

class DopplerModel : public MeasurementModel {
 public:
  /// R_e_n: the local frame's orientation; gyro: the raw IMU rate at the epoch.
  DopplerModel(const Eigen::Matrix3d& R_e_n, const Eigen::Vector3d& gyro,
               std::vector<DopplerObservation> observations);
  std::string name() const override { return "doppler"; }
  /// v_n_b, q_n_b, b_g, p_b_g, cdt_dot (receiver clock drift times c [m/s])
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return static_cast<int>(obs_.size()); }
  /// residual = los . (v_sat - v_antenna) - c dts_dot + cdt_dot - (-lambda D)
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override;

 private:
  Eigen::Matrix3d R_e_n_;
  Eigen::Vector3d gyro_;
  std::vector<DopplerObservation> obs_;
};

}  // namespace giocal
