// What a symmetric information matrix leaves unobserved, judged on its Jacobi-scaled form (unit
// diagonal), so that a Hessian mixing metres, radians and cycles is judged alike in each unit.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace giocal {

/// An eigenvalue of the Jacobi-scaled matrix below this share of its largest is no information.
constexpr double kNullEigenvalue = 1e-10;

/// d with d_i = 1 / sqrt(H_ii) where H_ii > 0, else 1: diag(d) H diag(d) has a unit diagonal.
Eigen::VectorXd jacobiScale(const Eigen::MatrixXd& H);

/// Of the indices `idx`, those along which H (symmetric, positive semidefinite) holds no
/// information: a zero diagonal, or a part of a null direction of the scaled matrix larger than
/// `share` (default 1e-3).
std::vector<int> unobservedIndices(const Eigen::MatrixXd& H, const std::vector<int>& idx,
                                   double share = 1e-3);

}  // namespace giocal
