#include "common/io/tum_trajectory.h"

#include <cmath>
#include <cstdio>

#include "common/geodesy/wgs84.h"
#include "common/io/atomic_file.h"

namespace giocal {

void writeTumTrajectory(const std::string& path, const std::vector<TruthSample>& samples,
                        const Eigen::Vector3d& origin_e) {
  const LocalFrame frame(origin_e);
  AtomicFile file(path);
  auto& out = file.stream();
  out << "# timestamp[s, GPS] x y z[m, ENU] qx qy qz qw (q_n_b); giocal export --tum\n";
  char buf[256];
  for (const TruthSample& s : samples) {
    const Eigen::Vector3d p_e =
        ecefFromGeodetic({s.lat_deg * M_PI / 180.0, s.lon_deg * M_PI / 180.0, s.h});
    // q_n_b is in the local-level frame at the sample; the TUM pose is in the frame at the origin.
    const Eigen::Matrix3d R_n0_n =
        frame.R_e_n().transpose() *
        rotationEcefFromEnu(s.lat_deg * M_PI / 180.0, s.lon_deg * M_PI / 180.0);
    const Eigen::Quaterniond q(Eigen::Quaterniond(R_n0_n) * s.q_n_b);
    const Eigen::Vector3d p = frame.enuFromEcef(p_e);
    std::snprintf(buf, sizeof(buf), "%.6f %.4f %.4f %.4f %.9f %.9f %.9f %.9f\n", s.t, p.x(), p.y(),
                  p.z(), q.x(), q.y(), q.z(), q.w());
    out << buf;
  }
  file.commit();
}

}  // namespace giocal
