#include "common/gnss/tdcp_track.h"

#include <cmath>

#include "common/geodesy/wgs84.h"

namespace giocal {

namespace {
// A single point velocity from Doppler, 1-sigma per axis [m/s]: a few centimetres per second of
// Doppler noise through the geometry, with a margin.
constexpr double kDopplerVelocitySigma = 0.1;
}  // namespace

SppOptions sppOnSkyOf(const TdcpOptions& tdcp) {
  SppOptions spp;
  spp.systems = tdcp.systems;
  spp.elevation_mask_deg = tdcp.elevation_mask_deg;
  spp.ionosphere_free = tdcp.spp_ionosphere_free;
  return spp;
}

std::optional<PositionFix> TdcpTrack::add(const ObsEpoch& epoch) {
  const SppSolution spp = solveSpp(epoch, orbits_, spp_);
  started_stretch_ = false;
  if (!spp.valid) {
    if (last_) builder_.add(epoch, last_->p_e);  // the slip tests see the epoch
    last_.reset();
    last_velocity_.reset();
    return std::nullopt;
  }
  const TdcpPair pair = builder_.add(epoch, spp.p_e);
  const TdcpDisplacement step =
      last_ && !pair.rows.empty() ? solveTdcpDisplacement(pair, last_->p_e) : TdcpDisplacement{};
  PositionFix fix;
  // Without a phase step, the Doppler velocities at both ends carry the track (decimetres per
  // step instead of millimetres: a rover file without carrier phase still gives a heading).
  const double dt = last_ ? epoch.t - last_->t : 0.0;
  const bool by_doppler =
      !step.valid && last_ && spp.velocity_valid && last_velocity_ && dt > 0.0 && dt <= max_step_s_;
  if (step.valid || by_doppler) {
    fix = *last_;
    fix.t = epoch.t;
    fix.p_e = last_->p_e + (step.valid ? step.d_e : 0.5 * dt * (*last_velocity_ + spp.v_e));
    cov_e_ += step.valid ? step.cov
                         : Eigen::Matrix3d(Eigen::Matrix3d::Identity() *
                                           std::pow(kDopplerVelocitySigma * dt, 2));
    const Geodetic g = geodeticFromEcef(fix.p_e);
    const Eigen::Matrix3d R_e_enu = rotationEcefFromEnu(g.lat, g.lon);
    fix.cov_enu = R_e_enu.transpose() * cov_e_ * R_e_enu;
  } else {
    fix = sppFix(spp, epoch.t, spp_sigma_min_);  // a new stretch
    cov_e_.setZero();
    started_stretch_ = true;
  }
  last_ = fix;
  last_velocity_ = spp.velocity_valid ? std::optional<Eigen::Vector3d>(spp.v_e) : std::nullopt;
  return fix;
}

}  // namespace giocal
