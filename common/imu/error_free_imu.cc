#include "common/imu/error_free_imu.h"

#include <Eigen/Geometry>

namespace giocal {

ImuSample errorFreeImu(const LocalFrame& frame, const NavState& x, const Eigen::Vector3d& a_n_b,
                       const Eigen::Vector3d& w_nb_b) {
  const Eigen::Matrix3d R_n_b = x.q_n_b.toRotationMatrix();
  const Eigen::Vector3d w_ie_n = frame.omega_ie_n();
  ImuSample s;
  s.t = x.t;
  // Earth-fixed n: a = R f + g - 2 w_ie x v, with g the normal gravity at the position.
  s.acc = R_n_b.transpose() * (a_n_b - frame.gravity_n(x.p_n_b) + 2.0 * w_ie_n.cross(x.v_n_b));
  s.gyro = w_nb_b + R_n_b.transpose() * w_ie_n;
  return s;
}

}  // namespace giocal
