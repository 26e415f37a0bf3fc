// whitener: the square-root information S (S^T S = C^-1) that turns a residual of covariance C
// into one of identity covariance; shared by every place that whitens a model.
#pragma once

#include <Eigen/Core>
#include <string>

namespace giocal {

/// S = L^-1 with C = L L^T. Throws std::invalid_argument naming `what` if C is not positive
/// definite or not finite.
Eigen::MatrixXd whitener(const Eigen::MatrixXd& C, const std::string& what);

}  // namespace giocal
