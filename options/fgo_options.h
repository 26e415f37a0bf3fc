// FgoOptions: the factor graph's own options (window, solver, robust losses) with their defaults,
// loadable from the "fgo" section of a giocal YAML config.
#pragma once

#include <string>

namespace giocal {

class YamlFields;

/// How the window is solved. Both minimize the same robust cost; Gauss-Newton forms the sparse
/// Hessian once per iteration and keeps its last factorization for the covariances (faster, the
/// default); Ceres (trust region started as Gauss-Newton) is the reference it is tested against.
enum class WindowSolver { kGaussNewton, kCeres };

struct FgoOptions {
  int window = 30;  // GNSS epochs kept in the window (chosen by measurement, docs/results.md)
  int max_iterations = 10;       // solver iterations per solve
  double stop_step_sigma = 0.1;  // Gauss-Newton ends when the step left is below this [sigma]
  WindowSolver solver = WindowSolver::kGaussNewton;  // "gauss_newton" or "ceres" (the reference)
  double code_huber = 3.0;       // Huber threshold of DD code and Doppler factors [sigma]
  double rejection_sigma = 5.0;  // rows with post-solve residuals beyond this are removed
  int max_rejections = 5;        // per epoch
  // An odometer sample this many speed sigmas off its interval's common offset from the IMU is
  // wheel slip and left out (0: no check; fgo/odometer_slip_check.cc).
  double odometer_slip_sigma = 5.0;
};

/// Throws DataError naming the file, line and problem; an empty path gives the defaults.
FgoOptions readFgoOptions(const std::string& path);
/// The same from a configuration already parsed (keys asked for are remembered, see
/// YamlFields::rejectUnknownKeys).
FgoOptions readFgoOptions(const YamlFields& y);

}  // namespace giocal
