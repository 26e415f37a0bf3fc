#include "fgo/right_quaternion_manifold.h"

#include <Eigen/Core>

#include "common/math/rotation.h"

namespace giocal {

bool RightQuaternionManifold::Plus(const double* x, const double* delta,
                                   double* x_plus_delta) const {
  quatToWxyz(boxPlus(quatFromWxyz(x), Eigen::Map<const Eigen::Vector3d>(delta)), x_plus_delta);
  return true;
}

bool RightQuaternionManifold::PlusJacobian(const double*, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, 4, 3, Eigen::RowMajor>> J(jacobian);
  J.setZero();
  J.topRows<3>().setIdentity();
  return true;
}

bool RightQuaternionManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  Eigen::Map<Eigen::Vector3d> out(y_minus_x);
  out = boxMinus(quatFromWxyz(y), quatFromWxyz(x));
  return true;
}

bool RightQuaternionManifold::MinusJacobian(const double*, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, 3, 4, Eigen::RowMajor>> J(jacobian);
  J.setZero();
  J.leftCols<3>().setIdentity();
  return true;
}

}  // namespace giocal
