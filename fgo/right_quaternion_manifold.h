// RightQuaternionManifold: Ceres manifold for quaternions stored [w, x, y, z] with the right
// perturbation q * Exp(d) that every model in common/ differentiates against.
#pragma once

#include <ceres/manifold.h>

namespace giocal {

/// The models return Jacobians already taken with respect to the tangent perturbation d, and
/// ModelCostFunction stores them in the first three of the four ambient columns. PlusJacobian is
/// therefore [I3; 0], which makes Ceres' product (ambient Jacobian) x (PlusJacobian) equal the
/// model's tangent Jacobian exactly.
class RightQuaternionManifold : public ceres::Manifold {
 public:
  int AmbientSize() const override { return 4; }
  int TangentSize() const override { return 3; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;
};

}  // namespace giocal
