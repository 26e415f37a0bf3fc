#include "common/gnss/tdcp_track.h"

#include "common/geodesy/wgs84.h"

namespace giocal {

std::optional<PositionFix> TdcpTrack::add(const ObsEpoch& epoch) {
  const SppSolution spp = solveSpp(epoch, orbits_, SppOptions{});
  if (!spp.valid) {
    builder_.add(epoch, last_ ? last_->p_e : Eigen::Vector3d::Zero());
    last_.reset();
    return std::nullopt;
  }
  const TdcpPair pair = builder_.add(epoch, spp.p_e);
  const TdcpDisplacement step =
      last_ && !pair.rows.empty() ? solveTdcpDisplacement(pair, last_->p_e) : TdcpDisplacement{};
  PositionFix fix;
  if (step.valid) {
    fix = *last_;
    fix.t = epoch.t;
    fix.p_e = last_->p_e + step.d_e;
    cov_e_ += step.cov;
    const Geodetic g = geodeticFromEcef(fix.p_e);
    const Eigen::Matrix3d R_e_enu = rotationEcefFromEnu(g.lat, g.lon);
    fix.cov_enu = R_e_enu.transpose() * cov_e_ * R_e_enu;
  } else {
    fix = sppFix(spp, epoch.t, spp_sigma_min_);  // a new stretch
    cov_e_.setZero();
  }
  last_ = fix;
  return fix;
}

}  // namespace giocal
