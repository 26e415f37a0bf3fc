#include "replay/ideal_imu.h"

#include <optional>

#include "common/geodesy/wgs84.h"
#include "common/math/rotation.h"
#include "common/math/so3.h"

namespace giocal {

std::vector<ImuSample> idealImuAlong(const ReferenceTrajectory& reference,
                                     const std::vector<ImuSample>& recorded) {
  std::vector<ImuSample> out = recorded;
  const std::optional<TruthSample> first = reference.at(reference.begin());
  if (!first || recorded.size() < 3) return out;
  const LocalFrame frame(
      ecefFromGeodetic({first->lat_deg * kDegToRad, first->lon_deg * kDegToRad, first->h}));
  const Eigen::Vector3d w_ie_n = frame.omega_ie_n();
  for (std::size_t k = 1; k + 1 < recorded.size(); ++k) {
    const double t = recorded[k].t;
    const double h = 0.25 * (recorded[k + 1].t - recorded[k - 1].t);
    const std::optional<TruthSample> a = reference.at(t - h), b = reference.at(t + h),
                                     c = reference.at(t);
    if (!a || !b || !c || !(h > 0.0)) continue;
    const NavState xa = navStateFromRow(frame, *a), xb = navStateFromRow(frame, *b),
                   x = navStateFromRow(frame, *c);
    const Eigen::Matrix3d R_b_n = x.q_n_b.toRotationMatrix().transpose();
    // n is fixed to the Earth: the gyro also sees the Earth's rotation, and the accelerometer
    // the Coriolis acceleration and gravity.
    out[k].gyro =
        logSO3((xa.q_n_b.conjugate() * xb.q_n_b).toRotationMatrix()) / (2.0 * h) + R_b_n * w_ie_n;
    const Eigen::Vector3d a_n = (xb.v_n_b - xa.v_n_b) / (2.0 * h);
    out[k].acc = R_b_n * (a_n + 2.0 * w_ie_n.cross(x.v_n_b) - frame.gravity_n(x.p_n_b));
  }
  return out;
}

}  // namespace giocal
