#include "common/gnss/sky_view.h"

#include <Eigen/LU>
#include <cmath>

#include "common/gnss/atmosphere.h"

namespace giocal {

double positionDop(const std::vector<Eigen::Vector3d>& los) {
  if (los.size() < 4) return NAN;
  Eigen::MatrixXd G(static_cast<long>(los.size()), 4);
  for (size_t i = 0; i < los.size(); ++i) {
    G.row(static_cast<long>(i)) << -los[i].normalized().transpose(), 1.0;
  }
  const Eigen::Matrix4d N = G.transpose() * G;
  const Eigen::FullPivLU<Eigen::Matrix4d> lu(N);
  if (!lu.isInvertible()) return NAN;
  return std::sqrt(lu.inverse().topLeftCorner<3, 3>().trace());
}

SkyView skyView(const ObsEpoch& epoch, const BroadcastOrbits& orbits, const Eigen::Vector3d& rx_e,
                double elevation_mask_deg) {
  std::vector<Eigen::Vector3d> los;
  const Topocentric sky(rx_e);
  for (const SatObs& s : epoch.sats) {
    const SignalObs* sig = s.bestOnBand(primaryBand(s.sat.sys));
    if (!sig || !std::isfinite(sig->P)) continue;
    const auto sat = orbits.atReception(s.sat, epoch.t, sig->P, sig->band, rx_e);
    if (!sat) continue;
    double el = 0.0, az = 0.0;
    sky.elevationAzimuth(sat->p_e, el, az);
    if (el * 180.0 / M_PI < elevation_mask_deg) continue;
    los.push_back(sat->p_e - rx_e);
  }
  return {static_cast<int>(los.size()), positionDop(los)};
}

}  // namespace giocal
