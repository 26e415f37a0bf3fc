#include "common/odometer/vehicle_velocity.h"

#include "common/math/so3.h"

namespace giocal {

VehicleVelocity vehicleVelocity(const Eigen::Vector3d& v_n_b, const Eigen::Quaterniond& q_n_b,
                                const Eigen::Vector3d& gyro, const Eigen::Vector3d& b_g,
                                const Eigen::Vector3d& p_b_m, const Eigen::Quaterniond& q_b_m) {
  const Mat3 R_b_n = q_n_b.toRotationMatrix().transpose();
  const Mat3 R_m_b = q_b_m.toRotationMatrix().transpose();
  const Vec3 w_b = gyro - b_g;
  const Vec3 v_b = R_b_n * v_n_b;
  const Vec3 u_b = v_b + w_b.cross(p_b_m);  // vehicle origin velocity in b
  VehicleVelocity out;
  out.v_m = R_m_b * u_b;
  out.w_m = R_m_b * w_b;
  out.dv_dv_n = R_m_b * R_b_n;
  out.dv_dq_n_b = R_m_b * skew(v_b);
  out.dv_dbg = R_m_b * skew(p_b_m);
  out.dv_dp_b_m = R_m_b * skew(w_b);
  out.dv_dq_b_m = skew(out.v_m);
  out.dw_dbg = -R_m_b;
  out.dw_dq_b_m = skew(out.w_m);
  return out;
}

}  // namespace giocal
