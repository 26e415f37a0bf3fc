// TdcpTrack: one receiver's antenna track, single point positions joined by time-differenced
// carrier phase displacements: its shape is good to centimetres over tens of metres while its
// offset carries the single point position's metres. What the single-receiver scheme's initial
// heading is measured on (a track of single point positions alone would need ~100 m of straight
// driving for 3 degrees).
#pragma once

#include <optional>

#include "common/gnss/pos_reader.h"
#include "common/gnss/spp.h"
#include "common/gnss/tdcp_displacement.h"
#include "common/gnss/time_differenced_phase.h"

namespace giocal {

/// Single point positions on the sky of the time differences: their systems and elevation mask,
/// ionosphere-free where two bands allow (spp_ionosphere_free), the rest SPP's defaults (one
/// receiver's scheme uses one sky).
SppOptions sppOnSkyOf(const TdcpOptions& tdcp);

class TdcpTrack {
 public:
  TdcpTrack(const BroadcastOrbits& orbits, const TdcpOptions& options, double spp_sigma_min)
      : orbits_(orbits),
        builder_(orbits, options),
        spp_(sppOnSkyOf(options)),
        spp_sigma_min_(spp_sigma_min),
        max_step_s_(options.max_interval_s) {}
  /// The track's point at the epoch, nullopt without a single point position. Its cov_enu is the
  /// uncertainty of its displacement from the start of its stretch (the TDCP steps summed); a
  /// step without a phase displacement is bridged by the Doppler velocities at both ends
  /// (decimetres), and without those starts a new stretch at the single point position, whose
  /// sigma (at least spp_sigma_min) it then carries.
  std::optional<PositionFix> add(const ObsEpoch& epoch);
  /// Whether the last add() started a new stretch (its offset is another single point position's).
  bool startedStretch() const { return started_stretch_; }

 private:
  const BroadcastOrbits& orbits_;
  TdcpBuilder builder_;
  SppOptions spp_;
  double spp_sigma_min_;
  double max_step_s_;
  std::optional<PositionFix> last_;
  std::optional<Eigen::Vector3d> last_velocity_;     // the Doppler velocity at last_ (ECEF)
  Eigen::Matrix3d cov_e_ = Eigen::Matrix3d::Zero();  // summed step covariance, ECEF
  bool started_stretch_ = false;
};

}  // namespace giocal
