#include "common/gnss/double_difference.h"

namespace giocal {

double ddRange(const Eigen::Vector3d& rover_e, const SdGeometry& sat, const SdGeometry& ref,
               Eigen::RowVector3d* d_rover) {
  const Eigen::Vector3d di = sat.sat_at_rover_e - rover_e;
  const Eigen::Vector3d dr = ref.sat_at_rover_e - rover_e;
  const double ri = di.norm(), rr = dr.norm();
  if (d_rover) *d_rover = (-di / ri + dr / rr).transpose();
  return (ri - sat.base_range) - (rr - ref.base_range);
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

}  // namespace giocal
