#include "common/calibration/reference_trajectory.h"

#include <algorithm>
#include <stdexcept>

#include "common/math/rotation.h"

namespace giocal {

ReferenceTrajectory::ReferenceTrajectory(std::vector<TruthSample> samples)
    : samples_(std::move(samples)) {
  if (samples_.size() < 2) throw std::invalid_argument("a reference trajectory needs two samples");
}

std::optional<TruthSample> ReferenceTrajectory::at(double t, double max_gap) const {
  if (!(t >= begin() && t <= end())) return std::nullopt;
  auto hi = std::lower_bound(samples_.begin(), samples_.end(), t,
                             [](const TruthSample& s, double v) { return s.t < v; });
  if (hi->t == t) return *hi;
  const TruthSample& b = *hi;
  const TruthSample& a = *(hi - 1);
  if (b.t - a.t > max_gap) return std::nullopt;
  return interpolateTruth(a, b, t);
}

TruthSample interpolateTruth(const TruthSample& a, const TruthSample& b, double t) {
  const double u = (t - a.t) / (b.t - a.t);
  TruthSample s;
  s.t = t;
  s.lat_deg = a.lat_deg + u * (b.lat_deg - a.lat_deg);
  s.lon_deg = a.lon_deg + u * (b.lon_deg - a.lon_deg);
  s.h = a.h + u * (b.h - a.h);
  s.v_enu = a.v_enu + u * (b.v_enu - a.v_enu);
  s.q_n_b = a.q_n_b.slerp(u, b.q_n_b).normalized();
  return s;
}

NavState navStateFromRow(const LocalFrame& frame, const TruthSample& s) {
  const Geodetic g{s.lat_deg * kDegToRad, s.lon_deg * kDegToRad, s.h};
  // Local level at the sample's position to the frame n (truthRow's R_here_n, transposed).
  const Eigen::Matrix3d R_n_here = frame.R_e_n().transpose() * rotationEcefFromEnu(g.lat, g.lon);
  NavState x;
  x.t = s.t;
  x.p_n_b = frame.enuFromEcef(ecefFromGeodetic(g));
  x.v_n_b = R_n_here * s.v_enu;
  x.q_n_b = Eigen::Quaterniond(R_n_here * s.q_n_b.toRotationMatrix()).normalized();
  return x;
}

Eigen::Vector3d antennaOfRow(const TruthSample& s, const Eigen::Vector3d& p_b_g) {
  const double lat = s.lat_deg * kDegToRad, lon = s.lon_deg * kDegToRad;
  return ecefFromGeodetic({lat, lon, s.h}) + rotationEcefFromEnu(lat, lon) * (s.q_n_b * p_b_g);
}

std::vector<TruthSample> positionRows(const std::vector<PositionFix>& fixes) {
  std::vector<TruthSample> rows;
  for (const PositionFix& f : fixes) {
    const Geodetic g = geodeticFromEcef(f.p_e);
    TruthSample s;
    s.t = f.t;
    s.lat_deg = g.lat * kRadToDeg;
    s.lon_deg = g.lon * kRadToDeg;
    s.h = g.h;
    rows.push_back(s);
  }
  return rows;
}

}  // namespace giocal
