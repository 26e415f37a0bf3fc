#include "common/gnss/pos_file.h"

#include <cmath>
#include <cstdio>

#include "common/geodesy/wgs84.h"
#include "common/io/atomic_file.h"
#include "common/math/rotation.h"
#include "common/time/gps_time.h"

namespace giocal {

namespace {
// RTKLIB writes off-diagonal covariances as signed square roots.
double signedSqrt(double x) { return x < 0.0 ? -std::sqrt(-x) : std::sqrt(x); }
}  // namespace

void writePosFile(const std::string& path, const PosHeader& header,
                  const std::vector<RtkSolution>& solutions) {
  AtomicFile file(path);
  auto& out = file.stream();
  out << "% program   : " << header.program << "\n";
  for (const auto& in : header.inputs) out << "% inp file  : " << in << "\n";
  out << "% pos mode  : kinematic\n";
  const Geodetic b = geodeticFromEcef(header.base_e);
  char buf[256];
  std::snprintf(buf, sizeof(buf), "%% ref pos   :%14.9f %14.9f %10.4f\n", b.lat * kRadToDeg,
                b.lon * kRadToDeg, b.h);
  out << buf;
  out << "%\n% (lat/lon/height=WGS84/ellipsoidal,Q=1:fix,2:float,3:sbas,4:dgps,5:single,6:ppp,ns=# "
         "of satellites)\n";
  out << "%  GPST                  latitude(deg) longitude(deg)  height(m)   Q  ns   sdn(m)   "
         "sde(m)   sdu(m)  sdne(m)  sdeu(m)  sdun(m) age(s)  ratio\n";
  for (const RtkSolution& s : solutions) {
    if (s.quality == 0) continue;
    const Geodetic g = geodeticFromEcef(s.p_e);
    const Eigen::Matrix3d R = rotationEcefFromEnu(g.lat, g.lon);
    const Eigen::Matrix3d Q = R.transpose() * s.cov_e * R;  // ENU
    std::snprintf(
        buf, sizeof(buf),
        "%s %14.9f %14.9f %10.4f %3d %3d %8.4f %8.4f %8.4f %8.4f %8.4f %8.4f %6.2f %6.1f\n",
        formatCalendar(calendarFromGpsSeconds(s.t)).c_str(), g.lat * kRadToDeg, g.lon * kRadToDeg,
        g.h, s.quality, s.satellites, std::sqrt(Q(1, 1)), std::sqrt(Q(0, 0)), std::sqrt(Q(2, 2)),
        signedSqrt(Q(1, 0)), signedSqrt(Q(0, 2)), signedSqrt(Q(2, 1)), s.age, s.ratio);
    out << buf;
  }
  file.commit();
}

}  // namespace giocal
