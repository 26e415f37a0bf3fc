// Central-difference Jacobians of vector functions, for checking every analytic Jacobian.
#pragma once

#include <Eigen/Core>
#include <functional>

namespace giocal::test {

/// d f(x0 (+) d) / d d at d = 0, where `f_of_delta` applies the perturbation d (of size n) itself,
/// so the same helper checks vector blocks (x0 + d) and rotations (q0 * Exp(d)).
inline Eigen::MatrixXd numericJacobian(
    const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f_of_delta, int n,
    double h = 1e-6) {
  const Eigen::VectorXd f0 = f_of_delta(Eigen::VectorXd::Zero(n));
  Eigen::MatrixXd J(f0.size(), n);
  for (int k = 0; k < n; ++k) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
    d[k] = h;
    const Eigen::VectorXd fp = f_of_delta(d);
    d[k] = -h;
    const Eigen::VectorXd fm = f_of_delta(d);
    J.col(k) = (fp - fm) / (2.0 * h);
  }
  return J;
}

/// Largest absolute difference, scaled by max(1, largest entry of the numeric Jacobian).
inline double relativeDifference(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric) {
  const double scale = std::max(1.0, numeric.cwiseAbs().maxCoeff());
  return (analytic - numeric).cwiseAbs().maxCoeff() / scale;
}

}  // namespace giocal::test
