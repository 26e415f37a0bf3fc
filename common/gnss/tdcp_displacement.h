// The antenna's displacement between the two epochs of a TDCP pair, by weighted least squares on
// the satellites' phase changes with one receiver clock change per system and band, leaving out
// the worst satellite until the residuals pass a chi-square test. A receiver alone, no motion
// model: the check of the TDCP layer on real logs, and the start value of an epoch's motion.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/gnss/time_differenced_phase.h"

namespace giocal {

struct TdcpDisplacementOptions {
  double chi2_probability = 0.999;
  int max_rejections = 4;
  int min_satellites = 5;  // signals left, over the clock changes, to solve three axes
};

struct TdcpDisplacement {
  bool valid = false;
  Eigen::Vector3d d_e = Eigen::Vector3d::Zero();  // p1 - p0, ECEF [m]
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  int signals_used = 0;
  std::vector<int> rejected;  // signal indices left out by the chi-square test
  double chi2 = 0.0;          // of the signals used
  int dof = 0;
};

/// p0_e: the antenna's approximate position at the first epoch (metres are enough).
TdcpDisplacement solveTdcpDisplacement(const TdcpPair& pair, const Eigen::Vector3d& p0_e,
                                       const TdcpDisplacementOptions& options = {});

}  // namespace giocal
