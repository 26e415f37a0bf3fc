// The chi-square of a window factor's residual as the rest of the window predicts it (the
// deleted residual): what an EKF's innovation test sees, from a solve that includes the factor.
#pragma once

#include "fgo/sliding_window.h"

namespace giocal {

struct PredictedResidual {
  double chi2 = 0.0;
  int dof = 0;  // directions the rest of the window predicts; the others cannot be tested
};

/// At the window's solution a factor's whitened residual e has shrunk by what the factor pulled:
/// with A = J_w Sigma J_w^T (its share of the solution, from the posterior Sigma of its
/// variables), the residual the rest of the window predicts is (I - A)^-1 e with covariance
/// (I - A)^-1, so chi2 = e^T (I - A)^-1 e (exact for linear factors). Directions where the factor
/// alone decides the solution (1 - a below `min_share`) are left out of chi2 and dof.
PredictedResidual predictedResidual(const SlidingWindow& window, const Factor& factor,
                                    double min_share = 0.05);

}  // namespace giocal
