#include "evaluation/ideal_imu.h"

#include <optional>

#include "common/geodesy/wgs84.h"
#include "common/imu/error_free_imu.h"
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
  for (std::size_t k = 1; k + 1 < recorded.size(); ++k) {
    const double t = recorded[k].t;
    const double h = 0.25 * (recorded[k + 1].t - recorded[k - 1].t);
    const std::optional<TruthSample> a = reference.at(t - h), b = reference.at(t + h),
                                     c = reference.at(t);
    if (!a || !b || !c || !(h > 0.0)) continue;
    const NavState xa = navStateFromRow(frame, *a), xb = navStateFromRow(frame, *b),
                   x = navStateFromRow(frame, *c);
    const Eigen::Vector3d w_nb_b =
        logSO3((xa.q_n_b.conjugate() * xb.q_n_b).toRotationMatrix()) / (2.0 * h);
    const ImuSample ideal = errorFreeImu(frame, x, (xb.v_n_b - xa.v_n_b) / (2.0 * h), w_nb_b);
    out[k].gyro = ideal.gyro;
    out[k].acc = ideal.acc;
  }
  return out;
}

}  // namespace giocal
