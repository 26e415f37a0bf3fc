// Reader of RTKLIB-style solution files (.pos, giocal rtk's or RTKLIB's rnx2rtkp's with
// latitude/longitude/height output): '%' header lines, then per epoch the GPST time
// ("yyyy/mm/dd hh:mm:ss.sss" or "week tow"), lat lon height, Q, ns and the ENU standard
// deviations with their signed-square-root covariances.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace giocal {

struct PositionFix {
  double t = 0.0;                                         // GPS seconds
  Eigen::Vector3d p_e = Eigen::Vector3d::Zero();          // ECEF [m]
  Eigen::Matrix3d cov_enu = Eigen::Matrix3d::Identity();  // at the position [m^2]
  int quality = 0;                                        // 1 fix, 2 float, 5 single (RTKLIB's Q)
  int satellites = 0;
};

/// How far in time a position solution may be from the rover epoch it stands for [s].
constexpr double kPositionTolerance = 0.05;

/// The fix within `tolerance` seconds of t (the nearest), or null. `fixes` in rising time.
const PositionFix* fixAt(const std::vector<PositionFix>& fixes, double t, double tolerance);

/// Throws DataError naming the file, line and field for anything it cannot read; the times
/// must increase. A covariance that is not positive definite (RTKLIB's fixed solutions often
/// print correlations beyond +-1) becomes the nearest positive definite one with the same
/// standard deviations; `warnings` (if given) gets one line counting them and naming the first.
std::vector<PositionFix> readPosFile(const std::string& path,
                                     std::vector<std::string>* warnings = nullptr);

/// The correlations of `cov` made a positive definite correlation matrix (eigenvalues floored,
/// then the diagonal put back to 1), with cov's standard deviations.
Eigen::Matrix3d nearestPositiveDefinite(const Eigen::Matrix3d& cov);

}  // namespace giocal
