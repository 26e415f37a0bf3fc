// Single point positioning by iterative weighted least squares (one receiver clock per system) and
// Doppler velocity with a receiver clock drift, both with residual-based outlier rejection.
#pragma once

#include <Eigen/Core>
#include <map>
#include <vector>

#include "common/geodesy/wgs84.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/observation.h"
#include "common/gnss/pos_reader.h"
#include "common/gnss/weighting.h"

namespace giocal {

struct SppOptions {
  double elevation_mask_deg = 10.0;
  std::vector<GnssSystem> systems;  // the systems used; empty: every system
  double cn0_mask_dbhz = 0.0;       // 0 disables the C/N0 mask
  ElevationNoise code{0.6};         // broadcast-orbit SPP: code noise plus unmodelled errors
  ElevationNoise doppler{0.05};     // [m/s]
  double max_gdop = 30.0;
  double chi2_probability = 0.999;  // outlier test: reject the worst until the chi2 test passes
  int max_rejections = 4;
  // A satellite with code on a second band enters as their ionosphere-free combination (three
  // times one band's noise, no ionosphere model); without one, its primary band with the
  // broadcast (Klobuchar) model, whose error is metres of slow, common bias.
  bool ionosphere_free = false;
};

struct SppSolution {
  bool valid = false;
  Eigen::Vector3d p_e = Eigen::Vector3d::Zero();
  Eigen::Matrix3d cov_p = Eigen::Matrix3d::Zero();
  std::map<GnssSystem, double> clock_m;  // receiver clock per system [m]
  double gdop = 0.0;
  // The position's covariance (ECEF) per unit [m^2] of independent range errors on the satellites
  // used, through the weighted solution: (N^-1 H^T W)(N^-1 H^T W)^T's position block.
  Eigen::Matrix3d range_error_cov_p = Eigen::Matrix3d::Zero();
  std::vector<SatId> used, rejected;
  bool velocity_valid = false;
  Eigen::Vector3d v_e = Eigen::Vector3d::Zero();
  double clock_drift_m_s = 0.0;  // receiver clock drift times c [m/s]
  std::vector<SatId> doppler_rejected;
};

SppSolution solveSpp(const ObsEpoch& epoch, const BroadcastOrbits& orbits,
                     const SppOptions& options);

/// The solution as a position fix at time t (RTKLIB's quality 5, single), its ENU covariance's
/// standard deviations raised to at least `sigma_min` [m]: a single point position's errors are
/// metres and slow, which its own covariance, from the code noise alone, does not say.
PositionFix sppFix(const SppSolution& spp, double t, double sigma_min);

/// The covariance, in the local frame n, of the position error that a slow range error of `sigma`
/// [m] on every satellite, independently, makes through the solution: sigma^2 range_error_cov_p
/// turned from ECEF into n. Broadcast
/// orbits and clocks and the atmosphere models err by decimetres to metres per satellite for
/// minutes; under few satellites their sum is metres.
Eigen::Matrix3d sppBiasCovariance(const LocalFrame& frame, const SppSolution& spp, double sigma);

/// chi-square quantile for `dof` degrees of freedom (Wilson-Hilferty approximation).
double chi2Quantile(double probability, int dof);

}  // namespace giocal
