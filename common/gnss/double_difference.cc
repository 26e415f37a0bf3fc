#include "common/gnss/double_difference.h"

namespace giocal {

double ddRange(const Eigen::Vector3d& rover_e, const SdGeometry& sat, const SdGeometry& ref,
               Eigen::RowVector3d* d_rover) {
  const Eigen::Vector3d di = sat.sat_at_rover_e - rover_e;
  const Eigen::Vector3d dr = ref.sat_at_rover_e - rover_e;
  const double ri = di.norm(), rr = dr.norm();
  if (d_rover) *d_rover = (-di / ri + dr / rr).transpose();
  return (ri - sat.base_range + sat.tropo_sd) - (rr - ref.base_range + ref.tropo_sd);
}

double ddPredict(const DdObservation& o, const std::vector<SdGeometry>& geometry,
                 const Eigen::Vector3d& rover_e, double n_sat, double n_ref,
                 Eigen::RowVector3d* d_rover) {
  const double range = ddRange(rover_e, geometry[static_cast<size_t>(o.sat_index)],
                               geometry[static_cast<size_t>(o.ref_index)], d_rover);
  return o.phase ? range + o.lambda * (n_sat - n_ref) : range;
}

int chooseReference(const std::vector<SdGeometry>& geometry, const std::vector<int>& candidates,
                    int previous, double keep_elevation) {
  int best = -1;
  for (int i : candidates) {
    if (i == previous && geometry[static_cast<size_t>(i)].el >= keep_elevation) return i;
    if (best < 0 || geometry[static_cast<size_t>(i)].el > geometry[static_cast<size_t>(best)].el)
      best = i;
  }
  return best;
}

Eigen::MatrixXd ddCovariance(const std::vector<DdObservation>& obs,
                             const std::vector<std::pair<double, double>>& var) {
  const long m = static_cast<long>(obs.size());
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(m, m);
  auto v = [&](const DdObservation& o, int idx) {
    const auto& p = var[static_cast<size_t>(idx)];
    return o.phase ? p.second : p.first;
  };
  // Rows share their reference's variance when they share the reference, band and kind: each
  // row's group found once (its first row), the rows of a group chained, and only they paired.
  const auto n = static_cast<size_t>(m);
  std::vector<long> first(n), next(n, -1), last(n, -1);
  for (size_t a = 0; a < n; ++a) {
    const DdObservation& o = obs[a];
    first[a] = static_cast<long>(a);
    for (size_t b = 0; b < a; ++b) {
      const DdObservation& ob = obs[b];
      if (first[b] == static_cast<long>(b) && ob.ref == o.ref && ob.band == o.band &&
          ob.phase == o.phase) {
        first[a] = static_cast<long>(b);
        break;
      }
    }
    const auto g = static_cast<size_t>(first[a]);
    if (last[g] >= 0) next[static_cast<size_t>(last[g])] = static_cast<long>(a);
    last[g] = static_cast<long>(a);
  }
  for (long a = 0; a < m; ++a) {
    const DdObservation& o = obs[static_cast<size_t>(a)];
    R(a, a) = v(o, o.sat_index);
    for (long b = first[static_cast<size_t>(a)]; b >= 0; b = next[static_cast<size_t>(b)])
      R(a, b) += v(o, o.ref_index);
  }
  return R;
}

}  // namespace giocal
