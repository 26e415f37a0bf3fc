// RtkFilter: kinematic RTK between a rover and a base at a known position: an extended Kalman
// filter over rover position, velocity and single-differenced ambiguities fed with DD code and
// phase, LAMBDA fixing with the ratio test and partial AR, optional fix-and-hold.
#pragma once

#include <Eigen/Core>
#include <map>
#include <utility>
#include <vector>

#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/cycle_slip.h"
#include "common/gnss/dd_epoch.h"
#include "common/gnss/fix_validation.h"
#include "common/gnss/lambda.h"
#include "common/gnss/observation.h"
#include "common/gnss/spp.h"
#include "common/gnss/weighting.h"
#include "common/math/kalman_workspace.h"

namespace giocal {

struct RtkOptions {
  DdOptions dd;                   // mask, frequencies, systems, noise, cycle slips
  double accel_noise = 1.0;       // rover acceleration density [m/s^2/sqrt(Hz)]
  double ambiguity_noise = 1e-4;  // SD ambiguity random walk [cycles/sqrt(s)]
  double innovation_gate = 5.0;   // reject DD rows whose innovation exceeds this many sigma
  LambdaOptions lambda;
  bool fix_and_hold = false;
  double hold_sigma_cycles = 1e-3;
  double max_base_offset = 0.5;    // largest rover-base time-tag difference [s]
  double divergence_sigma = 10.0;  // code and phase innovations (medians) this far off: restart
  double max_outage = 5.0;         // an ambiguity not observed for longer is dropped [s]
  double max_fix_sigma = 0.02;  // a fix leaving a larger horizontal sigma is reported as float [m]
  double max_fix_residual = 4.0;  // every fixed-solution DD phase residual within this many sigma
};

struct RtkSolution {
  double t = 0.0;
  int quality = 0;  // 1 fixed, 2 float, 5 single, 0 none (RTKLIB's Q)
  Eigen::Vector3d p_e = Eigen::Vector3d::Zero();
  Eigen::Matrix3d cov_e = Eigen::Matrix3d::Zero();
  Eigen::Vector3d v_e = Eigen::Vector3d::Zero();
  int satellites = 0;
  double ratio = 0.0;
  double age = 0.0;  // rover minus base time tag [s]
};

class RtkFilter {
 public:
  RtkFilter(const BroadcastOrbits& orbits, const Eigen::Vector3d& base_e,
            const RtkOptions& options);
  /// One rover epoch with the base epoch nearest in time (nullptr when none: SPP only).
  RtkSolution process(const ObsEpoch& rover, const ObsEpoch* base);

 private:
  using AmbKey = std::pair<SatId, char>;
  int ambiguityIndex(const AmbKey& key) const;
  void addAmbiguity(const AmbKey& key, double value, double variance);
  void removeAmbiguity(const AmbKey& key);
  /// `normalized`: each row's |innovation| / its predicted sigma.
  bool diverged(const std::vector<DdObservation>& rows, const Eigen::VectorXd& normalized) const;
  /// The fixed solution's DD phase residuals over the active rows not left out (fix_validation.h).
  FixCheck checkFix(const DdEpoch& ep, const std::vector<bool>& active,
                    const std::vector<SatId>& excluded, const Eigen::VectorXd& x_fix) const;

  const BroadcastOrbits& orbits_;
  Eigen::Vector3d base_e_;
  RtkOptions options_;
  DdEpochBuilder dd_builder_;
  bool initialized_ = false;
  bool restarting_ = false;
  double t_last_ = 0.0;
  Eigen::VectorXd x_;  // [p (3), v (3), N...]
  Eigen::MatrixXd P_;
  KalmanWorkspace workspace_;
  std::vector<AmbKey> amb_keys_;        // state order of the ambiguities
  std::map<AmbKey, double> last_seen_;  // rover time each ambiguity was last observed
};

}  // namespace giocal
